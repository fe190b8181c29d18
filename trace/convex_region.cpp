#include "trace/convex_region.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace povwall::trace {

namespace {

Real max_abs(const Vector3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

}  // namespace

Bounds3 convex_region_bounds(const Bounds3& box, std::span<const HalfSpace> cuts) {
    if (cuts.empty() || cuts.size() > kMaxConvexCuts || box.empty()) return box;
    // Every plane with a unit normal, so that the triple product below measures how far
    // three planes are from meeting in a line, whatever the cuts' scales.
    std::vector<HalfSpace> planes;
    planes.reserve(cuts.size() + 6);
    Real mag = 1;
    for (const HalfSpace& c : cuts) {
        const Real n = length(c.normal);
        if (!(n > 0) || !std::isfinite(n) || !std::isfinite(c.offset)) return box;
        planes.push_back({c.normal / n, c.offset / n});
        mag = std::max(mag, std::fabs(c.offset / n));
    }
    for (int a = 0; a < 3; ++a) {
        if (std::isfinite(box.lo[a])) mag = std::max(mag, std::fabs(box.lo[a]));
        if (std::isfinite(box.hi[a])) mag = std::max(mag, std::fabs(box.hi[a]));
    }
    // The box's open sides are closed far away: a vertex found out there means the region
    // is open that way (or reaches so far that it might as well be).
    const Real far = 1e6 * mag;
    for (int a = 0; a < 3; ++a) {
        Vector3 axis{0, 0, 0};
        axis[a] = 1;
        planes.push_back({axis, std::isfinite(box.hi[a]) ? box.hi[a] : far});
        planes.push_back({-axis, std::isfinite(box.lo[a]) ? -box.lo[a] : far});
    }
    // The region is the hull of its vertices: each where three of the planes meet and
    // inside all the others. A vertex is kept within its rounding (Cramer's rule on unit
    // normals is off by a few ulps of the offsets over the triple product), and widened
    // by it: a doubtful vertex only makes the box larger. Three planes whose normals lie
    // within 1e-10 of one plane (the sides of a prism, which meet in parallel lines, give
    // a triple product of rounding) are taken as meeting nowhere: a vertex only such
    // planes make, a needle's tip sharper than that, would be missed.
    Bounds3 found;
    const size_t m = planes.size();
    for (size_t i = 0; i < m; ++i) {
        for (size_t j = i + 1; j < m; ++j) {
            const Vector3 ij = cross(planes[i].normal, planes[j].normal);
            for (size_t k = j + 1; k < m; ++k) {
                const HalfSpace &a = planes[i], &b = planes[j], &c = planes[k];
                const Vector3 jk = cross(b.normal, c.normal);
                const Real det = dot(a.normal, jk);
                if (!(std::fabs(det) > 1e-10)) continue;
                const Vector3 v = (jk * a.offset + cross(c.normal, a.normal) * b.offset +
                                   ij * c.offset) /
                                  det;
                const Real err = 64 * DBL_EPSILON *
                                 (std::fabs(a.offset) + std::fabs(b.offset) +
                                  std::fabs(c.offset) + max_abs(v)) /
                                 std::fabs(det);
                bool inside = true;
                for (size_t l = 0; l < m && inside; ++l) {
                    const Real slack =
                        err + 1e-9 * (max_abs(v) + std::fabs(planes[l].offset));
                    inside = dot(planes[l].normal, v) - planes[l].offset <= slack;
                }
                if (!inside) continue;
                found.extend(v - Vector3(err));
                found.extend(v + Vector3(err));
            }
        }
    }
    if (found.empty()) return box;
    // Each side past far / 2 is open; the others are padded by far more than the
    // rounding of their own coordinates (not of the far vertices').
    Bounds3 out;
    for (int a = 0; a < 3; ++a) {
        const bool open_lo = found.lo[a] < -far / 2;
        const bool open_hi = found.hi[a] > far / 2;
        const Real reach = std::max(open_lo ? 0 : std::fabs(found.lo[a]),
                                    open_hi ? 0 : std::fabs(found.hi[a]));
        const Real extent = open_lo || open_hi ? 0 : found.hi[a] - found.lo[a];
        const Real pad = 1e-9 * (extent + reach) + 1e-300;
        out.lo[a] = open_lo ? -kInfinity : found.lo[a] - pad;
        out.hi[a] = open_hi ? kInfinity : found.hi[a] + pad;
    }
    return intersection(out, box);
}

}  // namespace povwall::trace
