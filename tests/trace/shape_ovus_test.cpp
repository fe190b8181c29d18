// ovus: crossings of each part (spheres on their own parts, the band between), normals,
// the inside test, in POV-Ray's arithmetic.
#include <gtest/gtest.h>

#include <cmath>

#include "trace/shapes/ovus.h"

namespace povwall::trace {
namespace {

Crossings hits(const Ovus& s, const Point3& o, const Vector3& d) {
    Crossings out;
    intersect_ovus(s, o, normalize(d), out);
    return out;
}

TEST(ShapeOvus, BandOfTheWideBottomCase) {
    const Ovus s = make_ovus(1, 0.65);
    EXPECT_EQ(s.band_radius, 2.0);
    EXPECT_DOUBLE_EQ(s.band_height, 0.08875);
    EXPECT_DOUBLE_EQ(s.band_offset, std::sqrt(1 - 0.08875 * 0.08875));
    EXPECT_DOUBLE_EQ(s.band_bottom, -0.08875);
    EXPECT_DOUBLE_EQ(s.band_top, 0.91125 * 0.65 / 1.35 + 1);
    // The band meets each sphere where their normals agree (tangent).
    const Real y = s.band_bottom;
    const Real rho = std::sqrt(1 - y * y);
    EXPECT_NEAR(std::pow(rho + s.band_offset, 2) + std::pow(y - s.band_height, 2), 4,
                1e-12);
}

TEST(ShapeOvus, AlongTheAxisTheSpheresOnly) {
    const Ovus s = make_ovus(1, 0.65);
    Crossings c = hits(s, {0, 5, 0}, {0, -1, 0});
    ASSERT_EQ(c.n, 2);
    EXPECT_EQ(c.c[0].face, kOvusBottom);  // POV-Ray's order: bottom sphere first
    EXPECT_NEAR(c.c[0].t, 6, 1e-14);
    EXPECT_EQ(c.c[1].face, kOvusTop);
    EXPECT_NEAR(c.c[1].t, 3.35, 1e-14);
}

TEST(ShapeOvus, HorizontalRayMeetsTheBand) {
    const Ovus s = make_ovus(1, 0.65);
    Crossings c = hits(s, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(c.n, 2);
    const Real rho =
        std::sqrt(4 - (0.5 - s.band_height) * (0.5 - s.band_height)) - s.band_offset;
    for (int i = 0; i < 2; ++i) EXPECT_EQ(c.c[i].face, kOvusBand);
    const Real t0 = std::min(c.c[0].t, c.c[1].t), t1 = std::max(c.c[0].t, c.c[1].t);
    EXPECT_NEAR(t0, 5 - rho, 1e-9);
    EXPECT_NEAR(t1, 5 + rho, 1e-9);
    const Vector3 n = normalize(ovus_normal(s, {-rho, 0.5, 0}, kOvusBand));
    EXPECT_NEAR(n.x, -(rho + s.band_offset) / 2, 1e-12);
    EXPECT_NEAR(n.y, (0.5 - s.band_height) / 2, 1e-12);
    EXPECT_EQ(n.z, 0);
}

TEST(ShapeOvus, TallTopCaseAndSturm) {
    Ovus s = make_ovus(0.8, 1.5);
    EXPECT_EQ(s.band_radius, 3.0);
    const Crossings closed = hits(s, {-6, 0.9, 0.1}, {1, 0, 0});
    s.sturm = true;
    const Crossings sturm = hits(s, {-6, 0.9, 0.1}, {1, 0, 0});
    ASSERT_EQ(closed.n, sturm.n);
    for (int i = 0; i < closed.n; ++i) EXPECT_NEAR(closed.c[i].t, sturm.c[i].t, 1e-9);
}

TEST(ShapeOvus, Inside) {
    const Ovus s = make_ovus(1, 0.65);
    EXPECT_TRUE(inside_ovus(s, {0, 0, 0}));
    EXPECT_TRUE(inside_ovus(s, {0, 1.6, 0}));     // the top sphere
    EXPECT_TRUE(inside_ovus(s, {1.0015, 0, 0}));  // the band bulges past the sphere
    EXPECT_FALSE(inside_ovus(s, {1.003, 0, 0}));
    EXPECT_FALSE(inside_ovus(s, {0, 1.66, 0}));
    EXPECT_FALSE(inside_ovus(s, {0, -1, 0}));  // on the surface: strict
}

}  // namespace
}  // namespace povwall::trace
