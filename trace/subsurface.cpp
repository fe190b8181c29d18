#include "trace/subsurface.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>

#include "core/hash_fold.h"
#include "trace/light_rays.h"
#include "trace/radiosity/gatherer.h"
#include "trace/tracer.h"

namespace povwall::trace {
namespace subsurface {

double diffuse_fresnel_reflectance(double eta) {
    if (eta < 1) return eta * eta - std::pow(eta, 2.25);
    const double x = 1 - 1 / eta;
    return (x + 3 * std::pow(x, 4.5)) / 4;
}

double fresnel_transmittance(double cos_angle, double eta) {
    if (!(cos_angle >= -1 && cos_angle <= 1)) return 1;
    const double g2 = eta * eta + cos_angle * cos_angle - 1;
    if (!(g2 >= 0)) return 1;
    const double g = std::sqrt(g2), c = cos_angle;
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1) / (c * (g - c) + 1);
    const double f = 0.5 * a * a * (1 + b * b);
    if (!(f >= 0)) return 1;  // NaN: POV-Ray's clamp makes it 0
    return 1 - std::min(f, 1.0);
}

double dipole_reflectance(double extinction, double absorption, double albedo, double a,
                          double r2) {
    const double st = extinction;
    const double str = std::sqrt(3 * absorption * st);
    const double zr = 1 / st, zv = zr * (1 + 4 * a / 3);
    const double dr = std::sqrt(zr * zr + r2), dv = std::sqrt(zv * zv + r2);
    const double real = zr * (str + 1 / dr) * std::exp(-str * dr) / (dr * dr);
    const double virt = zv * (str + 1 / dv) * std::exp(-str * dv) / (dv * dv);
    return albedo / (4 * kPi) * (real + virt);
}

namespace {

// Total diffuse reflectance of a semi-infinite slab of reduced albedo `alpha`, with
// A = (1 + Fdr) / (1 - Fdr) (Jensen et al.'s equation 15).
double slab_reflectance(double alpha, double a) {
    const double s = std::sqrt(3 * (1 - alpha));
    return alpha / 2 * (1 + std::exp(-4.0 / 3.0 * a * s)) * std::exp(-s);
}

}  // namespace

AlbedoTable::AlbedoTable(double ior) : ior_(ior) {
    const double fdr = diffuse_fresnel_reflectance(ior);
    const double a = (1 + fdr) / (1 - fdr);
    table_[0] = 0;
    table_[100] = 1;
    // Each entry solves R(alpha) = k / 100; R rises from 0 at 0 to 1 at 1, so the root
    // lies below the one above. Bisection to 1e-10 in R (any solver to that precision
    // rounds to the same float).
    double high = 1;
    for (int k = 99; k >= 1; --k) {
        const double want = k / 100.0;
        double lo = 0, hi = high;
        double mid = 0.5 * (lo + hi);
        for (int it = 0; it < 200; ++it) {
            mid = 0.5 * (lo + hi);
            const double r = slab_reflectance(mid, a) - want;
            if (std::fabs(r) < 1e-10) break;
            (r < 0 ? lo : hi) = mid;
        }
        table_[size_t(k)] = float(mid);
        high = mid;
    }
}

double AlbedoTable::reduced_albedo(double reflectance) const {
    // POV-Ray reads past its table for a reflectance outside [0, 1]; clamped here.
    const double x = 100 * std::clamp(reflectance, 0.0, 1.0);
    const double i0 = std::floor(x), i1 = std::ceil(x);
    const double p = x - i0;
    return (1 - p) * double(table_[size_t(i0)]) + p * double(table_[size_t(i1)]);
}

namespace {

struct Tables {
    std::vector<double> uniform;
    std::vector<Vector3> directions;
    Tables() : uniform(kTableSize), directions(kTableSize) {
        std::mt19937 engine;  // seed 5489, as a default-constructed boost engine
        for (double& u : uniform) u = double(engine()) / 4294967296.0;
        auto radical_inverse = [](size_t j, size_t base) {
            double r = 0, f = 1.0 / double(base);
            for (; j > 0; j /= base, f /= double(base)) r += f * double(j % base);
            return r;
        };
        for (size_t k = 0; k < kTableSize; ++k) {
            const double x = -1 + 2 * radical_inverse(k + 1, 2);
            const double phi = 2 * kPi * radical_inverse(k + 1, 3);
            const double r = std::sqrt(1 - x * x);
            directions[k] = Vector3(x, r * std::cos(phi), r * std::sin(phi));
        }
    }
};

const Tables& tables() {
    static const Tables t;
    return t;
}

}  // namespace

double uniform_number(size_t k) { return tables().uniform[k % kTableSize]; }
const Vector3& sphere_direction(size_t k) { return tables().directions[k % kTableSize]; }

}  // namespace subsurface

