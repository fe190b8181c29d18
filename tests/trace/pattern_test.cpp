// Pattern values and pigments compared pixel by pixel with POV-Ray 3.7 renders of the
// same pigment on a plane (ambient-only, linear 16-bit output).
#include "trace/pattern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/trace/pov_reference.h"

namespace povwall::trace {
namespace {

constexpr int kSize = 16;

ColourMap grey_map() { return {{0.0f, Colour{Rgb{0.0f}}}, {1.0f, Colour{Rgb{1.0f}}}}; }

Pigment patterned(PatternKind kind) {
    Pigment p;
    p.pattern.edit().kind = kind;
    p.maps.edit().colour_map = grey_map();
    return p;
}

Warp classic_turb(Vector3 amount, int octaves = 6, Real omega = 0.5, Real lambda = 2.0) {
    Warp w;
    w.kind = Warp::Kind::Turbulence;
    w.turbulence = amount;
    w.octaves = octaves;
    w.omega = omega;
    w.lambda = lambda;
    return w;
}

// Largest per-channel difference between POV-Ray's render of `pov_pigment` and
// evaluate_pigment over the same points.
double max_pigment_error(const std::string& pov_pigment, const Pigment& pigment,
                         const test::TopView& view = {}, const std::string& globals = "",
                         const PatternEnv& env = {}) {
    std::string scene = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 " + globals +
                        " }\n" + view.camera() + "plane { y, " +
                        std::to_string(view.height) + " pigment { " + pov_pigment +
                        " } finish { ambient 1 diffuse 0 } }\n";
    test::RgbImage img = test::render_with_povray(scene, kSize);
    double worst = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            Colour c = evaluate_pigment(pigment, view.point(x, y, kSize), env);
            const float mine[3] = {c.rgb.r, c.rgb.g, c.rgb.b};
            for (int ch = 0; ch < 3; ++ch) {
                double expected = std::clamp(double(mine[ch]), 0.0, 1.0);
                worst = std::max(worst, std::fabs(img.at(x, y, ch) - expected));
            }
        }
    }
    std::printf("max error %.2e  pigment { %s }\n", worst, pov_pigment.c_str());
    return worst;
}

constexpr double kTol = 1e-3;
const std::string kGrey = " colour_map { [0 rgb 0] [1 rgb 1] }";

TEST(PatternVsPovray, BozoNoiseGenerators) {
    for (int gen : {1, 2, 3}) {
        Pigment p = patterned(PatternKind::Bozo);
        p.pattern.edit().noise_generator = gen;
        std::string pov = "bozo" + kGrey + " noise_generator " + std::to_string(gen);
        double err = max_pigment_error(pov, p);
        RecordProperty("noise_generator_" + std::to_string(gen), std::to_string(err));
        EXPECT_LE(err, kTol) << "noise_generator " << gen;
    }
}

TEST(PatternVsPovray, BozoFarFromOriginAndNegative) {
    test::TopView view;
    view.extent = 37.5;
    view.centre = {-123.25, 0, 4711.5};
    view.height = -17.3;
    EXPECT_LE(max_pigment_error("bozo" + kGrey, patterned(PatternKind::Bozo), view),
              kTol);
}

TEST(PatternVsPovray, SimplePatterns) {
    struct Case {
        const char* pov;
        PatternKind kind;
    };
    const Case cases[] = {
        {"spotted", PatternKind::Spotted},
        {"bumps", PatternKind::Bumps},
        {"dents", PatternKind::Dents},
        {"granite", PatternKind::Granite},
        {"leopard", PatternKind::Leopard},
        {"onion", PatternKind::Onion},
        {"radial", PatternKind::Radial},
        {"wrinkles", PatternKind::Wrinkles},
        {"boxed", PatternKind::Boxed},
        {"spherical", PatternKind::Spherical},
        {"cylindrical", PatternKind::Cylindrical},
        {"planar", PatternKind::Planar},
        {"ripples", PatternKind::Ripples},
        {"waves", PatternKind::Waves},
    };
    for (const Case& c : cases) {
        test::TopView view;
        view.extent = 3.3;
        view.height = 0.37;
        double err =
            max_pigment_error(std::string(c.pov) + kGrey, patterned(c.kind), view);
        EXPECT_LE(err, kTol) << c.pov;
    }
}

