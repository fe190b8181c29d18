// The version a scene runs under, as POV-Ray 3.7 keeps it: `version` reads 3.7 until a
// #version sets it, behaviour asks the effective version (3.62 until then), includes that
// save and restore `version` leave an explicit 3.7, +MV starts the scene at a version,
// versions below 3.5 are raised once parsed, and the gamma mode follows as the parse
// goes.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "parser/parser.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::full_error_of;
using test::parse;

// A snippet parsed as if +MV (Version=) set the language version it starts under.
Scene parse_at_version(const std::string& text, std::string* debug = nullptr,
                       std::optional<int> version = std::nullopt) {
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.language_version = version;
    Scene s = parse_scene_text(text, "test.pov", o);
    if (debug) *debug = messages.str();
    return s;
}

// Below 3.5 each camera item applies where it stands; POV-Ray asks the version as set,
// so a scene without #version (effective 3.62) has the 3.5+ fixed order.
TEST(Version, CameraItemsApplyInWrittenOrderBelowThreeFive) {
    const std::string camera =
        "camera { look_at <5, 0, 0> location <0, 0, -5> translate x angle 60 }\n";
    Scene old = parse_at_version("#version 3.1;\n" + camera);
    // look_at turned the camera standing at the origin toward +x, location then moved it
    // without turning it, translate moved it again, and angle rescaled the direction.
    EXPECT_DOUBLE_EQ(old.camera.location.x, 1);
    EXPECT_DOUBLE_EQ(old.camera.location.z, -5);
    EXPECT_NEAR(old.camera.direction.x, 1.33 / std::tan(kPi / 6) / 2, 1e-12);
    EXPECT_NEAR(old.camera.direction.z, 0, 1e-12);
    // No #version: 3.5+ order, look_at from the location.
    Scene modern = parse_at_version(camera);
    EXPECT_EQ(modern.language_version, 362);
    EXPECT_NEAR(modern.camera.direction.x, modern.camera.direction.z, 1e-12);
    // A turn after look_at turns the old camera's vectors and location at once.
    Scene turned = parse_at_version(
        "#version 3.0;\ncamera { location <0, 0, -5> look_at 0 "
        "rotate <0, 90, 0> }");
    EXPECT_NEAR(turned.camera.location.x, -5, 1e-12);
    EXPECT_NEAR(turned.camera.direction.x, 1, 1e-12);
    EXPECT_NE(full_error_of("#version 3.1;\ncamera { angle -1 }")
                  .find("error: negative viewing angle"),
              std::string::npos);
    // 3.5 and later scenes too (POV-Ray's Parse_Camera, every camera type).
    const std::pair<const char*, int> types[] = {
        {"", 40}, {"orthographic ", 53}, {"fisheye ", 48}};
    for (const auto& [type, column] : types) {
        EXPECT_EQ(
            error_of(std::string("#version 3.7;\ncamera { ") + type +
                     "location -5*z look_at 0 angle -90 }"),
            "test.pov:2:" + std::to_string(column) + ": error: negative viewing angle");
    }
}

TEST(Version, ReadsThreeSevenBeforeAnyDirectiveButTheSceneStaysLegacy) {
    std::string debug;
    Scene s = parse_at_version("#debug str(version, 0, 2)\nsphere { 0, 1 }", &debug);
    EXPECT_EQ(debug, "3.70");
    EXPECT_EQ(s.language_version, 362);
    EXPECT_FALSE(s.version_set);
    EXPECT_EQ(s.gamma_mode, GammaMode::None);
    EXPECT_EQ(s.settings.noise_generator, 2);
}

// What colors.inc and most standard includes do around their body.
TEST(Version, AnIncludesSaveAndRestoreLeavesAnExplicitThreeSeven) {
    std::string debug;
    Scene s = parse_at_version(R"(#declare Saved = version;
#version 3.5;
#debug str(version, 0, 2)
#version Saved;
#debug concat(" ", str(version, 0, 2))
sphere { 0, 1 })",
                               &debug);
    EXPECT_EQ(debug, "3.50 3.70");
    EXPECT_EQ(s.language_version, 370);
    EXPECT_TRUE(s.version_set);
    EXPECT_EQ(s.gamma_mode, GammaMode::Implied37);
}

TEST(Version, StandardColorsIncLeavesTheSceneAtThreeSeven) {
    Scene s =
        parse_at_version("#include \"colors.inc\"\nsphere { 0, 1 pigment { Red } }");
    EXPECT_EQ(s.language_version, 370);
    EXPECT_TRUE(s.gamma_handling());
}

