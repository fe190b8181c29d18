#include "core/scene.h"

#include <utility>

namespace povwall {

Scene copy_scene_keeping(Scene& whole, const std::function<bool(const Object&)>& keep) {
    std::vector<Object> objects = std::move(whole.objects);
    whole.objects.clear();
    Scene copy = whole;
    whole.objects = std::move(objects);
    copy.object_first_node.clear();
    copy.object_nodes_total = 0;
    copy.objects_left_out = 0;
    for (const Object& o : whole.objects) {
        const auto nodes = uint32_t(object_node_count(o));
        if (keep(o)) {
            copy.object_first_node.push_back(copy.object_nodes_total);
            copy.objects.push_back(o);
        } else {
            ++copy.objects_left_out;
        }
        copy.object_nodes_total += nodes;
    }
    return copy;
}

}  // namespace povwall
