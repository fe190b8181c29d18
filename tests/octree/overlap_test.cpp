#include "octree/overlap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace povwall::octree {
namespace {

Real up(Real v) { return std::nextafter(v, kInfinity); }

std::string text(const Point3& p) {
    char s[96];
    std::snprintf(s, sizeof s, " <%.17g, %.17g, %.17g>", p.x, p.y, p.z);
    return s;
}

TEST(SphereOverlap, TouchingACellCornerCounts) {
    // |(1, 2, 2)| = 3 exactly: the sphere touches the box at its corner only.
    Bounds3 cell{{1, 2, 2}, {5, 5, 5}};
    EXPECT_TRUE(sphere_overlaps({0, 0, 0}, 3, cell));
    Bounds3 moved{{up(1), 2, 2}, {5, 5, 5}};
    EXPECT_FALSE(sphere_overlaps({0, 0, 0}, 3, moved));
}

TEST(SphereOverlap, TouchingAFaceWithAnInexactRadius) {
    // 0.1 is not exact in binary, nor is its square; the tangency must still hold
    // exactly.
    EXPECT_TRUE(sphere_overlaps({0, 0, 0}, 0.1, {{0.1, -1, -1}, {1, 1, 1}}));
    EXPECT_FALSE(sphere_overlaps({0, 0, 0}, 0.1, {{up(0.1), -1, -1}, {1, 1, 1}}));
}

TEST(SphereOverlap, ExactWhereDoublesRoundToATouch) {
    // In doubles x^2 + y^2 rounds to <= 0.1^2, exactly it is larger: the corner is
    // outside.
    const Real x = 0.056704775781208826, y = 0.08236849157052006;
    ASSERT_LE(x * x + y * y, 0.1 * 0.1);
    EXPECT_FALSE(sphere_overlaps({0, 0, 0}, 0.1, {{x, y, -1}, {1, 1, 1}}));
    EXPECT_TRUE(
        sphere_overlaps({0, 0, 0}, 0.1, {{x, std::nextafter(y, 0.0), -1}, {1, 1, 1}}));
}

TEST(SphereOverlap, BoundsOverlapButSphereMissesTheCorner) {
    // The sphere's bounding box covers the cell's corner region; the ball does not.
    EXPECT_FALSE(sphere_overlaps({0, 0, 0}, 1, {{0.6, 0.6, 0.6}, {2, 2, 2}}));
    EXPECT_TRUE(sphere_overlaps({0, 0, 0}, 1, {{0.5, 0.5, 0.5}, {2, 2, 2}}));
    EXPECT_TRUE(
        sphere_overlaps({0.5, 0.5, 0.5}, 0.01, {{0, 0, 0}, {1, 1, 1}}));  // inside
    EXPECT_TRUE(
        sphere_overlaps({0.5, 0.5, 0.5}, 10, {{0, 0, 0}, {1, 1, 1}}));  // encloses
}

TEST(TriangleOverlap, CrossingACellWithoutAnyVertexInside) {
    Bounds3 cell{{0, 0, 0}, {1, 1, 1}};
    EXPECT_TRUE(triangle_overlaps({-5, 0.5, -5}, {5, 0.5, -5}, {0, 0.5, 10}, cell));
    // A sliver through the cell's interior, vertices far outside on both sides.
    EXPECT_TRUE(triangle_overlaps({-3, -3, 0.5}, {4, 4, 0.5}, {4, 4.01, 0.5}, cell));
}

TEST(TriangleOverlap, TiltedTrianglesUseThe3dPredicate) {
    Bounds3 cell{{0, 0, 0}, {1, 1, 1}};
    // y = 0.5 + (z + 5) / 150: crosses the cell at y ~ 0.54 with every vertex outside.
    EXPECT_TRUE(triangle_overlaps({-5, 0.5, -5}, {5, 0.5, -5}, {0, 0.6, 10}, cell));
    // Covers x + y >= 2.5 only, tilted in z; its bounds overlap the cell.
    EXPECT_FALSE(triangle_overlaps({3, -0.5, 0.4}, {-0.5, 3, 0.5}, {3, 3, 0.6}, cell));
    EXPECT_TRUE(triangle_overlaps({3, -1, 0.4}, {-1, 3, 0.5}, {3, 3, 0.6}, cell));
}

TEST(TriangleOverlap, BoundsOverlapButTriangleMisses) {
    Bounds3 cell{{0, 0, 0}, {1, 1, 1}};
    // Half-plane x + y >= 2.5 at z = 0.5: the cell's largest x + y is 2.
    EXPECT_FALSE(triangle_overlaps({3, -0.5, 0.5}, {-0.5, 3, 0.5}, {3, 3, 0.5}, cell));
    // x + y >= 2 touches the corner edge (1, 1, z) exactly.
    EXPECT_TRUE(triangle_overlaps({3, -1, 0.5}, {-1, 3, 0.5}, {3, 3, 0.5}, cell));
    // Just above the cell.
    EXPECT_FALSE(triangle_overlaps({-5, -5, up(1)}, {5, -5, up(1)}, {0, 5, up(1)}, cell));
    EXPECT_TRUE(triangle_overlaps({-5, -5, 1}, {5, -5, 1}, {0, 5, 1}, cell));
}

TEST(TriangleOverlap, DegenerateTrianglesAreSegmentsOrPoints) {
    Bounds3 cell{{0, 0, 0}, {1, 1, 1}};
    EXPECT_TRUE(triangle_overlaps({-1, 0.5, 0.5}, {2, 0.5, 0.5}, {0.5, 0.5, 0.5}, cell));
    // Segment on x + y = 0.5 crosses the cell; on x + y = 2.5 it misses it.
    EXPECT_TRUE(triangle_overlaps({-1, 1.5, 0.5}, {1.5, -1, 0.5}, {-1, 1.5, 0.5}, cell));
    EXPECT_FALSE(triangle_overlaps({3, -0.5, 0.5}, {-0.5, 3, 0.5}, {3, -0.5, 0.5}, cell));
    EXPECT_TRUE(triangle_overlaps({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, cell));
    EXPECT_FALSE(triangle_overlaps({up(1), 1, 1}, {up(1), 1, 1}, {up(1), 1, 1}, cell));
}

// The double-precision shortcuts of triangle_overlaps never disagree with CGAL's exact
// predicate: random triangles on a coarse grid (exact touches, shared planes, degenerate
// ones) and in general position, against cells around and across them.
TEST(TriangleOverlap, ShortcutsAgreeWithTheExactPredicate) {
    std::mt19937_64 rng(20261206);
    std::uniform_int_distribution<int> grid(-4, 8);
    std::uniform_real_distribution<Real> real(-1.5, 2.5);
    std::uniform_int_distribution<int> nudge(0, 5);
    const Bounds3 cells[] = {{{0, 0, 0}, {1, 1, 1}},
                             {{0.5, 0, 0.25}, {1, 0.5, 0.5}},
                             {{-1e-3, 0.2, 0.3}, {1e-3, 0.2 + 1e-3, 0.3 + 1e-3}}};
    size_t overlapping = 0, disjoint = 0;
    for (int i = 0; i < 200000; ++i) {
        Point3 p[3];
        const bool on_grid = i % 2 == 0;
        for (auto& q : p) {
            for (int k = 0; k < 3; ++k) {
                q[k] = on_grid ? grid(rng) * 0.25 : real(rng);
                // One step off the grid: touches become gaps or overlaps of an ulp.
                if (on_grid && nudge(rng) == 0) q[k] = std::nextafter(q[k], kInfinity);
                if (on_grid && nudge(rng) == 1) q[k] = std::nextafter(q[k], -kInfinity);
            }
        }
        if (i % 7 == 0) p[2] = p[1];                          // a segment
        if (i % 11 == 0) p[1] = p[0] + (p[2] - p[0]) * 0.25;  // collinear
        // Far from the origin too, where the coordinates' ulps are coarser.
        const Vector3 shift = i % 3 == 0 ? Vector3{1000, -2000, 500} : Vector3{0, 0, 0};
        for (auto& q : p) q = q + shift;
        for (Bounds3 cell : cells) {
            cell = {cell.lo + shift, cell.hi + shift};
            const bool fast = triangle_overlaps(p[0], p[1], p[2], cell);
            ASSERT_EQ(fast, triangle_overlaps_exactly(p[0], p[1], p[2], cell))
                << text(p[0]) << text(p[1]) << text(p[2]) << " in " << text(cell.lo)
                << text(cell.hi);
            (fast ? overlapping : disjoint) += 1;
        }
    }
    // Both answers occur often, so both sides of every shortcut are exercised.
    EXPECT_GT(overlapping, 100000u);
    EXPECT_GT(disjoint, 100000u);
}

TEST(BoxOverlap, ClosedBoxes) {
    Bounds3 cell{{0, 0, 0}, {1, 1, 1}};
    EXPECT_TRUE(box_overlaps({{1, 1, 1}, {2, 2, 2}}, cell));
    EXPECT_FALSE(box_overlaps({{up(1), 0, 0}, {2, 2, 2}}, cell));
    EXPECT_TRUE(box_overlaps({{-1, -1, -1}, {3, 3, 3}}, cell));
}

}  // namespace
}  // namespace povwall::octree
