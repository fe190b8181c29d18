// glyph: one character of a `text` object, a TrueType outline extruded along z (POV-Ray's
// TrueType shape). The text itself is a union of glyphs (parser/shape_text.cpp).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// POV-Ray's TTF_Tolerance: the smallest accepted depth (world distance).
constexpr Real kGlyphTolerance = 1e-6;

// Even-odd crossing count of the +x ray from (x, y) over every segment, with POV-Ray's
// half-open rule for lines and its end filters for curves (Inside_Glyph).
bool inside_glyph_outline(const GlyphOutline& g, Real x, Real y);
// The roots of a s^2 + b s + c in [0, 1] as POV-Ray's TrueType solver finds them: none
// when the discriminant is below 1e-10 (tangents are missed), the larger-sign root first.
int glyph_solve_quad(Real a, Real b, Real c, Real roots[2]);
// The parameter of the point (x, y) on a curve segment (for its normal).
Real glyph_curve_parameter(const GlyphSegment& s, Real x, Real y);

void shape_hits(const Glyph& g, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Glyph& g, const ShapeHit& h);
bool shape_inside(const Glyph& g, const Point3& p);
Bounds3 shape_bounds(const Glyph& g);
PovBBox shape_pov_bbox(const Glyph& g, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Glyph&) { return true; }
constexpr bool shape_convex(const Glyph&) { return false; }
constexpr bool shape_invertible(const Glyph&) { return true; }
bool shape_oracle_first(const Glyph& g, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
