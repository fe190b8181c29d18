// prism: exact crossings, normals and inside tests of the kernel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "parser/parser.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

Object parse_one_prism(const std::string& text) {
    parser::ParseOptions o;
    Scene s = parser::parse_scene_text(text, "test.pov", o);
    EXPECT_EQ(s.objects.size(), 1u);
    return s.objects.empty() ? Object{} : s.objects[0];
}

ShapeHits hits_of(const Object& o, const Point3& origin, const Vector3& dir) {
    ShapeHits hits;
    leaf_hits(o, leaf_ray(o, Ray{origin, normalize(dir)}), hits);
    return hits;
}

const char* kSquarePrism =
    "prism { linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }";

TEST(Prism, LinearWallsAndCapsAtExactDistances) {
    const Object o = parse_one_prism(kSquarePrism);
    ASSERT_TRUE(std::holds_alternative<Prism>(o.shape));
    EXPECT_EQ(std::get<Prism>(o.shape).segments.size(), 4u);
    // Along +z at mid height: in through the wall z = -1, out through z = 1.
    ShapeHits h = hits_of(o, {0.25, 0.5, -5}, {0, 0, 1});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_DOUBLE_EQ(h[0].t, 4);
    EXPECT_DOUBLE_EQ(h[1].t, 6);
    // The wall's normal (dv, 0, -du) of the segment <-1,-1> -> <1,-1>: (0, 0, -2).
    const Vector3 n = leaf_normal(o, h[0]);
    EXPECT_EQ(n.x, 0);
    EXPECT_EQ(n.y, 0);
    EXPECT_LT(n.z, 0);
    // Down through the cap (y = 1) and the base (y = 0); both normals are +y.
    h = hits_of(o, {0.3, 5, 0.2}, {0, -1, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_DOUBLE_EQ(h[0].t, 4);
    EXPECT_EQ(h[0].face, kPrismCap);
    EXPECT_DOUBLE_EQ(h[1].t, 5);
    EXPECT_EQ(h[1].face, kPrismBase);
    EXPECT_EQ(leaf_normal(o, h[1]).y, 1);
    // A ray exactly vertical outside the outline meets nothing (no wall test at all).
    EXPECT_TRUE(hits_of(o, {1.5, 5, 0}, {0, -1, 0}).empty());
}

TEST(Prism, InsideIsEvenOddWithAnOpenTop) {
    const Object o = parse_one_prism(
        "prism { linear_spline 0, 1, 10, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>,"
        " <-0.5,-0.5>, <0.5,-0.5>, <0.5,0.5>, <-0.5,0.5>, <-0.5,-0.5> }");
    EXPECT_TRUE(leaf_inside(o, {0.75, 0.5, 0}));
    EXPECT_FALSE(leaf_inside(o, {0, 0.5, 0}));   // in the hole
    EXPECT_TRUE(leaf_inside(o, {0.75, 0, 0}));   // the base plane is inside
    EXPECT_FALSE(leaf_inside(o, {0.75, 1, 0}));  // the top plane is not
    EXPECT_FALSE(leaf_inside(o, {1.5, 0.5, 0}));
}

TEST(Prism, ConicSweepScalesTheOutlineWithHeight) {
    const Object o = parse_one_prism(
        "prism { conic_sweep linear_spline 0.5, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, "
        "<-1,-1> }");
    // At y = 0.5 the square is half as wide: along +x at z = 0 it is entered at x = -0.5.
    ShapeHits h = hits_of(o, {-5, 0.5 + 1e-9, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 4.5, 1e-8);
    EXPECT_NEAR(h[1].t, 5.5, 1e-8);
    EXPECT_TRUE(leaf_inside(o, {0.7, 0.75, 0}));  // |x| < 0.75 at y = 0.75
    EXPECT_FALSE(leaf_inside(o, {0.8, 0.75, 0}));
    // The bounds cover the widest section.
    const Bounds3 b = leaf_bounds(o);
    EXPECT_EQ(b.lo.x, -1);
    EXPECT_EQ(b.hi.z, 1);
    EXPECT_EQ(b.lo.y, 0.5);
}

TEST(Prism, OpenPrismHasNoCaps) {
    Object o = parse_one_prism(
        "prism { linear_spline 0, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> open }");
    EXPECT_TRUE(std::get<Prism>(o.shape).open);
    EXPECT_TRUE(hits_of(o, {0.3, 5, 0.2}, {0, -1, 0}).empty());
}

TEST(Prism, CubicAndBezierOutlinesMatchTheirPoints) {
    // A Bezier segment from <1,0> over control points back: t = 0 is its last point.
    const Object o = parse_one_prism(
        "prism { bezier_spline 0, 1, 8, <-1, 0>, <-1, 1>, <1, 1>, <1, 0>,"
        " <1, 0>, <1, -1>, <-1, -1>, <-1, 0> }");
    const Prism& p = std::get<Prism>(o.shape);
    ASSERT_EQ(p.segments.size(), 2u);
    EXPECT_EQ(p.segments[0].d[0], 1);  // t = 0 is <1, 0>
    EXPECT_EQ(p.segments[0].d[1], 0);
    // The outline passes through x = +-1 at z = 0, where the two segments meet: as in
    // POV-Ray, each segment gives that crossing (t = 1 of one, t = 0 of the other).
    ShapeHits h = hits_of(o, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 4u);
    EXPECT_NEAR(h[0].t, 4, 1e-12);
    EXPECT_NEAR(h[1].t, 4, 1e-12);
    EXPECT_NEAR(h[2].t, 6, 1e-12);
    EXPECT_NEAR(h[3].t, 6, 1e-12);
    // Elsewhere each crossing once: at z = 0.75 the upper curve z = 1.5 t (1 - t) * ...
    h = hits_of(o, {-5, 0.5, 0.5}, {1, 0, 0});
    EXPECT_EQ(h.size(), 2u);
}

}  // namespace
}  // namespace povwall::trace
