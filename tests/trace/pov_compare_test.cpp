// povwall's renderer against real POV-Ray 3.7 on scenes written twice: as .pov text for
// povray and as a core::Scene built in C++ (independent of the parser). Thresholds are
// the golden ones: rmse <= 0.01 and bad-pixel fraction <= 0.002 on the encoded values.
#include <gtest/gtest.h>

#include "tests/trace/pov_image_reference.h"
#include "tests/trace/scene_builder.h"
#include "trace/render.h"

namespace povwall::trace {
namespace {

using test::object;
using test::point_light;
using test::solid;

constexpr int kW = 96, kH = 72;

const char* kHeader = R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,1,-6> direction <0,-0.1,1.6> right <4/3,0,0> up <0,1,0> }
)";

Scene base_scene() {
    Scene s;
    s.language_version = 370;
    s.version_set = true;
    s.settings.assumed_gamma = GammaCurve::power(1.0f);
    s.camera.location = {0, 1, -6};
    s.camera.direction = {0, -0.1, 1.6};
    s.camera.right = {4.0 / 3.0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.background = Colour(Rgb(0.0f), 0, 0);
    return s;
}

Texture tex(Rgb c, Finish f = {}, float filter = 0, float transmit = 0) {
    Texture t = solid(c, filter, transmit);
    t.finish = f;
    return t;
}

void expect_matches(const std::string& name, const std::string& pov_body,
                    const Scene& scene, const RenderSettings& settings = {},
                    const std::string& extra = "-A") {
    if (!test::povray_available()) GTEST_SKIP() << "povray not installed";
    RenderSettings rs = settings;
    rs.width = kW;
    rs.height = kH;
    rs.threads = 2;
    Image ours = render_scene(scene, rs);
    test::PovImage pov =
        test::render_with_povray(name, kHeader + pov_body, kW, kH, extra);
    ASSERT_EQ(pov.width, kW) << "povray failed on " << name;
    test::dump_ppm(ours, name);
    test::Diff d = test::compare(ours, pov);
    EXPECT_LE(d.rmse, 0.01) << name;
    EXPECT_LE(d.bad_fraction, 0.002) << name;
    // Tighter than the golden bar: these scenes have no patterns or text, so the
    // renderer alone is measured.
    EXPECT_LE(d.rmse, 0.004) << name << " max_abs " << d.max_abs;
}

TEST(PovCompare, LightingShadowsPhongSpecular) {
    Scene s = base_scene();
    s.background = Colour(Rgb(0.1f, 0.15f, 0.3f));
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.6f, 0.6f, 0.5f})}));
    Finish ph;
    ph.phong = 0.8f;
    ph.phong_size = 30;
    s.objects.push_back(object(Sphere{{0, 0, 0}, 1}, {}, {tex({0.8f, 0.2f, 0.2f}, ph)}));
    Finish sp;
    sp.specular = 0.6f;
    sp.roughness = 0.02f;
    sp.diffuse = 0.7f;
    sp.brilliance = 2;
    s.objects.push_back(
        object(Sphere{{1.8, -0.3, 1}, 0.7}, {}, {tex({0.2f, 0.4f, 0.9f}, sp)}));
    s.objects.push_back(
        object(Box{{-0.5, -1, -0.5}, {0.5, 0.5, 0.5}},
               Transform::rotate({0, 30, 0}).then(Transform::translate({-2, 0, 1})),
               {tex({0.3f, 0.8f, 0.3f})}));
    s.lights.push_back(point_light({-5, 8, -6}));
    s.lights.push_back(point_light({6, 4, -3}, {0.4f, 0.4f, 0.5f}));
    expect_matches("lighting", R"(
background { rgb <0.1,0.15,0.3> }
plane { y, -1 pigment { rgb <0.6,0.6,0.5> } }
sphere { 0, 1 pigment { rgb <0.8,0.2,0.2> } finish { phong 0.8 phong_size 30 } }
sphere { <1.8,-0.3,1>, 0.7 pigment { rgb <0.2,0.4,0.9> }
         finish { specular 0.6 roughness 0.02 diffuse 0.7 brilliance 2 } }
box { <-0.5,-1,-0.5>, <0.5,0.5,0.5> rotate y*30 translate <-2,0,1> pigment { rgb <0.3,0.8,0.3> } }
light_source { <-5,8,-6> rgb 1 }
light_source { <6,4,-3> rgb <0.4,0.4,0.5> }
)",
                   s);
}

