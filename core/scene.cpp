#include "core/scene.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace povwall {

std::mutex& derived_slot_mutex() {
    static std::mutex m;
    return m;
}

Scene take_scene_keeping(Scene&& whole, const std::vector<uint32_t>& keep) {
    std::vector<Object> objects = std::move(whole.objects);
    whole.objects.clear();
    Scene taken = std::move(whole);
    taken.objects.clear();
    taken.objects.reserve(keep.size());
    taken.object_first_node.clear();
    taken.object_first_node.reserve(keep.size());
    taken.object_nodes_total = 0;
    taken.left_out_nodes.clear();
    taken.left_out_interiors.clear();
    size_t next = 0;  // in `keep`
    for (size_t i = 0; i < objects.size(); ++i) {
        if (next < keep.size() && keep[next] == i) {
            taken.object_first_node.push_back(taken.object_nodes_total);
            taken.objects.push_back(objects[i]);
            ++next;
        } else {
            taken.leave_out(objects[i], taken.object_nodes_total);
        }
        taken.object_nodes_total += uint32_t(object_node_count(objects[i]));
    }
    taken.objects_left_out = objects.size() - taken.objects.size();
    whole.objects = std::move(objects);
    return taken;
}

bool interior_is_default(const Interior& in) {
    const Interior d;
    return in.ior == d.ior && in.caustics == d.caustics &&
           in.dispersion == d.dispersion &&
           in.dispersion_samples == d.dispersion_samples &&
           in.fade_distance == d.fade_distance && in.fade_power == d.fade_power &&
           in.fade_colour == d.fade_colour && in.old_refract == d.old_refract &&
           in.media.empty();
}

void Scene::leave_out(const Object& o, uint32_t first_node) {
    // The tree's sharers of an interior (same id, see Interior::id) hold equal copies
    // of it: one is kept for them all.
    std::unordered_map<uint32_t, const Interior*> kept;
    uint32_t node = first_node;
    auto walk = [&](auto& self, const Object& n) -> void {
        LeftOutNode record;
        record.node = node++;
        record.hollow = n.interior ? n.interior->hollow : n.hollow;
        if (n.interior && !interior_is_default(*n.interior)) {
            const uint32_t id = n.interior->id;
            auto same = id != 0 ? kept.find(id) : kept.end();
            if (same != kept.end()) {
                record.interior = same->second;
            } else {
                left_out_interiors.push_back(
                    std::make_shared<const Interior>(*n.interior));
                record.interior = left_out_interiors.back().get();
                if (id != 0) kept.emplace(id, record.interior);
            }
        }
        if (record.hollow || record.interior) left_out_nodes.push_back(record);
        if (auto c = std::get_if<Csg>(&n.shape))
            for (const Object& child : c->children) self(self, child);
    };
    walk(walk, o);
}

const LeftOutNode* Scene::left_out_node(uint32_t node) const {
    auto it =
        std::lower_bound(left_out_nodes.begin(), left_out_nodes.end(), node,
                         [](const LeftOutNode& r, uint32_t n) { return r.node < n; });
    return it != left_out_nodes.end() && it->node == node ? &*it : nullptr;
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
