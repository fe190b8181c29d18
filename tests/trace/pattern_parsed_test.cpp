// Patterns read by the parser from the same text POV-Ray 3.7 renders, compared value for
// value: the pigment on a plane seen from above (ambient only, linear 16-bit output),
// and normals on a white plane lit by three coloured parallel lights (N.L per channel).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "parser/parser.h"
#include "tests/trace/pov_reference.h"
#include "trace/pattern.h"

namespace povwall::trace {
namespace {

constexpr int kSize = 16;
constexpr double kTol = 1e-3;

std::string plane_scene(const test::TopView& view, const std::string& texture,
                        const std::string& extra = "") {
    return "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n" + view.camera() +
           extra + "plane { y, " + std::to_string(view.height) + " " + texture + " }\n";
}

const Texture& first_layer(const Scene& scene) {
    EXPECT_EQ(scene.objects.size(), 1u);
    EXPECT_FALSE(scene.objects.front().texture.empty());
    return scene.objects.front().texture.front();
}

// Largest per-channel difference between POV-Ray's render of `pigment { text }` on the
// plane and evaluate_pigment of what povwall parses from the same text.
double max_pigment_error(const std::string& text, const test::TopView& view = {}) {
    const std::string scene_text =
        plane_scene(view, "pigment { " + text + " } finish { ambient 1 diffuse 0 }");
    const test::RgbImage img = test::render_with_povray(scene_text, kSize);
    const Scene scene = parser::parse_scene_text(scene_text, "test.pov", {});
    const Pigment& pigment = first_layer(scene).pigment;
    double worst = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Colour c = evaluate_pigment(pigment, view.point(x, y, kSize), {});
            const float mine[3] = {c.rgb.r, c.rgb.g, c.rgb.b};
            for (int ch = 0; ch < 3; ++ch) {
                const double expected = std::clamp(double(mine[ch]), 0.0, 1.0);
                worst = std::max(worst, std::fabs(img.at(x, y, ch) - expected));
            }
        }
    }
    std::printf("max error %.2e  pigment { %s }\n", worst, text.c_str());
    return worst;
}

const Vector3 kLights[3] = {normalize(Vector3{1, 2, 0}), Vector3{0, 1, 0},
                            normalize(Vector3{0, 2, -1})};

double max_normal_error(const std::string& text, const test::TopView& view = {}) {
    const std::string scene_text = plane_scene(
        view, "pigment { rgb 1 } normal { " + text + " } finish { ambient 0 diffuse 1 }",
        "light_source { <100,200,0> rgb <1,0,0> parallel point_at <0,0,0> }\n"
        "light_source { <0,100,0> rgb <0,1,0> parallel point_at <0,0,0> }\n"
        "light_source { <0,200,-100> rgb <0,0,1> parallel point_at <0,0,0> }\n");
    const test::RgbImage img = test::render_with_povray(scene_text, kSize);
    const Scene scene = parser::parse_scene_text(scene_text, "test.pov", {});
    const Texture& layer = first_layer(scene);
    EXPECT_TRUE(bool(layer.normal));
    if (!layer.normal) return 1;
    double worst = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Vector3 n =
                perturb_normal(*layer.normal, view.point(x, y, kSize), {0, 1, 0}, {});
            for (int ch = 0; ch < 3; ++ch) {
                const double expected = std::clamp(dot(n, kLights[ch]), 0.0, 1.0);
                worst = std::max(worst, std::fabs(img.at(x, y, ch) - expected));
            }
        }
    }
    std::printf("max error %.2e  normal { %s }\n", worst, text.c_str());
    return worst;
}