TEST(PovCompare, ReflectionTraceLevelFalloffExponent) {
    Scene s = base_scene();
    s.settings.max_trace_level = 3;
    s.background = Colour(Rgb(0.3f, 0.5f, 0.7f));
    Finish fp;
    fp.reflection_min = Rgb(0.1f);
    fp.reflection_max = Rgb(0.6f);
    fp.reflection_falloff = 2;
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.5f, 0.5f, 0.5f}, fp)}));
    Finish f1;
    f1.reflection_min = f1.reflection_max = Rgb(0.7f);
    s.objects.push_back(
        object(Sphere{{-1.1, 0, 0}, 1}, {}, {tex({0.2f, 0.2f, 0.2f}, f1)}));
    Finish f2;
    f2.reflection_min = f2.reflection_max = Rgb(0.8f, 0.6f, 0.3f);
    f2.reflection_exponent = 0.7f;
    f2.phong = 1;
    s.objects.push_back(
        object(Sphere{{1.1, 0, 0}, 1}, {}, {tex({0.9f, 0.1f, 0.1f}, f2)}));
    s.lights.push_back(point_light({-4, 6, -5}));
    expect_matches("reflection", R"(
global_settings { max_trace_level 3 }
background { rgb <0.3,0.5,0.7> }
plane { y, -1 pigment { rgb 0.5 } finish { reflection { 0.1, 0.6 falloff 2 } } }
sphere { <-1.1,0,0>, 1 pigment { rgb 0.2 } finish { reflection 0.7 } }
sphere { <1.1,0,0>, 1 pigment { rgb <0.9,0.1,0.1> }
         finish { reflection { rgb <0.8,0.6,0.3> exponent 0.7 } phong 1 } }
light_source { <-4,6,-5> rgb 1 }
)",
                   s);
}

TEST(PovCompare, FilterTransmitLayersAndColouredShadows) {
    Scene s = base_scene();
    s.background = Colour(Rgb(0.2f, 0.2f, 0.2f));
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    s.objects.push_back(
        object(Sphere{{-1.2, 0, 0}, 1}, {}, {tex({1.0f, 0.5f, 0.2f}, {}, 0.7f, 0)}));
    s.objects.push_back(object(Box{{0.3, -1, -0.5}, {1.6, 0.6, 0.8}}, {},
                               {tex({0.2f, 0.9f, 0.3f}, {}, 0, 0.5f)}));
    // Two layers: red below, a blue transmitting layer on top.
    s.objects.push_back(object(Sphere{{2.3, -0.4, 1.5}, 0.6}, {},
                               {tex({1, 0, 0}), tex({0, 0, 1}, {}, 0, 0.6f)}));
    s.lights.push_back(point_light({-3, 7, -4}));
    expect_matches("transparency", R"(
background { rgb 0.2 }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <-1.2,0,0>, 1 pigment { rgbf <1,0.5,0.2,0.7> } }
box { <0.3,-1,-0.5>, <1.6,0.6,0.8> pigment { rgbt <0.2,0.9,0.3,0.5> } }
sphere { <2.3,-0.4,1.5>, 0.6 texture { pigment { rgb <1,0,0> } }
         texture { pigment { rgbt <0,0,1,0.6> } } }
light_source { <-3,7,-4> rgb 1 }
)",
                   s);
}

