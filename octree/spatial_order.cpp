#include "octree/spatial_order.h"

#include <algorithm>
#include <numeric>

namespace povwall::octree {
namespace {

// Spreads the low 21 bits of v so that two zero bits follow each.
uint64_t spread_bits(uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

}  // namespace

std::vector<uint32_t> morton_order(std::span<const Bounds3> bounds) {
    Bounds3 world;
    for (const Bounds3& b : bounds) {
        if (b.infinite() || b.lo.x > b.hi.x) continue;
        world.extend(b.lo);
        world.extend(b.hi);
    }
    std::vector<uint64_t> code(bounds.size(), ~0ull);
    const Real scale = Real((1 << 21) - 1);
    for (size_t i = 0; i < bounds.size(); ++i) {
        const Bounds3& b = bounds[i];
        if (b.infinite() || b.lo.x > b.hi.x) continue;
        uint64_t key = 0;
        for (int a = 0; a < 3; ++a) {
            const Real extent = world.hi[a] - world.lo[a];
            const Real c = (b.lo[a] + b.hi[a]) * 0.5;
            const Real u = extent > 0 ? (c - world.lo[a]) / extent : 0;
            key |= spread_bits(uint64_t(std::clamp(u, Real(0), Real(1)) * scale)) << a;
        }
        code[i] = key;
    }
    std::vector<uint32_t> order(bounds.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return code[a] < code[b]; });
    return order;
}

}  // namespace povwall::octree