TEST(PatternVsPovray, GradientWithWaves) {
    Pigment p = patterned(PatternKind::Gradient);
    p.pattern.edit().vector = {1, 0, 1};
    EXPECT_LE(max_pigment_error("gradient <1,0,1>" + kGrey, p), kTol);
    struct Wave {
        const char* pov;
        WaveType wave;
    };
    for (Wave w :
         {Wave{"sine_wave", WaveType::Sine}, Wave{"triangle_wave", WaveType::Triangle},
          Wave{"scallop_wave", WaveType::Scallop}, Wave{"cubic_wave", WaveType::Cubic},
          Wave{"poly_wave 2.5", WaveType::Poly}}) {
        Pigment q = p;
        q.pattern.edit().wave = w.wave;
        q.pattern.edit().wave_exponent = 2.5;
        q.pattern.edit().frequency = 1.7;
        q.pattern.edit().phase = 0.3;
        std::string pov =
            "gradient <1,0,1>" + kGrey + " " + w.pov + " frequency 1.7 phase 0.3";
        EXPECT_LE(max_pigment_error(pov, q), kTol) << w.pov;
    }
}

TEST(PatternVsPovray, TurbulentPatterns) {
    // marble/wood/spiral default to triangle_wave in POV-Ray (the parser sets it).
    Pigment marble = patterned(PatternKind::Marble);
    marble.pattern.edit().wave = WaveType::Triangle;
    marble.pattern.edit().warps.push_back(classic_turb({0.8, 0.8, 0.8}));
    EXPECT_LE(max_pigment_error("marble turbulence 0.8" + kGrey, marble), kTol);

    Pigment wood = patterned(PatternKind::Wood);
    wood.pattern.edit().wave = WaveType::Triangle;
    wood.pattern.edit().warps.push_back(classic_turb({0.3, 0.5, 0.2}, 3, 0.6, 2.5));
    EXPECT_LE(
        max_pigment_error(
            "wood turbulence <0.3,0.5,0.2> octaves 3 omega 0.6 lambda 2.5" + kGrey, wood),
        kTol);

    Pigment agate = patterned(PatternKind::Agate);
    EXPECT_LE(max_pigment_error("agate" + kGrey, agate), kTol);
    agate.pattern.edit().scalar = 0.4;
    EXPECT_LE(max_pigment_error("agate agate_turb 0.4" + kGrey, agate), kTol);

    Pigment bozo = patterned(PatternKind::Bozo);
    bozo.pattern.edit().warps.push_back(classic_turb({0.5, 0.5, 0.5}));
    EXPECT_LE(max_pigment_error("bozo turbulence 0.5" + kGrey, bozo), kTol);

    Pigment spiral = patterned(PatternKind::Spiral1);
    spiral.pattern.edit().scalar = 3;
    spiral.pattern.edit().wave = WaveType::Triangle;
    EXPECT_LE(max_pigment_error("spiral1 3" + kGrey, spiral), kTol);
    Pigment spiral2 = spiral;
    spiral2.pattern.edit().kind = PatternKind::Spiral2;
    EXPECT_LE(max_pigment_error("spiral2 3" + kGrey, spiral2), kTol);
}

TEST(PatternVsPovray, MarbleIgnoresWarpTurbulenceButIsWarped) {
    Pigment m = patterned(PatternKind::Marble);
    m.pattern.edit().wave = WaveType::Triangle;
    Warp w = classic_turb({0.7, 0.7, 0.7});
    w.classic = false;
    m.pattern.edit().warps.push_back(w);
    EXPECT_LE(max_pigment_error("marble" + kGrey + " warp { turbulence 0.7 }", m), kTol);
    // Classic and warp turbulence together: the classic one is applied last.
    Pigment b = patterned(PatternKind::Bozo);
    b.pattern.edit().warps.push_back(classic_turb({0.3, 0.3, 0.3}));
    Warp extra = classic_turb({0.9, 0.1, 0.4});
    extra.classic = false;
    b.pattern.edit().warps.push_back(extra);
    EXPECT_LE(
        max_pigment_error(
            "bozo" + kGrey + " turbulence 0.3 warp { turbulence <0.9,0.1,0.4> }", b),
        kTol);
}