TEST(PovCompare, RefractionFadeFresnel) {
    Scene s = base_scene();
    s.background = Colour(Rgb(0.5f, 0.6f, 0.8f));
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.8f, 0.3f, 0.2f})}));
    s.objects.push_back(
        object(Box{{-3, -1, 2}, {3, 2, 2.5}}, {}, {tex({0.1f, 0.6f, 0.2f})}));
    Finish g;
    g.reflection_min = Rgb(0.0f);
    g.reflection_max = Rgb(1.0f);
    g.reflection_fresnel = true;
    g.diffuse = 0.1f;
    g.ambient = Rgb(0.0f);
    g.specular = 0.8f;
    Object glass = object(Sphere{{-0.8, 0, 0}, 1}, {}, {tex({1, 1, 1}, g, 0.95f, 0)});
    Interior in;
    in.ior = 1.5f;
    in.fade_distance = 1;
    in.fade_power = 2;
    in.fade_colour = Rgb(0.3f, 0.6f, 0.9f);
    glass.interior = in;
    s.objects.push_back(glass);
    Object cyl = object(Cylinder{{1.2, -0.95, 0}, {1.2, 1, 0}, 0.6, false}, {},
                        {tex({0.9f, 0.9f, 1.0f}, {}, 0, 0.8f)});
    Interior in2;
    in2.ior = 1.33f;
    cyl.interior = in2;
    s.objects.push_back(cyl);
    s.lights.push_back(point_light({-3, 7, -4}));
    expect_matches("refraction", R"(
background { rgb <0.5,0.6,0.8> }
plane { y, -1 pigment { rgb <0.8,0.3,0.2> } }
box { <-3,-1,2>, <3,2,2.5> pigment { rgb <0.1,0.6,0.2> } }
sphere { <-0.8,0,0>, 1 pigment { rgbf <1,1,1,0.95> }
         finish { reflection { 0, 1 fresnel on } diffuse 0.1 ambient 0 specular 0.8 }
         interior { ior 1.5 fade_distance 1 fade_power 2 fade_color rgb <0.3,0.6,0.9> } }
cylinder { <1.2,-0.95,0>, <1.2,1,0>, 0.6 pigment { rgbt <0.9,0.9,1,0.8> } interior { ior 1.33 } }
light_source { <-3,7,-4> rgb 1 }
)",
                   s);
}

TEST(PovCompare, SpotParallelFadeShadowlessLights) {
    Scene s = base_scene();
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    s.objects.push_back(object(Sphere{{0, 0, 1}, 1}, {}, {tex({0.9f, 0.8f, 0.2f})}));
    Light spot = point_light({-3, 5, -2}, {1.0f, 0.8f, 0.8f});
    spot.kind = Light::Kind::Spot;
    spot.point_at = {-1, -1, 0};
    spot.radius = 15;
    spot.falloff = 25;
    spot.tightness = 10;
    s.lights.push_back(spot);
    Light par = point_light({5, 5, -5}, {0.3f, 0.3f, 0.6f});
    par.kind = Light::Kind::Parallel;
    par.point_at = {0, 0, 0};
    s.lights.push_back(par);
    Light fade = point_light({2, 0.5, -1.5}, {0.8f, 1.0f, 0.8f});
    fade.fade_distance = 1.5;
    fade.fade_power = 2;
    s.lights.push_back(fade);
    Light fill = point_light({0, 10, -10}, {0.15f, 0.1f, 0.1f});
    fill.shadowless = true;
    s.lights.push_back(fill);
    expect_matches("lights", R"(
plane { y, -1 pigment { rgb 0.9 } }
sphere { <0,0,1>, 1 pigment { rgb <0.9,0.8,0.2> } }
light_source { <-3,5,-2> rgb <1,0.8,0.8> spotlight point_at <-1,-1,0>
               radius 15 falloff 25 tightness 10 }
light_source { <5,5,-5> rgb <0.3,0.3,0.6> parallel point_at <0,0,0> }
light_source { <2,0.5,-1.5> rgb <0.8,1,0.8> fade_distance 1.5 fade_power 2 }
light_source { <0,10,-10> rgb <0.15,0.1,0.1> shadowless }
)",
                   s);
}