TEST(BlockPatternsVsPovray, SquareTriangularCubicPigments) {
    test::TopView view;
    view.extent = 7.3;
    view.centre = {-0.4, 0, 0.7};
    for (const char* text :
         {"square", "square rgb <0.2,0.4,0.6>, rgb <0.9,0.1,0.3> rgb 0.5, rgb <0,0.7,1>",
          "square rgb 0.3", "square pigment { rgb <1,0.5,0> } scale 0.7 rotate y*20",
          "triangular", "triangular rgb 0.1, rgb 0.2, rgb 0.3, rgb 0.4, rgb 0.5, rgb 0.6",
          "triangular rgb <1,0,0> rgb <0,1,0> scale 0.6 translate <0.2,0,-0.3>",
          "triangular pigment { bozo scale 0.3 } pigment { rgb 1 } pigment { rgb 0.5 }",
          "cubic", "cubic rgb 0.1, rgb 0.2, rgb 0.3, rgb 0.4, rgb 0.5, rgb 0.6",
          "cubic rgb 1 translate <0.3,0,0.2>", "cubic turbulence 0.3"}) {
        EXPECT_LE(max_pigment_error(text, view), kTol) << text;
    }
    // Below the plane's origin cubic shows its -y face, and -x/-z at the sides.
    view.height = -0.9;
    view.extent = 3;
    EXPECT_LE(max_pigment_error("cubic", view), kTol);
    EXPECT_LE(max_pigment_error(
                  "cubic rgb 0.1, rgb 0.2, rgb 0.3, rgb 0.4, rgb 0.5, rgb 0.6", view),
              kTol);
}

TEST(BlockPatternsVsPovray, AsNormalsAndInMaps) {
    test::TopView view;
    view.extent = 5.3;
    EXPECT_LE(max_normal_error("square 0.5", view), kTol);
    EXPECT_LE(max_normal_error("triangular 0.7 scale 0.8", view), kTol);
    EXPECT_LE(max_normal_error("cubic 0.4 translate <0,-0.2,0>", view), kTol);
    EXPECT_LE(
        max_normal_error("square normal { bumps 0.5 scale 0.3 }, normal { gradient x "
                         "0.4 } normal { granite 0.3 } normal { dents 0.4 }",
                         view),
        kTol);
}

// A plane on a brick joint (textures/patterns/brick.pov's box faces): POV-Ray keeps the
// mortar in single precision, so the default 0.5 (less 2e-10) is 0.5 and the joint plane
// reads as mortar.
TEST(BlockPatternsVsPovray, BrickJointPlanes) {
    test::TopView view;
    view.extent = 9.7;
    view.height = 2.5;
    EXPECT_LE(max_pigment_error("brick", view), kTol);
    view.height = 0.9;
    EXPECT_LE(max_pigment_error("brick brick_size <1, 0.5, 1> mortar 0.1", view), kTol);
    view.height = 0.7;
    EXPECT_LE(max_pigment_error("brick rgb 1, rgb 0 brick_size 1.4 mortar 0.3", view),
              kTol);
}

TEST(WarpsVsPovray, CubicWarp) {
    test::TopView view;
    view.extent = 4.1;
    view.centre = {0.3, 0, -0.2};
    for (const char* text :
         {"gradient x colour_map { [0 rgb 0] [1 rgb 1] } warp { cubic }",
          "gradient y colour_map { [0 rgb 0] [1 rgb <1,0.5,0>] } warp { cubic }",
          "checker rgb 0, rgb 1 scale 0.1 warp { cubic }",
          "onion colour_map { [0 rgb 0] [1 rgb 1] } warp { cubic } scale 2"}) {
        EXPECT_LE(max_pigment_error(text, view), kTol) << text;
    }
    view.height = -0.6;
    EXPECT_LE(max_pigment_error("gradient x colour_map { [0 rgb 0] [1 rgb 1] } warp { "
                                "cubic } translate <0.2,0,0.1>",
                                view),
              kTol);
}

