// box: two opposite corners, axis-aligned in its own space (POV-Ray's Box).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Slabs along a unit `dir`: the entry and exit above kBoxTolerance.
void intersect_box(const Box& b, const Point3& o, const Vector3& dir, Crossings& out);
// POV-Ray's box (3.7:source/backend/shape/boxes.cpp, Box::Intersect and
// All_Intersections): the slabs in object space with the direction as the inverse
// transform leaves it, not normalised, so `t` is the ray's own parameter (the world
// distance). The interval starts at [0, BOUND_HUGE]; x narrows it exactly, y and z only
// where they move an end by more than kBoxCloseTolerance, and an entry within that of the
// current one is never compared with the exit. So a box thinner than 1e-6 along the ray
// is met wherever its slabs nearly overlap. Where two faces are that close, the face
// kept is the one the direction points at most directly (y against x; z against the
// axis of the face so far). The entry counts above kBoxTolerance, the exit always; no
// hit when the exit is below kBoxTolerance.
constexpr Real kBoxCloseTolerance = 1e-6;
constexpr Real kBoxBoundHuge = 2e10;
void intersect_box_pov(const Box& b, const Point3& o, const Vector3& dir, Crossings& out);
// POV-Ray's Box::Intersect on the box lo..hi: the span [tmin, tmax] along o + t dir (tmin
// from 0, tmax from BOUND_HUGE) and the faces entered and left (2 axis + (1 for the high
// side); -1: none); false when the box is missed or left before 1e-6.
bool box_span_pov(const Point3& lo, const Point3& hi, const Point3& o, const Vector3& dir,
                  Real& tmin, Real& tmax, int& fmin, int& fmax);
// Faces: 2 axis + (1 for the high side).
Vector3 box_normal(const Box& b, int face);
bool inside_box(const Box& b, const Point3& p);

void shape_hits(const Box& b, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Box& b, const ShapeHit& h);
bool shape_inside(const Box& b, const Point3& p);
Bounds3 shape_bounds(const Box& b);
PovBBox shape_pov_bbox(const Box& b, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Box&) { return false; }
constexpr bool shape_convex(const Box&) { return true; }
constexpr bool shape_invertible(const Box&) { return true; }
bool shape_oracle_first(const Box& b, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