TEST(PovCompare, ShapesAndCsg) {
    Scene s = base_scene();
    s.background = Colour(Rgb(0.1f, 0.1f, 0.2f));
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.7f, 0.7f, 0.7f})}));
    s.objects.push_back(object(Cone{{-2.6, -1, 1}, {-2.6, 0.8, 1}, 0.7, 0.2, true}, {},
                               {tex({0.9f, 0.5f, 0.1f})}));
    s.objects.push_back(
        object(Torus{0.6, 0.2},
               Transform::rotate({-60, 0, 0}).then(Transform::translate({2.4, 0.2, 1})),
               {tex({0.2f, 0.7f, 0.9f})}));
    s.objects.push_back(object(Disc{{0, 0, 0}, {0, 0, -1}, 0.5, 0.2},
                               Transform::translate({-1.2, 1.3, 0}),
                               {tex({0.9f, 0.9f, 0.2f})}));
    s.objects.push_back(object(Triangle{{{0.6, 1, 0}, {1.6, 1.6, 0.5}, {1.2, 0.7, -0.5}}},
                               {}, {tex({0.9f, 0.2f, 0.6f})}));
    Polygon poly;
    for (auto [x, y] : {std::pair{0.0, 0.0},
                        {1.0, 0.0},
                        {1.0, 1.0},
                        {0.0, 1.0},
                        {0.0, 0.0},
                        {0.25, 0.25},
                        {0.75, 0.25},
                        {0.75, 0.75},
                        {0.25, 0.75},
                        {0.25, 0.25}}) {
        poly.points.push_back({x, y, 0});
    }
    s.objects.push_back(object(
        poly, Transform::rotate({0, -20, 0}).then(Transform::translate({-3, 1, 0})),
        {tex({0.4f, 0.9f, 0.9f})}));
    Finish shiny;
    shiny.phong = 0.8f;
    s.objects.push_back(object(
        SmoothTriangle{
            {{2.0, 1.0, -0.5}, {3.0, 1.2, 0.0}, {2.4, 2.0, 0.2}},
            std::array<Vector3, 3>{{{-0.5, 0.2, -1}, {0.6, 0.1, -1}, {0, 0.8, -1}}}},
        {}, {tex({0.9f, 0.9f, 0.9f}, shiny)}));
    Object diff;
    Csg d;
    d.kind = CsgKind::Difference;
    d.children.push_back(
        object(Box{{-1.5, -1, -0.5}, {-0.5, 0, 0.5}}, {}, {tex({0.8f, 0.8f, 0.3f})}));
    d.children.push_back(
        object(Sphere{{-1, 0, -0.5}, 0.6}, {}, {tex({0.9f, 0.2f, 0.2f})}));
    diff.shape = d;
    s.objects.push_back(diff);
    Object inter;
    Csg i;
    i.kind = CsgKind::Intersection;
    i.children.push_back(
        object(Sphere{{0.5, -0.3, 0}, 0.7}, {}, {tex({0.3f, 0.9f, 0.3f})}));
    i.children.push_back(object(Cylinder{{0.5, -1, -1}, {0.5, 1, 1}, 0.45, false}, {},
                                {tex({0.3f, 0.3f, 0.9f})}));
    inter.shape = i;
    s.objects.push_back(inter);
    s.lights.push_back(point_light({-3, 6, -5}));
    expect_matches("shapes", R"(
background { rgb <0.1,0.1,0.2> }
plane { y, -1 pigment { rgb 0.7 } }
cone { <-2.6,-1,1>, 0.7, <-2.6,0.8,1>, 0.2 open pigment { rgb <0.9,0.5,0.1> } }
torus { 0.6, 0.2 rotate <-60,0,0> translate <2.4,0.2,1> pigment { rgb <0.2,0.7,0.9> } }
disc { <0,0,0>, <0,0,-1>, 0.5, 0.2 translate <-1.2,1.3,0> pigment { rgb <0.9,0.9,0.2> } }
triangle { <0.6,1,0>, <1.6,1.6,0.5>, <1.2,0.7,-0.5> pigment { rgb <0.9,0.2,0.6> } }
polygon { 10, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>, <0.25,0.25>, <0.75,0.25>, <0.75,0.75>,
          <0.25,0.75>, <0.25,0.25> rotate <0,-20,0> translate <-3,1,0> pigment { rgb <0.4,0.9,0.9> } }
smooth_triangle { <2,1,-0.5>, <-0.5,0.2,-1>, <3,1.2,0>, <0.6,0.1,-1>, <2.4,2,0.2>, <0,0.8,-1>
                  pigment { rgb 0.9 } finish { phong 0.8 } }
difference {
  box { <-1.5,-1,-0.5>, <-0.5,0,0.5> pigment { rgb <0.8,0.8,0.3> } }
  sphere { <-1,0,-0.5>, 0.6 pigment { rgb <0.9,0.2,0.2> } }
}
intersection {
  sphere { <0.5,-0.3,0>, 0.7 pigment { rgb <0.3,0.9,0.3> } }
  cylinder { <0.5,-1,-1>, <0.5,1,1>, 0.45 pigment { rgb <0.3,0.3,0.9> } }
}
light_source { <-3,6,-5> rgb 1 }
)",
                   s);
}

