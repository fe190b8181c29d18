// isosurface as POV-Ray 3.7 parses it: the defaults, the container (box corners sorted,
// sphere), the options in any order, the clamped values with their warnings, the
// settings its function reads, and what is refused.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeIsosurface, DefaultsAndOptions) {
    auto d = only_shape<Isosurface>(parse("isosurface { function { x } }"));
    ASSERT_TRUE(d.function);
    EXPECT_FALSE(d.sphere_container);
    EXPECT_EQ(d.corner1.x, -1.0);
    EXPECT_EQ(d.corner2.z, 1.0);
    EXPECT_EQ(d.threshold, 0.0);
    EXPECT_EQ(d.accuracy, 0.001);
    EXPECT_EQ(d.max_gradient, 1.1);
    EXPECT_EQ(d.max_trace, 1);
    EXPECT_TRUE(d.closed);
    auto o = only_shape<Isosurface>(
        parse("isosurface { function { x } max_trace 3.7 open threshold 0.5 "
              "contained_by { box { <1, -2, 3>, <-1, 2, -3> } } accuracy 0.01 "
              "max_gradient 4 }"));
    EXPECT_EQ(o.max_trace, 3);
    EXPECT_FALSE(o.closed);
    EXPECT_EQ(o.threshold, 0.5);
    EXPECT_EQ(o.accuracy, 0.01);
    EXPECT_EQ(o.max_gradient, 4.0);
    EXPECT_EQ(o.corner1.x, -1.0);
    EXPECT_EQ(o.corner2.x, 1.0);
    EXPECT_EQ(o.corner1.z, -3.0);
    auto s = only_shape<Isosurface>(
        parse("isosurface { function { x } contained_by { sphere { <1, 2, 3>, 2 } } "
              "all_intersections }"));
    EXPECT_TRUE(s.sphere_container);
    EXPECT_EQ(s.centre.y, 2.0);
    EXPECT_EQ(s.radius, 2.0);
    EXPECT_EQ(s.max_trace, 10);
}

TEST(ShapeIsosurface, Evaluate) {
    auto e = only_shape<Isosurface>(
        parse("isosurface { function { x } evaluate 1, 10 0.99 max_gradient 1.4 }"));
    EXPECT_TRUE(e.evaluate);
    EXPECT_EQ(e.eval_param[0], 1.0);
    EXPECT_EQ(e.eval_param[1], 10.0);
    EXPECT_EQ(e.eval_param[2], 0.99);
    EXPECT_EQ(e.max_gradient, 1.4);
    EXPECT_FALSE(only_shape<Isosurface>(parse("isosurface { function { x } }")).evaluate);
}

TEST(ShapeIsosurface, ClampedValuesWarn) {
    std::string messages;
    auto i = only_shape<Isosurface>(
        parse("isosurface { function { x } accuracy 0 max_gradient -1 max_trace 20 }",
              &messages));
    EXPECT_EQ(i.accuracy, 0.001);
    EXPECT_EQ(i.max_gradient, 1.1);
    EXPECT_EQ(i.max_trace, 10);
    EXPECT_NE(messages.find("'accuracy' is not positive"), std::string::npos);
    EXPECT_NE(messages.find("'max_gradient' is not positive"), std::string::npos);
    EXPECT_NE(messages.find("exceeds maximum of 10"), std::string::npos);
    EXPECT_EQ(only_shape<Isosurface>(parse("isosurface { function { x } max_trace 0 }"))
                  .max_trace,
              1);
}

TEST(ShapeIsosurface, TheFunctionReadsTheFinalSettings) {
    Scene s = parse(
        "union { isosurface { function { x } } sphere { 0, 1 } }\n"
        "global_settings { noise_generator 1 number_of_waves 3 }");
    const auto& u = std::get<Csg>(s.objects[0].shape);
    const auto& iso = std::get<Isosurface>(u.children[0].shape);
    EXPECT_EQ(iso.noise_generator, 1);
    EXPECT_EQ(iso.number_of_waves, 3);
}

TEST(ShapeIsosurface, ClippedBy) {
    Scene s = parse("isosurface { function { x } clipped_by { plane { y, 0 } } }");
    EXPECT_EQ(s.objects.at(0).clipped_by->size(), 1u);
}

TEST(ShapeIsosurface, Errors) {
    EXPECT_EQ(error_of("isosurface { function { x } sturm }"),
              "test.pov:1:29: error: 'sturm' cannot be used with this object");
    EXPECT_EQ(error_of("isosurface { threshold 1 }").substr(0, 24),
              "test.pov:1:14: error: ex");
}

}  // namespace
}  // namespace povwall::parser
