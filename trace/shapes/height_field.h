// height_field: a grid of heights, two triangles per cell, as POV-Ray 3.7's HField
// (3.7:source/backend/shape/hfield.cpp): the box, the block walk, the DDA over cells and
// its early exit, the inside test that makes everything below the surface solid.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Hits: face kHeightFieldLower (the cell's triangle at (x, z), (x+1, z), (x, z+1)) or
// kHeightFieldUpper (at (x+1, z+1)); ShapeHit::param and param2 are the cell's x and z.
constexpr int kHeightFieldLower = 0, kHeightFieldUpper = 1;

void shape_hits(const HeightField& h, const LocalRay& r, ShapeHits& out);
// The triangle's normal; with `smooth`, the blend of the vertex normals in object space
// (height_field_world_normal gives POV-Ray's, which blends them after the transform).
Vector3 shape_normal(const HeightField& h, const ShapeHit& hit);
// The unit world normal at a hit of a height field placed by `xf`: a smooth field blends
// its four vertex normals each transformed and normalised, as POV-Ray does.
Vector3 height_field_world_normal(const HeightField& h, const ShapeHit& hit,
                                  const CompactTransform& xf);
bool shape_inside(const HeightField& h, const Point3& p);
Bounds3 shape_bounds(const HeightField& h);
PovBBox shape_pov_bbox(const HeightField& h, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const HeightField&) { return true; }
constexpr bool shape_convex(const HeightField&) { return false; }
constexpr bool shape_invertible(const HeightField&) { return true; }
bool shape_oracle_first(const HeightField& h, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
