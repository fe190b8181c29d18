#include "core/scene.h"

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