TEST(PatternVsPovray, WarpTurbulenceAndTransform) {
    Pigment p = patterned(PatternKind::Bozo);
    Warp w = classic_turb({0.6, 0.3, 0.9}, 4, 0.7, 1.9);
    w.classic = false;
    p.pattern.edit().warps.push_back(w);
    p.pattern.edit().transform =
        Transform::scale({0.5, 0.5, 0.5}).then(Transform::translate({1, 2, 3}));
    std::string pov = "bozo" + kGrey +
                      " warp { turbulence <0.6,0.3,0.9> octaves 4 omega 0.7 lambda 1.9 }"
                      " scale 0.5 translate <1,2,3>";
    EXPECT_LE(max_pigment_error(pov, p), kTol);
}

TEST(PatternVsPovray, DiscretePatternsAndDefaultMaps) {
    test::TopView view;
    view.extent = 7.3;
    Pigment checker;
    // Specs as parsed: the list patterns start at frequency 0 (initial_frequency).
    checker.pattern.edit().kind = PatternKind::Checker;
    checker.pattern.edit().frequency = 0;
    EXPECT_LE(max_pigment_error("checker", checker, view), kTol);  // default blue/green
    Pigment a, b;
    a.colour = Colour{Rgb{0.2f, 0.4f, 0.6f}};
    b.colour = Colour{Rgb{0.9f, 0.1f, 0.3f}};
    checker.maps.edit().list = {a, b};
    EXPECT_LE(
        max_pigment_error("checker rgb <0.2,0.4,0.6>, rgb <0.9,0.1,0.3>", checker, view),
        kTol);
    Pigment hex;
    hex.pattern.edit().kind = PatternKind::Hexagon;
    hex.pattern.edit().frequency = 0;
    EXPECT_LE(max_pigment_error("hexagon", hex, view), kTol);
    Pigment brick;
    brick.pattern.edit().kind = PatternKind::Brick;
    brick.pattern.edit().frequency = 0;
    brick.pattern.edit().vector2 = {1, 0.5, 0.7};
    brick.pattern.edit().scalar = 0.1;
    test::TopView side = view;
    side.height = 0.3;
    EXPECT_LE(max_pigment_error("brick brick_size <1,0.5,0.7> mortar 0.1", brick, side),
              kTol);
    for (PatternKind k : {PatternKind::Bozo, PatternKind::Marble, PatternKind::Agate,
                          PatternKind::Radial, PatternKind::Wood}) {
        Pigment d;
        d.pattern.edit().kind = k;
        if (k == PatternKind::Marble || k == PatternKind::Wood)
            d.pattern.edit().wave = WaveType::Triangle;
        const char* names[] = {"bozo", "marble", "agate", "radial", "wood"};
        int i = k == PatternKind::Bozo     ? 0
                : k == PatternKind::Marble ? 1
                : k == PatternKind::Agate  ? 2
                : k == PatternKind::Radial ? 3
                                           : 4;
        EXPECT_LE(max_pigment_error(names[i], d, view), kTol) << names[i];
    }
}

TEST(PatternVsPovray, FrequencyPhaseOnWaveSources) {
    Pigment r = patterned(PatternKind::Ripples);
    r.pattern.edit().frequency = 2.3;
    r.pattern.edit().phase = 0.4;
    EXPECT_LE(max_pigment_error("ripples" + kGrey + " frequency 2.3 phase 0.4", r), kTol);
    Pigment w = patterned(PatternKind::Waves);
    w.pattern.edit().frequency = 1.6;
    PatternEnv env;
    env.number_of_waves = 5;
    EXPECT_LE(max_pigment_error("waves" + kGrey + " frequency 1.6", w, {},
                                "number_of_waves 5", env),
              kTol);
}

