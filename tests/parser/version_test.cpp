// The version a scene runs under, as POV-Ray 3.7 keeps it: `version` reads 3.7 until a
// #version sets it, behaviour asks the effective version (3.62 until then), includes that
// save and restore `version` leave an explicit 3.7, +MV starts the scene at a version,
// versions below 3.5 are raised once parsed, and the gamma mode follows as the parse
// goes.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "parser/parser.h"

namespace povwall::parser {
namespace {

Scene parse(const std::string& text, std::string* debug = nullptr,
            std::optional<int> version = std::nullopt) {
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.language_version = version;
    Scene s = parse_scene_text(text, "test.pov", o);
    if (debug) *debug = messages.str();
    return s;
}

std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "(no error)";
}

// Below 3.5 each camera item applies where it stands; POV-Ray asks the version as set,
// so a scene without #version (effective 3.62) has the 3.5+ fixed order.
TEST(Version, CameraItemsApplyInWrittenOrderBelowThreeFive) {
    const std::string camera =
        "camera { look_at <5, 0, 0> location <0, 0, -5> translate x angle 60 }\n";
    Scene old = parse("#version 3.1;\n" + camera);
    // look_at turned the camera standing at the origin toward +x, location then moved it
    // without turning it, translate moved it again, and angle rescaled the direction.
    EXPECT_DOUBLE_EQ(old.camera.location.x, 1);
    EXPECT_DOUBLE_EQ(old.camera.location.z, -5);
    EXPECT_NEAR(old.camera.direction.x, 1.33 / std::tan(kPi / 6) / 2, 1e-12);
    EXPECT_NEAR(old.camera.direction.z, 0, 1e-12);
    // No #version: 3.5+ order, look_at from the location.
    Scene modern = parse(camera);
    EXPECT_EQ(modern.language_version, 362);
    EXPECT_NEAR(modern.camera.direction.x, modern.camera.direction.z, 1e-12);
    // A turn after look_at turns the old camera's vectors and location at once.
    Scene turned = parse(
        "#version 3.0;\ncamera { location <0, 0, -5> look_at 0 "
        "rotate <0, 90, 0> }");
    EXPECT_NEAR(turned.camera.location.x, -5, 1e-12);
    EXPECT_NEAR(turned.camera.direction.x, 1, 1e-12);
    EXPECT_NE(error_of("#version 3.1;\ncamera { angle -1 }")
                  .find("error: negative viewing angle"),
              std::string::npos);
}

TEST(Version, ReadsThreeSevenBeforeAnyDirectiveButTheSceneStaysLegacy) {
    std::string debug;
    Scene s = parse("#debug str(version, 0, 2)\nsphere { 0, 1 }", &debug);
    EXPECT_EQ(debug, "3.70");
    EXPECT_EQ(s.language_version, 362);
    EXPECT_FALSE(s.version_set);
    EXPECT_EQ(s.gamma_mode, GammaMode::None);
    EXPECT_EQ(s.settings.noise_generator, 2);
}

// What colors.inc and most standard includes do around their body.
TEST(Version, AnIncludesSaveAndRestoreLeavesAnExplicitThreeSeven) {
    std::string debug;
    Scene s = parse(R"(#declare Saved = version;
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
    Scene s = parse("#include \"colors.inc\"\nsphere { 0, 1 pigment { Red } }");
    EXPECT_EQ(s.language_version, 370);
    EXPECT_TRUE(s.gamma_handling());
}

TEST(Version, BelowThreeFiveIsRaisedAndTakesNoiseGeneratorOne) {
    Scene s = parse("#version 3.1;\nsphere { 0, 1 }");
    EXPECT_EQ(s.language_version, 350);
    EXPECT_EQ(s.settings.noise_generator, 1);
    EXPECT_EQ(s.gamma_mode, GammaMode::None);
    // The generator follows the final version, unless the scene names one.
    EXPECT_EQ(parse("#version 3.1;\n#version 3.6;").settings.noise_generator, 2);
    EXPECT_EQ(parse("#version 3.1; global_settings { noise_generator 3 }")
                  .settings.noise_generator,
              3);
}

TEST(Version, SwitchStartsTheSceneAtAVersion) {
    std::string debug;
    Scene s = parse("#debug str(version, 0, 2)", &debug, 360);
    EXPECT_EQ(debug, "3.60");
    EXPECT_EQ(s.language_version, 360);
    EXPECT_FALSE(s.gamma_handling());
    // +MV3.7 on a scene that ends as a legacy one still turns output gamma on, as
    // POV-Ray's front end does; the scene's own #version 3.7 does the same.
    EXPECT_EQ(parse("#version 3.6;", nullptr, 370).gamma_mode, GammaMode::Implied37);
    EXPECT_EQ(parse("sphere { 0, 1 }", nullptr, 370).language_version, 370);
}

TEST(Version, AssumedGammaModeFollowsTheEffectiveVersionAndTheFirstOneWins) {
    std::string debug;
    Scene s = parse(
        "global_settings { assumed_gamma 2.2 }\n"
        "global_settings { assumed_gamma 1.0 }",
        &debug);
    EXPECT_EQ(s.gamma_mode, GammaMode::Assumed36);
    EXPECT_FLOAT_EQ(*s.settings.assumed_gamma, 2.2f);
    EXPECT_NE(debug.find("test.pov:2:19: warning: new instance of assumed_gamma ignored"),
              std::string::npos)
        << debug;
    EXPECT_EQ(parse("global_settings { assumed_gamma 1 }\n#version 3.7;").gamma_mode,
              GammaMode::Assumed37);
}

TEST(Version, BackgroundRemembersTheVersionItWasGivenUnder) {
    EXPECT_TRUE(parse("background { rgbt <1, 0, 0, 0.5> }").background_legacy);
    EXPECT_FALSE(
        parse("#version 3.7;\nbackground { rgbt <1, 0, 0, 0.5> }").background_legacy);
}

TEST(Version, UnofficialAndNewerVersionsAreRefusedWhereTheyStand) {
    EXPECT_EQ(error_of("#version unofficial megapov 1.21;"),
              "test.pov:1:10: error: unsupported: MegaPOV scene\n"
              "#version unofficial megapov 1.21;\n"
              "         ^~~~~~~~~~");
    EXPECT_EQ(error_of("camera { }\n#version 3.8;"),
              "test.pov:2:10: error: unsupported: #version 3.8 (povwall renders POV-Ray "
              "3.7 scenes)\n"
              "#version 3.8;\n"
              "         ^~~");
}

TEST(Version, SrgbNeedsAssumedGammaAndDecodesIntoTheWorkingGamma) {
    EXPECT_EQ(error_of("#version 3.7;\nsphere { 0, 1 pigment { srgb 0.5 } }"),
              "test.pov:2:25: error: cannot read sRGB colours before assumed_gamma has "
              "been set\n"
              "sphere { 0, 1 pigment { srgb 0.5 } }\n"
              "                        ^~~~");
    Scene s = parse(
        "global_settings { assumed_gamma 2.2 }\n"
        "sphere { 0, 1 pigment { srgb 0.5 } }");
    // sRGB 0.5 is linear 0.21404114, which gamma 2.2 encodes as 0.4962.
    EXPECT_NEAR(s.objects[0].texture[0].pigment.colour.rgb.r, 0.49623, 1e-5);
}


// Below 3.0 a pattern, colour or finish item written straight in a texture is POV-Ray's
// version 1 syntax (not read yet): a located unsupported, not a syntax error, and not a
// 3.x texture_map pattern rendered without its map. From 3.0 on, the 3.x rules.
TEST(Version, VersionOneTextureItemsAreRefusedBelowThreeZero) {
    auto first_line = [](const std::string& text) {
        const std::string e = error_of(text);
        return e.substr(0, e.find('\n'));
    };
    EXPECT_EQ(first_line("#version 2.0;\nsphere { 0, 1 texture { marble } }"),
              "test.pov:2:25: error: unsupported: POV-Ray 1.0/2.0 texture syntax "
              "('marble' written straight in a texture)");
    EXPECT_EQ(
        first_line("#version 1.0\nsphere { 0, 1 texture { pigment { rgb 1 } 0.2 } }"),
        "test.pov:2:43: error: unsupported: POV-Ray 1.0/2.0 texture syntax ('a "
        "number' written straight in a texture)");
    EXPECT_EQ(first_line("#version 1.0\nsphere { 0, 1 texture { pigment { rgb 1 } } }"),
              "(no error)");
    EXPECT_EQ(first_line("#version 3.0;\nsphere { 0, 1 texture { marble } }"),
              "(no error)");
}

}  // namespace
}  // namespace povwall::parser