using namespace subsurface;

namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON in its SSLT code
using Channels = std::array<double, 3>;

Channels channels(const Rgb& c) { return {double(c.r), double(c.g), double(c.b)}; }
double grey(const Channels& c) { return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]; }
bool all_below(const Channels& c, double e) {
    return std::fabs(c[0]) < e && std::fabs(c[1]) < e && std::fabs(c[2]) < e;
}

// The medium under the surface, per channel (POV-Ray's reduced coefficients, 1/mm).
struct Medium {
    Channels scattering, extinction, absorption, albedo;
    double a;  // (1 + Fdr) / (1 - Fdr) for the relative index
};

double dipole(const Medium& m, int c, double r2) {
    return dipole_reflectance(m.extinction[size_t(c)], m.absorption[size_t(c)],
                              m.albedo[size_t(c)], m.a, r2);
}

// Where a stream starts for an evaluation at `p` (and SSLT depth): a hash of the point.
size_t stream_start(const Point3& p, int depth, uint64_t salt) {
    uint64_t h = 0x9e3779b97f4a7c15ull * (salt + 1) + uint64_t(depth);
    for (double v : {p.x, p.y, p.z}) h = hash_fold(h, v);
    return size_t(h % kTableSize);
}

}  // namespace

SubsurfaceTracer::SubsurfaceTracer(Tracer& tracer, RayContext& ctx)
    : tracer_(tracer), ctx_(ctx) {}

const AlbedoTable& SubsurfaceTracer::table_for(double ior) {
    for (const AlbedoTable& t : tables_)
        if (t.ior() == ior) return t;
    tables_.emplace_back(ior);
    return tables_.back();
}

