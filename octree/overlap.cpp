// The only translation unit that includes CGAL: exact overlap predicates on CGAL's
// exact-predicate kernels. Triangles use Epick (inputs are doubles, the predicate is
// exact); spheres need r^2, which doubles cannot hold exactly, so they go to Epeck after
// a double prefilter that decides every case far from tangency.
#include "octree/overlap.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>

namespace povwall::octree {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

CGAL::Bbox_3 to_bbox(const Bounds3& b) {
    return CGAL::Bbox_3(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z);
}

}  // namespace

bool sphere_overlaps(const Point3& c, Real r, const Bounds3& cell) {
    // Squared distance from the centre to the box, in doubles: each term is off by a few
    // ulps at most, so a relative margin of 1e-9 leaves only near-tangent cases to CGAL.
    Real d2 = 0;
    for (int a = 0; a < 3; ++a) {
        Real v = std::clamp(c[a], cell.lo[a], cell.hi[a]) - c[a];
        d2 += v * v;
    }
    const Real r2 = r * r;
    if (d2 < r2 * (1 - 1e-9)) return true;
    if (d2 > r2 * (1 + 1e-9) + 1e-300) return false;
    Epeck::FT er(r);
    Epeck::Sphere_3 s(Epeck::Point_3(c.x, c.y, c.z), er * er);
    // CGAL's Bbox_3/Sphere_3 test counts a sphere whose surface touches the box.
    return CGAL::do_intersect(to_bbox(cell), s);
}

bool box_overlaps(const Bounds3& b, const Bounds3& cell) {
    return CGAL::do_overlap(to_bbox(b), to_bbox(cell));
}

