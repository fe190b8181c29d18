#include "core/scene.h"

#include <utility>

namespace povwall {

namespace {
// `rest`'s object list (empty) becomes the objects of `objects` that `keep` accepts,
// copied, with their node numbering.
void keep_objects(Scene& rest, const std::vector<Object>& objects,
                  const std::function<bool(const Object&)>& keep) {
    rest.objects.clear();
    rest.object_first_node.clear();
    rest.object_nodes_total = 0;
    rest.objects_left_out = 0;
    for (const Object& o : objects) {
        const auto nodes = uint32_t(object_node_count(o));
        if (keep(o)) {
            rest.object_first_node.push_back(rest.object_nodes_total);
            rest.objects.push_back(o);
        } else {
            ++rest.objects_left_out;
        }
        rest.object_nodes_total += nodes;
    }
}
}  // namespace

Scene copy_scene_keeping(Scene& whole, const std::function<bool(const Object&)>& keep) {
    std::vector<Object> objects = std::move(whole.objects);
    whole.objects.clear();
    Scene copy = whole;
    whole.objects = std::move(objects);
    keep_objects(copy, whole.objects, keep);
    return copy;
}

Scene take_scene_keeping(Scene&& whole, const std::function<bool(const Object&)>& keep) {
    std::vector<Object> objects = std::move(whole.objects);
    whole.objects.clear();
    Scene taken = std::move(whole);
    keep_objects(taken, objects, keep);
    whole.objects = std::move(objects);
    return taken;
}

}  // namespace povwall
