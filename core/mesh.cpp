// The mesh's face tree (mesh.h). Median splits keep it balanced: its depth is at most
// log2 of the face count, which the walks' fixed stacks rely on.
#include "core/mesh.h"

#include <algorithm>
#include <numeric>

namespace povwall {
namespace {

constexpr uint32_t kLeafFaces = 4;

Point3 single(const Point3& p) { return {float(p.x), float(p.y), float(p.z)}; }

}  // namespace

MeshTree::MeshTree(const std::vector<Bounds3>& boxes) {
    if (boxes.empty()) return;
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    std::vector<Point3> centres;
    centres.reserve(boxes.size());
    for (const Bounds3& b : boxes) {
        Point3 c = b.centre();
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(c[a])) c[a] = 0;  // any finite place will do
        centres.push_back(c);
    }
    nodes_.reserve(2 * boxes.size() / kLeafFaces + 1);
    build(boxes, centres, 0, uint32_t(boxes.size()));
}

uint32_t MeshTree::build(const std::vector<Bounds3>& boxes,
                         const std::vector<Point3>& centres, uint32_t begin,
                         uint32_t end) {
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.emplace_back();
    Bounds3 box, spread;
    for (uint32_t i = begin; i < end; ++i) {
        box.extend(boxes[order_[i]]);
        spread.extend(centres[order_[i]]);
    }
    for (int a = 0; a < 3; ++a) {
        nodes_[index].lo[a] = box.lo[a];
        nodes_[index].hi[a] = box.hi[a];
    }
    if (end - begin <= kLeafFaces) {
        nodes_[index].first = begin;
        nodes_[index].count = end - begin;
        return index;
    }
    const Vector3 extent = spread.diagonal();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](uint32_t a, uint32_t b) {
                         return centres[a][axis] < centres[b][axis] ||
                                (centres[a][axis] == centres[b][axis] && a < b);
                     });
    build(boxes, centres, begin, mid);
    const uint32_t right = build(boxes, centres, mid, end);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
}

const MeshTree& MeshData::tree() const {
    std::call_once(tree_built_, [this] {
        std::vector<Bounds3> boxes;
        boxes.reserve(faces.size());
        for (const MeshFace& f : faces) {
            Bounds3 b;
            for (uint32_t v : f.v) b.extend(single(vertices[v]));
            boxes.push_back(b);
        }
        tree_ = MeshTree(boxes);
    });
    return tree_;
}

}  // namespace povwall