TEST(Version, BelowThreeFiveIsRaisedAndTakesNoiseGeneratorOne) {
    Scene s = parse_at_version("#version 3.1;\nsphere { 0, 1 }");
    EXPECT_EQ(s.language_version, 350);
    EXPECT_EQ(s.settings.noise_generator, 1);
    EXPECT_EQ(s.gamma_mode, GammaMode::None);
    // The generator follows the final version, unless the scene names one.
    EXPECT_EQ(parse_at_version("#version 3.1;\n#version 3.6;").settings.noise_generator,
              2);
    EXPECT_EQ(parse_at_version("#version 3.1; global_settings { noise_generator 3 }")
                  .settings.noise_generator,
              3);
}

TEST(Version, SwitchStartsTheSceneAtAVersion) {
    std::string debug;
    Scene s = parse_at_version("#debug str(version, 0, 2)", &debug, 360);
    EXPECT_EQ(debug, "3.60");
    EXPECT_EQ(s.language_version, 360);
    EXPECT_FALSE(s.gamma_handling());
    // +MV3.7 on a scene that ends as a legacy one still turns output gamma on, as
    // POV-Ray's front end does; the scene's own #version 3.7 does the same.
    EXPECT_EQ(parse_at_version("#version 3.6;", nullptr, 370).gamma_mode,
              GammaMode::Implied37);
    EXPECT_EQ(parse_at_version("sphere { 0, 1 }", nullptr, 370).language_version, 370);
}

TEST(Version, AssumedGammaModeFollowsTheEffectiveVersionAndTheFirstOneWins) {
    std::string debug;
    Scene s = parse_at_version(
        "global_settings { assumed_gamma 2.2 }\n"
        "global_settings { assumed_gamma 1.0 }",
        &debug);
    EXPECT_EQ(s.gamma_mode, GammaMode::Assumed36);
    EXPECT_FLOAT_EQ(s.settings.assumed_gamma->decoding_exponent, 2.2f);
    EXPECT_NE(debug.find("test.pov:2:19: warning: new instance of assumed_gamma ignored"),
              std::string::npos)
        << debug;
    EXPECT_EQ(
        parse_at_version("global_settings { assumed_gamma 1 }\n#version 3.7;").gamma_mode,
        GammaMode::Assumed37);
}

TEST(Version, BackgroundRemembersTheVersionItWasGivenUnder) {
    EXPECT_TRUE(parse_at_version("background { rgbt <1, 0, 0, 0.5> }").background_legacy);
    EXPECT_FALSE(parse_at_version("#version 3.7;\nbackground { rgbt <1, 0, 0, 0.5> }")
                     .background_legacy);
}

TEST(Version, UnofficialAndNewerVersionsAreRefusedWhereTheyStand) {
    EXPECT_EQ(full_error_of("#version unofficial megapov 1.21;"),
              "test.pov:1:10: error: unsupported: MegaPOV scene\n"
              "#version unofficial megapov 1.21;\n"
              "         ^~~~~~~~~~");
    EXPECT_EQ(full_error_of("camera { }\n#version 3.8;"),
              "test.pov:2:10: error: unsupported: #version 3.8 (povwall renders POV-Ray "
              "3.7 scenes)\n"
              "#version 3.8;\n"
              "         ^~~");
}

TEST(Version, SrgbNeedsAssumedGammaAndDecodesIntoTheWorkingGamma) {
    EXPECT_EQ(full_error_of("#version 3.7;\nsphere { 0, 1 pigment { srgb 0.5 } }"),
              "test.pov:2:25: error: cannot read sRGB colours before assumed_gamma has "
              "been set\n"
              "sphere { 0, 1 pigment { srgb 0.5 } }\n"
              "                        ^~~~");
    Scene s = parse_at_version(
        "global_settings { assumed_gamma 2.2 }\n"
        "sphere { 0, 1 pigment { srgb 0.5 } }");
    // sRGB 0.5 is linear 0.21404114, which gamma 2.2 encodes as 0.4962.
    EXPECT_NEAR(s.objects[0].texture[0].pigment.colour.rgb.r, 0.49623, 1e-5);
}

