#include "trace/shapes/sort_hits.h"

#include <algorithm>
#include <cmath>

namespace povwall::trace {

void stable_sort_by_depth(ShapeHits& out, size_t first) {
    const size_t n = out.size();
    // Without NaN the order by depth is a strict weak order, so every stable sort gives
    // the same sequence; insertion is the cheapest for a few.
    bool plain = n - first <= 16;
    for (size_t i = first; i < n && plain; ++i) plain = !std::isnan(out[i].t);
    if (!plain) {
        std::stable_sort(out.begin() + std::ptrdiff_t(first), out.end(),
                         [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
        return;
    }
    for (size_t i = first + 1; i < n; ++i) {
        const ShapeHit v = out[i];
        size_t j = i;
        for (; j > first && v.t < out[j - 1].t; --j) out[j] = out[j - 1];
        out[j] = v;
    }
}

}  // namespace povwall::trace
