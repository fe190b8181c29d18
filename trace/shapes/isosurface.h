// isosurface: F(x, y, z) - threshold = 0 inside a box or sphere, as POV-Ray 3.7's
// IsoSurface (notes: shape-isosurface.md): the container's span along the object-space
// ray (world distances), the container's own surface where F < 0 there (closed), and up
// to max_trace roots by POV-Ray's recursive halving against max_gradient, each `accuracy`
// wide; the normal by forward differences of step `accuracy` (a box face's or the
// sphere's on the container); inside the container where F <= 0.
#pragma once

#include <string>
#include <vector>

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// The raw function (without the threshold) at an object-space point.
Real isosurface_function(const Isosurface& s, const Point3& p);

void shape_hits(const Isosurface& s, const LocalRay& r, ShapeHits& out);
// The crossings of a clipped isosurface. POV-Ray tests the clip inside the search
// (IsoSurface::All_Intersections), not after it: a clipped container hit neither counts
// toward max_trace nor turns the search around, and a clipped root still uses up its
// trace (with max_trace 1 the surface behind it is not seen).
void shape_hits(const Isosurface& s, const LocalRay& r, const ShapeClip& clip,
                ShapeHits& out);
Vector3 shape_normal(const Isosurface& s, const ShapeHit& h);
bool shape_inside(const Isosurface& s, const Point3& p);
Bounds3 shape_bounds(const Isosurface& s);
PovBBox shape_pov_bbox(const Isosurface& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Isosurface&) { return true; }
constexpr bool shape_convex(const Isosurface&) { return false; }
constexpr bool shape_invertible(const Isosurface&) { return true; }
// The first sign change of F inside the container, found by dense sampling (POV-Ray's
// roots are only `accuracy` close to it).
bool shape_oracle_first(const Isosurface& s, const OracleRay& r, OracleBest& best);

// POV-Ray's messages after a render about the scene's isosurfaces (each located at its
// function, "FILE:LINE:COL: warning: ..."): a max_gradient below the steepest slope the
// searches met (holes) or far above it (slow), or with `evaluate` what the estimates
// did. As POV-Ray's IsoSurface::DispatchShutdownMessages: isosurfaces placed in the
// scene themselves, not copies of a declared one nor parts of CSG; the slopes of the
// copies count.
std::vector<std::string> isosurface_messages(const Scene& scene);

}  // namespace povwall::trace
