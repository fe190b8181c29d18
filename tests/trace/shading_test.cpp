// Shading: values computed by hand from POV-Ray's formulas, trace-level rules, and the
// spawn/combine split (the recursive driver must equal a manual combination of children).
#include <gtest/gtest.h>

#include <random>

#include "tests/trace/scene_builder.h"
#include "trace/camera.h"
#include "trace/render.h"
#include "trace/tracer.h"

namespace povwall::trace {
namespace {

using test::object;
using test::point_light;
using test::solid;

Rgb centre_pixel(const Scene& s) {
    RenderSettings rs;
    rs.width = 1;
    rs.height = 1;
    rs.threads = 1;
    Image img = render_scene(s, rs);
    return {img.rgba[0], img.rgba[1], img.rgba[2]};
}

void expect_rgb(const Rgb& a, const Rgb& b, float tol = 1e-6f) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

TEST(Shading, SphereLitHeadOnByHand) {
    // Camera, light and hit point on the z axis: N.L = 1, phong R.L = 1, specular H.N
    // = 1.
    Scene s;
    Texture t = solid({0.8f, 0.6f, 0.4f});
    t.finish.edit().ambient = Rgb(0.1f);
    t.finish.edit().diffuse = 0.6f;
    t.finish.edit().phong = 0.5f;
    t.finish.edit().specular = 0.3f;
    s.objects.push_back(object(Sphere{{0, 0, 5}, 1}, {}, {t}));
    Light l = point_light({0, 0, 0}, Rgb(0.5f));
    l.fade_distance = 2;  // 2 / (1 + (4/2)^2) = 0.4 at the hit 4 units away
    l.fade_power = 2;
    s.lights.push_back(l);
    const float light = 0.5f * 0.4f;
    const Rgb pig{0.8f, 0.6f, 0.4f};
    Rgb expected =
        pig * 0.1f + pig * (0.6f * light) + Rgb(0.5f * light) + Rgb(0.3f * light);
    expect_rgb(centre_pixel(s), expected);
    // fade_power without fade_distance: no fade (POV-Ray 3.7's Attenuate_Light).
    s.lights[0].fade_distance = 0;
    {
        const float l2 = 0.5f;
        Rgb e2 = pig * 0.1f + pig * (0.6f * l2) + Rgb(0.5f * l2) + Rgb(0.3f * l2);
        expect_rgb(centre_pixel(s), e2);
    }
    s.lights[0].fade_distance = 2;
    // ambient_light scales the ambient term only.
    s.settings.ambient_light = Rgb(0.5f, 0.0f, 1.0f);
    expect_rgb(centre_pixel(s), expected - pig * 0.1f + pig * Rgb(0.05f, 0.0f, 0.1f));
}

TEST(Shading, BrillianceAndObliqueDiffuse) {
    // Light at 60 degrees from the normal: diffuse = cos^brilliance * diffuse.
    Scene s;
    Texture t = solid({1, 1, 1});
    t.finish.edit().ambient = Rgb(0.0f);
    t.finish.edit().diffuse = 1;
    t.finish.edit().brilliance = 3;
    s.objects.push_back(object(Plane{{0, 0, -1}, -5}, {}, {t}));
    // Plane z = 5 facing the camera; light far along (sin60, 0, -cos60) from the hit.
    Real d = 1000;
    s.lights.push_back(
        point_light({d * std::sin(kPi / 3), 0, 5 - d * std::cos(kPi / 3)}, Rgb(1.0f)));
    float c = float(std::pow(0.5, 3));
    expect_rgb(centre_pixel(s), Rgb(c), 1e-5f);
}

TEST(Shading, ReflectionAndMaxTraceLevel) {
    Scene s;
    s.background = Colour(Rgb(0.2f, 0.4f, 0.6f));
    Texture mirror = solid({0, 0, 0});
    mirror.finish.edit().ambient = Rgb(0.0f);
    mirror.finish.edit().diffuse = 0;
    mirror.finish.edit().reflection_min = mirror.finish.edit().reflection_max = Rgb(0.5f);
    s.objects.push_back(object(Plane{{0, 0, -1}, -5}, {}, {mirror}));
    expect_rgb(centre_pixel(s), Rgb(0.1f, 0.2f, 0.3f));
    // Level 1 only: the reflected ray is refused and contributes black.
    s.settings.max_trace_level = 1;
    expect_rgb(centre_pixel(s), Rgb(0.0f));
    // adc_bailout above the reflected weight (0.5) also refuses it.
    s.settings.max_trace_level = 5;
    s.settings.adc_bailout = 0.6f;
    expect_rgb(centre_pixel(s), Rgb(0.0f));
}

TEST(Shading, PassThroughTransparencyKeepsItsParentsTraceLevel) {
    // A surface without IOR change continues the ray at its level (POV-Ray 3.7's
    // continued ray), but TraceRay meets every ray at that level first: at
    // max_trace_level 1 the camera ray's level is used up and nothing shows through.
    Scene s;
    s.background = Colour(Rgb(1.0f));
    s.settings.max_trace_level = 1;
    Texture t = solid({1.0f, 0.5f, 0.0f}, 1.0f, 0.0f);
    t.finish.edit().ambient = Rgb(1.0f);
    s.objects.push_back(object(Sphere{{0, 0, 5}, 1}, {}, {t}));
    expect_rgb(centre_pixel(s), Rgb(0.0f));
    // At level 2 the ray filters twice (two surfaces, one level: the second continued
    // ray starts at level 1 too).
    s.settings.max_trace_level = 2;
    expect_rgb(centre_pixel(s), Rgb(1.0f, 0.25f, 0.0f));
    // With an IOR change the refracted ray takes a level: still through at 2, but it
    // leaves the sphere by a second refraction at level 2: black.
    Interior in;
    in.ior = 1.5f;
    s.objects[0].interior = in;
    expect_rgb(centre_pixel(s), Rgb(0.0f));
}

TEST(Shading, OpaqueBlockerAndFilteredShadow) {
    // Plane lit through a filtering pane: light * rgb * filter; an opaque pane: black.
    Scene s;
    Texture floor = solid({1, 1, 1});
    floor.finish.edit().ambient = Rgb(0.0f);
    floor.finish.edit().diffuse = 1;
    s.objects.push_back(object(Plane{{0, 0, -1}, -5}, {}, {floor}));
    Texture pane = solid({0.5f, 1.0f, 0.25f}, 0.8f, 0.1f);
    s.objects.push_back(object(Box{{-10, -10, 2}, {10, 10, 2.5}}, {}, {pane}));
    s.objects.back().no_image = true;  // camera sees the floor; the light does not
    s.lights.push_back(point_light({0, 0, 0}));
    // rgbTransm = rgb*filter + transmit, applied at each of the pane's two faces.
    Rgb once{0.5f * 0.8f + 0.1f, 1.0f * 0.8f + 0.1f, 0.25f * 0.8f + 0.1f};
    expect_rgb(centre_pixel(s), once * once, 1e-6f);
    s.objects.back().texture = {solid({0.5f, 1.0f, 0.25f})};
    expect_rgb(centre_pixel(s), Rgb(0.0f));
    s.objects.back().no_shadow = true;
    expect_rgb(centre_pixel(s), Rgb(1.0f));
}

TEST(Shading, LooksLikeObjectCastsNoShadow) {
    Scene s;
    Texture wall = solid({1, 1, 1});
    wall.finish.edit().ambient = Rgb(0.0f);
    wall.finish.edit().diffuse = 1;
    s.objects.push_back(object(Plane{{0, 0, -1}, -5}, {}, {wall}));
    Light l = point_light({0, 3, 2});
    l.looks_like.push_back(object(Sphere{{0, 3, 2}, 0.2}, {}, {solid({1, 1, 0})}));
    s.lights.push_back(l);
    // The shadow ray ends inside the bulb: it must not be blocked by it.
    expect_rgb(centre_pixel(s), Rgb(float(std::sqrt(0.5))), 1e-6f);
}

Scene busy_scene() {
    Scene s;
    s.background = Colour(Rgb(0.3f, 0.5f, 0.7f));
    s.camera.location = {0, 1, -6};
    Texture floor = solid({0.7f, 0.6f, 0.5f});
    floor.finish.edit().reflection_min = Rgb(0.1f);
    floor.finish.edit().reflection_max = Rgb(0.5f);
    floor.finish.edit().reflection_falloff = 2;
    s.objects.push_back(object(Plane{{0, 1, 0}, -1}, {}, {floor}));
    Texture glass = solid({0.9f, 1.0f, 0.9f}, 0.9f, 0.0f);
    glass.finish.edit().phong = 0.9f;
    glass.finish.edit().reflection_min = glass.finish.edit().reflection_max = Rgb(0.2f);
    Object g = object(Sphere{{-1, 0, 0}, 1}, {}, {glass});
    Interior in;
    in.ior = 1.5f;
    in.fade_distance = 2;
    in.fade_power = 1;
    g.interior = in;
    s.objects.push_back(g);
    Texture chrome = solid({0.8f, 0.8f, 0.9f});
    chrome.finish.edit().reflection_min = chrome.finish.edit().reflection_max = Rgb(0.7f);
    chrome.finish.edit().reflection_exponent = 0.6f;
    chrome.finish.edit().specular = 0.5f;
    s.objects.push_back(object(Sphere{{1.2, 0, 0.5}, 1}, {}, {chrome}));
    s.lights.push_back(point_light({-4, 6, -5}));
    s.lights.push_back(point_light({4, 3, -3}, Rgb(0.4f)));
    return s;
}

TEST(Shading, SpawnCombineEqualsRecursiveDriver) {
    Scene s = busy_scene();
    PreparedScene prepared(s);
    Tracer driver(prepared), children(prepared);
    RayContext ctx;
    prepared.init_context(ctx);
    int compared = 0, with_children = 0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 32; ++x) {
            TraceRay ray;
            ray.ray = *camera_ray(s.camera, x + 0.5, y + 0.5, 32, 24);
            TraceResult direct = driver.trace(ray);
            Hit hit;
            if (!prepared.closest_hit(ray.ray, 0, kInfinity, RayUse::Camera, hit, ctx)) {
                EXPECT_EQ(direct.colour, s.background.rgb);
                continue;
            }
            ShadingRecord rec;
            spawn_children(prepared, ray, hit, rec);
            std::vector<TraceResult> results;
            for (const ChildRay& c : rec.children) {
                TraceResult r;
                if (c.kind == ChildRay::Kind::Shadow) {
                    r.colour = shadow_transmittance(prepared, c, ctx);
                } else {
                    r = children.trace(c.trace);
                }
                results.push_back(r);
            }
            TraceResult manual = combine_children(rec, results.data());
            EXPECT_EQ(manual.colour, direct.colour) << x << "," << y;
            EXPECT_EQ(manual.transmit, direct.transmit) << x << "," << y;
            ++compared;
            with_children += rec.children.size() > 2;
            // Linearity: a child with exponent 1 contributes coeff * result.
            for (size_t i = 0; i < rec.children.size(); ++i) {
                if (rec.children[i].exponent != 1) continue;
                std::vector<TraceResult> bumped = results;
                bumped[i].colour += Rgb(0.25f);
                TraceResult b = combine_children(rec, bumped.data());
                expect_rgb(b.colour - manual.colour, rec.children[i].coeff * 0.25f,
                           1e-5f);
            }
        }
    }
    EXPECT_GT(compared, 300);
    EXPECT_GT(with_children, 100);
}

TEST(Shading, RenderIsDeterministicAcrossThreadCounts) {
    Scene s = busy_scene();
    RenderSettings rs;
    rs.width = 40;
    rs.height = 30;
    rs.antialias = true;
    rs.threads = 1;
    Image a = render_scene(s, rs);
    rs.threads = 3;
    Image b = render_scene(s, rs);
    EXPECT_EQ(a.rgba, b.rgba);
}

}  // namespace
}  // namespace povwall::trace