// The fractals live in the x-y plane: rotated onto the viewed x-z plane.
TEST(FractalsVsPovray, JuliaMandelExponentsMagnet) {
    test::TopView view;
    view.extent = 3.2;
    view.centre = {-0.3, 0, 0.1};
    const std::string grey = " colour_map { [0 rgb 0] [1 rgb 1] } rotate x*90";
    for (const std::string f :
         {"julia <-0.745, 0.113>, 40", "julia <0.353, 0.288> 30 exponent 3",
          "julia <0.3, 0.5>, 25 exponent 4", "julia <0.2, 0.6>, 20 exponent 5",
          "julia <-0.4, 0.3>, 20 exponent 8", "mandel 30 exponent 3",
          "mandel 30 exponent 4", "mandel 20 exponent 6", "mandel 25 exponent 1",
          "magnet 1 mandel 30", "magnet 2 mandel 30", "magnet 1 julia <0.6, 0.4>, 30",
          "magnet 2 julia <1.2, -0.3> 30",
          "julia <-0.745, 0.113>, 40 exterior 2, 0.6 interior 1, 0.8",
          "julia <0.28, 0.01>, 40 exterior 7, 5 interior 6, 0.5",
          "magnet 1 mandel 40 exterior 6, 0.01 interior 2, 1.5"}) {
        EXPECT_LE(max_pigment_error(f + grey, view), kTol) << f;
    }
    // Default colour maps: mandel's own only with exponent 2, grey for the others.
    for (const std::string f : {"julia <-0.745, 0.113>, 40", "mandel 30 exponent 3",
                                "magnet 2 mandel 30", "mandel 30 exponent 2"}) {
        EXPECT_LE(max_pigment_error(f + " rotate x*90", view), kTol) << f;
    }
    EXPECT_LE(max_normal_error("julia <-0.745, 0.113>, 40 0.3 rotate x*90", view), kTol);
    // fractals1.pov's floor: magnet colourings, and its normal with a slope_map at a tiny
    // accuracy.
    view.extent = 1.3;
    view.centre = {0.4, 0, 0.3};
    EXPECT_LE(
        max_pigment_error("magnet 1 mandel 50 colour_map { [0 rgb <1,.8,.5>] [1 rgb "
                          "<.8,.5,.4>] } interior 1,200 exterior 5,1 rotate x*90",
                          view),
        kTol);
    EXPECT_LE(max_normal_error("magnet 1 mandel 50 .2 slope_map { [0 <1,0>][1 <0,-1>] } "
                               "interior 1,200 accuracy .0005 rotate x*90",
                               view),
              kTol);
}

TEST(TilingVsPovray, EveryTiling) {
    test::TopView view;
    view.extent = 6.1;
    view.centre = {-0.7, 0, 0.45};
    const std::string grey = " colour_map { [0 rgb 0] [1 rgb 1] }";
    for (int n = 1; n <= 27; ++n) {
        const std::string text = "tiling " + std::to_string(n) + grey;
        EXPECT_LE(max_pigment_error(text, view), kTol) << text;
        EXPECT_LE(max_pigment_error(text + " scale 0.37 rotate y*25", view), kTol)
            << text;
    }
    // The Penrose tilings (25-27) are not periodic: far from the origin too, many levels
    // down their subdivision, and around one vertex closely.
    for (int n = 25; n <= 27; ++n) {
        const std::string text = "tiling " + std::to_string(n) + grey;
        for (auto [x, z, extent] : {std::tuple{37.3, -12.1, 8.0},
                                    {-523.7, 311.9, 6.0},
                                    {12345.6, -6789.1, 4.0},
                                    {1.0, 0.0, 0.02}}) {
            test::TopView far;
            far.centre = {x, 0, z};
            far.extent = extent;
            EXPECT_LE(max_pigment_error(text, far), kTol)
                << text << " at " << x << ", " << z;
        }
    }
    EXPECT_LE(max_pigment_error("tiling 5", view), kTol);  // the default grey map
    EXPECT_LE(max_normal_error("tiling 9 0.5 scale 0.8", view), kTol);
}

TEST(FacetsVsPovray, FollowingNormalAndCoords) {
    test::TopView view;
    view.extent = 2.3;
    for (const char* text : {"facets", "facets size 0.03", "facets coords 0.5",
                             "facets coords 0.8 size 0.2 metric 3",
                             "facets coords 0.4 metric 1 scale 0.3"}) {
        EXPECT_LE(max_normal_error(text, view), kTol) << text;
    }
}

}  // namespace
}  // namespace povwall::trace
