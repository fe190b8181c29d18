#include "trace/numerics_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "trace/camera.h"
#include "trace/oracle.h"
#include "trace/prepared_scene.h"
#include "trace/render.h"

namespace povwall::trace {

NumericsReport check_numerics(const Scene& scene, int width, int height) {
    NumericsReport rep;
    // The oracle's rules: exact bounds (POV-Ray's float box tests are not numerics).
    PrepareOptions exact;
    exact.pov_float_bounds = false;
    PreparedScene prepared(scene, nullptr, exact);
    RayContext ctx;
    prepared.init_context(ctx);
    std::map<std::string, std::vector<double>> errors;
    rep.verdict.assign(size_t(width) * height, PixelVerdict::Agree);
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            const std::optional<Ray> camera =
                camera_ray(scene.camera, px + 0.5, py + 0.5, width, height);
            if (!camera) continue;  // outside a fisheye's circle: no ray
            const Ray& ray = *camera;
            ++rep.rays;
            Hit fast;
            bool fast_hit =
                prepared.closest_hit(ray, 0, kInfinity, RayUse::Camera, fast, ctx);
            OracleHit truth = oracle_first_hit(scene, ray, 0);
            PixelVerdict& v = rep.verdict[size_t(py) * width + px];
            if (!truth.supported) {
                ++rep.unsupported;
                v = PixelVerdict::Unsupported;
                continue;
            }
            if (!fast_hit && !truth.hit) continue;
            const Object* fast_leaf =
                fast_hit && fast.material ? fast.material->object : nullptr;
            const Object* kind_of = truth.hit ? truth.leaf : fast_leaf;
            const std::string kind = kind_of ? shape_kind_name(*kind_of) : "?";
            ShapeKindNumerics& k = rep.kinds[kind];
            std::vector<double>& errs = errors[kind];
            ++k.rays;
            bool finite = std::isfinite(fast.t) && std::isfinite(fast.normal.x) &&
                          std::isfinite(fast.normal.y) && std::isfinite(fast.normal.z);
            if (fast_hit != truth.hit || (fast_hit && !finite)) {
                ++k.hit_miss;
                v = PixelVerdict::Disagree;
                continue;
            }
            double rel = std::fabs(fast.t - truth.t) / truth.t;
            if (fast_leaf != truth.leaf && rel > kOracleAgreement) {
                ++k.other_object;
                v = PixelVerdict::Disagree;
                continue;
            }
            ++k.compared;
            errs.push_back(rel);
            if (rel > kOracleAgreement) v = PixelVerdict::Disagree;
        }
    }
    for (auto& [name, errs] : errors) {
        if (errs.empty()) continue;
        std::sort(errs.begin(), errs.end());
        rep.kinds[name].max_rel_error = errs.back();
        rep.kinds[name].median_rel_error = errs[errs.size() / 2];
    }
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    Image img = render_scene(scene, settings);
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        bool bad = false;
        for (int c = 0; c < 4; ++c) bad = bad || !std::isfinite(img.rgba[i + c]);
        rep.nonfinite_pixels += bad;
    }
    return rep;
}

}  // namespace povwall::trace
