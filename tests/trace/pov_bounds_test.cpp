// Tiny objects as POV-Ray 3.7 sees them: its single-precision bounding boxes and the
// float tests rays meet them with (trace/pov_bounds.h), the box's CLOSE_TOLERANCE rule,
// exact degeneracy of triangles and polygons, the torus's root elimination. The scene
// cases were rendered by povray 3.7.0.10 (1x1 image, the camera's centre ray) and their
// hit or miss is written down here.
#include "trace/pov_bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "parser/parser.h"
#include "trace/camera.h"
#include "trace/prepared_scene.h"
#include "trace/roots.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

TEST(PovBounds, CornerAndLengthsRoundToFloat) {
    const PovBBox b = pov_bbox({{1.3, 1.7, 0.4}, {1.3 + 1e-7, 1.7 + 3e-7, 0.4}});
    EXPECT_EQ(b.lo[0], 0x1.4ccccc0000000p+0f);  // 1.29999995...
    EXPECT_EQ(b.lo[1], 0x1.b333340000000p+0f);  // 1.70000005...
    EXPECT_EQ(b.lo[2], 0x1.99999a0000000p-2f);
    EXPECT_EQ(b.len[0], float((1.3 + 1e-7) - 1.3));
    EXPECT_EQ(b.len[1], float((1.7 + 3e-7) - 1.7));
    EXPECT_EQ(b.len[2], 0.0f);
    // Read back: lo + len in double.
    const Bounds3 r = pov_bbox_bounds(b);
    EXPECT_EQ(r.hi.x, double(b.lo[0]) + double(b.len[0]));
    // A sphere's box is centre - radius, lengths 2 radius (not (c + r) - (c - r)).
    const PovBBox s = pov_sphere_bbox({0.1, 0, 0}, 0.3);
    EXPECT_EQ(s.lo[0], float(0.1 - 0.3));
    EXPECT_EQ(s.len[0], float(0.6));
    EXPECT_TRUE(pov_bbox_finite(s));
}

TEST(PovBounds, SlabTreeAndOwnBoxTests) {
    const PovBBox box = pov_bbox({{1, 1, 1}, {2, 2, 2}});
    auto ray = [](Point3 o, Vector3 d) { return PovRay(Ray{o, d}); };
    // Through the middle, along x.
    EXPECT_TRUE(slab_tree_accepts(box, ray({0, 1.5, 1.5}, {1, 0, 0})));
    EXPECT_TRUE(own_bbox_accepts(box, ray({0, 1.5, 1.5}, {1, 0, 0}), 1e-4f, 1e30f));
    // Parallel to y and z, outside in y.
    EXPECT_FALSE(slab_tree_accepts(box, ray({0, 2.5, 1.5}, {1, 0, 0})));
    EXPECT_FALSE(own_bbox_accepts(box, ray({0, 2.5, 1.5}, {1, 0, 0}), 1e-4f, 1e30f));
    // Behind the origin.
    EXPECT_FALSE(slab_tree_accepts(box, ray({3, 1.5, 1.5}, {1, 0, 0})));
    EXPECT_FALSE(own_bbox_accepts(box, ray({3, 1.5, 1.5}, {1, 0, 0}), 1e-4f, 1e30f));
    // Starting inside: the slab test takes it, the own test too (it ends beyond 1e-4).
    EXPECT_TRUE(slab_tree_accepts(box, ray({1.5, 1.5, 1.5}, {0, 0, 1})));
    EXPECT_TRUE(own_bbox_accepts(box, ray({1.5, 1.5, 1.5}, {0, 0, 1}), 1e-4f, 1e30f));
    // ... but not when it ends closer than the own test's minimum depth.
    EXPECT_FALSE(
        own_bbox_accepts(box, ray({1.5, 1.5, 1.99995}, {0, 0, 1}), 1e-4f, 1e30f));
    // A non-unit direction is normalised first (POV-Ray's rays are unit).
    const PovRay scaled(Ray{{0, 1.5, 1.5}, {4, 0, 0}});
    EXPECT_EQ(scaled.inv[0], 1.0f);
    EXPECT_FALSE(scaled.nonzero[1]);
}