TEST(PovCompare, AreaLightGridNoJitter) {
    Scene s = base_scene();
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    s.objects.push_back(object(Sphere{{0, 0, 0}, 0.8}, {}, {tex({0.9f, 0.3f, 0.3f})}));
    s.objects.push_back(
        object(Box{{1.2, -1, -0.5}, {1.8, 0.8, 0.5}}, {}, {tex({0.3f, 0.9f, 0.3f})}));
    Light a = point_light({-2, 5, -3});
    AreaLight al;
    al.axis1 = {2, 0, 0};
    al.axis2 = {0, 0, 2};
    al.size1 = 5;
    al.size2 = 4;
    a.area = al;
    s.lights.push_back(a);
    Light b = point_light({3, 4, -4}, {0.5f, 0.5f, 0.5f});
    AreaLight bl;
    bl.axis1 = {1.5, 0, 0};
    bl.axis2 = {0, 1.5, 0};
    bl.size1 = 9;
    bl.size2 = 9;
    bl.adaptive = 1;
    b.area = bl;
    s.lights.push_back(b);
    // adaptive 0 refines only where corner samples differ; circular + orient reshape the
    // grid.
    Light c = point_light({0, 3, -2}, {0.4f, 0.3f, 0.2f});
    AreaLight cl;
    cl.axis1 = {3, 0, 0};
    cl.axis2 = {0, 0, 3};
    cl.size1 = 6;
    cl.size2 = 6;
    cl.adaptive = 0;
    cl.circular = true;
    cl.orient = true;
    c.area = cl;
    s.lights.push_back(c);
    expect_matches("arealight", R"(
plane { y, -1 pigment { rgb 0.9 } }
sphere { 0, 0.8 pigment { rgb <0.9,0.3,0.3> } }
box { <1.2,-1,-0.5>, <1.8,0.8,0.5> pigment { rgb <0.3,0.9,0.3> } }
light_source { <-2,5,-3> rgb 1 area_light <2,0,0>, <0,0,2>, 5, 4 }
light_source { <3,4,-4> rgb 0.5 area_light <1.5,0,0>, <0,1.5,0>, 9, 9 adaptive 1 }
light_source { <0,3,-2> rgb <0.4,0.3,0.2> area_light <3,0,0>, <0,0,3>, 6, 6 adaptive 0
               circular orient }
)",
                   s);
}

// A ball hides only the centre sample of a 3x3 grid from the floor below it: with
// adaptive 0 the equal corners stop the refinement (full light), the default refines (3/4
// light).
TEST(PovCompare, AreaLightAdaptiveRefinement) {
    for (int adaptive : {0, 100}) {
        Scene s = base_scene();
        s.camera.location = {0, 6, -3};
        s.camera.direction = {0, -1.6, 0.8};
        s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
        s.objects.push_back(
            object(Sphere{{0, 2, 0}, 0.3}, {}, {tex({0.9f, 0.3f, 0.3f})}));
        Light a = point_light({0, 5, 0});
        AreaLight al;
        al.axis1 = {4, 0, 0};
        al.axis2 = {0, 0, 4};
        al.size1 = 3;
        al.size2 = 3;
        al.adaptive = adaptive;
        a.area = al;
        s.lights.push_back(a);
        std::string adaptive_kw = adaptive == 0 ? "adaptive 0" : "";
        expect_matches("arealight_adaptive" + std::to_string(adaptive),
                       R"(
#declare Dummy = 0;
camera { location <0,6,-3> direction <0,-1.6,0.8> right <4/3,0,0> up <0,1,0> }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <0,2,0>, 0.3 pigment { rgb <0.9,0.3,0.3> } }
light_source { <0,5,0> rgb 1 area_light <4,0,0>, <0,0,4>, 3, 3 )" +
                           adaptive_kw + " }\n",
                       s);
    }
}

TEST(PovCompare, ConstantAndGroundFog) {
    Scene s = base_scene();
    s.background = Colour(Rgb(0.2f, 0.3f, 0.8f));
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    s.objects.push_back(object(Sphere{{-1, 0, 2}, 1}, {}, {tex({0.9f, 0.2f, 0.2f})}));
    s.objects.push_back(object(Sphere{{2, 0.5, 8}, 1.5}, {}, {tex({0.2f, 0.9f, 0.2f})}));
    s.lights.push_back(point_light({-3, 6, -5}));
    Fog constant;
    constant.distance = 25;
    constant.colour = Colour(Rgb(0.6f, 0.6f, 0.7f), 0.3f, 0.2f);
    s.fogs.push_back(constant);
    Fog ground;
    ground.type = 2;
    ground.distance = 6;
    ground.offset = -0.5;
    ground.alt = 0.4;
    ground.colour = Colour(Rgb(0.9f, 0.8f, 0.6f));
    s.fogs.push_back(ground);
    expect_matches("fog", R"(
background { rgb <0.2,0.3,0.8> }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <-1,0,2>, 1 pigment { rgb <0.9,0.2,0.2> } }
sphere { <2,0.5,8>, 1.5 pigment { rgb <0.2,0.9,0.2> } }
light_source { <-3,6,-5> rgb 1 }
fog { distance 25 color rgbft <0.6,0.6,0.7,0.3,0.2> }
fog { fog_type 2 distance 6 fog_offset -0.5 fog_alt 0.4 color rgb <0.9,0.8,0.6> }
)",
                   s);
}