TEST(PatternVsPovray, OtherNoiseGenerators) {
    Pigment g = patterned(PatternKind::Granite);
    g.pattern.edit().noise_generator = 1;
    EXPECT_LE(max_pigment_error("granite" + kGrey + " noise_generator 1", g), kTol);
    Pigment w = patterned(PatternKind::Wrinkles);
    w.pattern.edit().noise_generator = 3;
    EXPECT_LE(max_pigment_error("wrinkles" + kGrey + " noise_generator 3", w), kTol);
    Pigment m = patterned(PatternKind::Marble);
    m.pattern.edit().wave = WaveType::Triangle;
    m.pattern.edit().warps.push_back(classic_turb({1.2, 1.2, 1.2}, 4));
    PatternEnv env;
    env.noise_generator = 3;
    EXPECT_LE(max_pigment_error("marble turbulence 1.2 octaves 4" + kGrey, m, {},
                                "noise_generator 3", env),
              kTol);
    Pigment a = patterned(PatternKind::Agate);
    a.pattern.edit().noise_generator = 1;
    a.pattern.edit().warps.push_back(classic_turb({0.2, 0.2, 0.2}, 3, 0.7, 2.2));
    EXPECT_LE(max_pigment_error("agate turbulence 0.2 octaves 3 omega 0.7 lambda 2.2"
                                " noise_generator 1" +
                                    kGrey,
                                a),
              kTol);
}

TEST(PatternVsPovray, RepeatWarp) {
    Pigment p = patterned(PatternKind::Bozo);
    Warp w;
    w.kind = Warp::Kind::Repeat;
    w.repeat = {0.7, 0, 0};
    w.offset = {0.1, 0.3, 0.2};
    w.flip = {1, 0, 0};
    p.pattern.edit().warps.push_back(w);
    EXPECT_LE(max_pigment_error("bozo" + kGrey +
                                    " warp { repeat x*0.7 offset <0.1,0.3,0.2> "
                                    "flip x }",
                                p),
              kTol);
}

TEST(PatternVsPovray, CellsAndCrackle) {
    test::TopView view;
    view.extent = 6.1;
    view.centre = {-1.3, 0, 0.6};
    EXPECT_LE(max_pigment_error("cells" + kGrey, patterned(PatternKind::Cells), view),
              kTol);
    EXPECT_LE(max_pigment_error("crackle" + kGrey, patterned(PatternKind::Crackle), view),
              kTol);
    Pigment c = patterned(PatternKind::Crackle);
    c.pattern.edit().vector = {0.5, -0.3, 0.4};
    c.pattern.edit().scalar = 1.5;
    c.pattern.edit().vector2 = {0.2, 0, 0};
    EXPECT_LE(max_pigment_error(
                  "crackle form <0.5,-0.3,0.4> metric 1.5 offset 0.2" + kGrey, c, view),
              kTol);
    Pigment solid = patterned(PatternKind::Crackle);
    solid.pattern.edit().vector2 = {0, 1, 0};
    EXPECT_LE(max_pigment_error("crackle solid" + kGrey, solid, view), kTol);
}

TEST(PatternVsPovray, BlackHoleAndMappingWarps) {
    test::TopView view;
    view.extent = 5;
    Pigment base = patterned(PatternKind::Gradient);
    base.pattern.edit().vector = {1, 0, 0.3};
    base.pattern.edit().frequency = 3;
    Pigment bh = base;
    Warp w;
    w.kind = Warp::Kind::BlackHole;
    w.centre = {0.4, 0.37, -0.2};
    w.radius = 1.7;
    w.strength = 1.3;
    w.falloff = 1.5;
    bh.pattern.edit().warps.push_back(w);
    const std::string g = "gradient <1,0,0.3>" + kGrey + " frequency 3";
    EXPECT_LE(
        max_pigment_error(g + " warp { black_hole <0.4,0.37,-0.2>, 1.7 strength 1.3 "
                              "falloff 1.5 }",
                          bh, view),
        kTol);
    Pigment rep = base;
    w.inverse = true;
    w.repeat = {1.5, 0, 1.5};
    w.turbulence = {0.3, 0, 0.3};
    w.radius = 0.6;
    rep.pattern.edit().warps.push_back(w);
    EXPECT_LE(
        max_pigment_error(g + " warp { black_hole <0.4,0.37,-0.2>, 0.6 strength 1.3 "
                              "falloff 1.5 inverse repeat <1.5,0,1.5> "
                              "turbulence <0.3,0,0.3> }",
                          rep, view),
        kTol);
    struct Mapping {
        Warp::Kind kind;
        const char* pov;
    };
    for (Mapping m :
         {Mapping{Warp::Kind::Cylindrical, "cylindrical orientation y dist_exp 0.5"},
          Mapping{Warp::Kind::Spherical, "spherical orientation y dist_exp 1"},
          Mapping{Warp::Kind::Toroidal,
                  "toroidal orientation y dist_exp 0.7 "
                  "major_radius 1.2"},
          Mapping{Warp::Kind::Planar, "planar y, 0.3"}}) {
        Pigment q = base;
        Warp mw;
        mw.kind = m.kind;
        mw.orientation = {0, 1, 0};
        mw.dist_exp = m.kind == Warp::Kind::Cylindrical ? 0.5
                      : m.kind == Warp::Kind::Spherical ? 1.0
                                                        : 0.7;
        mw.major_radius = 1.2;
        mw.plane_offset = 0.3;
        q.pattern.edit().warps.push_back(mw);
        EXPECT_LE(max_pigment_error(g + " warp { " + m.pov + " }", q, view), kTol)
            << m.pov;
    }
}

