// The bounding-box hierarchy over boxes (box_tree.h).
#include "core/box_tree.h"

#include <algorithm>
#include <numeric>

namespace povwall {
namespace {

constexpr uint32_t kLeafSize = 4;

}  // namespace

BoxTree::BoxTree(const std::vector<Bounds3>& boxes) {
    if (boxes.empty()) return;
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    std::vector<Point3> centres;
    centres.reserve(boxes.size());
    for (const Bounds3& b : boxes) {
        // An unbounded box's centre is not a number: any finite place will do.
        Point3 c = b.centre();
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(c[a])) c[a] = 0;
        centres.push_back(c);
    }
    nodes_.reserve(2 * boxes.size() / kLeafSize + 1);
    build(boxes, centres, 0, uint32_t(boxes.size()));
}

uint32_t BoxTree::build(const std::vector<Bounds3>& boxes,
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
    if (end - begin <= kLeafSize) {
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

template <class Meets>
void BoxTree::collect(Meets&& meets, std::vector<uint32_t>& out) const {
    if (nodes_.empty()) return;
    uint32_t stack[64];
    int size = 0;
    stack[size++] = 0;
    while (size > 0) {
        const uint32_t index = stack[--size];
        const Node& n = nodes_[index];
        if (!meets(n)) continue;
        if (n.count > 0) {
            out.insert(out.end(), order_.begin() + n.first,
                       order_.begin() + n.first + n.count);
            continue;
        }
        stack[size++] = n.first;
        stack[size++] = index + 1;
    }
}

void BoxTree::line_candidates(const Point3& p, const Vector3& d,
                              std::vector<uint32_t>& out) const {
    const Real inv[3] = {1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    collect(
        [&](const Node& n) {
            Real lo = -kInfinity, hi = kInfinity;
            for (int a = 0; a < 3; ++a) {
                if (d[a] == 0.0) {
                    if (p[a] < n.lo[a] || p[a] > n.hi[a]) return false;
                    continue;
                }
                Real t0 = (n.lo[a] - p[a]) * inv[a];
                Real t1 = (n.hi[a] - p[a]) * inv[a];
                if (t0 > t1) std::swap(t0, t1);
                lo = std::max(lo, t0);
                hi = std::min(hi, t1);
            }
            return lo <= hi;
        },
        out);
}

void BoxTree::point_candidates(const Point3& p, std::vector<uint32_t>& out) const {
    collect(
        [&](const Node& n) {
            return !(p.x < n.lo[0] || p.x > n.hi[0] || p.y < n.lo[1] || p.y > n.hi[1] ||
                     p.z < n.lo[2] || p.z > n.hi[2]);
        },
        out);
}

}  // namespace povwall