// A bright light dimmed by the fog (media_attenuation), and a solid (non-hollow) glass
// ball whose inside has no fog while a hollow one is fogged.
TEST(PovCompare, FogMediaAttenuationAndHollow) {
    Scene s = base_scene();
    s.background = Colour(Rgb(0.2f, 0.3f, 0.8f));
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    for (int i = 0; i < 2; ++i) {
        Finish f;
        f.ambient = Rgb(0.0f);
        f.diffuse = 0;
        Object ball = object(Sphere{{i ? 1.3 : -1.3, 0.2, 1}, 1.2}, {},
                             {tex({1, 1, 1}, f, 0, 0.9f)});
        ball.hollow = i == 1;
        s.objects.push_back(ball);
    }
    Light l = point_light({-20, 30, -20}, Rgb(30.0f));
    l.media_attenuation = true;
    s.lights.push_back(l);
    Fog fog;
    fog.distance = 12;
    fog.colour = Colour(Rgb(0.5f, 0.5f, 0.5f));
    s.fogs.push_back(fog);
    expect_matches("fog_attenuation", R"(
background { rgb <0.2,0.3,0.8> }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <-1.3,0.2,1>, 1.2 pigment { rgbt <1,1,1,0.9> } finish { ambient 0 diffuse 0 } }
sphere { <1.3,0.2,1>, 1.2 pigment { rgbt <1,1,1,0.9> } finish { ambient 0 diffuse 0 } hollow }
light_source { <-20,30,-20> rgb 30 media_attenuation on }
fog { distance 12 color rgb 0.5 }
)",
                   s);
}

TEST(PovCompare, LayeredSkySphereOverBackground) {
    Scene s = base_scene();
    s.background =
        Colour(Rgb(0.9f, 0.9f, 0.1f), 0.0f, 0.6f);  // transmit darkens it, +UA or not
    s.objects.push_back(object(Sphere{{0, 0, 0}, 1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    s.lights.push_back(point_light({-3, 6, -5}));
    SkySphere sky;
    Pigment under, over;
    under.colour = Colour(Rgb(0.2f, 0.4f, 0.9f), 0.0f, 0.3f);
    over.colour = Colour(Rgb(1.0f, 0.5f, 0.2f), 0.5f, 0.0f);
    sky.pigments = {under, over};  // the last one is on top, as POV-Ray composites them
    s.sky_sphere = sky;
    expect_matches("sky", R"(
background { rgbt <0.9,0.9,0.1,0.6> }
sphere { 0, 1 pigment { rgb 0.9 } }
light_source { <-3,6,-5> rgb 1 }
sky_sphere { pigment { rgbt <0.2,0.4,0.9,0.3> } pigment { rgbf <1,0.5,0.2,0.5> } }
)",
                   s);
}

TEST(PovCompare, AntialiasMethod1NoJitter) {
    Scene s = base_scene();
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {tex({0.9f, 0.9f, 0.9f})}));
    s.objects.push_back(object(Sphere{{0, 0, 0}, 1}, {}, {tex({0.9f, 0.2f, 0.2f})}));
    s.objects.push_back(object(Box{{1.2, -1, -0.5}, {2.0, 0.2, 0.5}},
                               Transform::rotate({0, 0, 20}), {tex({0.2f, 0.2f, 0.9f})}));
    s.lights.push_back(point_light({-3, 6, -5}));
    RenderSettings rs;
    rs.antialias = true;
    rs.aa_threshold = 0.3;
    rs.aa_depth = 3;
    rs.aa_jitter = false;
    expect_matches("antialias", R"(
plane { y, -1 pigment { rgb 0.9 } }
sphere { 0, 1 pigment { rgb <0.9,0.2,0.2> } }
box { <1.2,-1,-0.5>, <2.0,0.2,0.5> rotate z*20 pigment { rgb <0.2,0.2,0.9> } }
light_source { <-3,6,-5> rgb 1 }
)",
                   s, rs, "+A0.3 +R3 -J");
}

}  // namespace
}  // namespace povwall::trace
