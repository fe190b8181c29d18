// sphere_sweep: crossings of the joint spheres, caps and envelopes and POV-Ray's culling
// of the inner ones, normals, the root-based inside test, the Bernstein sign test, the
// matrix path's distances and points, and the boxes.
#include <gtest/gtest.h>

#include <cmath>

#include "trace/shapes/sphere_sweep.h"

namespace povwall::trace {
namespace {

SphereSweep make_sweep(SweepSpline spline, std::vector<SweepSphere> spheres) {
    SphereSweep s;
    s.data =
        std::make_shared<SphereSweepData>(make_sphere_sweep(spline, std::move(spheres)));
    return s;
}

// The world ray met as POV-Ray meets a sweep without a matrix.
ShapeHits hits(const SphereSweep& s, const Point3& o, const Vector3& d) {
    LocalRay r{o, d, d, 1, false};
    ShapeHits out;
    shape_hits(s, r, out);
    return out;
}

// A capsule: <0,0,0> to <4,0,0>, radius 1.
const std::vector<SweepSphere> kCapsule = {{{0, 0, 0}, 1}, {{4, 0, 0}, 1}};

TEST(ShapeSphereSweep, LinearAcrossTheTube) {
    const SphereSweep s = make_sweep(SweepSpline::Linear, kCapsule);
    // Straight down through the middle: the ray meets the axis at a right angle, so the
    // envelope's double root u = 0.5 is met as its sphere.
    ShapeHits h = hits(s, {2, 5, 0}, {0, -1, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[0].t, 4.0);
    EXPECT_EQ(h[1].t, 6.0);
    EXPECT_EQ(shape_normal(s, h[0]).y, 1.0);
    EXPECT_EQ(shape_normal(s, h[1]).y, -1.0);
    // Slanted: the envelope's own depth t = -(2 d u + e) / b and its unit normal.
    const Vector3 d = normalize(Vector3{1, -1, 0});
    h = hits(s, {-3, 5, 0}, d);
    ASSERT_EQ(h.size(), 2u);
    // Enters the tube's top y = 1 at x = 1 and leaves its bottom y = -1 at x = 3.
    EXPECT_NEAR(h[0].t, 4 * std::sqrt(2.0), 1e-13);
    EXPECT_NEAR(h[1].t, 6 * std::sqrt(2.0), 1e-13);
    const Vector3 n = shape_normal(s, h[0]);
    EXPECT_NEAR(n.x, 0, 1e-15);
    EXPECT_NEAR(n.y, 1, 1e-15);
}

TEST(ShapeSphereSweep, AlongTheAxisCapsAndInnerSphereHitsAreCulled) {
    const SphereSweep s = make_sweep(SweepSpline::Linear, kCapsule);
    // Joint spheres at 4, 6 and 8, 10, caps at 5 and 9 (no envelope: its polynomial
    // vanishes): only the first entry and the last exit survive.
    std::vector<SweepCrossing> all;
    sweep_crossings(*s.data, {-5, 0, 0}, {1, 0, 0}, all);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].t, 4.0);
    EXPECT_EQ(all[1].t, 10.0);
    EXPECT_EQ(all[0].normal.x, -1.0);
    EXPECT_EQ(all[1].normal.x, 1.0);
    // The whole line is collected: from inside, the entry behind comes first.
    sweep_crossings(*s.data, {2, 0, 0}, {1, 0, 0}, all);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[1].t, 3.0);
    // ...and only hits beyond the tolerance are pushed.
    ShapeHits h = hits(s, {2, 0, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 1u);
    EXPECT_EQ(h[0].t, 3.0);
}

TEST(ShapeSphereSweep, InsideIsARootInTheSegment) {
    const SphereSweep s = make_sweep(SweepSpline::Linear, kCapsule);
    EXPECT_TRUE(shape_inside(s, {2, 0, 0}));
    EXPECT_TRUE(shape_inside(s, {-0.5, 0.5, 0}));  // in the end sphere
    EXPECT_FALSE(shape_inside(s, {2, 2, 0}));
    EXPECT_FALSE(shape_inside(s, {-1.5, 0, 0}));
    // POV-Ray's quirk: deep inside a short fat segment no root lies in [0, 1].
    const SphereSweep fat =
        make_sweep(SweepSpline::Linear, {{{0, 0, 0}, 1}, {{0.1, 0, 0}, 1}});
    EXPECT_FALSE(shape_inside(fat, {0.05, 0, 0}));
    EXPECT_TRUE(shape_inside(fat, {-0.9, 0.3, 0}));
}

TEST(ShapeSphereSweep, CubicEnvelopeThroughTheDegreeTenPolynomial) {
    // A B-spline through evenly spaced spheres is the straight capsule x in [1, 2].
    const SphereSweep s =
        make_sweep(SweepSpline::BSpline,
                   {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{2, 0, 0}, 1}, {{3, 0, 0}, 1}});
    ASSERT_EQ(s.data->joints.size(), 2u);
    EXPECT_NEAR(s.data->joints[0].centre.x, 1.0, 1e-15);
    EXPECT_NEAR(s.data->joints[1].centre.x, 2.0, 1e-15);
    const Vector3 d = normalize(Vector3{0.2, -1, 0.1});
    const Point3 o{1.5 - 0.2 * 5, 5, -0.5};
    ShapeHits h = hits(s, o, d);
    ASSERT_EQ(h.size(), 2u);
    // The exact crossings of the infinite cylinder y^2 + z^2 = 1.
    const Real a = d.y * d.y + d.z * d.z, b = 2 * (o.y * d.y + o.z * d.z),
               c = o.y * o.y + o.z * o.z - 1;
    const Real root = std::sqrt(b * b - 4 * a * c);
    EXPECT_NEAR(h[0].t, (-b - root) / (2 * a), 1e-9);
    EXPECT_NEAR(h[1].t, (-b + root) / (2 * a), 1e-9);
    // Normal: radial.
    const Vector3 n = normalize(shape_normal(s, h[0]));
    EXPECT_NEAR(n.x, 0, 1e-6);
    EXPECT_TRUE(shape_inside(s, {0.3, 0.3, 0}));
    EXPECT_FALSE(shape_inside(s, {1.5, 0.8, 0.8}));
    // Short and fat (length 1, radius 1): its middle has no root in [0, 1], outside.
    EXPECT_FALSE(shape_inside(s, {1.5, 0.5, 0.5}));
}

