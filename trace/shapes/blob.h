// blob: the field of spherical and cylindrical components, as POV-Ray 3.7's Blob
// (notes: shape-blob.md): each element's interval of influence along the unit ray,
// sorted as POV-Ray inserts them, the field's quartic summed interval by interval, the
// Bezier hull test, POV-Ray's solver (core/pov_polysolve.h, root elimination 1e-11),
// depth tolerance 1e-2; inside where the field passes threshold - 1e-6; the normal the
// field's gradient; POV-Ray's box from the positive components' bounding spheres.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

constexpr Real kBlobDepthTolerance = 1e-2;
constexpr Real kBlobInsideTolerance = 1e-6;

// One element's field at a point in blob space (0 outside its region).
Real blob_element_field(const BlobElement& e, const Point3& p);
// The indices of the elements whose region may hold p (blob space), in their stored
// order: the others' field there is zero.
void blob_elements_at(const BlobData& d, const Point3& p, std::vector<uint32_t>& out);
// The field at a point in blob space (the elements' sum in their stored order).
Real blob_field(const BlobData& d, const Point3& p);
// The field's gradient direction as POV-Ray's normal sums it (not normalised; (1, 0, 0)
// where it vanishes).
Vector3 blob_gradient(const BlobData& d, const Point3& p);
// An element's bounding sphere in blob space (POV-Ray's get_element_bounding_sphere).
void blob_element_sphere(const BlobElement& e, Point3& centre, Real& radius2);

void shape_hits(const Blob& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Blob& s, const ShapeHit& h);
bool shape_inside(const Blob& s, const Point3& p);
Bounds3 shape_bounds(const Blob& s);
PovBBox shape_pov_bbox(const Blob& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Blob&) { return true; }
constexpr bool shape_convex(const Blob&) { return false; }
constexpr bool shape_invertible(const Blob&) { return true; }
bool shape_oracle_first(const Blob& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
