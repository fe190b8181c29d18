// cubic, quartic, poly, polynomial and quadric as POV-Ray 3.7 parses them: the term
// layout, optional commas, orders, sturm, the error messages, and the quadric's
// transforms folded into its coefficients with its box.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

std::string zeros(int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += i ? ", 0" : "0";
    return s;
}

TEST(ShapePoly, CubicQuarticAndPolyOrders) {
    auto c = only_shape<Poly>(parse("cubic { <1, " + zeros(18) + ", -1> sturm }"));
    EXPECT_EQ(c.order, 3);
    ASSERT_EQ(c.coeffs.size(), 20u);
    EXPECT_EQ(c.coeffs[0], 1.0);
    EXPECT_EQ(c.coeffs[19], -1.0);
    EXPECT_TRUE(c.sturm);
    auto q = only_shape<Poly>(parse("quartic { <" + zeros(34) + " 2> }"));
    EXPECT_EQ(q.order, 4);
    EXPECT_EQ(q.coeffs.size(), 35u);
    EXPECT_EQ(q.coeffs[34], 2.0);
    EXPECT_FALSE(q.sturm);
    // The order is a float truncated as a C cast; commas are optional.
    auto p = only_shape<Poly>(parse("poly { 5.9 <" + zeros(55) + " 3> sturm off }"));
    EXPECT_EQ(p.order, 5);
    EXPECT_EQ(p.coeffs.size(), 56u);
    EXPECT_EQ(p.coeffs[55], 3.0);
    EXPECT_EQ(only_shape<Poly>(parse("poly { 2, <" + zeros(10) + "> }")).coeffs.size(),
              10u);
    EXPECT_EQ(only_shape<Poly>(parse("poly { 35, <" + zeros(8436) + "> }")).order, 35);
}

TEST(ShapePoly, PolynomialTermsInPovRaysLayout) {
    auto p = only_shape<Poly>(
        parse("polynomial { 4, xyz(4, 0, 0): 1, xyz(0 0 0): -2 xyz(1, 1, 1): 5,"
              " xyz(1, 1, 1): 6 xyz(0, 1, 0): 7 }"));
    EXPECT_EQ(p.order, 4);
    ASSERT_EQ(p.coeffs.size(), 35u);
    EXPECT_EQ(p.coeffs[0], 1.0);    // x^4
    EXPECT_EQ(p.coeffs[34], -2.0);  // constant
    EXPECT_EQ(p.coeffs[14], 6.0);   // xyz: the later value wins
    EXPECT_EQ(p.coeffs[29], 7.0);   // y
    // Glob_5's layout: 3 = x^4, 44 = y^2, 53 = z^2 of order 5.
    auto g = only_shape<Poly>(
        parse("polynomial { 5, xyz(4, 0, 0): 1, xyz(0, 2, 0): 2, xyz(0, 0, 2): 3 }"));
    EXPECT_EQ(g.coeffs[3], 1.0);
    EXPECT_EQ(g.coeffs[44], 2.0);
    EXPECT_EQ(g.coeffs[53], 3.0);
}

TEST(ShapePoly, Errors) {
    EXPECT_EQ(error_of("poly { 1, <0, 0, 0, 0> }"),
              "test.pov:1:8: error: Order of poly is out of range.");
    EXPECT_EQ(error_of("poly { 36, <0> }"),
              "test.pov:1:8: error: Order of poly is out of range.");
    EXPECT_EQ(error_of("polynomial { 36 }"),
              "test.pov:1:14: error: Order of polynom is out of range.");
    EXPECT_EQ(error_of("polynomial { 1.5 }"),
              "test.pov:1:14: error: Order of polynom is out of range.");
    EXPECT_EQ(error_of("polynomial { 2, xyz(2, 1, 0): 1 }"),
              "test.pov:1:21: error: Coefficient of polynom is out of range.");
    EXPECT_EQ(error_of("polynomial { 2, xyz(-1, 0, 0): 1 }"),
              "test.pov:1:21: error: Coefficient of polynom is out of range.");
    EXPECT_EQ(error_of("poly { 2, <1, 2, 3, 4, 5, 6, 7, 8, 9, <1, 2, 3>> }"),
              "test.pov:1:39: error: Float expected but vector or color expression "
              "found.");
    EXPECT_EQ(error_of("quadric { 1, 0, 0, -1 sturm }"),
              "test.pov:1:23: error: 'sturm' cannot be used with this object");
}

