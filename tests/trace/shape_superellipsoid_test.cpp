// superellipsoid: crossings, normals and the inside test on rays with known answers;
// POV-Ray's search stops where |F| < 1e-10, so distances are exact to about that.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/trace/scene_builder.h"
#include "trace/prepared_scene.h"
#include "trace/shapes/superellipsoid.h"

namespace povwall::trace {
namespace {

ShapeHits hits(const Superellipsoid& s, const Point3& o, const Vector3& d,
               Real length = 1) {
    ShapeHits out;
    intersect_superellipsoid(s, o, normalize(d), length, out);
    return out;
}

TEST(ShapeSuperellipsoid, UnitExponentsAreTheUnitSphere) {
    const Superellipsoid s{1, 1};
    ShapeHits h = hits(s, {0, 0, -5}, {0, 0, 1});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 4, 1e-10);
    EXPECT_NEAR(h[1].t, 6, 1e-10);
    const Vector3 n = superellipsoid_normal(s, {0, 0, -1});  // a pole: exactly -z
    EXPECT_EQ(n.x, 0);
    EXPECT_EQ(n.y, 0);
    EXPECT_EQ(n.z, -1);
    h = hits(s, {-5, 0.6, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 4.2, 1e-10);
    EXPECT_NEAR(h[1].t, 5.8, 1e-10);
    const Vector3 m = normalize(superellipsoid_normal(s, h[0].p));
    EXPECT_NEAR(m.x, -0.8, 1e-9);
    EXPECT_NEAR(m.y, 0.6, 1e-9);
    EXPECT_NEAR(m.z, 0, 1e-15);
}

TEST(ShapeSuperellipsoid, RoundedCubeFace) {
    // e = n = 0.1: |x|^20 + |y|^20 + |z|^20 = 1.
    const Superellipsoid s{0.1, 0.1};
    ShapeHits h = hits(s, {0.3, 0.2, -5}, {0, 0, 1});
    ASSERT_EQ(h.size(), 2u);
    const Real z = std::pow(1 - std::pow(0.3, 20) - std::pow(0.2, 20), 1.0 / 20);
    EXPECT_NEAR(h[0].t, 5 - z, 1e-10);
    EXPECT_NEAR(h[1].t, 5 + z, 1e-10);
    const Vector3 n = normalize(superellipsoid_normal(s, h[1].p));
    EXPECT_NEAR(n.z, 1, 1e-12);
    // Along an edge's diagonal plane, through a rounded edge.
    h = hits(s, {-5, -5, 0}, {1, 1, 0});
    ASSERT_EQ(h.size(), 2u);
    const Real c = std::pow(0.5, 1.0 / 20);  // x = y = c on the surface
    EXPECT_NEAR(h[0].t, std::sqrt(2.0) * (5 - c), 1e-9);
    const Vector3 e = normalize(superellipsoid_normal(s, h[0].p));
    EXPECT_NEAR(e.x, -std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(e.y, -std::sqrt(0.5), 1e-9);
}

TEST(ShapeSuperellipsoid, WorldDistancesAndDepthLimits) {
    const Superellipsoid s{0.5, 0.5};
    // Object space twice the world's (scale 0.5): world distances are halved.
    ShapeHits h = hits(s, {0, 0, -5}, {0, 0, 1}, 2);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 2, 1e-10);
    EXPECT_NEAR(h[1].t, 3, 1e-10);
    EXPECT_NEAR(h[0].p.z, -1, 1e-10);
    // From inside: only the exit.
    h = hits(s, {0, 0, 0}, {0, 1, 0});
    ASSERT_EQ(h.size(), 1u);
    EXPECT_NEAR(h[0].t, 1, 1e-10);
    // Behind the origin, or beside the search box: nothing.
    EXPECT_TRUE(hits(s, {0, 0, 5}, {0, 0, 1}).empty());
    EXPECT_TRUE(hits(s, {1.02, 0, -5}, {0, 0, 1}).empty());
}

TEST(ShapeSuperellipsoid, StarShapeHasFourCrossings) {
    // e = n = 3 (exponent 2/3): concave faces; a line near a face crosses two arms.
    const Superellipsoid s{3, 3};
    ShapeHits h = hits(s, {-5, 0.05, 0.05}, {1, 0, 0});
    ASSERT_EQ(h.size(), 2u);
    h = hits(s, {-5, 0.2, 0}, {1, 0, 0});
    ASSERT_GE(h.size(), 2u);
    for (size_t i = 1; i < h.size(); ++i) EXPECT_LT(h[i - 1].t, h[i].t);
    for (const ShapeHit& x : h) EXPECT_LT(std::fabs(superellipsoid_value(s, x.p)), 1e-9);
}

TEST(ShapeSuperellipsoid, Inside) {
    const Superellipsoid s{0.2, 0.7};
    EXPECT_TRUE(shape_inside(s, {0, 0, 0}));
    EXPECT_TRUE(shape_inside(s, {0.9, 0.9, 0}));  // a near-square cross section
    EXPECT_FALSE(shape_inside(s, {0.9, 0.9, 0.9}));
    EXPECT_FALSE(shape_inside(s, {1.001, 0, 0}));
    EXPECT_TRUE(shape_inside(s, {1, 0, 0}));  // F = 0 < EPSILON: on the surface is in
}

TEST(ShapeSuperellipsoid, ThroughTheTracerWithATransform) {
    Scene scene;
    Transform xf = Transform::scale({2, 2, 2});
    scene.objects.push_back(test::object(Superellipsoid{0.3, 0.3}, xf));
    PreparedScene prepared(scene);
    RayContext ctx;
    prepared.init_context(ctx);
    Hit hit;
    ASSERT_TRUE(prepared.closest_hit({{0, 0, -10}, {0, 0, 1}}, 0, kInfinity,
                                     RayUse::Camera, hit, ctx));
    EXPECT_NEAR(hit.t, 8, 1e-9);
    EXPECT_NEAR(hit.normal.z, -1, 1e-12);
}

}  // namespace
}  // namespace povwall::trace
