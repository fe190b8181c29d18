// lathe { SPLINE N, points }: spline keywords (the last wins), counts per kind, the
// negative-radius rule, sturm.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeLathe, KindsCountsAndSturm) {
    auto l = only_shape<Lathe>(parse("lathe { 2, <1, 0>, <1, 1> }"));
    EXPECT_EQ(l.spline->kind, LatheSplineKind::Linear);
    EXPECT_EQ(l.spline->segments.size(), 1u);
    EXPECT_FALSE(l.sturm);
    l = only_shape<Lathe>(parse(
        "lathe { linear_spline cubic_spline 5 <1, 0> <1, 1> 1 <1, 3> <1, 4> sturm }"));
    EXPECT_EQ(l.spline->kind, LatheSplineKind::Cubic);
    EXPECT_EQ(l.spline->segments.size(), 2u);
    EXPECT_TRUE(l.sturm);
    l = only_shape<Lathe>(parse("lathe { quadratic_spline 3, <1, 0>, <1, 1>, <1, 2> }"));
    EXPECT_EQ(l.spline->kind, LatheSplineKind::Quadratic);
    EXPECT_EQ(l.spline->segments.size(), 1u);
    l = only_shape<Lathe>(
        parse("lathe { bezier_spline 8, <1, 0>, <1, 1>, <1, 2>, <1, 3>, "
              "<1, 3>, <2, 4>, <2, 5>, <0, 6> }"));
    EXPECT_EQ(l.spline->segments.size(), 2u);
    // End points may be negative.
    l = only_shape<Lathe>(parse("lathe { 3, <-1, 0>, <1, 1>, <-0.5, 2> }"));
    EXPECT_EQ(l.spline->radius1, -1.0);
    Scene two =
        parse("#declare L = lathe { 2, <1, 0>, <1, 1> } object { L } lathe { L }");
    EXPECT_EQ(std::get<Lathe>(two.objects[0].shape).spline,
              std::get<Lathe>(two.objects[1].shape).spline);
}

TEST(ShapeLathe, Errors) {
    EXPECT_EQ(
        error_of("lathe { 1, <1, 0> }"),
        "test.pov:1:9: error: Lathe with linear splines must have at least two points");
    EXPECT_EQ(
        error_of("lathe { quadratic_spline 2, <1, 0>, <1, 1> }"),
        "test.pov:1:26: error: Lathe with quadratic splines must have at least three "
        "points");
    EXPECT_EQ(
        error_of("lathe { cubic_spline 3, <1, 0>, <1, 1>, <1, 2> }"),
        "test.pov:1:22: error: Lathe with cubic splines must have at least four points");
    EXPECT_EQ(
        error_of("lathe { bezier_spline 5, <1, 0>, <1, 1>, <1, 2>, <1, 3>, <1, 4> }"),
        "test.pov:1:23: error: Lathe with Bezier splines must have four points per "
        "segment");
    EXPECT_EQ(error_of("lathe { 3, <1, 0>, <-1, 1>, <1, 2> }"),
              "test.pov:1:20: error: Incorrect point in lathe");
    EXPECT_EQ(error_of("lathe { 2, <1, 0>, <1, 1> open }"),
              "test.pov:1:27: error: 'open' cannot be used with this object");
    EXPECT_EQ(error_of("lathe { bezier_spline 0 }"),
              "test.pov:1:23: error: unsupported: a lathe without segments");
}

}  // namespace
}  // namespace povwall::parser
