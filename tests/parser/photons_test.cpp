// The photons blocks (parser/photons.cpp): global_settings' values as POV-Ray 3.7 sets
// them, object flags and how a CSG's come down to its children, a light's switches, and
// what is refused with a located `unsupported:`.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::parse;

TEST(Photons, GlobalBlockTakesPovRaysDefaultsThenItsItems) {
    auto s = parse("global_settings { photons { spacing 0.02 } }");
    ASSERT_TRUE(s.settings.photons);
    const PhotonSettings& p = *s.settings.photons;
    EXPECT_FLOAT_EQ(p.spacing, 0.02f);
    EXPECT_EQ(p.count, 0);
    EXPECT_EQ(p.gather_min, 20);
    EXPECT_EQ(p.gather_max, 100);
    EXPECT_FLOAT_EQ(p.jitter, 0.4f);
    EXPECT_FLOAT_EQ(p.autostop, 0.5f);
    EXPECT_FLOAT_EQ(p.expand_tolerance, 0.2f);
    EXPECT_EQ(p.expand_min, 35);
    EXPECT_EQ(p.max_trace_level, -1);
    EXPECT_FLOAT_EQ(p.radius, -1);

    s = parse(
        "global_settings { photons { count 5000 gather 10, 50 jitter 0.2 autostop 0 "
        "expand_thresholds 0.1, 20 max_trace_level 4 adc_bailout 0.01 radius 0.3, 2 "
        "media 0 } }");
    const PhotonSettings& q = *s.settings.photons;
    EXPECT_EQ(q.count, 5000);
    EXPECT_EQ(q.gather_min, 10);
    EXPECT_EQ(q.gather_max, 50);
    EXPECT_FLOAT_EQ(q.jitter, 0.2f);
    EXPECT_FLOAT_EQ(q.autostop, 0);
    EXPECT_FLOAT_EQ(q.expand_tolerance, 0.1f);
    EXPECT_EQ(q.expand_min, 20);
    EXPECT_EQ(q.max_trace_level, 4);
    EXPECT_FLOAT_EQ(q.adc_bailout, 0.01f);
    EXPECT_FLOAT_EQ(q.radius, 0.3f);
    EXPECT_FLOAT_EQ(q.radius_multiplier, 2);
    EXPECT_EQ(q.media_steps, 0);
    // Media photons: steps and spacing factor; radius's third and fourth values are the
    // media map's.
    const PhotonSettings m =
        *parse("global_settings { photons { media 100, 2 radius 0, 1, 0.5, 3 } }")
             .settings.photons;
    EXPECT_EQ(m.media_steps, 100);
    EXPECT_FLOAT_EQ(m.media_spacing_factor, 2);
    EXPECT_FLOAT_EQ(m.media_radius, 0.5f);
    EXPECT_FLOAT_EQ(m.media_radius_multiplier, 3);
    // gather's maximum 0: no photon maps (POV-Ray).
    EXPECT_FALSE(parse("global_settings { photons { gather 0, 0 } }").settings.photons);
}

TEST(Photons, ObjectFlagsComeDownToTheChildren) {
    auto s = parse(
        "global_settings { photons { spacing 0.1 } }\n"
        "union { sphere { 0, 1 photons { reflection off } } sphere { 1, 1 }\n"
        "  photons { target 0.5 refraction on reflection on collect off } "
        "split_union off }\n"
        "sphere { 0, 1 photons { pass_through } }");
    ASSERT_EQ(s.objects.size(), 2u);
    const Csg& u = std::get<Csg>(s.objects[0].shape);
    for (const Object& c : u.children) {
        EXPECT_TRUE(c.photons.target);
        EXPECT_FLOAT_EQ(c.photons.spacing_multiplier, 0.5f);
        EXPECT_EQ(c.photons.refraction, PhotonSwitch::On);
        // The parent's switch wins (POV-Ray's Post_Process).
        EXPECT_EQ(c.photons.reflection, PhotonSwitch::On);
        EXPECT_FALSE(c.photons.collect);
    }
    EXPECT_FALSE(s.objects[0].split_union);
    EXPECT_TRUE(s.objects[1].photons.pass_through);
    EXPECT_FALSE(s.objects[1].photons.target);
}

TEST(Photons, PassThroughWithTargetAndRefractionGivesWay) {
    // POV-Ray's CheckPassThru: the item given last gives way.
    auto s = parse(
        "sphere { 0, 1 photons { target refraction on pass_through } }\n"
        "sphere { 0, 1 photons { pass_through target } }");
    EXPECT_EQ(s.objects[0].photons.refraction, PhotonSwitch::Off);
    EXPECT_TRUE(s.objects[0].photons.pass_through);
    EXPECT_EQ(s.objects[1].photons.refraction, PhotonSwitch::Off);
    EXPECT_TRUE(s.objects[1].photons.pass_through);
}

TEST(Photons, LightSwitches) {
    auto s = parse("light_source { 0, 1 photons { refraction on reflection off } }");
    EXPECT_EQ(s.lights[0].photon_refraction, PhotonSwitch::On);
    EXPECT_EQ(s.lights[0].photon_reflection, PhotonSwitch::Off);
}

TEST(Photons, RefusedWhereTheMapDoesNotGoYet) {
    EXPECT_EQ(error_of("global_settings { photons { spacing 0.1 save_file \"a.ph\" } }"),
              "test.pov:1:41: error: unsupported: photons save_file");
    EXPECT_EQ(error_of("global_settings { photons { load_file \"a.ph\" } }"),
              "test.pov:1:29: error: unsupported: photons load_file");
    EXPECT_EQ(error_of("global_settings { photons { spacing 0.1 } }\n"
                       "sphere { 0, 1 hollow interior { media { absorption 1 } } }"),
              "(no error)");
    // Parallel and cylinder lights shoot photons too, and area lights from their grids.
    EXPECT_EQ(error_of("light_source { 0, 1 parallel }\n"
                       "global_settings { photons { spacing 0.1 } }"),
              "(no error)");
    EXPECT_EQ(error_of("light_source { 0, 1 cylinder }\n"
                       "global_settings { photons { spacing 0.1 } }"),
              "(no error)");
    const Scene s = parse(
        "light_source { 0, 1 area_light x, y, 2, 3 photons { area_light } }\n"
        "light_source { 0, 1 }");
    EXPECT_TRUE(s.lights[0].photon_area_light);
    EXPECT_FALSE(s.lights[1].photon_area_light);
}

}  // namespace
}  // namespace povwall::parser
