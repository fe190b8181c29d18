// Ray-primitive intersections through the prepared scene: exact distances and normals,
// transforms, grazing rays, rays starting inside, POV-Ray's minimum depths.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "tests/trace/scene_builder.h"
#include "trace/prepared_scene.h"
#include "trace/roots.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

using test::object;

struct Probe {
    Scene scene;
    Hit hit;
    bool found = false;
};

bool shoot(const Scene& scene, Ray ray, Hit& hit, Real t_min = 0) {
    ray.direction = normalize(ray.direction);
    PreparedScene prepared(scene);
    RayContext ctx;
    prepared.init_context(ctx);
    return prepared.closest_hit(ray, t_min, kInfinity, RayUse::Camera, hit, ctx);
}

Scene one(Object o) {
    Scene s;
    s.objects.push_back(std::move(o));
    return s;
}

void expect_vec(const Vector3& a, const Vector3& b, Real tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Intersect, SphereFrontHitDistanceAndNormal) {
    Hit h;
    ASSERT_TRUE(shoot(one(object(Sphere{{0, 0, 5}, 1})), {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    expect_vec(h.normal, {0, 0, -1});
    expect_vec(h.point, {0, 0, 4});
}

TEST(Intersect, SphereMissJustOutside) {
    Hit h;
    EXPECT_FALSE(
        shoot(one(object(Sphere{{0, 0, 5}, 1})), {{1.000001, 0, 0}, {0, 0, 1}}, h));
}

TEST(Intersect, SphereGrazingRays) {
    // Half chord exactly 0: POV-Ray needs it above EPSILON (1e-10), so a tangent ray
    // misses (otherwise it would enter the sphere and bounce inside; see
    // interior/atten1.pov).
    Hit h;
    EXPECT_FALSE(shoot(one(object(Sphere{{0, 0, 5}, 1})), {{1, 0, 0}, {0, 0, 1}}, h));
    Object scaled = object(Sphere{{0, 0, 0}, 1}, Transform::scale({2, 2, 2}));
    EXPECT_FALSE(shoot(one(scaled), {{0, 2, -10}, {0, 0, 1}}, h));
    // Just inside the rim it hits, at the half-chord distance before the closest
    // approach.
    ASSERT_TRUE(shoot(one(object(Sphere{{0, 0, 5}, 1})), {{0.999, 0, 0}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(1 - 0.999 * 0.999), 1e-12);
}

TEST(Intersect, SphereFromInsideHitsFarSide) {
    Hit h;
    ASSERT_TRUE(shoot(one(object(Sphere{{0, 0, 5}, 2})), {{0, 0, 5}, {0, 1, 0}}, h));
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    expect_vec(h.normal, {0, 1, 0});
}

TEST(Intersect, HitsCloserThanMinIsectDepthAreIgnored) {
    // Surface 5e-5 ahead (< MIN_ISECT_DEPTH 1e-4): the next crossing is returned.
    Hit h;
    ASSERT_TRUE(
        shoot(one(object(Sphere{{0, 0, 5}, 1})), {{0, 0, 4 - 5e-5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 2 + 5e-5, 1e-12);
    // 2e-4 ahead is accepted.
    ASSERT_TRUE(
        shoot(one(object(Sphere{{0, 0, 5}, 1})), {{0, 0, 4 - 2e-4}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 2e-4, 1e-12);
}

TEST(Intersect, ScaledTranslatedSphere) {
    Transform xf = Transform::scale({1, 2, 1}).then(Transform::translate({0, 0, 5}));
    Scene s = one(object(Sphere{{0, 0, 0}, 1}, xf));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 4.0, 1e-12);
    expect_vec(h.normal, {0, 0, -1});
    ASSERT_TRUE(shoot(s, {{0, 10, 5}, {0, -1, 0}}, h));
    EXPECT_NEAR(h.t, 8.0, 1e-12);
    expect_vec(h.normal, {0, 1, 0});
    // Off-axis on the ellipsoid: x = 0.6 gives y = 2 * 0.8 = 1.6, normal ~ (0.6, 0.8/2,
    // 0).
    ASSERT_TRUE(shoot(s, {{0.6, 10, 5}, {0, -1, 0}}, h));
    EXPECT_NEAR(h.t, 10 - 1.6, 1e-12);
    expect_vec(h.normal, normalize(Vector3{0.6, 0.4, 0}), 1e-12);
}

TEST(Intersect, BoxFacesFromOutsideAndInside) {
    Scene s = one(object(Box{{-1, -2, -3}, {1, 2, 3}}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0, -10}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 7.0);
    expect_vec(h.normal, {0, 0, -1});
    ASSERT_TRUE(shoot(s, {{5, 0, 0}, {-1, 0, 0}}, h));
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    expect_vec(h.normal, {1, 0, 0});
    ASSERT_TRUE(shoot(s, {{0, 0, 0}, {0, 1, 0}}, h));  // inside: exit face
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    expect_vec(h.normal, {0, 1, 0});
    // Swapped corners describe the same box.
    Scene s2 = one(object(Box{{1, 2, 3}, {-1, -2, -3}}));
    ASSERT_TRUE(shoot(s2, {{0, 0, -10}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 7.0);
    EXPECT_FALSE(shoot(s, {{0, 2.5, -10}, {0, 0, 1}}, h));
}

TEST(Intersect, RotatedBox) {
    // Unit cube rotated 45 degrees about y: the corner points at the viewer.
    Scene s =
        one(object(Box{{-1, -1, -1}, {1, 1, 1}},
                   Transform::rotate({0, 45, 0}).then(Transform::translate({0, 0, 10}))));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0.5, 0}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 10 - std::sqrt(2.0), 1e-12);
    ASSERT_TRUE(shoot(s, {{0.1, 0, 0}, {0, 0, 1}}, h));
    // Face x = -1 rotated: normal (-1,0,0) -> (-cos45, 0, sin45) ... facing -z and -x.
    expect_vec(h.normal, normalize(Vector3{1, 0, -1}), 1e-12);
}

TEST(Intersect, PlaneFromAboveAndParallel) {
    Scene s = one(object(Plane{{0, 1, 0}, -1}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0, 0}, {0, -1, 1}}, h));
    EXPECT_NEAR(h.t, std::sqrt(2.0), 1e-12);
    expect_vec(h.normal, {0, 1, 0});
    EXPECT_FALSE(shoot(s, {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_FALSE(shoot(s, {{0, 0, 0}, {0, 1, 1}}, h));
}

// A ray pointing away from a plane is rejected before POV-Ray's arithmetic (normalised
// direction, object-space depth); near-parallel rays on either side, and rays starting on
// the plane, must still get exactly that arithmetic's answer.
TEST(Intersect, PlaneAwayRejectionKeepsPovRaysAnswer) {
    const Vector3 n = normalize(Vector3{0.3, 1, -0.2});
    const Real d = 0.7;
    Scene s = one(object(Plane{n, d}));
    PreparedScene prepared(s);
    RayContext ctx;
    prepared.init_context(ctx);
    // The prepared plane (identity transform): its normal normalised again, its distance
    // as the dot product with a point on it.
    const Vector3 pn = normalize(n);
    const Real pd = dot(pn, n * d);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<Real> u(-1, 1);
    std::uniform_int_distribution<int> tiny(0, 40);
    int hits = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray;
        ray.origin = Point3{u(rng), u(rng), u(rng)} * 5;
        if (i % 7 == 0) ray.origin = ray.origin + n * (d - dot(n, ray.origin));  // on it
        // Directions nearly along the plane: the normal component from 1 down to 1e-40.
        Vector3 along = normalize(cross(n, Vector3{u(rng), u(rng), u(rng)}));
        ray.direction = normalize(along + n * (u(rng) * std::pow(10.0, -tiny(rng))));
        // POV-Ray's arithmetic for a plane it keeps without a transform: the depth along
        // the ray as given, no re-normalisation (planes.cpp Plane::Intersect).
        const Real nd = dot(pn, ray.direction);
        bool want = false;
        Real want_t = 0;
        if (!(std::fabs(nd) < kPovEpsilon)) {
            const Real t = (pd - dot(pn, ray.origin)) / nd;
            if (t > 1e-6 && t < 1e7) {
                want_t = t;
                want = want_t >= kMinIsectDepth;
            }
        }
        Hit h;
        const bool got = prepared.closest_hit(ray, 0, kInfinity, RayUse::Camera, h, ctx);
        ASSERT_EQ(got, want) << "ray " << i;
        if (want) {
            ASSERT_EQ(h.t, want_t) << "ray " << i;
        }
        (want ? hits : misses) += 1;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 5000);
}

TEST(Intersect, TransformedPlane) {
    // plane { y, 0 } rotated <-90,0,0> (y goes to -z, left-handed) and moved to z = 3.
    Scene s =
        one(object(Plane{{0, 1, 0}, 0},
                   Transform::rotate({-90, 0, 0}).then(Transform::translate({0, 0, 3}))));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 3.0, 1e-12);
    expect_vec(h.normal, {0, 0, -1}, 1e-12);
}

// Where rays can hit an object (black boxes skip a box whose objects a ray cannot meet):
// an axis-parallel plane only on its surface, anything else within its bounds.
TEST(Intersect, HitBoundsOfAnAxisParallelPlaneAreItsSurface) {
    // plane { y, -1 } moved by <5, 3, 0>: the surface y = 2, unbounded in x and z.
    Bounds3 b =
        object_hit_bounds(object(Plane{{0, 1, 0}, -1}, Transform::translate({5, 3, 0})));
    EXPECT_EQ(b.lo.y, 2);
    EXPECT_EQ(b.hi.y, 2);
    EXPECT_EQ(b.lo.x, -kInfinity);
    EXPECT_EQ(b.hi.z, kInfinity);
    // A normal that is not unit length: dot(n, p) = 3 is z = 1.5.
    b = object_hit_bounds(object(Plane{{0, 0, 2}, 3}));
    EXPECT_EQ(b.lo.z, 1.5);
    EXPECT_EQ(b.hi.z, 1.5);
    EXPECT_EQ(b.lo.y, -kInfinity);
    // Oblique, or turned by a rotation that leaves rounding in the normal: unbounded.
    b = object_hit_bounds(object(Plane{{1, 1, 0}, 0}));
    EXPECT_EQ(b.lo.y, -kInfinity);
    EXPECT_EQ(b.hi.x, kInfinity);
    b = object_hit_bounds(object(Plane{{0, 1, 0}, 0}, Transform::rotate({-90, 0, 0})));
    EXPECT_EQ(b.lo.z, -kInfinity);
    EXPECT_EQ(b.hi.z, kInfinity);
    // Other shapes: their world bounds.
    b = object_hit_bounds(object(Sphere{{1, 2, 3}, 0.5}));
    EXPECT_EQ(b.lo.x, 0.5);
    EXPECT_EQ(b.hi.z, 3.5);
}

TEST(Intersect, InverseSphereNormalPointsInward) {
    Object o = object(Sphere{{0, 0, 5}, 1});
    o.inverse = true;
    Hit h;
    ASSERT_TRUE(shoot(one(o), {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    expect_vec(h.normal, {0, 0, 1});
}

TEST(Intersect, NoImageObjectsAreInvisibleToCameraRays) {
    Scene s;
    s.objects.push_back(object(Sphere{{0, 0, 5}, 1}));
    s.objects.back().no_image = true;
    s.objects.push_back(object(Sphere{{0, 0, 10}, 1}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 9.0);
}

TEST(Intersect, ClosestOfManyThroughTheOctree) {
    Scene s;
    for (int i = 0; i < 200; ++i)
        s.objects.push_back(object(Sphere{{0, 0, 10.0 + i}, 0.25}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 0, 0}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 9.75);
    ASSERT_TRUE(shoot(s, {{0, 0, 300}, {0, 0, -1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 300 - 209.25);
}

TEST(Intersect, AGiantSkySphereStaysOutOfTheOctreeAndIsStillHit) {
    // 4,096 small spheres in a 16-unit cube inside a sky sphere of radius 1e6: the tree
    // spans the small ones only (with the sky in it, the depth limit left them in leaves
    // of hundreds), and the sky is hit from inside and casts shadows.
    Scene s;
    s.objects.push_back(object(Sphere{{0, 0, 0}, 1e6}));
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j)
            for (int k = 0; k < 16; ++k)
                s.objects.push_back(object(Sphere{{Real(i), Real(j), Real(k)}, 0.2}));
    PreparedScene prepared(s);
    const Bounds3& root = prepared.tree().bounds();
    EXPECT_LT(root.hi.x - root.lo.x, 20);
    RayContext ctx;
    prepared.init_context(ctx);
    Hit h;
    // Along a row of small spheres: the first one, after a few tests.
    ASSERT_TRUE(prepared.closest_hit({{-1, 5, 5}, {1, 0, 0}}, 0, kInfinity,
                                     RayUse::Camera, h, ctx));
    EXPECT_DOUBLE_EQ(h.t, 0.8);
    EXPECT_LT(ctx.tests, 40u);
    // Between the rows, out to the sky.
    ASSERT_TRUE(prepared.closest_hit({{5.5, 5.5, 5.5}, {0, 0, 1}}, 0, kInfinity,
                                     RayUse::Camera, h, ctx));
    EXPECT_NEAR(h.t, std::sqrt(1e12 - 2 * 5.5 * 5.5) - 5.5, 1e-6);
    bool transparent = false;
    EXPECT_TRUE(prepared.opaque_blocker({{5.5, 5.5, 5.5}, {0, 0, 1}}, 1e-3, 2e6,
                                        transparent, ctx, -1));
    EXPECT_FALSE(prepared.opaque_blocker({{5.5, 5.5, 5.5}, {0, 0, 1}}, 1e-3, 1e5,
                                         transparent, ctx, -1));
}

TEST(Intersect, CylinderSideAndCaps) {
    Scene s = one(object(Cylinder{{0, 0, 0}, {0, 2, 0}, 1, false}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 1, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 4.0, 1e-12);
    expect_vec(h.normal, {0, 0, -1}, 1e-12);
    ASSERT_TRUE(shoot(s, {{0.5, 5, 0}, {0, -1, 0}}, h));
    EXPECT_NEAR(h.t, 3.0, 1e-12);
    expect_vec(h.normal, {0, 1, 0});
    Scene open = one(object(Cylinder{{0, 0, 0}, {0, 2, 0}, 1, true}));
    EXPECT_FALSE(shoot(open, {{0.5, 5, 0}, {0, -1, 0}}, h));  // no caps: through the tube
    ASSERT_TRUE(shoot(open, {{0, 1, 0}, {1, 0, 0}}, h));      // from inside: the wall
    EXPECT_NEAR(h.t, 1.0, 1e-12);
}

TEST(Intersect, TorusQuartic) {
    Scene s = one(object(Torus{2, 0.5}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{-10, 0, 0}, {1, 0, 0}}, h));
    EXPECT_NEAR(h.t, 7.5, 1e-9);
    expect_vec(h.normal, {-1, 0, 0}, 1e-9);
    ASSERT_TRUE(shoot(s, {{2, 10, 0}, {0, -1, 0}}, h));
    EXPECT_NEAR(h.t, 9.5, 1e-9);
    EXPECT_FALSE(shoot(s, {{0, 10, 0}, {0, -1, 0}}, h));  // through the hole
    // A thin torus at large scale: POV-Ray's closed-form quartic puts the hit at
    // 999.995124566900 for the exact 999 (its trace() prints that, tests/lang/
    // torus_pov_solver.pov), and its pixels come from that root, so ours do too.
    Scene big = one(object(Torus{1000, 1}));
    ASSERT_TRUE(shoot(big, {{-2000, 0, 0}, {1, 0, 0}}, h));
    EXPECT_NEAR(h.t, 999.9951245669, 1e-9);
}

TEST(Intersect, PolygonWithHoleEvenOdd) {
    Polygon poly;
    for (auto [x, y] : {std::pair{0.0, 0.0},
                        {4.0, 0.0},
                        {4.0, 4.0},
                        {0.0, 4.0},
                        {0.0, 0.0},
                        {1.0, 1.0},
                        {3.0, 1.0},
                        {3.0, 3.0},
                        {1.0, 3.0},
                        {1.0, 1.0}}) {
        poly.points.push_back({x, y, 2});
    }
    Scene s = one(object(poly));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0.5, 0.5, 0}, {0, 0, 1}}, h));
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    EXPECT_NEAR(std::fabs(h.normal.z), 1.0, 1e-12);
    EXPECT_FALSE(shoot(s, {{2, 2, 0}, {0, 0, 1}}, h));    // in the hole
    EXPECT_FALSE(shoot(s, {{4.5, 2, 0}, {0, 0, 1}}, h));  // outside
    ASSERT_TRUE(shoot(s, {{3.5, 2, 0}, {0, 0, 1}}, h));   // ring between hole and edge
}

TEST(Intersect, QuarticSolverRoots) {
    // (x-1)(x-2)(x-3)(x-4) = x^4 - 10x^3 + 35x^2 - 50x + 24
    Real c[5] = {24, -50, 35, -10, 1};
    Real r[4];
    ASSERT_EQ(solve_quartic_ferrari(c, r), 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], i + 1, 1e-12);
}

// Re-shooting from a hit point must never find the surface just left, at any scale.
TEST(Intersect, NoSelfIntersectionUnderRandomTransforms) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<Real> u(-1, 1), ang(0, 360), lscale(-2, 3);
    int checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        Real k = std::pow(10.0, lscale(rng));
        Vector3 sc{k * (1 + 0.5 * u(rng)), k * (1 + 0.5 * u(rng)),
                   k * (1 + 0.5 * u(rng))};
        Transform xf =
            Transform::scale(sc)
                .then(Transform::rotate({ang(rng), ang(rng), ang(rng)}))
                .then(Transform::translate({u(rng) * k, u(rng) * k, u(rng) * k}));
        ShapeData shape = (trial % 2) ? ShapeData(Sphere{{0, 0, 0}, 1})
                                      : ShapeData(Box{{-1, -1, -1}, {1, 1, 1}});
        Scene s = one(object(shape, xf));
        Point3 centre = xf.point({0, 0, 0});
        Point3 from = centre + Vector3{u(rng), u(rng), -3} * (4 * k);
        Vector3 dir =
            normalize(centre + Vector3{u(rng), u(rng), u(rng)} * (0.3 * k) - from);
        PreparedScene prepared(s);
        RayContext ctx;
        prepared.init_context(ctx);
        Hit h;
        if (!prepared.closest_hit({from, dir}, 0, kInfinity, RayUse::Camera, h, ctx))
            continue;
        ++checked;
        // Mirror ray off a convex solid: never hits it again.
        Vector3 n = dot(h.normal, dir) > 0 ? -h.normal : h.normal;
        Vector3 refl = normalize(dir - n * (2 * dot(dir, n)));
        Hit again;
        EXPECT_FALSE(prepared.closest_hit({h.point, refl}, 0, kInfinity, RayUse::Camera,
                                          again, ctx))
            << "trial " << trial << " scale " << k << " t " << again.t;
        // Straight on: the next hit is the far side, well away from the entry point.
        Hit far;
        ASSERT_TRUE(
            prepared.closest_hit({h.point, dir}, 0, kInfinity, RayUse::Camera, far, ctx))
            << "trial " << trial;
        EXPECT_GT(far.t, 1e-3 * k) << "trial " << trial;
        EXPECT_GT(dot(far.normal, dir), 0) << "trial " << trial;
    }
    EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace povwall::trace

namespace povwall::trace {
namespace {

const Real kSqrt125 = std::sqrt(1.25);

TEST(IntersectAudit, ConeSideCapInsideMissAndTransformed) {
    // Radius 1 at y = 0 down to 0 at y = 2: radius 0.5 at y = 1, side normal (0, 0.5,
    // -1).
    Scene s = one(object(Cone{{0, 0, 0}, {0, 2, 0}, 1, 0, false}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0, 1, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 4.5, 1e-12);
    expect_vec(h.normal, {0, 0.5 / kSqrt125, -1 / kSqrt125}, 1e-9);
    ASSERT_TRUE(shoot(s, {{0.5, -5, 0}, {0, 1, 0}}, h));  // base cap
    EXPECT_NEAR(h.t, 5.0, 1e-12);
    expect_vec(h.normal, {0, -1, 0});
    ASSERT_TRUE(shoot(s, {{0, 0.5, 0}, {1, 0, 0}}, h));  // from inside: radius 0.75
    EXPECT_NEAR(h.t, 0.75, 1e-12);
    EXPECT_FALSE(
        shoot(s, {{0.6, 1, -5}, {0, 0, 1}}, h));  // passes beside the narrow part
    Scene moved =
        one(object(Cone{{0, 0, 0}, {0, 2, 0}, 1, 0, false},
                   Transform::scale({2, 2, 2}).then(Transform::translate({0, 0, 10}))));
    ASSERT_TRUE(shoot(moved, {{0, 2, -5}, {0, 0, 1}}, h));  // world radius 1 at y = 2
    EXPECT_NEAR(h.t, 14.0, 1e-12);
    expect_vec(h.normal, {0, 0.5 / kSqrt125, -1 / kSqrt125}, 1e-9);
}

TEST(IntersectAudit, DiscWithHoleEdgeOnAndTransformed) {
    Scene s = one(object(Disc{{0, 0, 0}, {0, 1, 0}, 1, 0.5}));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0.75, 5, 0}, {0, -1, 0}}, h));
    EXPECT_NEAR(h.t, 5.0, 1e-12);
    expect_vec(h.normal, {0, 1, 0});
    EXPECT_FALSE(shoot(s, {{0.25, 5, 0}, {0, -1, 0}}, h));  // in the hole
    EXPECT_FALSE(shoot(s, {{1.1, 5, 0}, {0, -1, 0}}, h));   // beyond the rim
    EXPECT_FALSE(shoot(s, {{-5, 0, 0.75}, {1, 0, 0}}, h));  // in its plane: grazing
    Scene moved =
        one(object(Disc{{0, 0, 0}, {0, 1, 0}, 1, 0.5},
                   Transform::scale({2, 2, 2}).then(Transform::translate({0, 3, 0}))));
    ASSERT_TRUE(shoot(moved, {{1.5, 10, 0}, {0, -1, 0}}, h));
    EXPECT_NEAR(h.t, 7.0, 1e-12);
    EXPECT_FALSE(shoot(moved, {{0.9, 10, 0}, {0, -1, 0}}, h));  // hole radius 1 now
}

TEST(IntersectAudit, TriangleHitMissGrazingAndTransformed) {
    Triangle tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    Scene s = one(object(tri));
    Hit h;
    ASSERT_TRUE(shoot(s, {{0.25, 0.25, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 5.0, 1e-12);
    EXPECT_NEAR(std::fabs(h.normal.z), 1.0, 1e-12);
    EXPECT_FALSE(shoot(s, {{0.6, 0.6, -5}, {0, 0, 1}}, h));
    EXPECT_FALSE(shoot(s, {{-1, 0.25, 0}, {1, 0, 0}}, h));  // in its plane
    Scene moved = one(
        object(tri, Transform::scale({2, 2, 2}).then(Transform::translate({0, 0, 3}))));
    ASSERT_TRUE(shoot(moved, {{0.9, 0.9, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 8.0, 1e-12);
}

TEST(IntersectAudit, SmoothTriangleInterpolatesNormals) {
    SmoothTriangle tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                       std::array<Vector3, 3>{{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}}};
    Hit h;
    ASSERT_TRUE(shoot(one(object(tri)), {{0.5, 0.25, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 5.0, 1e-12);
    // Weights 0.25, 0.5, 0.25 of the corners' normals.
    Vector3 want = normalize(Vector3{0.5, 0.25, 1});
    expect_vec(h.normal * (h.normal.z > 0 ? 1 : -1), want, 1e-12);
}

// Exporter input: never hit, never a NaN.
TEST(IntersectAudit, DegenerateShapesAreNeverHitOrGiveFiniteNormals) {
    Hit h;
    EXPECT_FALSE(shoot(one(object(Triangle{{{0, 0, 0}, {0, 0, 0}, {1, 1, 0}}})),
                       {{0.5, 0.5, -5}, {0, 0, 1}}, h));
    EXPECT_FALSE(shoot(one(object(Triangle{{{0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}}})),
                       {{0.5, 0.5, -5}, {0, 0, 1}}, h));
    EXPECT_FALSE(shoot(one(object(Cylinder{{0, 0, 0}, {0, 2, 0}, 0, false})),
                       {{0, 1, -5}, {0, 0, 1}}, h));
    EXPECT_FALSE(shoot(one(object(Cone{{0, 0, 0}, {0, 2, 0}, 0, 0, false})),
                       {{0, 1, -5}, {0, 0, 1}}, h));
    EXPECT_FALSE(shoot(one(object(Sphere{{0, 0, 0}, 0})), {{0, 0, -5}, {0, 0, 1}}, h));
    // A flat box is hit on its face at the exact distance with a unit normal.
    if (shoot(one(object(Box{{0, 0, 0}, {1, 1, 0}})), {{0.5, 0.5, -5}, {0, 0, 1}}, h)) {
        EXPECT_NEAR(h.t, 5.0, 1e-12);
        EXPECT_NEAR(length(h.normal), 1.0, 1e-12);
    }
}

Mesh tetrahedron(std::optional<Vector3> inside_vector = std::nullopt) {
    auto m = std::make_shared<MeshData>();
    m->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (auto f : {std::array<uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
        Mesh::Face face;
        for (int k = 0; k < 3; ++k) face.v[k] = f[k];
        m->faces.push_back(face);
    }
    if (inside_vector) m->inside_vector = *inside_vector;
    Mesh mesh;
    mesh.data = m;
    return mesh;
}

TEST(IntersectAudit, MeshHitsAndInsideVectorMakesItSolid) {
    Mesh m = tetrahedron();
    Hit h;
    ASSERT_TRUE(shoot(one(object(m)), {{0.2, 0.2, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 5.0, 1e-12);
    EXPECT_NEAR(std::fabs(h.normal.z), 1.0, 1e-12);
    EXPECT_FALSE(
        inside_object(object(m), {0.1, 0.1, 0.1}));  // no inside_vector: a surface
    m = tetrahedron(Vector3{1, 0.01, 0.02});
    EXPECT_TRUE(inside_object(object(m), {0.1, 0.1, 0.1}));
    EXPECT_FALSE(inside_object(object(m), {0.5, 0.5, 0.5}));   // beyond the slanted face
    EXPECT_FALSE(inside_object(object(m), {-0.5, 0.1, 0.1}));  // crosses in and out again
    Object moved = object(m, Transform::translate({5, 0, 0}));
    EXPECT_TRUE(inside_object(moved, {5.1, 0.1, 0.1}));
    EXPECT_FALSE(inside_object(moved, {0.1, 0.1, 0.1}));
}

TEST(IntersectAudit, DifferenceWithASolidMeshCutsTheSphere) {
    Mesh m = tetrahedron(Vector3{1, 0.01, 0.02});
    Csg diff;
    diff.kind = CsgKind::Difference;
    diff.children.push_back(object(Sphere{{0, 0, 0}, 0.5}));
    diff.children.push_back(object(m, Transform::translate({-0.2, -0.2, -0.7})));
    Object o;
    o.shape = diff;
    Hit h;
    // Along z through x = y = 0.1 the shifted tetrahedron spans z in [-0.7, -0.3]: it
    // swallows the sphere's front (z = -sqrt(0.23)), so the first surface is its slanted
    // face at z = -0.3, inside the sphere. Its normal has POV-Ray's sign for a mesh face,
    // (p2 - p0) x (p1 - p0): inward for these faces wound counter-clockwise from outside,
    // and the difference turns it over.
    ASSERT_TRUE(shoot(one(o), {{0.1, 0.1, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 4.7, 1e-9);
    const Real k = 1 / std::sqrt(3.0);
    expect_vec(h.normal, {k, k, k}, 1e-9);
    // Beside the tetrahedron the sphere is untouched.
    ASSERT_TRUE(shoot(one(o), {{-0.3, 0, -5}, {0, 0, 1}}, h));
    EXPECT_NEAR(h.t, 5 - 0.4, 1e-9);
}

}  // namespace
}  // namespace povwall::trace