TEST(PatternVsPovray, MandelAndQuilted) {
    test::TopView view;
    view.extent = 3;
    view.centre = {-0.5, 0, 0};
    Pigment m = patterned(PatternKind::Mandel);
    m.pattern.edit().scalar = 25;
    m.pattern.edit().transform =
        Transform::rotate({90, 0, 0});  // mandel lives in the x-y plane
    EXPECT_LE(max_pigment_error("mandel 25" + kGrey + " rotate x*90", m, view), kTol);
    // Every exterior and interior colouring type (values outside 0..1 included).
    struct Colouring {
        int exterior, interior;
        Real efactor, ifactor;
    };
    for (const Colouring& c :
         {Colouring{0, 1, 0.7, 1.3}, Colouring{2, 2, 0.4, 0.9}, Colouring{3, 3, 0.5, 1.1},
          Colouring{4, 4, 0.25, 2}, Colouring{5, 5, 0.3, 1.7}, Colouring{6, 6, 0.2, 0.6},
          Colouring{7, 0, 4, 0.35}, Colouring{8, 1, 5, 0.5}}) {
        Pigment f = m;
        f.pattern.edit().fractal = {uint8_t(c.exterior), uint8_t(c.interior), c.efactor,
                                    c.ifactor};
        const std::string pov = "mandel 25 exterior " + std::to_string(c.exterior) +
                                ", " + std::to_string(c.efactor) + " interior " +
                                std::to_string(c.interior) + ", " +
                                std::to_string(c.ifactor) + kGrey + " rotate x*90";
        EXPECT_LE(max_pigment_error(pov, f, view), kTol) << pov;
    }
    Pigment q = patterned(PatternKind::Quilted);
    q.pattern.edit().vector = {1, 1, 0};
    EXPECT_LE(max_pigment_error("quilted" + kGrey, q, view), kTol);
    q.pattern.edit().vector = {0.3, 0.8, 0};
    EXPECT_LE(max_pigment_error("quilted control0 0.3 control1 0.8" + kGrey, q, view),
              kTol);
}

TEST(PatternVsPovray, ColourMapBlendPoints) {
    Pigment p;
    p.pattern.edit().kind = PatternKind::Granite;
    p.maps.edit().colour_map = {{0.1f, Colour{Rgb{1, 0, 0}}},
                                {0.4f, Colour{Rgb{0, 1, 0}}},
                                {0.4f, Colour{Rgb{0, 0, 1}}},
                                {0.8f, Colour{Rgb{1, 1, 0.5f}}}};
    std::string pov =
        "granite colour_map { [0.1 rgb <1,0,0>] [0.4 rgb <0,1,0>] [0.4 rgb <0,0,1>]"
        " [0.8 rgb <1,1,0.5>] }";
    EXPECT_LE(max_pigment_error(pov, p), kTol);
}

