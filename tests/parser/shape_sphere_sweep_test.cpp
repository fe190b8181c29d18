// sphere_sweep { SPLINE N, <c>, r ... [tolerance T] }: the kinds and their segments,
// optional commas, tolerance, POV-Ray's errors, and the transforms it moves its spheres
// by until it keeps a matrix.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeSphereSweep, KindsSegmentsAndTolerance) {
    auto s =
        only_shape<SphereSweep>(parse("sphere_sweep { linear_spline 3, <0, 0, 0>, 1, <2, "
                                      "0, 0>, 0.5, <2, 2, 0>, 0.25 }"));
    EXPECT_EQ(s.data->spline, SweepSpline::Linear);
    ASSERT_EQ(s.data->segments.size(), 2u);
    ASSERT_EQ(s.data->joints.size(), 3u);
    EXPECT_EQ(s.tolerance, 1e-6);
    EXPECT_FALSE(s.has_matrix);
    const SweepSegment& l = s.data->segments[1];
    EXPECT_EQ(l.coefficients, 2);
    EXPECT_EQ(l.centre_coef[0].x, 2.0);
    EXPECT_EQ(l.centre_coef[1].y, 2.0);
    EXPECT_EQ(l.radius_coef[1], -0.25);
    EXPECT_EQ(s.data->joints[2].radius, 0.25);
    EXPECT_EQ(s.data->joints[2].centre.y, 2.0);
    // Commas optional; cubic kinds take segments of four spheres.
    s = only_shape<SphereSweep>(
        parse("sphere_sweep { cubic_spline, 5 <0, 0, 0> 1 <1, 0, 0> 1 <2, 0, 0> 1 "
              "<3, 0, 0> 1 <4, 0, 0> 1 tolerance 0.01 }"));
    EXPECT_EQ(s.data->spline, SweepSpline::CatmullRom);
    ASSERT_EQ(s.data->segments.size(), 2u);
    EXPECT_EQ(s.tolerance, 0.01);
    // Catmull-Rom runs from the second sphere to the last but one.
    EXPECT_EQ(s.data->joints.front().centre.x, 1.0);
    EXPECT_EQ(s.data->joints.back().centre.x, 3.0);
    EXPECT_EQ(s.data->segments[0].centre_deriv[0].x, 1.0);
    s = only_shape<SphereSweep>(
        parse("sphere_sweep { b_spline 4, <0, 0, 0>, 6, <6, 0, 0>, 6, <12, 0, 0>, 6, "
              "<18, 0, 0>, 6 }"));
    EXPECT_EQ(s.data->spline, SweepSpline::BSpline);
    ASSERT_EQ(s.data->segments.size(), 1u);
    // B-spline: (P0 + 4 P1 + P2) / 6 at u = 0.
    EXPECT_NEAR(s.data->joints[0].centre.x, 6.0, 1e-15);
    EXPECT_NEAR(s.data->joints[0].radius, 6.0, 1e-15);
    EXPECT_NEAR(s.data->joints[1].centre.x, 12.0, 1e-14);
    // The count is truncated.
    s = only_shape<SphereSweep>(
        parse("sphere_sweep { linear_spline 2.9, <0, 0, 0>, 1, <1, 0, 0>, 1 }"));
    EXPECT_EQ(s.data->modeling.size(), 2u);
    // Copies share the spheres.
    Scene two = parse(
        "#declare S = sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 } "
        "object { S } sphere_sweep { S }");
    EXPECT_EQ(std::get<SphereSweep>(two.objects[0].shape).data,
              std::get<SphereSweep>(two.objects[1].shape).data);
}

TEST(ShapeSphereSweep, TransformsMoveTheSpheresUntilAMatrixIsKept) {
    const char* base = "sphere_sweep { linear_spline 2, <1, 0, 0>, 0.5, <1, 2, 0>, 0.25 ";
    // translate, rotate and uniform scale (a negative one too) move centres and radii.
    Scene sc = parse(std::string(base) + "translate <1, 2, 3> scale -2 rotate 90 * y }");
    auto s = only_shape<SphereSweep>(sc);
    EXPECT_FALSE(s.has_matrix);
    EXPECT_TRUE(sc.objects[0].transform.is_identity());
    EXPECT_EQ(s.data->modeling[0].radius, -1.0);
    EXPECT_EQ(s.data->modeling[1].radius, -0.5);
    EXPECT_NEAR(s.data->modeling[0].centre.x, -6, 1e-15);
    EXPECT_NEAR(s.data->modeling[0].centre.y, -4, 1e-15);
    EXPECT_NEAR(s.data->modeling[0].centre.z, 4, 1e-15);
    EXPECT_EQ(s.data->segments[0].radius_coef[0], -1.0);
    // A non-uniform scale keeps a matrix; later transforms go into it.
    sc = parse(std::string(base) + "scale <1, 2, 1> translate x }");
    s = only_shape<SphereSweep>(sc);
    EXPECT_TRUE(s.has_matrix);
    EXPECT_EQ(s.data->modeling[0].centre.x, 1.0);
    EXPECT_EQ(s.data->modeling[0].radius, 0.5);
    EXPECT_EQ(sc.objects[0].transform.point({0, 1, 0}).x, 1.0);
    EXPECT_EQ(sc.objects[0].transform.point({0, 1, 0}).y, 2.0);
    // So does `matrix` or `transform`, even when it is the identity.
    sc = parse(std::string(base) + "transform { translate 0 } translate x }");
    s = only_shape<SphereSweep>(sc);
    EXPECT_TRUE(s.has_matrix);
    EXPECT_EQ(s.data->modeling[0].centre.x, 1.0);
    // Inside CSG the children move their spheres as well.
    sc = parse(std::string("union { ") + base + "} sphere { 0, 1 } translate y }");
    const Object& child = std::get<Csg>(sc.objects[0].shape).children[0];
    EXPECT_EQ(std::get<SphereSweep>(child.shape).data->modeling[0].centre.y, 1.0);
    EXPECT_TRUE(child.transform.is_identity());
    // A light moves its looks_like object by translate too.
    sc = parse(std::string("light_source { <0, 1, 0>, rgb 1 looks_like { ") + base +
               "} } translate z }");
    const Object& look = sc.lights.at(0).looks_like.at(0);
    const auto& moved = std::get<SphereSweep>(look.shape);
    EXPECT_FALSE(moved.has_matrix);
    EXPECT_EQ(moved.data->modeling[0].centre.y, 1.0);
    EXPECT_EQ(moved.data->modeling[0].centre.z, 1.0);
}

TEST(ShapeSphereSweep, Errors) {
    EXPECT_EQ(error_of("sphere_sweep { 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }"),
              "test.pov:1:16: error: Invalid type of interpolation");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 1, <0, 0, 0>, 1 }"),
              "test.pov:1:30: error: Too few modeling spheres for interpolation type");
    EXPECT_EQ(error_of("sphere_sweep { cubic_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, "
                       "<2, 0, 0>, 1 }"),
              "test.pov:1:29: error: Too few modeling spheres for interpolation type");
    EXPECT_EQ(error_of("sphere_sweep { b_spline 3.9, <0, 0, 0>, 1, <1, 0, 0>, 1, "
                       "<2, 0, 0>, 1 }"),
              "test.pov:1:25: error: Too few modeling spheres for interpolation type");
    EXPECT_EQ(
        error_of("sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 sturm }"),
        "test.pov:1:60: error: 'sturm' cannot be used with this object");
}

}  // namespace
}  // namespace povwall::parser
