// The only translation unit that includes CGAL: exact overlap predicates on CGAL's
// exact-predicate kernels. Triangles use Epick (inputs are doubles, the predicate is
// exact); spheres need r^2, which doubles cannot hold exactly, so they go to Epeck after
// a double prefilter that decides every case far from tangency.
#include "octree/overlap.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

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

bool triangle_overlaps(const Point3& a, const Point3& b, const Point3& c,
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
