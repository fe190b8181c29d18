// sphere_sweep: a sphere moved along a linear, Catmull-Rom or B-spline, as POV-Ray 3.7's
// SphereSweep (3.7:source/backend/shape/sphsweep.cpp): the joint spheres, each
// segment's end caps and its envelope (degree 2, or the degree-10 polynomial through
// POV-Ray's Bernstein sign test and Sturm solver) collected along the whole line, sorted,
// thinned by POV-Ray's enter/leave count, and the inside test by the roots of each
// segment's distance polynomial.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// A crossing along the line before the culling: object-space distance along the unit
// direction, point and normal (each part's own, as POV-Ray keeps them).
struct SweepCrossing {
    Real t;
    Point3 p;
    Vector3 normal;
};

// Every crossing of the sweep's parts with the line o + t dir (dir unit), sorted and
// culled as POV-Ray's All_Intersections before its depth test: what remains, ascending.
void sweep_crossings(const SphereSweepData& s, const Point3& o, const Vector3& dir,
                     std::vector<SweepCrossing>& out);
// POV-Ray's bezier_01: no roots when the polynomial's Bernstein coefficients on [0, 1]
// (degree 6 or 10, c highest power first) all have one sign; its solver otherwise.
int sweep_bezier_roots(int degree, const Real* c, Real* roots);

void shape_hits(const SphereSweep& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const SphereSweep& s, const ShapeHit& h);
bool shape_inside(const SphereSweep& s, const Point3& p);
Bounds3 shape_bounds(const SphereSweep& s);
PovBBox shape_pov_bbox(const SphereSweep& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const SphereSweep&) { return true; }
constexpr bool shape_convex(const SphereSweep&) { return false; }
constexpr bool shape_invertible(const SphereSweep&) { return true; }
bool shape_oracle_first(const SphereSweep& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