TEST(PatternVsPovray, AveragePigments) {
    Pigment a = patterned(PatternKind::Bozo);
    Pigment b;
    b.pattern.edit().kind = PatternKind::Checker;
    b.pattern.edit().frequency = 0;
    Pigment avg;
    avg.pattern.edit().kind = PatternKind::Average;
    avg.pattern.edit().transform = Transform::scale({0.7, 0.7, 0.7});
    avg.maps.edit().map_values = {1.0f, 3.0f};
    avg.maps.edit().list = {a, b};
    EXPECT_LE(max_pigment_error("average pigment_map { [1 bozo" + kGrey +
                                    "] [3 checker] }"
                                    " scale 0.7",
                                avg),
              kTol);
}

TEST(PatternMaps, SearchMapFollowsPovRayBlendRules) {
    const float v[] = {0.2f, 0.5f, 0.5f, 0.9f};
    MapLookup below = search_map(v, 4, 0.1);
    EXPECT_EQ(below.prev, 0);
    EXPECT_EQ(below.cur, 0);
    MapLookup mid = search_map(v, 4, 0.35);
    EXPECT_EQ(mid.prev, 0);
    EXPECT_EQ(mid.cur, 1);
    EXPECT_NEAR(mid.fraction, 0.5, 1e-7);
    // At a repeated value the first of the pair wins (fraction 1 onto it; the entry
    // difference is single precision, as in POV-Ray).
    MapLookup at = search_map(v, 4, 0.5);
    EXPECT_EQ(at.cur, 1);
    EXPECT_NEAR(at.fraction, 1.0, 1e-6);
    MapLookup after = search_map(v, 4, 0.6);
    EXPECT_EQ(after.prev, 2);
    EXPECT_EQ(after.cur, 3);
    MapLookup above = search_map(v, 4, 0.95);
    EXPECT_EQ(above.prev, 3);
    EXPECT_EQ(above.cur, 3);
}

TEST(PatternMaps, PickEntriesOfCheckerTextures) {
    PatternSpec spec;
    spec.kind = PatternKind::Checker;
    spec.frequency = 0;
    MapPick a = pick_map_entries(spec, nullptr, 0, {0.5, 0.5, 0.5}, {});
    MapPick b = pick_map_entries(spec, nullptr, 0, {1.5, 0.5, 0.5}, {});
    EXPECT_EQ(a.lookup.cur, 0);
    EXPECT_EQ(b.lookup.cur, 1);
    spec.transform = Transform::scale({2, 2, 2});
    MapPick c = pick_map_entries(spec, nullptr, 0, {1.5, 0.5, 0.5}, {});
    EXPECT_EQ(c.lookup.cur, 0);
    EXPECT_DOUBLE_EQ(c.point.x, 0.75);
}

TEST(PatternVsPovray, PigmentMap) {
    Pigment inner1 = patterned(PatternKind::Bozo);
    inner1.pattern.edit().transform = Transform::scale({0.3, 0.3, 0.3});
    Pigment inner2;
    inner2.pattern.edit().kind = PatternKind::Checker;
    inner2.pattern.edit().frequency = 0;
    Pigment p;
    p.pattern.edit().kind = PatternKind::Gradient;
    p.pattern.edit().vector = {1, 0, 0};
    p.maps.edit().map_values = {0.2f, 0.8f};
    p.maps.edit().list = {inner1, inner2};
    std::string pov =
        "gradient x pigment_map { [0.2 bozo" + kGrey + " scale 0.3] [0.8 checker] }";
    EXPECT_LE(max_pigment_error(pov, p), kTol);
    // Nested pigments are evaluated in the outer pattern's space (POV-Ray passes them the
    // warped point), so an outer transform reaches them without being copied into them.
    Pigment outer = p;
    outer.pattern.edit().transform =
        Transform::scale({2, 2, 2}).then(Transform::rotate({0, 30, 0}));
    outer.pattern.edit().warps.push_back(classic_turb({0.2, 0.2, 0.2}));
    std::string pov2 = "gradient x pigment_map { [0.2 bozo" + kGrey +
                       " scale 0.3] [0.8 checker] } turbulence 0.2 scale 2 rotate y*30";
    EXPECT_LE(max_pigment_error(pov2, outer), kTol);
}

}  // namespace
}  // namespace povwall::trace
