// sor: the spline POV-Ray builds, crossings of the caps and the curve, normals, the
// inside test, and the bounding-cylinder intervals.
#include <gtest/gtest.h>

#include <cmath>

#include "trace/shapes/bounding_cylinders.h"
#include "trace/shapes/sor.h"

namespace povwall::trace {
namespace {

Sor make_sor(const std::vector<ProfilePoint>& pts, bool open = false) {
    auto spline = std::make_shared<SorSpline>();
    EXPECT_EQ(make_sor_spline(pts, *spline), "");
    return Sor{spline, open, false};
}

ShapeHits hits(const Sor& s, const Point3& o, const Vector3& d) {
    ShapeHits out;
    intersect_sor(s, o, normalize(d), 1, out);
    std::sort(out.begin(), out.end(),
              [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
    return out;
}

// A cylinder of radius 1 from y = 0 to 2: r^2 = 1 on every segment.
const std::vector<ProfilePoint> kCylinder = {{1, -1}, {1, 0}, {1, 1}, {1, 2}, {1, 3}};

TEST(ShapeSor, ConstantRadiusIsACylinder) {
    const Sor s = make_sor(kCylinder);
    ASSERT_EQ(s.spline->segments.size(), 2u);
    for (const auto& e : s.spline->segments) {
        EXPECT_EQ(e.a, 0);
        EXPECT_EQ(e.b, 0);
        EXPECT_EQ(e.c, 0);
        EXPECT_NEAR(e.d, 1, 1e-15);
    }
    EXPECT_EQ(s.spline->height1, 0);
    EXPECT_EQ(s.spline->height2, 2);
    EXPECT_NEAR(s.spline->base_radius2, 1, 1e-15);
    ShapeHits h = hits(s, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 4, 1e-12);
    EXPECT_NEAR(h[1].t, 6, 1e-12);
    const Vector3 n = normalize(sor_normal(s, h[0].p, h[0].face));
    EXPECT_NEAR(n.x, -1, 1e-12);
    EXPECT_NEAR(n.y, 0, 1e-12);
    // Down the axis: the cap and the base (closed), nothing when open.
    h = hits(s, {0.3, 5, 0}, {0, -1, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[0].face, kSorCap);
    EXPECT_NEAR(h[0].t, 3, 1e-15);
    EXPECT_EQ(h[1].face, kSorBase);
    EXPECT_NEAR(h[1].t, 5, 1e-15);
    EXPECT_EQ(sor_normal(s, h[0].p, kSorCap).y, 1);
    EXPECT_TRUE(hits(make_sor(kCylinder, true), {0.3, 5, 0}, {0, -1, 0}).empty());
}

TEST(ShapeSor, ConeInterpolatesRSquared) {
    // r = h on [0, 2] with matching end slopes: r^2 = h^2 exactly.
    const Sor s = make_sor({{-1, -1}, {0, 0}, {1, 1}, {2, 2}, {3, 3}});
    for (const auto& e : s.spline->segments) {
        EXPECT_NEAR(e.a, 0, 1e-12);
        EXPECT_NEAR(e.b, 1, 1e-12);
        EXPECT_NEAR(e.c, 0, 1e-12);
        EXPECT_NEAR(e.d, 0, 1e-12);
    }
    ShapeHits h = hits(s, {-5, 1.5, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 3.5, 1e-12);
    const Vector3 n = normalize(sor_normal(s, h[0].p, h[0].face));
    EXPECT_NEAR(n.x, -std::sqrt(0.5), 1e-12);  // outward: out and down the cone
    EXPECT_NEAR(n.y, -std::sqrt(0.5), 1e-12);
    EXPECT_TRUE(inside_sor(s, {0.5, 1, 0.5}));
    EXPECT_FALSE(inside_sor(s, {0.8, 1, 0.8}));
    EXPECT_FALSE(inside_sor(s, {0, 2.1, 0}));
}

TEST(ShapeSor, ErrorsOfTheSpline) {
    SorSpline sp;
    // P[3].y = P[1].y: a segment without height.
    EXPECT_EQ(make_sor_spline({{1, 0}, {1, 1}, {1, 2}, {1, 1}}, sp),
              "Incorrect point in surface of revolution");
}

TEST(ShapeSor, BoundingCylinderIntervalsInEntryOrder) {
    const Sor s = make_sor(kCylinder);
    std::vector<SegmentInterval> in;
    // Down the axis inside the wall: no thick cylinder is met (the caps are).
    bounding_cylinder_intervals(s.spline->cylinders, {0.5, 5, 0}, {0, -1, 0}, in);
    EXPECT_TRUE(in.empty());
    // Descending across: the upper segment entered at x = -1, the lower one where the
    // ray leaves at x = 1 (the wall counted as inner and outer cylinder: 2 crossings).
    const Vector3 d = normalize(Vector3{1, -0.2, 0});
    bounding_cylinder_intervals(s.spline->cylinders, {-5, 1.9, 0}, d, in);
    ASSERT_EQ(in.size(), 2u);
    const Real unit = std::sqrt(1.04);
    EXPECT_EQ(in[0].segment, 1u);
    EXPECT_NEAR(in[0].entry, 4 * unit, 1e-12);
    EXPECT_EQ(in[1].segment, 0u);
    EXPECT_NEAR(in[1].entry, 6 * unit, 1e-12);
    // From the axis: the thin wall (r from 1 to 1) is ahead, the crossing behind skipped.
    bounding_cylinder_intervals(s.spline->cylinders, {0.5, 0.5, 0}, {1, 0, 0}, in);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0].entry, 0.5);
    // From inside a thick cylinder (the cone r = h): entered at 0.
    const Sor cone = make_sor({{-1, -1}, {0, 0}, {1, 1}, {2, 2}});
    bounding_cylinder_intervals(cone.spline->cylinders, {0.5, 0.5, 0}, {1, 0, 0}, in);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0].entry, 0);
}

}  // namespace
}  // namespace povwall::trace
