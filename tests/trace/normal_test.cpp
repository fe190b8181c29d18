// Perturbed normals compared with POV-Ray: a white plane lit by three parallel lights
// (red, green, blue from different directions) with diffuse 1 shows N.L per channel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/pattern_lists.h"
#include "tests/trace/pov_reference.h"
#include "trace/pattern.h"

namespace povwall::trace {
namespace {

constexpr int kNormalImageSize = 16;
const Vector3 kLights[3] = {normalize(Vector3{1, 2, 0}), Vector3{0, 1, 0},
                            normalize(Vector3{0, 2, -1})};

double max_normal_error(const std::string& pov_normal, const Normal& normal) {
    test::TopView view;
    view.extent = 3.1;
    std::string scene =
        "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n" + view.camera() +
        "light_source { <100,200,0> rgb <1,0,0> parallel point_at <0,0,0> }\n"
        "light_source { <0,100,0> rgb <0,1,0> parallel point_at <0,0,0> }\n"
        "light_source { <0,200,-100> rgb <0,0,1> parallel point_at <0,0,0> }\n"
        "plane { y, 0.37 pigment { rgb 1 } normal { " +
        pov_normal + " } finish { ambient 0 diffuse 1 } }\n";
    test::RgbImage img = test::render_with_povray(scene, kNormalImageSize);
    double worst = 0;
    for (int y = 0; y < kNormalImageSize; ++y) {
        for (int x = 0; x < kNormalImageSize; ++x) {
            Vector3 n =
                perturb_normal(normal, view.point(x, y, kNormalImageSize), {0, 1, 0}, {});
            for (int ch = 0; ch < 3; ++ch) {
                double expected = std::clamp(dot(n, kLights[ch]), 0.0, 1.0);
                worst = std::max(worst, std::fabs(img.at(x, y, ch) - expected));
            }
        }
    }
    std::printf("max error %.2e  normal { %s }\n", worst, pov_normal.c_str());
    return worst;
}

constexpr double kNormalTolerance = 1e-3;

Normal with(PatternKind kind, double amount) {
    Normal n;
    n.pattern.edit().kind = kind;
    n.pattern.edit().frequency = initial_frequency(kind);  // as parsed
    n.amount = amount;
    return n;
}

TEST(NormalVsPovray, DedicatedNormals) {
    EXPECT_LE(max_normal_error("bumps 0.6", with(PatternKind::Bumps, 0.6)),
              kNormalTolerance);
    EXPECT_LE(max_normal_error("dents 0.9", with(PatternKind::Dents, 0.9)),
              kNormalTolerance);
    EXPECT_LE(max_normal_error("wrinkles 0.4", with(PatternKind::Wrinkles, 0.4)),
              kNormalTolerance);
    EXPECT_LE(max_normal_error("ripples 0.5", with(PatternKind::Ripples, 0.5)),
              kNormalTolerance);
    EXPECT_LE(max_normal_error("waves 0.5", with(PatternKind::Waves, 0.5)),
              kNormalTolerance);
}

TEST(NormalVsPovray, ScaledBumps) {
    Normal n = with(PatternKind::Bumps, 0.5);
    n.pattern.edit().transform = Transform::scale({0.3, 0.6, 0.2});
    EXPECT_LE(max_normal_error("bumps 0.5 scale <0.3,0.6,0.2>", n), kNormalTolerance);
}

TEST(NormalVsPovray, PatternNormals) {
    Normal g = with(PatternKind::Granite, 0.3);
    EXPECT_LE(max_normal_error("granite 0.3", g), kNormalTolerance);
    Normal a = with(PatternKind::Agate, 0.5);
    a.accuracy = 0.05;
    EXPECT_LE(max_normal_error("agate 0.5 accuracy 0.05", a), kNormalTolerance);
    Normal gr = with(PatternKind::Gradient, 0.5);
    gr.pattern.edit().vector = {1, 0, 0};
    gr.pattern.edit().wave = WaveType::Sine;
    EXPECT_LE(max_normal_error("gradient x 0.5 sine_wave", gr), kNormalTolerance);
}

TEST(NormalVsPovray, QuiltedAndDiscreteNormals) {
    Normal q = with(PatternKind::Quilted, 0.7);
    q.pattern.edit().vector = {1, 1, 0};
    q.pattern.edit().transform = Transform::scale({0.6, 0.6, 0.6});
    EXPECT_LE(max_normal_error("quilted 0.7 scale 0.6", q), kNormalTolerance);
    q.pattern.edit().vector = {0.2, 0.9, 0};
    EXPECT_LE(max_normal_error("quilted 0.7 control0 0.2 control1 0.9 scale 0.6", q),
              kNormalTolerance);
    Normal c = with(PatternKind::Crackle, 0.5);
    EXPECT_LE(max_normal_error("crackle 0.5", c), kNormalTolerance);
    Normal h = with(PatternKind::Hexagon, 0.5);
    h.pattern.edit().transform = Transform::scale({0.4, 0.4, 0.4});
    EXPECT_LE(max_normal_error("hexagon 0.5 scale 0.4", h), kNormalTolerance);
}

TEST(NormalVsPovray, AverageNormals) {
    Normal avg;
    avg.pattern.edit().kind = PatternKind::Average;
    avg.map_values = {1.0f, 2.0f};
    avg.list = {with(PatternKind::Bumps, 0.9), with(PatternKind::Granite, 0.4)};
    EXPECT_LE(
        max_normal_error("average normal_map { [1 bumps 0.9] [2 granite 0.4] }", avg),
        kNormalTolerance);
}

TEST(NormalVsPovray, ScaledPatternNormalAndNormalMap) {
    Normal g = with(PatternKind::Granite, 0.4);
    g.pattern.edit().transform = Transform::scale({2, 2, 2});
    EXPECT_LE(max_normal_error("granite 0.4 scale 2", g), kNormalTolerance);
    Normal m;
    m.pattern.edit().kind = PatternKind::Gradient;
    m.pattern.edit().vector = {1, 0, 0};
    m.map_values = {0.3f, 0.7f};
    m.list = {with(PatternKind::Bumps, 0.8), with(PatternKind::Wrinkles, 0.5)};
    EXPECT_LE(max_normal_error(
                  "gradient x normal_map { [0.3 bumps 0.8] [0.7 wrinkles 0.5] }", m),
              kNormalTolerance);
}

}  // namespace
}  // namespace povwall::trace
