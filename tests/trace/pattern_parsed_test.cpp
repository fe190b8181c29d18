// Patterns read by the parser from the same text POV-Ray 3.7 renders, compared value for
// value: the pigment on a plane seen from above (ambient only, linear 16-bit output),
// and normals on a white plane lit by three coloured parallel lights (N.L per channel).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/pattern_lists.h"
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

// Pavement: many settings side by side in one render (POV-Ray starts once for a whole
// set). Panel i of `pigments` (a row of `columns` panels of `panel` units from `corner`,
// then the next row, towards +z) is a box whose top face y = 0 shows that pigment; every
// pixel's value is compared with povwall's at the pixel's point. Returns how many pixels
// differ by more than 1e-4 (the 16-bit output is good to 8e-6), printing the worst.
int pavement_panels_bad(const std::vector<std::string>& pigments, int columns,
                        double panel, int pixels_per_panel, Vector3 corner) {
    const int rows = int((pigments.size() + size_t(columns) - 1) / size_t(columns));
    const int side = std::max(columns, rows);
    test::TopView view;
    view.extent = side * panel;
    view.height = 0;
    view.centre = corner + Vector3{view.extent / 2, 0, view.extent / 2};
    std::ostringstream text;
    text.precision(17);
    text << "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n" << view.camera();
    for (size_t i = 0; i < pigments.size(); ++i) {
        const double x0 = corner.x + panel * double(int(i) % columns);
        const double z0 = corner.z + panel * double(int(i) / columns);
        text << "box { <" << x0 << ",-1," << z0 << ">, <" << x0 + panel << ",0,"
             << z0 + panel << "> pigment { " << pigments[i]
             << " } finish { ambient 1 diffuse 0 } }\n";
    }
    const int n = side * pixels_per_panel;
    const test::RgbImage img = test::render_with_povray(text.str(), n);
    const Scene scene = parser::parse_scene_text(text.str(), "test.pov", {});
    EXPECT_EQ(scene.objects.size(), pigments.size());
    int bad = 0;
    double worst = 0;
    std::string worst_at;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const size_t i =
                size_t((n - 1 - y) / pixels_per_panel * columns + x / pixels_per_panel);
            if (x / pixels_per_panel >= columns || i >= pigments.size()) continue;
            const Point3 p = view.point(x, y, n);
            const Pigment& pigment = scene.objects[i].texture.front().pigment;
            const double mine =
                std::clamp(double(evaluate_pigment(pigment, p, {}).rgb.r), 0.0, 1.0);
            const double d = std::fabs(img.at(x, y, 0) - mine);
            if (d > 1e-4) ++bad;
            if (d > worst) {
                worst = d;
                std::ostringstream at;
                at.precision(17);
                at << pigments[i] << " at " << p.x << ", " << p.z << ": " << mine
                   << ", POV-Ray " << img.at(x, y, 0);
                worst_at = at.str();
            }
        }
    }
    std::printf("%zu pavements: %d pixels differ by more than 1e-4; worst %.2e (%s)\n",
                pigments.size(), bad, worst, worst_at.c_str());
    return bad;
}

// Every tiling pavement has: sides 3, 4, 6 and tiles 1-6 (hexagons 1-5), with
// pavement_patterns of each.
std::vector<std::tuple<int, int, int>> pavement_shapes() {
    std::vector<std::tuple<int, int, int>> out;
    for (int sides : {3, 4, 6})
        for (int tiles = 1; tiles <= 6; ++tiles)
            for (int p = 1; p <= pavement_patterns(sides, tiles); ++p)
                out.emplace_back(sides, tiles, p);
    return out;
}

// Combination c of exterior, interior and form (form 0-3 on squares, 0-2 else).
std::string pavement_settings(int sides, int c) {
    const int forms = sides == 4 ? 4 : 3;
    c %= 9 * forms;
    return " exterior " + std::to_string(c / (3 * forms)) + " interior " +
           std::to_string(c / forms % 3) + " form " + std::to_string(c % forms);
}

const std::string kPavementGrey = " colour_map { [0 rgb 0] [1 rgb 1] }";

std::string pavement_text(int sides, int tiles, int pattern,
                          const std::string& settings) {
    return "pavement number_of_sides " + std::to_string(sides) + " number_of_tiles " +
           std::to_string(tiles) + " pattern " + std::to_string(pattern) + settings +
           kPavementGrey;
}

