// ovus: two spheres and the band of a spindle torus between them. POV-Ray solves the
// torus's quartic with its own solver and root elimination (pov_polysolve.h) and keeps
// only roots on the band.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Which part of the ovus a crossing is on (ShapeHit::face).
enum OvusPart : int { kOvusBottom = 0, kOvusTop = 1, kOvusBand = 2 };

// The crossings along a unit direction from `o`, in POV-Ray's order (bottom sphere, top
// sphere, band), object distances above EPSILON.
void intersect_ovus(const Ovus& s, const Point3& o, const Vector3& dir, Crossings& out);
Vector3 ovus_normal(const Ovus& s, const Point3& p, int part);
bool inside_ovus(const Ovus& s, const Point3& p);

void shape_hits(const Ovus& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Ovus& s, const ShapeHit& h);
bool shape_inside(const Ovus& s, const Point3& p);
Bounds3 shape_bounds(const Ovus& s);
PovBBox shape_pov_bbox(const Ovus& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Ovus&) { return true; }
constexpr bool shape_convex(const Ovus&) { return false; }
constexpr bool shape_invertible(const Ovus&) { return true; }
bool shape_oracle_first(const Ovus& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
