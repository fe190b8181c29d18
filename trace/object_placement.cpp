#include "trace/object_placement.h"

#include <algorithm>
#include <cmath>

#include "trace/shapes/shape.h"

namespace povwall::trace {

Bounds3 object_placement_bounds(const Object& o, const Bounds3& world) {
    const bool turned =
        std::holds_alternative<Lathe>(o.shape) || std::holds_alternative<Sor>(o.shape);
    if (!turned || o.inverse || o.transform.is_identity() || world.empty() ||
        world.infinite())
        return world;
    const Bounds3 local = leaf_bounds(o);
    if (local.empty() || local.infinite()) return world;
    // The cylinder of the box's x and z reach about y: along world axis i its disc
    // reaches r |(M_i0, M_i2)| either side of the axis (M the transform's linear part),
    // padded by far more than the rounding here.
    const auto& m = o.transform.forward().m;
    const Real r = std::max({std::fabs(local.lo.x), std::fabs(local.hi.x),
                             std::fabs(local.lo.z), std::fabs(local.hi.z)});
    const Point3 base = o.transform.point({0, local.lo.y, 0}),
                 top = o.transform.point({0, local.hi.y, 0});
    Bounds3 cylinder;
    for (int i = 0; i < 3; ++i) {
        const Real reach = r * std::hypot(m[i][0], m[i][2]);
        const Real pad = 1e-9 * (reach + std::fabs(base[i]) + std::fabs(top[i]));
        cylinder.lo[i] = std::min(base[i], top[i]) - reach - pad;
        cylinder.hi[i] = std::max(base[i], top[i]) + reach + pad;
    }
    return intersection(world, cylinder);
}

}  // namespace povwall::trace
