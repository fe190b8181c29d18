#include "octree/giants.h"

#include <algorithm>
#include <cmath>

namespace povwall::octree {

namespace {

Real diagonal_length(const Bounds3& b) { return b.empty() ? 0 : length(b.diagonal()); }

}  // namespace

std::vector<uint32_t> giant_primitives(std::span<const Bounds3> bounds) {
    // The largest kMaxGiants candidates, largest first.
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < bounds.size(); ++i)
        if (!bounds[i].empty() && !bounds[i].infinite()) order.push_back(i);
    if (order.size() < 2) return {};
    const size_t k = std::min(kMaxGiants, order.size() - 1);
    auto larger = [&](uint32_t a, uint32_t b) {
        const Real da = diagonal_length(bounds[a]), db = diagonal_length(bounds[b]);
        return da != db ? da > db : a < b;
    };
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(k), order.end(),
                      larger);
    // rest[j]: the union of every box but the j largest.
    Bounds3 others;
    for (size_t i = k; i < order.size(); ++i) others.extend(bounds[order[i]]);
    std::vector<Bounds3> rest(k + 1);
    rest[k] = others;
    for (size_t j = k; j-- > 0;) {
        rest[j] = rest[j + 1];
        rest[j].extend(bounds[order[j]]);
    }
    for (size_t j = k; j >= 1; --j) {
        if (diagonal_length(bounds[order[j - 1]]) >
            kGiantRatio * diagonal_length(rest[j])) {
            std::vector<uint32_t> giants(order.begin(),
                                         order.begin() + std::ptrdiff_t(j));
            std::sort(giants.begin(), giants.end());
            return giants;
        }
    }
    return {};
}

}  // namespace povwall::octree