namespace {

bool holds(const Bounds3& cell, const Point3& p) {
    return p.x >= cell.lo.x && p.x <= cell.hi.x && p.y >= cell.lo.y && p.y <= cell.hi.y &&
           p.z >= cell.lo.z && p.z <= cell.hi.z;
}

enum class Certain { kDisjoint, kOverlapping, kUnknown };

// The separating-axis test (the cell's faces, the triangle's plane, its edges crossed
// with the cell's axes) in doubles, with an error bound on every projection. The
// triangle is moved to the cell's centre first (a rounding of each coordinate, at most
// u times the local magnitude m). Every projection is then a polynomial of degree 2
// (edge axes) or 3 (the plane) in coordinates of magnitude <= m, evaluated in a dozen
// operations: its error, the moves included, stays below ~1e-13 m^2 or m^3, and a gap
// or an overlap ten times larger is certain. An uncertain axis leaves the answer to
// the exact predicate. Certain overlap on every axis (the cell's faces overlap: the
// bounds test came first) means the closed sets meet: the smallest overlap over the
// axes, each divided by its length, is how far they interpenetrate, and that exceeds
// the moves by far.
Certain separating_axes(const Point3& a, const Point3& b, const Point3& c,
                        const Bounds3& cell) {
    const Vector3 r = (cell.hi - cell.lo) * 0.5;  // half extents
    const Point3 centre = cell.lo + r;
    const Vector3 q0 = a - centre, q1 = b - centre, q2 = c - centre;
    Real m = std::max({r.x, r.y, r.z});
    for (const Vector3& q : {q0, q1, q2})
        m = std::max({m, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
    const Real bound2 = 1e-12 * m * m + 1e-290, bound3 = 1e-12 * m * m * m + 1e-290;
    bool certain_overlap = true;
    // Interval [lo, hi] of the triangle's projection against [-radius, radius]. An axis
    // that is exactly zero (an edge along a cell axis, a degenerate triangle's plane)
    // has projections exactly 0; the separating-axis test does not need it.
    auto axis = [&](bool zero_axis, Real lo, Real hi, Real radius, Real bound) {
        if (zero_axis) return false;
        if (lo > radius + bound || hi < -radius - bound) return true;
        certain_overlap = certain_overlap && lo < radius - bound && hi > -radius + bound;
        return false;
    };
    // The triangle's plane: every vertex projects to the same value.
    const Vector3 n = cross(q1 - q0, q2 - q0);
    const Real d = dot(n, q0);
    if (axis(n.x == 0 && n.y == 0 && n.z == 0, d, d,
             std::fabs(n.x) * r.x + std::fabs(n.y) * r.y + std::fabs(n.z) * r.z, bound3))
        return Certain::kDisjoint;
    // Each edge crossed with x, y and z: the edge's two ends project to one value, the
    // opposite vertex to another.
    const Vector3* ends[3][3] = {{&q0, &q1, &q2}, {&q1, &q2, &q0}, {&q2, &q0, &q1}};
    for (const auto& t : ends) {
        const Vector3 e = *t[1] - *t[0];
        const Vector3 &p = *t[0], &o = *t[2];
        Real s = e.z * p.y - e.y * p.z, u = e.z * o.y - e.y * o.z;  // e x (1,0,0)
        if (axis(e.y == 0 && e.z == 0, std::min(s, u), std::max(s, u),
                 std::fabs(e.z) * r.y + std::fabs(e.y) * r.z, bound2))
            return Certain::kDisjoint;
        s = e.x * p.z - e.z * p.x, u = e.x * o.z - e.z * o.x;  // e x (0,1,0)
        if (axis(e.z == 0 && e.x == 0, std::min(s, u), std::max(s, u),
                 std::fabs(e.x) * r.z + std::fabs(e.z) * r.x, bound2))
            return Certain::kDisjoint;
        s = e.y * p.x - e.x * p.y, u = e.y * o.x - e.x * o.y;  // e x (0,0,1)
        if (axis(e.x == 0 && e.y == 0, std::min(s, u), std::max(s, u),
                 std::fabs(e.y) * r.x + std::fabs(e.x) * r.y, bound2))
            return Certain::kDisjoint;
    }
    return certain_overlap ? Certain::kOverlapping : Certain::kUnknown;
}

}  // namespace

bool triangle_overlaps(const Point3& a, const Point3& b, const Point3& c,
                       const Bounds3& cell) {
    // Decided in doubles where that is certain (a vertex in the cell, disjoint bounds,
    // the separating axes with clear margins); CGAL's exact predicate settles the rest.
    if (holds(cell, a) || holds(cell, b) || holds(cell, c)) return true;
    for (int k = 0; k < 3; ++k) {
        if (std::max({a[k], b[k], c[k]}) < cell.lo[k] ||
            std::min({a[k], b[k], c[k]}) > cell.hi[k])
            return false;
    }
    // Coordinates below 1e90: no product overflows.
    bool moderate = true;
    for (const Point3* p : {&a, &b, &c, &cell.lo, &cell.hi})
        moderate = moderate && std::fabs(p->x) < 1e90 && std::fabs(p->y) < 1e90 &&
                   std::fabs(p->z) < 1e90;
    if (moderate) {
        const Certain answer = separating_axes(a, b, c, cell);
        if (answer != Certain::kUnknown) return answer == Certain::kOverlapping;
    }
    return triangle_overlaps_exactly(a, b, c, cell);
}

bool triangle_overlaps_exactly(const Point3& a, const Point3& b, const Point3& c,
                               const Bounds3& cell) {
    // A triangle in an axis plane (flat scenes, tessellated boxes) lies exactly on cell
    // faces, where the 3D predicate's filter always fails into slow exact arithmetic; in
    // the plane the question is 2D and exact in doubles' filter range.
    for (int axis = 0; axis < 3; ++axis) {
        if (a[axis] != b[axis] || a[axis] != c[axis]) continue;
        if (a[axis] < cell.lo[axis] || a[axis] > cell.hi[axis]) return false;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        Epick::Triangle_2 t2(Epick::Point_2(a[u], a[v]), Epick::Point_2(b[u], b[v]),
                             Epick::Point_2(c[u], c[v]));
        Epick::Iso_rectangle_2 r(Epick::Point_2(cell.lo[u], cell.lo[v]),
                                 Epick::Point_2(cell.hi[u], cell.hi[v]));
        if (t2.is_degenerate()) break;  // segment or point: handled below in 3D
        return CGAL::do_intersect(t2, r);
    }
    Epick::Triangle_3 t(Epick::Point_3(a.x, a.y, a.z), Epick::Point_3(b.x, b.y, b.z),
                        Epick::Point_3(c.x, c.y, c.z));
    if (t.is_degenerate()) {
        // CGAL's triangle predicates require a proper triangle: test the segments
        // instead.
        const Epick::Point_3 p[3] = {t[0], t[1], t[2]};
        for (int i = 0; i < 3; ++i) {
            Epick::Segment_3 s(p[i], p[(i + 1) % 3]);
            if (s.is_degenerate() ? CGAL::do_intersect(to_bbox(cell), p[i])
                                  : CGAL::do_intersect(to_bbox(cell), s)) {
                return true;
            }
        }
        return false;
    }
    return CGAL::do_intersect(to_bbox(cell), t);
}

}  // namespace povwall::octree
