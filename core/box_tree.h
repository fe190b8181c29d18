// A bounding-box hierarchy over boxes: a blob's elements (as POV-Ray's `hierarchy on`
// builds one of spheres: which elements a line or a point can be in the region of, so
// that a ray's intervals and a point's field need only those instead of every element),
// a mesh's faces (walked by trace/shapes/mesh.cpp in POV-Ray's order). Split where the
// surface-area cost is least, at the median below a fixed depth (box_tree.cpp), four
// elements a leaf: the depth stays within the walks' fixed stacks.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace povwall {

class BoxTree {
  public:
    struct Node {
        Real lo[3], hi[3];
        // A leaf: elements order()[first, first + count); an inner node (count 0): its
        // children are the next node and node `first`.
        uint32_t first = 0, count = 0;
    };

    BoxTree() = default;
    // Over the elements' boxes (each holding its element's region, in the shape's
    // space), indexed as the elements are.
    explicit BoxTree(const std::vector<Bounds3>& boxes);

    bool empty() const { return nodes_.empty(); }
    size_t element_count() const { return order_.size(); }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<uint32_t>& order() const { return order_; }

    // Appends the indices of the elements whose box the whole line p + t d (every t,
    // negative ones too) meets, in no particular order.
    void line_candidates(const Point3& p, const Vector3& d,
                         std::vector<uint32_t>& out) const;
    // Appends the indices of the elements whose box holds p, in no particular order.
    void point_candidates(const Point3& p, std::vector<uint32_t>& out) const;

    // Calls element(index) for each element of the leaves reached, depth first, through
    // the nodes meets(node) accepts. The depth stays under 64 (box_tree.cpp).
    template <class Meets, class Element>
    void walk(Meets&& meets, Element&& element) const {
        if (nodes_.empty()) return;
        uint32_t stack[64];
        int size = 0;
        stack[size++] = 0;
        while (size > 0) {
            const uint32_t index = stack[--size];
            const Node& n = nodes_[index];
            if (!meets(n)) continue;
            if (n.count > 0) {
                for (uint32_t i = n.first; i < n.first + n.count; ++i) element(order_[i]);
                continue;
            }
            stack[size++] = n.first;
            stack[size++] = index + 1;
        }
    }

  private:
    uint32_t build(const std::vector<Bounds3>& boxes, const std::vector<Point3>& centres,
                   uint32_t begin, uint32_t end, int depth);

    std::vector<Node> nodes_;
    std::vector<uint32_t> order_;  // element indices, leaf by leaf
};

}  // namespace povwall
