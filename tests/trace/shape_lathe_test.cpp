// lathe: the spline coefficients POV-Ray builds, crossings through each polynomial
// degree, normals, the even-odd inside test.
#include <gtest/gtest.h>

#include <cmath>

#include "trace/shapes/lathe.h"

namespace povwall::trace {
namespace {

Lathe make_lathe(LatheSplineKind kind, const std::vector<ProfilePoint>& pts,
                 bool sturm = false) {
    return Lathe{std::make_shared<LatheSpline>(make_lathe_spline(kind, pts)), sturm};
}

ShapeHits hits(const Lathe& s, const Point3& o, const Vector3& d) {
    ShapeHits out;
    intersect_lathe(s, o, normalize(d), 1, out);
    std::sort(out.begin(), out.end(),
              [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
    return out;
}

// A square outline r in [1, 2], h in [0, 1]: a tube with flat ends.
const std::vector<ProfilePoint> kSquareProfile = {{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}};

TEST(ShapeLathe, LinearTube) {
    const Lathe s = make_lathe(LatheSplineKind::Linear, kSquareProfile);
    ASSERT_EQ(s.spline->segments.size(), 4u);
    EXPECT_EQ(s.spline->radius1, 1.0);
    EXPECT_EQ(s.spline->radius2, 2.0);
    // Across at mid height: outer, inner, inner, outer wall.
    ShapeHits h = hits(s, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(h.size(), 4u);
    const Real expect[4] = {3, 4, 6, 7};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(h[i].t, expect[i], 1e-12);
    EXPECT_EQ(h[0].face, 1);  // the outer wall <2, 0> -> <2, 1>
    EXPECT_NEAR(h[0].param, 0.5, 1e-12);
    const Vector3 n = normalize(lathe_normal(s, h[0].p, h[0].face, h[0].param));
    EXPECT_NEAR(std::fabs(n.x), 1, 1e-12);
    // Down onto the top annulus (a flat segment, horizontal in the profile).
    h = hits(s, {1.5, 5, 0}, {0, -1, 0});
    ASSERT_EQ(h.size(), 2u);
    EXPECT_NEAR(h[0].t, 4, 1e-12);
    EXPECT_NEAR(h[1].t, 5, 1e-12);
    EXPECT_NEAR(std::fabs(normalize(lathe_normal(s, h[0].p, h[0].face, h[0].param)).y), 1,
                1e-12);
    // Through the hole: nothing.
    EXPECT_TRUE(hits(s, {0.5, 5, 0}, {0, -1, 0}).empty());
    EXPECT_TRUE(inside_lathe(s, {1.5, 0.5, 0}));
    EXPECT_TRUE(inside_lathe(s, {0, 0.5, -1.5}));
    EXPECT_FALSE(inside_lathe(s, {0.5, 0.5, 0}));
    EXPECT_FALSE(inside_lathe(s, {2.5, 0.5, 0}));
}

TEST(ShapeLathe, EveryKindThroughItsSolver) {
    // A straight outline at r = 1 from h = 0 to 1 in every kind: a cylinder wall.
    struct Case {
        LatheSplineKind kind;
        std::vector<ProfilePoint> pts;
    };
    const Case cases[] = {
        {LatheSplineKind::Linear, {{1, 0}, {1, 1}}},
        {LatheSplineKind::Quadratic, {{1, -1}, {1, 0}, {1, 1}}},
        {LatheSplineKind::Cubic, {{1, -1}, {1, 0}, {1, 1}, {1, 2}}},
        {LatheSplineKind::Bezier, {{1, 0}, {1, 1.0 / 3}, {1, 2.0 / 3}, {1, 1}}},
    };
    for (const Case& c : cases) {
        for (bool sturm : {false, true}) {
            const Lathe s = make_lathe(c.kind, c.pts, sturm);
            ShapeHits h = hits(s, {-5, 0.25, 0.5}, {1, 0.1, 0});
            ASSERT_EQ(h.size(), 2u) << int(c.kind);
            const Real x = std::sqrt(0.75);
            EXPECT_NEAR(h[0].t, (5 - x) * std::sqrt(1.01), 1e-9) << int(c.kind);
            EXPECT_NEAR(h[1].t, (5 + x) * std::sqrt(1.01), 1e-9) << int(c.kind);
        }
    }
}

TEST(ShapeLathe, CubicBoundsIncludeTheBulge) {
    // The Catmull-Rom segment between <1, 0> and <1, 1> bulges out toward <2, 0.5>.
    const Lathe s = make_lathe(LatheSplineKind::Cubic, {{0, -1}, {1, 0}, {1, 1}, {0, 2}});
    EXPECT_GT(s.spline->radius2, 1.0);
    const Real t = 0.5;
    const auto& e = s.spline->segments[0];
    const Real r = ((e.ar * t + e.br) * t + e.cr) * t + e.dr;
    EXPECT_NEAR(s.spline->radius2, r, 1e-12);
}

}  // namespace
}  // namespace povwall::trace
