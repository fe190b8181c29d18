#include "core/scene.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace povwall {

Scene take_scene_keeping(Scene&& whole, const std::vector<uint32_t>& keep) {
    std::vector<Object> objects = std::move(whole.objects);
    whole.objects.clear();
    Scene taken = std::move(whole);
    taken.objects.clear();
    taken.objects.reserve(keep.size());
    taken.object_first_node.clear();
    taken.object_first_node.reserve(keep.size());
    taken.object_nodes_total = 0;
    size_t next = 0;  // in `keep`
    for (size_t i = 0; i < objects.size(); ++i) {
        if (next < keep.size() && keep[next] == i) {
            taken.object_first_node.push_back(taken.object_nodes_total);
            taken.objects.push_back(objects[i]);
            ++next;
        }
        taken.object_nodes_total += uint32_t(object_node_count(objects[i]));
    }
    taken.objects_left_out = objects.size() - taken.objects.size();
    whole.objects = std::move(objects);
    return taken;
}

void GlyphOutline::index() {
    point_xmin = point_ymin = kInfinity;
    point_xmax = point_ymax = -kInfinity;
    for (const GlyphSegment& s : segments) {
        for (int k = 0; k < (s.curve ? 3 : 2); ++k) {
            point_xmin = std::min(point_xmin, s.x[k]);
            point_xmax = std::max(point_xmax, s.x[k]);
            point_ymin = std::min(point_ymin, s.y[k]);
            point_ymax = std::max(point_ymax, s.y[k]);
        }
    }
    band_words = int((segments.size() + 63) / 64);
    band_sets.assign(size_t(kBands) * size_t(band_words), 0);
    const Real height = point_ymax - point_ymin;
    band_scale = height > 0 && std::isfinite(height) ? kBands / height : 0;
    for (size_t i = 0; i < segments.size(); ++i) {
        const GlyphSegment& s = segments[i];
        Real lo = s.y[0], hi = s.y[0];
        for (int k = 1; k < (s.curve ? 3 : 2); ++k) {
            lo = std::min(lo, s.y[k]);
            hi = std::max(hi, s.y[k]);
        }
        for (int b = band(lo); b <= band(hi); ++b)
            band_sets[size_t(b) * size_t(band_words) + i / 64] |= uint64_t(1) << (i % 64);
    }
}

namespace {
const Media* scattering_in(const Object& o) {
    if (o.interior) {
        for (const Media& m : o.interior->media)
            if (m.scatters()) return &m;
    }
    if (const Csg* c = std::get_if<Csg>(&o.shape)) {
        for (const Object& child : c->children)
            if (const Media* m = scattering_in(child)) return m;
    }
    return nullptr;
}
}  // namespace

const Media* first_scattering_media(const Scene& scene) {
    for (const Media& m : scene.atmosphere_media)
        if (m.scatters()) return &m;
    for (const Object& o : scene.objects)
        if (const Media* m = scattering_in(o)) return m;
    return nullptr;
}

}  // namespace povwall
