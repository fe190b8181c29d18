// parametric as POV-Ray 3.7 parses it: the defaults, the three functions (of u and v),
// the uv corners sorted, the options, the precompute tree (sector 1 the union of its
// halves, the leaves parametric_interval's bounds), and what is refused or warned.
#include <gtest/gtest.h>

#include "core/parametric.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

constexpr const char* kTorus =
    "function { (1 + 0.3*cos(v))*cos(u) } function { 0.3*sin(v) } "
    "function { (1 + 0.3*cos(v))*sin(u) } ";

TEST(ShapeParametric, DefaultsAndOptions) {
    auto d = only_shape<Parametric>(parse(
        "parametric { function { u } function { v } function { 0 } <1, 2>, <0, 0> }"));
    for (const auto& f : d.functions) ASSERT_TRUE(f);
    EXPECT_EQ(d.umin, 0.0);
    EXPECT_EQ(d.umax, 1.0);
    EXPECT_EQ(d.vmin, 0.0);
    EXPECT_EQ(d.vmax, 2.0);
    EXPECT_FALSE(d.sphere_container);
    EXPECT_EQ(d.corner1.x, -1.0);
    EXPECT_EQ(d.corner2.z, 1.0);
    EXPECT_EQ(d.accuracy, 0.001);
    EXPECT_EQ(d.max_gradient, 1.0);  // not the isosurface's 1.1
    EXPECT_FALSE(d.precompute);
    // u and v read the functions' first two parameters.
    const FunctionHooks none;
    EXPECT_EQ(parametric_coordinate(*d.functions[0], none, 0.25, 0.5), 0.25);
    EXPECT_EQ(parametric_coordinate(*d.functions[1], none, 0.25, 0.5), 0.5);
    auto o =
        only_shape<Parametric>(parse(std::string("parametric { ") + kTorus +
                                     "<0, 0>, <2*pi, 2*pi> accuracy 0.01 max_gradient 0 "
                                     "contained_by { sphere { <1, 2, 3>, 2 } } }"));
    EXPECT_EQ(o.accuracy, 0.01);
    EXPECT_EQ(o.max_gradient, 0.0);  // POV-Ray checks neither
    EXPECT_TRUE(o.sphere_container);
    EXPECT_EQ(o.radius, 2.0);
    // A float stands for both coordinates of a corner; commas are optional.
    auto f = only_shape<Parametric>(
        parse("parametric { function { u }, function { v }, function { 0 } 0, 3 }"));
    EXPECT_EQ(f.vmax, 3.0);
}

TEST(ShapeParametric, PrecomputeTree) {
    auto p = only_shape<Parametric>(
        parse(std::string("parametric { ") + kTorus +
              "<0, 0>, <2*pi, pi> max_gradient 2 precompute 3, x, z }"));
    ASSERT_TRUE(p.precompute);
    const ParametricPrecompute& t = *p.precompute;
    EXPECT_EQ(t.depth, 3);
    EXPECT_TRUE(t.axis[0]);
    EXPECT_FALSE(t.axis[1]);
    EXPECT_TRUE(t.axis[2]);
    ASSERT_EQ(t.low[0].size(), 8u);
    EXPECT_TRUE(t.low[1].empty());
    // Leaves 4..7: u split first (the longer side), then u again (pi by pi).
    const FunctionHooks none;
    const double pi = 3.14159265358979323846;
    Real lo, hi;
    parametric_interval(*p.functions[0], none, 0.001, 2, 0, 0, pi / 2, pi, lo, hi);
    EXPECT_EQ(t.low[0][4], lo);
    EXPECT_EQ(t.high[0][4], hi);
    parametric_interval(*p.functions[2], none, 0.001, 2, 3 * pi / 2, 0, 2 * pi, pi, lo,
                        hi);
    EXPECT_EQ(t.low[2][7], lo);
    EXPECT_EQ(t.high[2][7], hi);
    EXPECT_EQ(t.low[0][1], std::min(t.low[0][2], t.low[0][3]));
    EXPECT_EQ(t.high[0][2], std::max(t.high[0][4], t.high[0][5]));
    // Axes out of order end the list; no axis: nothing precomputed.
    EXPECT_FALSE(only_shape<Parametric>(
                     parse(std::string("parametric { ") + kTorus + "0, 1 precompute 5 }"))
                     .precompute);
    EXPECT_EQ(error_of(std::string("parametric { ") + kTorus + "0, 1 precompute 5 z, y }")
                  .substr(0, 21),
              "test.pov:1:131: error");
}

TEST(ShapeParametric, Interval) {
    // f = u: corners 0, 0, 1, 1 less accuracy; slope 2 over the unit square widens each
    // edge by (2 * 1 - 0) / 2 = 1 along v, then across u by (2 - 1) / 2 = 0.5.
    auto p = only_shape<Parametric>(
        parse("parametric { function { u } function { v } function { 0 } 0, 1 }"));
    const FunctionHooks none;
    Real lo, hi;
    parametric_interval(*p.functions[0], none, 0.25, 2, 0, 0, 1, 1, lo, hi);
    EXPECT_EQ(lo, -0.25 - 1 - 0.5);
    EXPECT_EQ(hi, 0.75 + 1 + 0.5);
    // A slope limit below the corners' difference adds nothing across u.
    parametric_interval(*p.functions[0], none, 0, 0.5, 0, 0, 1, 1, lo, hi);
    EXPECT_EQ(lo, -0.25);
    EXPECT_EQ(hi, 1.25);
}

TEST(ShapeParametric, ErrorsAndWarnings) {
    const std::string torus = std::string("parametric { ") + kTorus + "0, 1 ";
    EXPECT_EQ(error_of(torus + "precompute 21 x }"),
              "test.pov:1:117: error: Precompute: invalid depth");
    EXPECT_EQ(error_of(torus + "sturm }"),
              "test.pov:1:117: error: 'sturm' cannot be used with this object");
    std::string messages;
    auto p = only_shape<Parametric>(parse(torus + "inverse }", &messages));
    EXPECT_NE(messages.find("Cannot invert a patch object."), std::string::npos);
    Scene s = parse("intersection { " + torus + "} sphere { 0, 1 } }", &messages);
    EXPECT_NE(messages.find("Patch objects not allowed in intersection."),
              std::string::npos);
    EXPECT_FALSE(s.objects[0].inverse);
}

}  // namespace
}  // namespace povwall::parser