TEST(PovBounds, TinyBoxNearFloatSpacing) {
    // A 1e-7 box at x = 1.3, where floats are 1.19e-7 apart: its box runs from
    // 1.29999995 to 1.29999995 + 1.0000000117e-7, which in float is 1.30000007. A ray
    // along z is tested by its origin rounded to float.
    const PovBBox box = pov_bbox({{1.3, 1.7, 0.4}, {1.3 + 1e-7, 1.7 + 1e-7, 0.4 + 1e-7}});
    EXPECT_EQ(box.lo[0], 0x1.4ccccc0000000p+0f);
    EXPECT_EQ(box.lo[0] + box.len[0], 0x1.4cccce0000000p+0f);
    auto along_z = [&](Real x) {
        return slab_tree_accepts(box, PovRay(Ray{{x, 1.7 + 0.5e-7, 0}, {0, 0, 1}}));
    };
    EXPECT_TRUE(along_z(1.3 + 0.5e-7));  // through the box
    // 2e-8 right of the box: rounds onto its high side and passes.
    EXPECT_TRUE(along_z(1.3 + 1.2e-7));
    // 7e-8 left of it: rounds onto its low side and passes.
    EXPECT_TRUE(along_z(1.3 - 0.7e-7));
    // 6e-8 right of it: rounds to 1.30000019, beyond.
    EXPECT_FALSE(along_z(1.3 + 1.6e-7));
}

TEST(PovBounds, ObjectBoxesPerShape) {
    // A cylinder's box is its canonical box [-1,1]^2 x [0,1] through its frame: along y
    // it is exactly base..cap and +-r around.
    Object cyl;
    cyl.shape = Cylinder{{0, 0, 0}, {0, 2, 0}, 0.5, false};
    PovBBox b = pov_object_bbox(cyl);
    EXPECT_NEAR(b.lo[1], 0.0f, 1e-15);  // the frame's rotation rounds
    EXPECT_FLOAT_EQ(b.len[1], 2.0f);
    EXPECT_FLOAT_EQ(b.lo[0], -0.5f);
    EXPECT_FLOAT_EQ(b.len[0], 1.0f);
    EXPECT_TRUE(pov_tests_own_bbox(cyl));
    // A disc's is padded by SMALL_TOLERANCE along its normal.
    Object disc;
    disc.shape = Disc{{0, 0, 0}, {0, 1, 0}, 1, 0};
    b = pov_object_bbox(disc);
    EXPECT_FLOAT_EQ(b.lo[1], -1e-3f);
    EXPECT_FLOAT_EQ(b.len[1], 2e-3f);
    // A triangle's corners +- EPSILON; the shape skips its own box test.
    Object tri;
    tri.shape = Triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    b = pov_object_bbox(tri);
    EXPECT_EQ(b.lo[0], float(-1e-10));
    EXPECT_EQ(b.len[2], float(2e-10));
    EXPECT_FALSE(pov_tests_own_bbox(tri));
    // A plane's box is infinite: never in the slab tree.
    Object plane;
    plane.shape = Plane{};
    EXPECT_FALSE(pov_bbox_finite(pov_object_bbox(plane)));
}

TEST(PovBounds, BoxCloseToleranceMeetsATinyBoxTheExactSlabsMiss) {
    // x enters at t = 1, leaves at 1 + 1e-7; y enters at 1.0000005, after x left: the
    // slabs do not overlap, but y's entry is within 1e-6 of x's, so POV-Ray never
    // compares it with the exit.
    const Box b{{0, 0, 0}, {1e-7, 1e-7, 1e-7}};
    const Point3 o{-1, 1.5e-7, 0.5e-7};
    const Vector3 d{1, -5e-8 / 1.0000005, 0};
    Crossings exact, pov;
    intersect_box(b, o, d, exact);
    EXPECT_EQ(exact.n, 0);
    intersect_box_pov(b, o, d, pov);
    ASSERT_EQ(pov.n, 2);
    EXPECT_EQ(pov.c[0].t, 1.0);
    EXPECT_EQ(pov.c[0].face, 0);  // x low
    EXPECT_EQ(pov.c[1].t, (1e-7 - -1.0) / 1.0);
    EXPECT_EQ(pov.c[1].face, 1);  // x high
}

TEST(PovBounds, BoxCloseEntriesKeepTheMoreDirectFace) {
    // y enters 1e-9 after x: the exact slabs say the y face, POV-Ray keeps x's because
    // the direction points more along x than along y.
    const Box b{{0, 0, 0}, {1, 1, 1}};
    const Point3 o{-1, -0.9 - 1e-9 * 0.9, 0.5};
    const Vector3 d{1, 0.9, 0};
    Crossings exact, pov;
    intersect_box(b, o, d, exact);
    ASSERT_EQ(exact.n, 2);
    EXPECT_EQ(exact.c[0].face, 2);  // y low
    intersect_box_pov(b, o, d, pov);
    ASSERT_EQ(pov.n, 2);
    EXPECT_EQ(pov.c[0].face, 0);  // x low
    EXPECT_EQ(pov.c[0].t, 1.0);
    // The depths are world distances along the direction as given (not normalised).
    Crossings far;
    intersect_box_pov(b, {-3, 0.5, 0.5}, {2, 0, 0}, far);
    ASSERT_EQ(far.n, 2);
    EXPECT_EQ(far.c[0].t, 1.5);
    EXPECT_EQ(far.c[1].t, 2.0);
}

