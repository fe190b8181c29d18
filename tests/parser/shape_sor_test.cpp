// sor { N, points [open] }: counts, point checks, `open` only after the points, sturm.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeSor, PointsOpenAndSturm) {
    auto s = only_shape<Sor>(parse("sor { 4, <1, 0>, <1, 1>, <1, 2>, <1, 3> }"));
    ASSERT_TRUE(s.spline);
    EXPECT_EQ(s.spline->segments.size(), 1u);
    EXPECT_FALSE(s.open);
    EXPECT_FALSE(s.sturm);
    // Commas optional, a float is <f, f>, open right after the points, sturm a modifier.
    s = only_shape<Sor>(
        parse("sor { 5 <1, 0> 1 <1, 2> <1, 3> <1, 4> open sturm scale 2 }"));
    EXPECT_EQ(s.spline->segments.size(), 2u);
    EXPECT_EQ(s.spline->height1, 1.0);
    EXPECT_TRUE(s.open);
    EXPECT_TRUE(s.sturm);
    // The first and last heights are free.
    s = only_shape<Sor>(parse("sor { 4, <1, 5>, <1, 1>, <1, 2>, <1, -3> }"));
    EXPECT_EQ(s.spline->height2, 2.0);
    // Copies share the spline.
    Scene two = parse(
        "#declare S = sor { 4, <1, 0>, <1, 1>, <1, 2>, <1, 3> }\n"
        "object { S } sor { S sturm }");
    EXPECT_EQ(std::get<Sor>(two.objects[0].shape).spline,
              std::get<Sor>(two.objects[1].shape).spline);
}

TEST(ShapeSor, Errors) {
    EXPECT_EQ(
        error_of("sor { 3, <1, 0>, <1, 1>, <1, 2> }"),
        "test.pov:1:7: error: Surface of revolution must have at least four points");
    EXPECT_EQ(error_of("sor { 4, <1, 0>, <-1, 1>, <1, 2>, <1, 3> }"),
              "test.pov:1:18: error: Incorrect point in surface of revolution");
    EXPECT_EQ(error_of("sor { 5, <1, 0>, <1, 1>, <1, 2>, <1, 2>, <1, 3> }"),
              "test.pov:1:34: error: Incorrect point in surface of revolution");
    EXPECT_EQ(error_of("sor { 4, <1, 0>, <1, 1>, <1, 2>, <1, 1> }"),
              "test.pov:1:1: error: Incorrect point in surface of revolution");
    EXPECT_EQ(error_of("sor { 4, <1, 0>, <1, 1, 0>, <1, 2>, <1, 3> }"),
              "test.pov:1:18: error: UV_Vector expected but vector or color expression "
              "found");
    EXPECT_EQ(error_of("sor { 4, <1, 0>, <1, 1>, <1, 2>, <1, 3> translate x open }"),
              "test.pov:1:53: error: 'open' cannot be used with this object");
}

}  // namespace
}  // namespace povwall::parser
