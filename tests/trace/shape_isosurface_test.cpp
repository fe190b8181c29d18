// isosurface kernel: the root search's distances (the end of the `accuracy`-wide step
// where F turns negative), the closed container's surface where F < 0 on it, open,
// max_trace, the sphere container, normals, the inside test and POV-Ray's box.
#include <gtest/gtest.h>

#include <cmath>

#include "parser/parser.h"
#include "tests/trace/local_rays.h"
#include "trace/shapes/isosurface.h"

namespace povwall::trace {
namespace {

Isosurface iso(const std::string& body) {
    parser::ParseOptions o;
    Scene s = parser::parse_scene_text("isosurface { " + body + " }", "test.pov", o);
    return std::get<Isosurface>(s.objects.at(0).shape);
}

TEST(ShapeIsosurface, RootWithinAccuracyFromOutside) {
    // The sphere r = 0.5 in the default box, from z = -3: the box is entered at t = 2,
    // F > 0 there, and the root is at t = 2.5, found as the first halving end past it.
    const Isosurface s = iso("function { sqrt(x*x + y*y + z*z) - 0.5 }");
    ShapeHits hits;
    LocalRay in_csg = untransformed_ray({0, 0, -3}, {0, 0, 1});
    in_csg.csg_child = true;
    shape_hits(s, in_csg, hits);
    ASSERT_EQ(hits.size(), 1u);  // max_trace 1
    EXPECT_GE(hits[0].t, 2.5);
    EXPECT_LT(hits[0].t, 2.5 + 0.001);
    EXPECT_EQ(hits[0].face, 0);
    // Outside CSG the search is made again from the hit, as POV-Ray's restarted ray
    // (a shadow through the surface): the far side too.
    hits.clear();
    shape_hits(s, untransformed_ray({0, 0, -3}, {0, 0, 1}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_GE(hits[1].t, 3.5);
    EXPECT_LT(hits[1].t, 3.5 + 0.002);
    const Vector3 n = shape_normal(s, hits[0]);
    EXPECT_NEAR(n.z, -1.0, 1e-3);
    // World distances along a longer direction: the same point, half the distance.
    hits.clear();
    shape_hits(s, untransformed_ray({0, 0, -3}, {0, 0, 2}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_GE(hits[0].t, 1.25);
    EXPECT_LT(hits[0].t, 1.25 + 0.001);
}

TEST(ShapeIsosurface, ClosedContainerWhereFIsInside) {
    // F = x*x + y*y + z*z - 2 is negative all over the face z = -1 near the axis: the
    // box's face is the hit (side 5: -z), with the face's normal.
    const Isosurface s = iso("function { x*x + y*y + z*z - 2 }");
    ShapeHits hits;
    shape_hits(s, untransformed_ray({0.2, 0.1, -3}, {0, 0, 1}), hits);
    ASSERT_GE(hits.size(), 1u);
    EXPECT_EQ(hits[0].t, 2.0);
    EXPECT_EQ(hits[0].face, 5);
    EXPECT_EQ(shape_normal(s, hits[0]).z, -1.0);
    // Open: no container surface; the ray starts inside F < 0 and the search turns
    // around, finding where it leaves (none inside the box: no hit).
    const Isosurface o = iso("function { x*x + y*y + z*z - 2 } open");
    hits.clear();
    shape_hits(o, untransformed_ray({0.2, 0.1, -3}, {0, 0, 1}), hits);
    EXPECT_TRUE(hits.empty());
}

TEST(ShapeIsosurface, MaxTraceFindsTheFarSide) {
    const Isosurface one = iso("function { abs(z) - 0.5 } max_gradient 1.1");
    ShapeHits hits;
    LocalRay r = untransformed_ray({0, 0, -3}, {0, 0, 1});
    r.csg_child = true;
    shape_hits(one, r, hits);
    ASSERT_EQ(hits.size(), 1u);
    const Isosurface two = iso("function { abs(z) - 0.5 } max_trace 2");
    hits.clear();
    shape_hits(two, r, hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_GE(hits[0].t, 2.5);
    EXPECT_LT(hits[0].t, 2.501);
    EXPECT_GE(hits[1].t, 3.5);
    EXPECT_LT(hits[1].t, 3.501);
}

// A clip keeping the world distances t >= *context.
ShapeClip keep_from(const Real& t_min) {
    return {[](const void* c, Real t) { return t >= *static_cast<const Real*>(c); },
            &t_min};
}

TEST(ShapeIsosurface, AClippedRootUsesUpItsTrace) {
    // The slab |z| <= 0.5 from z = -3: roots at 2.5 and 3.5. Clipping the first away,
    // max_trace 1 sees nothing behind it (POV-Ray tests the clip inside the search);
    // max_trace 2 finds the far side.
    const Real from = 3.0;
    LocalRay r = untransformed_ray({0, 0, -3}, {0, 0, 1});
    r.csg_child = true;
    ShapeHits hits;
    shape_hits(iso("function { abs(z) - 0.5 } max_gradient 1.1"), r, keep_from(from),
               hits);
    EXPECT_TRUE(hits.empty());
    shape_hits(iso("function { abs(z) - 0.5 } max_trace 2"), r, keep_from(from), hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_GE(hits[0].t, 3.5);
    EXPECT_LT(hits[0].t, 3.501);
}

TEST(ShapeIsosurface, AClippedContainerHitIsNoTrace) {
    // F = -cos(2 pi z) along the axis from z = -3: F < 0 on the box's face z = -1
    // (t = 2), then roots at z = -0.75 (F turns positive, t = 2.25) and z = -0.25 (F
    // turns negative, t = 2.75). Kept, the face is the first of max_trace 3 hits. Clipped
    // (the clip keeps t >= 2.5), it neither counts nor turns the search around: the
    // search starts where F < 0 and its first root is the face again (clipped, one
    // trace), then 2.25 (clipped, two), then 2.75, kept with max_trace 3 and not reached
    // with 2.
    const std::string f = "function { -cos(2 * pi * z) } max_gradient 7 ";
    LocalRay r = untransformed_ray({0, 0, -3}, {0, 0, 1});
    r.csg_child = true;
    ShapeHits hits;
    const Real all = -1, from = 2.5;
    shape_hits(iso(f + "max_trace 3"), r, keep_from(all), hits);
    ASSERT_EQ(hits.size(), 3u);
    EXPECT_EQ(hits[0].t, 2.0);
    EXPECT_EQ(hits[0].face, 5);
    EXPECT_NEAR(hits[1].t, 2.25, 1e-3);
    EXPECT_NEAR(hits[2].t, 2.75, 1e-3);
    hits.clear();
    shape_hits(iso(f + "max_trace 3"), r, keep_from(from), hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 2.75, 1e-3);
    hits.clear();
    shape_hits(iso(f + "max_trace 2"), r, keep_from(from), hits);
    EXPECT_TRUE(hits.empty());
}

TEST(ShapeIsosurface, SphereContainerInsideAndBoxes) {
    const Isosurface s = iso("function { y } contained_by { sphere { <0, 0, 0>, 1 } }");
    EXPECT_TRUE(shape_inside(s, {0, -0.5, 0}));
    EXPECT_FALSE(shape_inside(s, {0, 0.5, 0}));
    EXPECT_FALSE(shape_inside(s, {0, -1.5, 0}));  // outside the container
    EXPECT_TRUE(shape_inside(s, {0, 0, 0}));      // F = 0 counts as inside
    // From below the sphere: F < 0 on its surface, the container's hit; its normal is the
    // sphere's.
    ShapeHits hits;
    shape_hits(s, untransformed_ray({0, -3, 0}, {0, 1, 0}), hits);
    ASSERT_GE(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 2.0, 1e-15);
    EXPECT_EQ(hits[0].face, 0);
    EXPECT_NEAR(shape_normal(s, hits[0]).y, -1.0, 1e-12);
    const PovBBox b = shape_pov_bbox(s, CompactTransform{});
    EXPECT_EQ(b.lo[1], -1.0f);
    EXPECT_EQ(b.len[1], 2.0f);
    const Isosurface box = iso("function { y } contained_by { box { <0.1, 0, 0>, 1 } }");
    const PovBBox bb = shape_pov_bbox(box, Transform::translate({1, 0, 0}));
    EXPECT_EQ(bb.lo[0], float(1.1f));
    EXPECT_EQ(isosurface_function(box, {0, 0.25, 0}), 0.25);
}

}  // namespace
}  // namespace povwall::trace
