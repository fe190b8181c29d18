// A mesh's face tree, built once (mesh.h).
#include "core/mesh.h"

namespace povwall {
namespace {

Point3 single(const Point3& p) { return {float(p.x), float(p.y), float(p.z)}; }

}  // namespace

const BoxTree& MeshData::tree() const {
    std::call_once(tree_built_, [this] {
        std::vector<Bounds3> boxes;
        boxes.reserve(faces.size());
        for (const MeshFace& f : faces) {
            Bounds3 b;
            for (uint32_t v : f.v) b.extend(single(vertices[v]));
            boxes.push_back(b);
        }
        tree_ = BoxTree(boxes);
    });
    return tree_;
}

}  // namespace povwall
