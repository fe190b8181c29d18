// parametric kernel: the hit distance (the start of the last axis's span through the
// piece narrower than `accuracy`), its uv, no hit outside the container or before 4 *
// accuracy into it, world distances along a longer direction, the normal, no inside,
// precompute against the bounds computed on the way, and POV-Ray's box.
#include <gtest/gtest.h>

#include <cmath>

#include "parser/parser.h"
#include "tests/trace/local_rays.h"
#include "trace/shapes/parametric.h"

namespace povwall::trace {
namespace {

Parametric par(const std::string& body) {
    parser::ParseOptions o;
    Scene s = parser::parse_scene_text("parametric { " + body + " }", "test.pov", o);
    return std::get<Parametric>(s.objects.at(0).shape);
}

constexpr const char* kFlat =
    "function { u } function { v } function { 0 } <-1, -1>, <1, 1> ";

TEST(ShapeParametric, FlatSheetHitIsTheLastSpanStart) {
    // x = u, y = v, z = 0 seen along +z: x and y are parallel to the ray, so z's span
    // decides. The pieces are split to 2/2^11 < accuracy on both sides; z's bounds there
    // are -accuracy -+ max_gradient * (du + dv) / 2, and the hit is their near end.
    const Parametric s = par(kFlat);
    ShapeHits hits;
    shape_hits(s, untransformed_ray({0.3, 0.2, -3}, {0, 0, 1}), hits);
    ASSERT_EQ(hits.size(), 1u);
    const Real piece = 2.0 / 2048;
    EXPECT_NEAR(hits[0].t, 3 - 0.001 - piece, 1e-12);
    // The uv is the piece's low corner, within a few pieces of the ray's (x, y).
    EXPECT_NEAR(hits[0].param, 0.3, 4 * piece);
    EXPECT_NEAR(hits[0].param2, 0.2, 4 * piece);
    EXPECT_EQ(std::fmod(hits[0].param + 1, piece), 0.0);
    // World distances along a longer direction: half.
    hits.clear();
    shape_hits(s, untransformed_ray({0.3, 0.2, -3}, {0, 0, 2}), hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, (3 - 0.001 - piece) / 2, 1e-12);
    // The normal: d/du x d/dv = x cross y = +z (not turned toward the ray).
    const Vector3 n = shape_normal(s, hits[0]);
    EXPECT_GT(n.z, 0);
    EXPECT_EQ(n.x, 0);
    EXPECT_EQ(n.y, 0);
    EXPECT_FALSE(shape_inside(s, {0, 0, -0.5}));
    EXPECT_FALSE(shape_inside(s, {0, 0, 0}));
}

TEST(ShapeParametric, ContainerLimitsTheSearch) {
    // Outside the box's x range: no hit though the sheet is there in uv.
    const Parametric wide =
        par("function { 3*u } function { v } function { 0 } <-1, -1>, <1, 1>");
    ShapeHits hits;
    shape_hits(wide, untransformed_ray({2, 0, -3}, {0, 0, 1}), hits);
    EXPECT_TRUE(hits.empty());
    // From inside the container, closer than 4 * accuracy past its entry (the ray's
    // start here): no hit.
    shape_hits(par(kFlat), untransformed_ray({0.3, 0.2, -0.002}, {0, 0, 1}), hits);
    EXPECT_TRUE(hits.empty());
    shape_hits(par(kFlat), untransformed_ray({0.3, 0.2, -0.5}, {0, 0, 1}), hits);
    EXPECT_EQ(hits.size(), 1u);
}

TEST(ShapeParametric, TorusNormalAndPrecompute) {
    const std::string torus =
        "function { (1 + 0.3*cos(v))*cos(u) } function { 0.3*sin(v) } "
        "function { (1 + 0.3*cos(v))*sin(u) } <0, 0>, <2*pi, 2*pi> "
        "contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } } max_gradient 1.5 ";
    const Parametric plain = par(torus);
    const Parametric pre = par(torus + "precompute 12 x, y, z");
    // Down onto the tube's top at x = 1: the surface at y = 0.3.
    const LocalRay down = untransformed_ray({1.0, 2, 0.01}, {0, -1, 0});
    ShapeHits a, b;
    shape_hits(plain, down, a);
    shape_hits(pre, down, b);
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_NEAR(a[0].t, 1.7, 0.01);
    EXPECT_NEAR(b[0].t, 1.7, 0.01);
    // The precomputed bounds (unions of smaller pieces') prune differently, the leaves
    // are the same.
    EXPECT_NEAR(b[0].t, a[0].t, 1e-3);
    const Vector3 n = normalize(shape_normal(plain, a[0]));
    EXPECT_NEAR(std::fabs(n.y), 1.0, 0.02);
}

TEST(ShapeParametric, BoxIsTheContainersThroughTheMatrix) {
    const Parametric s =
        par(std::string(kFlat) + "contained_by { sphere { <1, 0, 0>, 2 } }");
    const Bounds3 b = shape_bounds(s);
    EXPECT_EQ(b.lo.x, -1.0);
    EXPECT_EQ(b.hi.x, 3.0);
    const PovBBox pb = shape_pov_bbox(s, CompactTransform());
    EXPECT_EQ(pb.lo[0], -1.0f);
    EXPECT_EQ(pb.len[1], 4.0f);
}

}  // namespace
}  // namespace povwall::trace