// Each of the 112 tilings once, 16 units of it (every table's period), each with other
// exterior, interior and form settings (every combination on squares and hexagons);
// then again far from the origin with other settings.
TEST(PavementVsPovray, EveryShape) {
    const auto shapes = pavement_shapes();
    ASSERT_EQ(shapes.size(), 112u);
    std::vector<std::string> near, far;
    for (size_t i = 0; i < shapes.size(); ++i) {
        const auto [s, t, p] = shapes[i];
        near.push_back(pavement_text(s, t, p, pavement_settings(s, int(i))));
        far.push_back(pavement_text(s, t, p, pavement_settings(s, int(i) * 5 + 3)));
    }
    EXPECT_EQ(pavement_panels_bad(near, 11, 16, 64, {-50.3, 0, -47.9}), 0);
    EXPECT_EQ(pavement_panels_bad(far, 11, 16, 40, {-1037.3, 0, 2412.9}), 0);
}

// The whole cross product, coarser: every tiling with every exterior, interior and
// form, one render per number of sides (2016 + 594 + 918 panels of 4.1 units).
TEST(PavementVsPovray, EveryShapeWithEverySetting) {
    for (int sides : {3, 4, 6}) {
        std::vector<std::string> all;
        for (const auto& [s, t, p] : pavement_shapes()) {
            if (s != sides) continue;
            for (int c = 0; c < (s == 4 ? 36 : 27); ++c)
                all.push_back(pavement_text(s, t, p, pavement_settings(s, c)));
        }
        const int columns = int(std::ceil(std::sqrt(double(all.size()))));
        EXPECT_EQ(pavement_panels_bad(all, columns, 4.1, 20, {-93.7, 0, -88.1}), 0)
            << sides << " sides";
    }
}

// Every exterior, interior and form setting on tilings with each kind of code word:
// square bends and corners, triangles' bends and pointy corners, and hexagons' forced
// concave corners.
TEST(PavementVsPovray, EverySetting) {
    for (const auto& [s, t, p] : {std::tuple{4, 6, 5},
                                  {4, 5, 3},
                                  {4, 3, 2},
                                  {3, 6, 12},
                                  {3, 6, 5},
                                  {3, 2, 1},
                                  {3, 4, 2},
                                  {6, 5, 2},
                                  {6, 3, 2}}) {
        std::vector<std::string> all;
        for (int c = 0; c < (s == 4 ? 36 : 27); ++c)
            all.push_back(pavement_text(s, t, p, pavement_settings(s, c)));
        EXPECT_EQ(pavement_panels_bad(all, 6, 7.3, 40, {-20.1, 0, -17.7}), 0)
            << s << "/" << t << "/" << p;
    }
    // The defaults (bare pavement: triangles), and the values as the parser reduces
    // them.
    std::vector<std::string> parsed;
    for (const char* text :
         {"pavement", "pavement number_of_sides 4 interior 4 exterior 5 form 5",
          "pavement number_of_sides 6 number_of_tiles 4.9 pattern 7.5 form 3",
          "pavement number_of_sides 3 number_of_tiles 6 pattern 9 exterior 4 form 5",
          "pavement number_of_sides 6 number_of_tiles 2 exterior 1 interior 1"})
        parsed.push_back(text + kPavementGrey);
    EXPECT_EQ(pavement_panels_bad(parsed, 3, 6.1, 48, {-9.4, 0, -8.2}), 0);
}

// As any pattern: transformed, with a wave, in maps, as a normal.
TEST(PavementVsPovray, AsPigmentNormalAndInMaps) {
    test::TopView view;
    view.extent = 6.1;
    view.centre = {-0.7, 0, 0.45};
    for (const std::string& text : std::vector<std::string>{
             "pavement number_of_sides 4 number_of_tiles 5 pattern 8 exterior 2 scale "
             "0.37 "
             "rotate y*25" +
                 kPavementGrey,
             "pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 2 frequency 2 "
             "phase 0.3 sine_wave" +
                 kPavementGrey,
             "pavement number_of_tiles 6 pattern 5 interior 2 turbulence 0.2" +
                 kPavementGrey,
             "pavement",  // the default grey map
             "gradient x pigment_map { [0 pavement number_of_sides 4 number_of_tiles 4 "
             "pattern 3 form 2 colour_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] }] [1 rgb 1] "
             "}",
             "pavement number_of_sides 6 number_of_tiles 4 pattern 5 pigment_map { [0 "
             "rgb <0.2,0.5,0.1>] [0.5 bozo scale 0.2] [1 rgb 1] }"}) {
        EXPECT_LE(max_pigment_error(text, view), kTol) << text;
    }
    EXPECT_LE(max_normal_error("pavement 0.6 number_of_sides 6 number_of_tiles 4 pattern "
                               "3 interior 1 scale 0.8",
                               view),
              kTol);
    EXPECT_LE(max_normal_error("pavement number_of_sides 4 number_of_tiles 6 pattern 17 "
                               "form 1 normal_map { [0 bumps 0.4 scale 0.2] [1 granite "
                               "0.3] }",
                               view),
              kTol);
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