TEST(ShapeQuadric, CoefficientsTransformsAndBox) {
    auto q = only_shape<Quadric>(parse("quadric { <1, 2, 3> <4, 5, 6> <7, 8, 9> 10 }"));
    EXPECT_EQ(q.square, Vector3(1, 2, 3));
    EXPECT_EQ(q.mixed, Vector3(4, 5, 6));
    EXPECT_EQ(q.linear, Vector3(7, 8, 9));
    EXPECT_EQ(q.constant, 10.0);
    // A unit sphere (a float promoted to a vector) moved by 2 in x: the coefficients of
    // (x-2)^2 + y^2 + z^2 - 1, the box moved with it.
    auto s = only_shape<Quadric>(parse("quadric { 1, 0, 0, -1 translate 2*x }"));
    EXPECT_EQ(s.square, Vector3(1, 1, 1));
    EXPECT_EQ(s.linear, Vector3(-4, 0, 0));
    EXPECT_EQ(s.constant, 3.0);
    EXPECT_EQ(s.box_lo[0], 1.0f);
    EXPECT_EQ(s.box_len[0], 2.0f);
    EXPECT_EQ(s.box_lo[1], -1.0f);
    EXPECT_TRUE(s.automatic_bounds);
    // A cylinder's box is infinite.
    auto c = only_shape<Quadric>(parse("quadric { <1, 0, 1>, 0, 0, -1 scale 2 }"));
    EXPECT_EQ(c.square, Vector3(0.25, 0, 0.25));
    EXPECT_GT(c.box_len[1], 1e9f);
}

TEST(ShapeQuadric, BoundedByPlanesInAnIntersection) {
    // Cylinder_Y between y = 0 and y = 1 (the inverse plane counts as not inverted in a
    // difference's later children... here, an intersection, it is left out).
    Scene s = parse(
        "intersection { quadric { <1, 0, 1>, 0, 0, -1 } plane { y, 1 } plane { -y, 0 }"
        " plane { x, 5 inverse } translate 2*z }");
    const auto& c = std::get<Csg>(s.objects.at(0).shape);
    const auto& q = std::get<Quadric>(c.children.at(0).shape);
    EXPECT_EQ(q.box_lo[0], -1.0f);
    EXPECT_EQ(q.box_len[0], 2.0f);
    EXPECT_EQ(q.box_lo[1], 0.0f);
    EXPECT_EQ(q.box_len[1], 1.0f);
    EXPECT_EQ(q.box_lo[2], 1.0f);  // moved with the intersection
}

TEST(ShapeQuadric, ClippedByABoxOrPlanes) {
    // The saddle of shapes.inc matches no case: its box is the clip's.
    auto q = only_shape<Quadric>(
        parse("quadric { <-1, 0, 1>, 0, <0, 1, 0>, 0 clipped_by { box { <2, 1, 0>, "
              "<-2, -1, 0.5> } plane { z, 0.25 } } translate x }"));
    EXPECT_EQ(q.box_lo[0], -1.0f);
    EXPECT_EQ(q.box_len[0], 4.0f);
    EXPECT_EQ(q.box_lo[2], 0.0f);
    EXPECT_EQ(q.box_len[2], 0.25f);
}

TEST(ShapeQuadric, RefusedWhereItsBoxComesFromOtherObjects) {
    EXPECT_EQ(
        error_of("quadric { 1, 0, 0, -1 clipped_by { sphere { 0, 1 } } }"),
        "test.pov:1:23: error: unsupported: clipped_by on a quadric by shapes other "
        "than boxes, planes and quadrics");
    EXPECT_EQ(
        error_of("intersection { quadric { 1, 0, 0, -1 } box { -1, 1 } }"),
        "test.pov:1:1: error: unsupported: a quadric in an intersection or difference "
        "with shapes other than planes and quadrics");
    EXPECT_EQ(error_of("intersection { box { -1, 1 } quadric { 1, 0, 0, -1 inverse } }"),
              "(no error)");
}

}  // namespace
}  // namespace povwall::parser
