// ovus { B, T }: the band as POV-Ray's parser computes it, sturm, its errors, and the
// sphere it substitutes when T >= 2B.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeOvus, RadiiBandAndSturm) {
    auto o = only_shape<Ovus>(parse("ovus { 1, 0.65 }"));
    EXPECT_EQ(o.bottom_radius, 1.0);
    EXPECT_EQ(o.top_radius, 0.65);
    EXPECT_EQ(o.band_radius, 2.0);
    EXPECT_FALSE(o.sturm);
    o = only_shape<Ovus>(parse("ovus { 1 1.5 sturm translate y }"));  // comma optional
    EXPECT_EQ(o.band_radius, 3.0);
    EXPECT_TRUE(o.sturm);
    o = only_shape<Ovus>(parse("ovus { 1, 0.5 sturm off }"));
    EXPECT_FALSE(o.sturm);
    o = only_shape<Ovus>(parse("#declare O = ovus { 2, 1 } ovus { O sturm }"));
    EXPECT_EQ(o.bottom_radius, 2.0);
    EXPECT_TRUE(o.sturm);
}

TEST(ShapeOvus, SphereWhenTheTopIsTwiceTheBottom) {
    std::string messages;
    auto s = only_shape<Sphere>(parse("ovus { 0.5, 1 }", &messages));
    EXPECT_EQ(s.centre.y, 0.5);
    EXPECT_EQ(s.radius, 1.0);
    EXPECT_NE(messages.find("Ovus second radius should be less than twice first radius"),
              std::string::npos)
        << messages;
    EXPECT_EQ(only_shape<Sphere>(parse("ovus { 0, 0 }")).radius, 0.0);
    EXPECT_EQ(error_of("ovus { 0.5, 1 sturm }"),
              "test.pov:1:15: error: 'sturm' cannot be used with this object");
}

TEST(ShapeOvus, Errors) {
    EXPECT_EQ(error_of("ovus { 1, -0.5 }"),
              "test.pov:1:11: error: Both Ovus radii must be positive");
    EXPECT_EQ(error_of("ovus { -1, 0.5 }"),
              "test.pov:1:12: error: Both Ovus radii must be positive");
}

}  // namespace
}  // namespace povwall::parser