// POV-Ray's Parse_Gamma: `srgb` (then srgb colours are working values as they are) or a
// positive power; below 1 it warns (an encoding gamma written for a decoding one).
TEST(Version, AssumedGammaIsSrgbOrAPositivePower) {
    std::string debug;
    Scene s = parse_at_version(
        "#version 3.7;\nglobal_settings { assumed_gamma srgb }\n"
        "sphere { 0, 1 pigment { srgb <0.5, 0.2, 0.9> } }",
        &debug);
    ASSERT_TRUE(s.settings.assumed_gamma);
    EXPECT_EQ(s.settings.assumed_gamma->kind, GammaCurve::Kind::Srgb);
    EXPECT_EQ(s.gamma_mode, GammaMode::Assumed37);
    EXPECT_EQ(s.objects[0].texture[0].pigment.colour.rgb.r, 0.5f);
    EXPECT_EQ(s.objects[0].texture[0].pigment.colour.rgb.g, 0.2f);
    EXPECT_EQ(full_error_of("global_settings { assumed_gamma 0 }"),
              "test.pov:1:33: error: gamma value must be positive.\n"
              "global_settings { assumed_gamma 0 }\n"
              "                                ^");
    parse_at_version("global_settings { assumed_gamma 0.45 }", &debug);
    EXPECT_NE(debug.find("test.pov:1:33: warning: Suspicious value 0.45 specified for "
                         "gamma. Did you mean 2.22222?"),
              std::string::npos)
        << debug;
}

// A block pattern's colour list takes every colour keyword (POV-Ray's Parse_Blend_List
// reads a colour at any colour key): srgb and red started a pigment colour instead.
TEST(Version, BlockPatternListsTakeEveryColourKeyword) {
    Scene s = parse_at_version(
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
        "sphere { 0, 1 pigment { hexagon srgb 0.5 red 1, red 1, srgbt <1, 1, 1, 0.5> } "
        "}");
    const Pigment& p = s.objects[0].texture[0].pigment;
    ASSERT_TRUE(p.maps.allocated());
    ASSERT_EQ(p.maps->list.size(), 3u);
    // A colour key after a colour's form goes on with it (POV-Ray: 1, 0.2140, 0.2140).
    EXPECT_EQ(p.maps->list[0].colour.rgb.r, 1.0f);
    EXPECT_NEAR(p.maps->list[0].colour.rgb.g, 0.21404, 1e-5);
    EXPECT_EQ(p.maps->list[1].colour.rgb.r, 1.0f);
    EXPECT_EQ(p.maps->list[1].colour.rgb.g, 0.0f);
    EXPECT_EQ(p.maps->list[2].colour.transmit, 0.5f);
    EXPECT_EQ(p.pattern->kind, PatternKind::Hexagon);
}

// Below 3.0 a pattern, colour or finish item written straight in a texture is POV-Ray's
// version 1 syntax (not read yet): a located unsupported, not a syntax error, and not a
// 3.x texture_map pattern rendered without its map. From 3.0 on, the 3.x rules.
// Below 3.0 pigment, normal and finish items are written straight in the texture
// (POV-Ray's Parse_Vers1_Texture): a pattern sets the pigment's type alone.
TEST(Version, VersionOneTextureItemsFillThePigmentNormalAndFinish) {
    std::string debug;
    Scene s = parse(
        "#version 1.0\n"
        "sphere { <0,0,0>, 1 texture { turbulence 0.5 colour_map { [0 1 colour red 1 "
        "colour blue 1 alpha 0.5] } marble octaves 12 quick_colour red 0.5 "
        "ripples 0.3 frequency 2 phase 0.1 ambient 0.2 diffuse 0.6 reflection 0.3 "
        "phong 1 phong_size 20 specular 0.4 roughness 0.05 brilliance 2 metallic 0.01 "
        "ior 1.5 } }",
        &debug);
    const Texture& t = s.objects[0].texture[0];
    EXPECT_EQ(t.pigment.pattern->kind, PatternKind::Marble);
    EXPECT_EQ(t.pigment.pattern->wave, WaveType::Ramp);  // not pigment { marble }'s
    ASSERT_EQ(t.pigment.pattern->warps.size(), 1u);
    EXPECT_EQ(t.pigment.pattern->warps[0].octaves, 10);
    EXPECT_DOUBLE_EQ(t.pigment.pattern->warps[0].turbulence.y, 0.5);
    ASSERT_EQ(t.pigment.maps->colour_map.size(), 2u);
    EXPECT_FLOAT_EQ(t.pigment.maps->colour_map[1].colour.filter, 0.5f);  // alpha
    EXPECT_FLOAT_EQ(t.pigment.maps->quick_colour->rgb.r, 0.5f);
    ASSERT_TRUE(t.normal);
    EXPECT_EQ(t.normal->pattern->kind, PatternKind::Ripples);
    EXPECT_FLOAT_EQ(float(t.normal->amount), 0.3f);
    EXPECT_DOUBLE_EQ(t.normal->pattern->frequency, 2);
    EXPECT_FLOAT_EQ(float(t.normal->pattern->phase), 0.1f);
    const Finish& f = *t.finish;
    EXPECT_FLOAT_EQ(f.ambient.r, 0.2f);
    EXPECT_FLOAT_EQ(f.diffuse, 0.6f);
    EXPECT_FLOAT_EQ(f.reflection_max.g, 0.3f);
    EXPECT_FLOAT_EQ(f.reflection_min.g, 0.3f);
    EXPECT_FLOAT_EQ(f.phong, 1);
    EXPECT_FLOAT_EQ(f.phong_size, 20);
    EXPECT_FLOAT_EQ(f.specular, 0.4f);
    EXPECT_FLOAT_EQ(f.roughness, 0.05f);
    EXPECT_FLOAT_EQ(f.brilliance, 2);
    EXPECT_FLOAT_EQ(f.metallic, 1);  // no amount: the float is crand
    EXPECT_FLOAT_EQ(f.crand, 0.01f);
    EXPECT_NE(debug.find("Found 'marble' that should be in 'pigment' statement."),
              std::string::npos);
    EXPECT_NE(debug.find("Found 'color_map' that should be in 'pigment' statement."),
              std::string::npos);
    EXPECT_NE(debug.find("Found 'ior' that should be in 'interior' statement."),
              std::string::npos);
    EXPECT_NE(debug.find("Index of refraction value should be specified"),
              std::string::npos);
    // 1.0 gives no level-1.5 warnings (crand without its keyword).
    EXPECT_EQ(debug.find("Should use crand"), std::string::npos);
}