TEST(ShapeSphereSweep, BernsteinSignTest) {
    // (u + 1)^6: every Bernstein coefficient positive, no roots.
    const Real plus[7] = {1, 6, 15, 20, 15, 6, 1};
    Real roots[10];
    EXPECT_EQ(sweep_bezier_roots(6, plus, roots), 0);
    // (u - 0.5)(u + 1)^5 changes sign on [0, 1]: the Sturm solver finds 0.5 (to its
    // residual |p(u) / u| < 1e-12, as POV-Ray's).
    const Real mixed[7] = {1, 4.5, 7.5, 5, 0, -1.5, -0.5};
    ASSERT_EQ(sweep_bezier_roots(6, mixed, roots), 1);
    EXPECT_NEAR(roots[0], 0.5, 1e-8);
}

TEST(ShapeSphereSweep, MatrixDistancesAreWorldAndPointsObject) {
    SphereSweep s = make_sweep(SweepSpline::Linear, kCapsule);
    s.has_matrix = true;
    // The object is scaled by 2 in world: its ray direction has length 0.5.
    const Vector3 dir{0, -0.5, 0};
    LocalRay r{{2, 5, 0}, dir, {0, -1, 0}, 0.5, true};
    ShapeHits h;
    shape_hits(s, r, h);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[0].t, 8.0);
    EXPECT_TRUE(h[0].own_point);
    EXPECT_EQ(h[0].p.y, 1.0);
}

TEST(ShapeSphereSweep, Boxes) {
    const SphereSweep s = make_sweep(SweepSpline::Linear, kCapsule);
    const Bounds3 b = shape_bounds(s);
    EXPECT_LE(b.lo.x, -1);
    EXPECT_GE(b.hi.x, 5);
    EXPECT_LE(b.lo.y, -1);
    const PovBBox pb = shape_pov_bbox(s, CompactTransform{});
    EXPECT_EQ(pb.lo[0], -1.0f);
    EXPECT_EQ(pb.len[0], 6.0f);
    // Catmull-Rom: twice the radii.
    const SphereSweep cr =
        make_sweep(SweepSpline::CatmullRom,
                   {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{2, 0, 0}, 1}, {{3, 0, 0}, 1}});
    EXPECT_EQ(shape_pov_bbox(cr, CompactTransform{}).lo[1], -2.0f);
    // A negative radius inverts it.
    const SphereSweep neg =
        make_sweep(SweepSpline::Linear, {{{0, 0, 0}, -1}, {{4, 0, 0}, -1}});
    EXPECT_EQ(shape_pov_bbox(neg, CompactTransform{}).len[1], -2.0f);
}

}  // namespace
}  // namespace povwall::trace