TEST(PovBounds, DegenerateTrianglesAndPolygons) {
    // Only an exactly zero normal makes a triangle degenerate: 1e-6 edges are hit.
    const Point3 tiny[3] = {{0, 0, 0}, {1e-6, 0, 0}, {0, 1e-6, 0}};
    EXPECT_FALSE(degenerate_triangle(tiny));
    const Point3 line[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    EXPECT_TRUE(degenerate_triangle(line));
    // A polygon needs points 1e-5 from its first and a parallelogram over 1e-5 in area
    // (squared lengths above EPSILON).
    Polygon small;
    small.points = {{0, 0, 0}, {2e-6, 0, 0}, {2e-6, 2e-6, 0}, {0, 2e-6, 0}, {0, 0, 0}};
    EXPECT_TRUE(degenerate_polygon(small));
    Polygon thin;
    thin.points = {
        {-1.4, 0.8, 0}, {1.4, 0.8, 0}, {1.4, 0.8 + 1e-6, 0}, {-1.4, 0.8 + 1e-6, 0}};
    EXPECT_TRUE(degenerate_polygon(thin));
    Polygon unit;
    unit.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_FALSE(degenerate_polygon(unit));
}

TEST(PovBounds, CubicAsPovRaySplitsIt) {
    Real r[3];
    // (x - 1)(x - 2)(x - 3)
    ASSERT_EQ(solve_cubic(-6, 11, -6, r), 3);
    std::sort(r, r + 3);
    EXPECT_NEAR(r[0], 1, 1e-14);
    EXPECT_NEAR(r[1], 2, 1e-14);
    EXPECT_NEAR(r[2], 3, 1e-14);
    // x^3 + x + 1: one real root.
    ASSERT_EQ(solve_cubic(0, 1, 1, r), 1);
    EXPECT_NEAR(r[0], -0.6823278038280193, 1e-15);
    // x^3: q = r = 0, the closed form's 0/0: no root (POV-Ray's are NaN, dropped).
    EXPECT_EQ(solve_cubic(0, 0, 0, r), 0);
}

TEST(PovBounds, TinyTorusUsesTheEliminatedCubic) {
    // A torus with minor radius 7.5e-8 seen from 0.05 away: the quartic's constant term
    // is below 1e-4 of its linear one, so POV-Ray solves the cubic left, whose roots are
    // not on the surface. A unit torus from the same distance keeps its exact roots.
    const Torus tiny{2e-7, 7.5e-8, false};
    const Point3 o{2e-7, 0.05, 0};
    const Vector3 d{0, -1, 0};
    Crossings cs;
    intersect_torus(tiny, o, d, cs);
    ASSERT_GE(cs.n, 1);
    const Point3 p = o + d * cs.c[0].t;
    const Real off = std::fabs(std::hypot(std::hypot(p.x, p.z) - 2e-7, p.y) - 7.5e-8);
    EXPECT_GT(off, 1e-9);  // well off the surface (the exact root is within 1e-20)
    const Torus unit{1, 0.25, false};
    Crossings us;
    intersect_torus(unit, {1, 5, 0}, {0, -1, 0}, us);
    ASSERT_EQ(us.n, 2);
    EXPECT_NEAR(us.c[0].t, 4.75, 1e-12);
    EXPECT_NEAR(us.c[1].t, 5.25, 1e-12);
}

struct TinyCase {
    const char* name;
    const char* object;
    const char* at;
    bool povray_hits;
};

// Each checked against povray 3.7.0.10 (+W1 +H1). "before" notes what povwall did
// before it applied these rules.
const TinyCase kTinyCases[] = {
    // The scene's root box (no infinite object) is rounded over 2.3 units: its high side
    // falls 1e-7 short of the box. Before: hit.
    {"box_1e7", "box { 0, 1e-7 translate P }", "P + 0.5e-7", false},
    {"box_2e7", "box { 0, 2e-7 translate P }", "P + 1e-7", true},
    {"box_3e7", "box { 0, 3e-7 translate P }", "P + 1.5e-7", true},
    {"box_1e7_near_origin", "box { 0, 1e-7 translate <0, 0, 0.4> }",
     "<0, 0, 0.4> + 0.5e-7", true},
    {"cylinder", "cylinder { 0, <3e-7, 0, 0>, 1e-7 translate P }", "P + <1.5e-7, 0, 0>",
     true},
    {"cone", "cone { 0, 2e-7, <0, 0, 3e-7>, 0 translate P }", "P + <0.3e-7, 0.2e-7, 0>",
     true},
    {"disc", "disc { 0, -z, 2e-7 translate P }", "P", true},
    // Before: never hit (|normal| < 1e-10 counted as degenerate).
    {"triangle_2e6", "triangle { 0, <2e-6, 0, 0>, <0, 2e-6, 0> translate P }",
     "P + <0.5e-6, 0.5e-6, 0>", true},
    {"mesh_triangle_2e7",
     "mesh { triangle { 0, <2e-7, 0, 0>, <0, 2e-7, 0> } translate P }",
     "P + <0.5e-7, 0.5e-7, 0>", true},
    // Made this small: degenerate, never hit. Before: hit.
    {"polygon_2e6",
     "polygon { 4, 0, <2e-6, 0, 0>, <2e-6, 2e-6, 0>, <0, 2e-6, 0> translate P }",
     "P + <1e-6, 1e-6, 0>", false},
    {"polygon_scaled", "polygon { 4, 0, x, x + y, y scale 2e-6 translate P }",
     "P + <1e-6, 1e-6, 0>", true},
    // Radius below sqrt(EPSILON): POV-Ray's half chord test never passes.
    {"sphere_4e6", "sphere { P, 4e-6 }", "P", false},
    {"sphere_2e5", "sphere { P, 2e-5 }", "P", true},
    {"ellipsoid", "sphere { 0, 1 scale <2e-7, 3e-7, 2e-7> translate P }", "P", true},
    {"torus_tube", "torus { 2e-7, 7.5e-8 rotate 90*x translate P }", "P + <2e-7, 0, 0>",
     true},
    {"torus_hole", "torus { 2e-7, 7.5e-8 rotate 90*x translate P }", "P", false},
    // 1e-3 objects 1e6-1e7 from the origin: their boxes are a float spacing (0.25-0.5)
    // off. Before: hit.
    {"far_sphere", "sphere { <3e6, 1e6, 7e6>, 1e-3 }", "<3e6, 1e6, 7e6>", false},
    {"far_box", "box { -1e-3, 1e-3 translate <3e6, 1e6, 7e6> }", "<3e6, 1e6, 7e6>",
     false},
};

class TinyObjects : public ::testing::TestWithParam<TinyCase> {};

TEST_P(TinyObjects, CentreRayHitsAsInPovray) {
    const TinyCase& c = GetParam();
    std::string text =
        "#version 3.7;\n"
        "global_settings { assumed_gamma 1.0 }\n"
        "#declare P = <1.3, 1.7, 0.4>;\n"
        "camera { location " +
        std::string(c.at) + " + <0, 0, -0.05> look_at " + c.at +
        " angle 1 }\n"
        "light_source { <-3, 6, -8> rgb 1 }\n"
        "sphere { <0, 0, 10>, 1 }\n" +
        c.object + "\n";
    parser::ParseOptions po;
    po.image_width = po.image_height = 1;
    const Scene scene = parser::parse_scene_text(std::move(text), "tiny.pov", po);
    ASSERT_EQ(scene.objects.size(), 2u);
    const std::optional<Ray> ray = camera_ray(scene.camera, 0.5, 0.5, 1, 1);
    ASSERT_TRUE(ray);
    PreparedScene prepared(scene);
    RayContext ctx;
    prepared.init_context(ctx);
    Hit hit;
    const bool found = prepared.closest_hit(*ray, 0, kInfinity, RayUse::Camera, hit, ctx);
    // The far sphere is 10 away; the tiny object 0.05.
    const bool tiny_hit = found && hit.t < 1;
    EXPECT_EQ(tiny_hit, c.povray_hits);
    if (tiny_hit) {
        EXPECT_NEAR(hit.t, 0.05, 1e-4);
        EXPECT_EQ(hit.material->object, &scene.objects[1]);
    }
    // With exact bounds (the numerics oracle's rules) the in-between sizes are all hit.
    PrepareOptions exact;
    exact.pov_float_bounds = false;
    PreparedScene exact_prepared(scene, nullptr, exact);
    RayContext ectx;
    exact_prepared.init_context(ectx);
    Hit ehit;
    const bool efound =
        exact_prepared.closest_hit(*ray, 0, kInfinity, RayUse::Camera, ehit, ectx);
    if (std::string(c.name).rfind("far_", 0) == 0 || std::string(c.name) == "box_1e7") {
        EXPECT_TRUE(efound && ehit.t < 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, TinyObjects, ::testing::ValuesIn(kTinyCases),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(PovBounds, ScaledUpBoxAndDiscKeepWorldTolerances) {
    // A box scaled by 1000 hit 5e-4 ahead: 5e-7 in its own units, below the old
    // object-space 1e-6, but POV-Ray compares world distances (box: its direction is
    // never normalised; disc: after the division by the length).
    parser::ParseOptions po;
    const Scene scene = parser::parse_scene_text(
        "box { -1, 1 scale 1000 }\n"
        "disc { <0, 0, 0>, y, 1 scale 1000 translate <0, -5000, 0> }\n",
        "scaled.pov", po);
    PreparedScene prepared(scene);
    RayContext ctx;
    prepared.init_context(ctx);
    Hit hit;
    ASSERT_TRUE(prepared.closest_hit(Ray{{0, 0, -1000.0005}, {0, 0, 1}}, 0, kInfinity,
                                     RayUse::Camera, hit, ctx));
    EXPECT_NEAR(hit.t, 5e-4, 1e-9);
    ASSERT_TRUE(prepared.closest_hit(Ray{{0, -4999.9995, 0}, {0, -1, 0}}, 0, kInfinity,
                                     RayUse::Reflection, hit, ctx));
    EXPECT_NEAR(hit.t, 5e-4, 1e-9);
}

// POV-Ray's walk of its slab tree stops at the first box entered beyond the nearest hit
// so far: a surface outside its object's box (a half-box kept by a disc's half-space,
// whose box is the disc's) is seen only where no nearer hit is found first.
TEST(PovBounds, WalkStopsBeforeASurfaceOutsideItsBox) {
    parser::ParseOptions po;
    const Scene scene = parser::parse_scene_text(
        "light_source { <0, 10, -10> rgb 1 }\n"
        "intersection { box { -0.9, 0.9 } disc { 0, z, 0.8 } }\n"
        "sphere { <0, 0, 0.3>, 0.5 }\n"
        "sphere { <5, 0, 0>, 0.5 bounded_by { box { <4.9, -0.1, -0.1>, <5.1, 0.1, 0.1> } "
        "} }\n"
        "sphere { <-5, 0, 0>, 0.5 }\n",
        "walk.pov", po);
    ASSERT_EQ(scene.objects.size(), 4u);
    const Bounds3 half = pov_walk_reach(scene.objects[0]);
    ASSERT_FALSE(half.empty());
    EXPECT_NEAR(half.lo.x, -0.9, 1e-6);
    EXPECT_NEAR(half.lo.z, -0.9, 1e-6);
    EXPECT_NEAR(half.hi.y, 0.9, 1e-6);
    EXPECT_TRUE(pov_walk_reach(scene.objects[1]).empty());
    EXPECT_FALSE(pov_walk_reach(scene.objects[2]).empty());
    EXPECT_TRUE(pov_walk_reach(scene.objects[3]).empty());
    PreparedScene prepared(scene);
    RayContext ctx;
    prepared.init_context(ctx);
    // The nearest hit's distance along +z from `origin` before t_max (-1: none).
    auto nearest = [&](Point3 origin, Real t_max, RayUse use) -> Real {
        Hit hit;
        return prepared.closest_hit(Ray{origin, {0, 0, 1}}, 0, t_max, use, hit, ctx)
                   ? hit.t
                   : -1;
    };
    // Through the disc's box: the sphere's box is entered first and its hit (t = 4.8)
    // lies before the disc's box; the half-box's face in front (t = 4.1) is never tested.
    EXPECT_NEAR(nearest({0, 0, -5}, kInfinity, RayUse::Camera), 4.8, 1e-9);
    // Past the sphere: nothing nearer, the face is seen.
    EXPECT_NEAR(nearest({0.6, 0, -5}, kInfinity, RayUse::Camera), 4.1, 1e-9);
    // Outside the disc's box the intersection is not tested at all.
    EXPECT_EQ(nearest({0.85, 0, -5}, kInfinity, RayUse::Camera), -1);
    // A ray that ends before the box is entered: not reached either.
    EXPECT_EQ(nearest({0.6, 0, -5}, 4.5, RayUse::Shadow), -1);
    // bounded_by: the sphere's hit (t = 4.5) lies before its bound's box (t = 4.9), with
    // nothing nearer: seen.
    EXPECT_NEAR(nearest({5, 0, -5}, kInfinity, RayUse::Camera), 4.5, 1e-9);
}

}  // namespace
}  // namespace povwall::trace
