// superellipsoid { <e, n> }: POV-Ray's UV vector (a float stands for both), no checks of
// the values, no `sturm`.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeSuperellipsoid, ExponentsAsWritten) {
    auto s = only_shape<Superellipsoid>(parse("superellipsoid { <0.25, 1.5> }"));
    EXPECT_EQ(s.east_west, 0.25);
    EXPECT_EQ(s.north_south, 1.5);
    // A float is promoted to both, as in advanced/cliche/cliche.pov.
    s = only_shape<Superellipsoid>(parse("superellipsoid { 0.15 }"));
    EXPECT_EQ(s.east_west, 0.15);
    EXPECT_EQ(s.north_south, 0.15);
    // Expressions, identifiers, and values POV-Ray does not reject.
    s = only_shape<Superellipsoid>(
        parse("#declare E = <0.5, 2>; superellipsoid { E * 2 - <0, 5> }"));
    EXPECT_EQ(s.east_west, 1.0);
    EXPECT_EQ(s.north_south, -1.0);
}

TEST(ShapeSuperellipsoid, IdentifierAndModifiers) {
    Scene s = parse(
        "#declare S = superellipsoid { <0.3, 0.4> scale 2 }\n"
        "superellipsoid { S translate x pigment { rgb 1 } }");
    auto se = only_shape<Superellipsoid>(s);
    EXPECT_EQ(se.east_west, 0.3);
    EXPECT_EQ(se.north_south, 0.4);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}).x, 1.0);
    EXPECT_EQ(s.objects[0].transform.point({1, 0, 0}).x, 3.0);
}

TEST(ShapeSuperellipsoid, Errors) {
    EXPECT_EQ(error_of("superellipsoid { <1, 2, 3> }"),
              "test.pov:1:18: error: UV_Vector expected but vector or color expression "
              "found");
    EXPECT_EQ(error_of("superellipsoid { rgb 1 }"),
              "test.pov:1:18: error: UV_Vector expected but vector or color expression "
              "found");
    EXPECT_EQ(error_of("superellipsoid { <1, 1> sturm }"),
              "test.pov:1:25: error: 'sturm' cannot be used with this object");
    EXPECT_EQ(error_of("superellipsoid { }").substr(0, 24), "test.pov:1:18: error: ex");
}

}  // namespace
}  // namespace povwall::parser