Rgb SubsurfaceTracer::light(const SubsurfacePoint& at) {
    if (depth_ >= 2) return {};
    const PreparedScene& scene = tracer_.scene();
    const Scene& sc = scene.scene();
    const RenderPlan& plan = scene.plan();
    const Quality quality = plan.quality;
    const SubsurfaceSettings& settings = *sc.settings.subsurface;
    const int diffuse_samples = depth_ == 1 ? 1 : settings.samples_diffuse;
    const int single_samples = depth_ == 1 ? 1 : settings.samples_single;
    struct DepthGuard {
        int& d;
        explicit DepthGuard(int& depth) : d(depth) { ++d; }
        ~DepthGuard() { --d; }
    } guard(depth_);

    const Material& own = at.material;
    const uintptr_t own_id = own.interior_id;
    auto same_object = [&](const Hit& h) {
        return h.material && h.material->interior_id == own_id;
    };
    const double mm = sc.settings.mm_per_unit;
    const double eta = at.eta;
    const Point3 xo = at.hit.point;
    const Vector3 no = at.normal;
    const Vector3 d = at.ray.ray.direction;

    // Step 0: the medium, from the reflectance (through the albedo table of the
    // interior's own index) and the free path.
    const AlbedoTable& table = table_for(double(at.ior));
    Medium med;
    const Channels reflectance = channels(at.reflectance);
    const Channels translucency = channels(at.translucency);
    for (size_t c = 0; c < 3; ++c) {
        // A black channel has albedo 0, an infinite extinction (POV-Ray: a NaN);
        // here a tiny albedo, which lets no light through that channel.
        const double albedo = std::max(table.reduced_albedo(reflectance[c]), 1e-9);
        med.scattering[c] = 1 / translucency[c];
        med.extinction[c] = med.scattering[c] / albedo;
        med.absorption[c] = med.extinction[c] - med.scattering[c];
        med.albedo[c] = med.scattering[c] / med.extinction[c];
    }
    {
        const double fdr = diffuse_fresnel_reflectance(eta);
        med.a = (1 + fdr) / (1 - fdr);
    }
    const double mean_extinction = grey(med.absorption) + grey(med.scattering);
    const double free_path = 1 / (mean_extinction * mm);  // scene units

    // Light `l` reaching `x` on this object (normal `n`, either side) after its shadow
    // test: its colour and the cosine at `x`; false when it adds nothing there.
    TraceRay from;
    from.depth = at.ray.depth;
    auto light_reaching = [&](size_t l, const Point3& x, const Vector3& n,
                              Channels& colour, double& cos_in) {
        const Light& light = sc.lights[l];
        if (!lights_material(light, own)) return false;
        LightSample s;
        if (!light_at(light, x, s)) return false;
        colour = channels(s.colour);
        if (all_below(colour, kEpsilon)) return false;
        cos_in = std::fabs(dot(n, s.dir));
        if (cos_in < kEpsilon) return false;
        ChildRay shadow = shadow_child(from, x, s, l);
        shadow.unoccluded = shadow.unoccluded || light.shadowless || !quality.shadows() ||
                            (l < plan.lights.size() && plan.lights[l].unoccluded);
        shadow.area = light.area.has_value() && quality.area_lights();
        shadow.light_colour = s.colour;
        if (!shadow.unoccluded) {
            const Channels f = channels(shadow_transmittance(scene, shadow, ctx_));
            if (all_below(f, kEpsilon)) return false;
            for (size_t c = 0; c < 3; ++c) colour[c] *= f[c];
        }
        return true;
    };
    auto nearest = [&](const Point3& o, const Vector3& dir, Real t_max, Hit& h) {
        return scene.closest_hit(Ray{o, dir}, 0, t_max, RayUse::Query, h, ctx_);
    };

    // Step 1: the base point the diffuse samples start from, inside the surface: half
    // way to its back when that is near, at most one mean free path deep.
    const Vector3 inward = -no;
    Point3 base;
    {
        Hit h;
        if (!nearest(xo, inward, 2 * free_path, h))
            base = xo + inward * free_path;
        else if (same_object(h))
            base = xo + inward * (h.t / 2);
        else
            base = xo + inward * std::min(free_path, h.t - kEpsilon);
    }

    // With `subsurface { radiosity on }` each sample point also takes the radiosity
    // there, through the dipole as light along its normal (POV-Ray's
    // ComputeDiffuseAmbientContribution1).
    RadiosityGatherer* const gatherer = settings.radiosity && sc.settings.radiosity &&
                                                quality.level >= 9 && ctx_.radiosity &&
                                                ctx_.radiosity->active_for(at.ray)
                                            ? ctx_.radiosity
                                            : nullptr;

    // Step 2: the dipole term, from points of the object's surface hit by rays from the
    // base point in every direction, each weighted by the surface area it stands for.
    Channels sum{0, 0, 0};
    const double cos_out = std::clamp(dot(-d, no), -1.0, 1.0);
    const double ft_out = fresnel_transmittance(cos_out, eta);
    size_t next_direction = stream_start(xo, depth_, 1);
    int counted = 0;
    for (int i = 0; i < diffuse_samples; ++i) {
        const Vector3& v = sphere_direction(next_direction++);
        Hit h;
        if (!nearest(base, v, kInfinity, h)) continue;
        ++counted;
        if (!same_object(h)) continue;
        const Vector3 ni = h.normal;
        const double delta = length(h.point - base) * mm;
        const double cos_phi = std::max(0.01, std::fabs(dot(v, ni)));
        const double area = 4 * kPi * delta * delta / cos_phi;
        const double r2 = dot(h.point - xo, h.point - xo) * mm * mm;
        if (gatherer) {
            // The sample's area is the gather's weight: a small one reuses more.
            const Channels e = channels(gatherer->ambient(at.ray, h.point, ni, ni, area));
            const double f = fresnel_transmittance(1, eta) * ft_out;
            for (int c = 0; c < 3; ++c)
                sum[size_t(c)] += e[size_t(c)] * f * dipole(med, c, r2) * area;
        }
        for (size_t l = 0; l < sc.lights.size(); ++l) {
            Channels colour;
            double cos_in;
            if (!light_reaching(l, h.point, ni, colour, cos_in)) continue;
            const double f = fresnel_transmittance(std::min(cos_in, 1.0), eta) * ft_out;
            for (int c = 0; c < 3; ++c)
                sum[size_t(c)] +=
                    colour[size_t(c)] * cos_in * f * dipole(med, c, r2) * area;
        }
    }
    if (counted > 0)
        for (double& s : sum) s /= counted;

    // Step 3: the eye ray refracted into the surface, and how far it goes inside.
    const double e = 1 / eta;
    const double c1 = -dot(d, no);
    const double c2sq = 1 + e * e * (c1 * c1 - 1);
    if (c2sq >= 0) {
        const Vector3 t = normalize(d * e + no * (e * c1 - std::sqrt(c2sq)));
        Hit exit;
        const bool exits = nearest(xo, t, kInfinity, exit);
        const double dist = exits ? exit.t * mm : kInfinity;
        const double cos_o = dot(-d, no);
        const double cos_o_in = std::sqrt(1 - e * e * (1 - cos_o * cos_o));
        const double ft_o = fresnel_transmittance(cos_o, eta);

        // Step 4: single scattering along the refracted ray, one distance per sample
        // and channel.
        size_t next_number = stream_start(xo, depth_, 2);
        for (int i = 0; i < single_samples; ++i) {
            for (int c = 0; c < 3; ++c) {
                const double eps = uniform_number(next_number++);
                const double st = med.extinction[size_t(c)];
                const double ss = med.scattering[size_t(c)];
                const double so = std::fabs(std::log(eps)) / st;
                if (!(so < dist)) continue;
                const Point3 q = xo + t * (so / mm);
                double lo = 0;
                for (size_t l = 0; l < sc.lights.size(); ++l) {
                    const Light& light = sc.lights[l];
                    if (!lights_material(light, own)) continue;
                    LightSample toward;
                    if (!light_ray_toward(light, q, light.location, toward)) continue;
                    Hit h;
                    if (!nearest(q, toward.dir, kInfinity, h) || !same_object(h))
                        continue;
                    // The light entering at that point (this light only).
                    Channels colour;
                    double cos_in;
                    if (!light_reaching(l, h.point, h.normal, colour, cos_in)) continue;
                    const double sin2 = (1 - cos_in * cos_in) / (eta * eta);
                    const double cos2 = 1 - sin2;
                    if (cos2 < 0) continue;
                    const double cos_in_refr = std::sqrt(cos2);
                    if (cos_in_refr <= kEpsilon) continue;
                    const double si = length(q - h.point) * mm;
                    const double si_refr = si * cos_in / cos_in_refr;
                    const double f = fresnel_transmittance(cos_in, eta) * ft_o;
                    const double g = std::fabs(cos_o_in / cos_in_refr);
                    const double combined = st + g * st;
                    const double factor =
                        std::min(ss * f * 0.25 / combined * std::exp(-si_refr * st) *
                                     std::exp(-so * st),
                                 DBL_MAX);
                    lo += colour[size_t(c)] * cos_in * factor;
                }
                sum[size_t(c)] += lo / single_samples;
            }
        }

        // Step 5: what is seen straight through the object, dimmed along the way.
        Channels att;
        for (size_t c = 0; c < 3; ++c)
            att[c] = exits ? std::exp(-med.extinction[c] * dist) : 0.0;
        const double w = std::max({att[0], att[1], att[2]});
        const float adc =
            at.ray.adc_bailout >= 0 ? at.ray.adc_bailout : sc.settings.adc_bailout;
        if (w > adc && exits && same_object(exit)) {
            Vector3 ny = exit.normal;
            if (dot(ny, t) > 0) ny = -ny;
            const double k1 = -dot(t, ny);
            const double k2sq = 1 + eta * eta * (k1 * k1 - 1);
            if (k2sq >= 0) {
                TraceRay through;
                through.ray = {exit.point,
                               normalize(t * eta + ny * (eta * k1 - std::sqrt(k2sq)))};
                through.depth = at.ray.depth + 1;
                through.weight = float(w);
                through.use = RayUse::Refraction;
                through.band = at.ray.band;
                const Channels x = channels(tracer_.trace_nested(through).colour);
                for (size_t c = 0; c < 3; ++c) sum[c] += x[c] * att[c];
            }
        }
    }
    return Rgb(float(sum[0]), float(sum[1]), float(sum[2]));
}

}  // namespace povwall::trace
