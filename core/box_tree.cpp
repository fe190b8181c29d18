// The bounding-box hierarchy over boxes (box_tree.h).
#include "core/box_tree.h"

#include <algorithm>
#include <numeric>

namespace povwall {
namespace {

constexpr uint32_t kLeafSize = 4;
// Below this depth a node is split where the surface-area cost is least (12 bins of its
// centres on each axis); deeper, or where no split pays, at the median: the depth stays
// under kMedianDepth + log2 of the element count, which the walks' fixed stacks (64)
// allow for any count a 32-bit index can hold.
constexpr int kMedianDepth = 24;
constexpr int kBins = 12;

Real area(const Bounds3& b) {
    const Vector3 d = b.diagonal();
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

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
    build(boxes, centres, 0, uint32_t(boxes.size()), 0);
}

uint32_t BoxTree::build(const std::vector<Bounds3>& boxes,
                        const std::vector<Point3>& centres, uint32_t begin, uint32_t end,
                        int depth) {
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
    uint32_t mid = end;
    if (depth < kMedianDepth && std::isfinite(area(box))) {
        // The least N_left A_left + N_right A_right over the bins' boundaries.
        Real best = area(box) * Real(end - begin);  // a leaf's cost, to beat
        int best_axis = -1, best_bin = 0;
        auto bin_of = [&](uint32_t e, int a) {
            const int k = int(kBins * (centres[e][a] - spread.lo[a]) / extent[a]);
            return std::clamp(k, 0, kBins - 1);
        };
        for (int a = 0; a < 3; ++a) {
            if (!(extent[a] > 0)) continue;
            Bounds3 bin_box[kBins];
            uint32_t bin_count[kBins] = {};
            for (uint32_t i = begin; i < end; ++i) {
                const int k = bin_of(order_[i], a);
                bin_box[k].extend(boxes[order_[i]]);
                ++bin_count[k];
            }
            Real right_area[kBins];
            uint32_t right_count[kBins];
            Bounds3 acc;
            uint32_t n = 0;
            for (int k = kBins - 1; k > 0; --k) {
                acc.extend(bin_box[k]);
                n += bin_count[k];
                right_area[k] = n ? area(acc) : 0;
                right_count[k] = n;
            }
            acc = Bounds3{};
            n = 0;
            for (int k = 0; k + 1 < kBins; ++k) {
                acc.extend(bin_box[k]);
                n += bin_count[k];
                if (n == 0 || right_count[k + 1] == 0) continue;
                const Real cost =
                    area(acc) * Real(n) + right_area[k + 1] * right_count[k + 1];
                if (cost < best) {
                    best = cost;
                    best_axis = a;
                    best_bin = k;
                }
            }
        }
        if (best_axis >= 0) {
            mid = uint32_t(
                std::stable_partition(
                    order_.begin() + begin, order_.begin() + end,
                    [&](uint32_t e) { return bin_of(e, best_axis) <= best_bin; }) -
                order_.begin());
        }
    }
    if (mid == end || mid == begin) {
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        mid = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + mid,
                         order_.begin() + end, [&](uint32_t a, uint32_t b) {
                             return centres[a][axis] < centres[b][axis] ||
                                    (centres[a][axis] == centres[b][axis] && a < b);
                         });
    }
    build(boxes, centres, begin, mid, depth + 1);
    const uint32_t right = build(boxes, centres, mid, end, depth + 1);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
}

void BoxTree::line_candidates(const Point3& p, const Vector3& d,
                              std::vector<uint32_t>& out) const {
    const Real inv[3] = {1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    walk(
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
        [&](uint32_t e) { out.push_back(e); });
}

void BoxTree::point_candidates(const Point3& p, std::vector<uint32_t>& out) const {
    walk(
        [&](const Node& n) {
            return !(p.x < n.lo[0] || p.x > n.hi[0] || p.y < n.lo[1] || p.y > n.hi[1] ||
                     p.z < n.lo[2] || p.z > n.hi[2]);
        },
        [&](uint32_t e) { out.push_back(e); });
}

}  // namespace povwall