TEST(Version, VersionOneTextureWarningsAndErrors) {
    auto first_line = [](const std::string& text) {
        const std::string e = error_of(text);
        return e.substr(0, e.find('\n'));
    };
    // From 1.5 a texture must end with a pigment type.
    EXPECT_EQ(first_line("#version 2.0\nsphere { 0, 1 texture { phong 1 } }"),
              "test.pov:2:33: error: Expected 'pigment identifier', } found instead");
    EXPECT_EQ(first_line("#version 1.0\nsphere { 0, 1 texture { phong 1 } }"),
              "(no error)");
    EXPECT_EQ(
        first_line("#version 2.0\n#default { texture { phong 1 } }\nsphere { 0, 1 }"),
        "(no error)");
    EXPECT_EQ(first_line("#version 2.0\nsphere { 0, 1 texture { frequency 2 colour "
                         "red 1 } }"),
              "test.pov:2:50: error: No normal type given.");
    EXPECT_EQ(first_line("#version 2.0\nsphere { 0, 1 texture { mandel 20 } }"),
              "test.pov:2:25: error: unsupported: mandel written straight in a POV-Ray "
              "1.0/2.0 texture");
    EXPECT_EQ(first_line("#version 2.0\nsphere { 0, 1 texture { radial colour red 1 } }"),
              "test.pov:2:25: error: expected a texture item or '}' but found 'radial'");
    EXPECT_EQ(first_line("#version 3.0;\nsphere { 0, 1 texture { marble } }"),
              "(no error)");
    std::string debug;
    Scene s = parse(
        "#version 2.0\n#declare T = texture { colour red 1 phong 1 }\n"
        "sphere { 0, 1 texture { checker colour red 1 colour blue 1 colour_map { [0 "
        "colour red 1] [1 colour blue 1] } bumps 0.5 frequency 3 0.2 roughness 0 } }\n"
        "sphere { 0, 1 texture { bozo T scale 2 } }",
        &debug);
    for (const char* w :
         {"Cannot use color map with this pigment type.",
          "Cannot use frequency with "
          "this normal.",
          "Should use crand keyword in finish statement.", "Zero roughness used.",
          "Texture identifier overwriting previous values."})
        EXPECT_NE(debug.find(w), std::string::npos) << w;
    // 2.0 says nothing about where the items belong.
    EXPECT_EQ(debug.find("that should be in"), std::string::npos);
    const Texture& checker = s.objects[0].texture[0];
    EXPECT_EQ(checker.pigment.pattern->kind, PatternKind::Checker);
    EXPECT_DOUBLE_EQ(checker.pigment.pattern->frequency, 0);
    EXPECT_EQ(checker.pigment.maps->list.size(), 0u);  // the colour_map replaced it
    EXPECT_FLOAT_EQ(checker.finish->crand, 0.2f);
    // The identifier replaced the bozo; the scale then applies to it.
    const Texture& replaced = s.objects[1].texture[0];
    EXPECT_FLOAT_EQ(replaced.pigment.colour.rgb.r, 1);
    EXPECT_FLOAT_EQ(replaced.finish->phong, 1);
}

}  // namespace
}  // namespace povwall::parser
