// The facets normal pattern as POV-Ray 3.7 defines it (normal.cpp of 3.7-stable read for
// semantics): the normal (or, with `coords`, the point) scaled by 1/size picks the
// nearest of one random point per unit cube, and that point becomes the normal (with
// `coords`, its noise gradient perturbs the normal).
#include <cmath>

#include "core/math_constants.h"
#include "core/noise.h"
#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

// The random point of the unit cube holding `v` (POV-Ray's PickInCube).
Point3 point_in_cube(const Vector3& v) {
    const Real fx = std::floor(v.x - kPovEpsilon), fy = std::floor(v.y - kPovEpsilon),
               fz = std::floor(v.z - kPovEpsilon);
    const auto seed = size_t(hash3d(int(fx), int(fy), int(fz)));
    return {fx + pattern_random(seed), fy + pattern_random(seed + 1),
            fz + pattern_random(seed + 2)};
}

}  // namespace

void facets_normal(const PatternSpec::Facets& f, const Point3& p, Vector3& n) {
    n = normalize(n);
    const Real scale = f.size < 1e-6 ? 1e6 : 1.0 / f.size;
    const Vector3 target = (f.coords != 0 ? Vector3(p) : n) * scale;
    const bool square = f.metric == 2, unity = f.metric == 1;
    // As POV-Ray: the unity metric sums the signed differences.
    auto distance = [&](const Vector3& d) {
        if (square) return dot(d, d);
        if (unity) return d.x + d.y + d.z;
        return std::pow(std::fabs(d.x), f.metric) + std::pow(std::fabs(d.y), f.metric) +
               std::pow(std::fabs(d.z), f.metric);
    };
    // The cubes within a 3D knight's move (offsets -2..2, at most one of them 2 away),
    // in POV-Ray's order: the first of equal distances wins.
    Point3 nearest{0, 0, 0};
    Real best = 0;
    bool first = true;
    for (int x = -2; x <= 2; ++x)
        for (int y = -2; y <= 2; ++y)
            for (int z = -2; z <= 2; ++z) {
                if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) > 1)
                    continue;
                const Point3 c = point_in_cube(target + Vector3(x, y, z));
                const Real d = distance(c - target);
                if (first || d < best) {
                    best = d;
                    nearest = c;
                    first = false;
                }
            }
    if (f.coords != 0) {
        Vector3 pert = dnoise(nearest);
        pert -= n * dot(pert, n);
        n += pert * f.coords;
    } else {
        n = nearest;
    }
}

}  // namespace povwall::trace::detail
