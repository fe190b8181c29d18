// poly and quadric kernels: exact hit distances for known rays, POV-Ray's filters (the
// exact-zero leading terms, the 1e-4 depth tolerance), normals and inside tests.
#include <gtest/gtest.h>

#include "core/quadric.h"
#include "tests/trace/local_rays.h"
#include "trace/shapes/poly.h"
#include "trace/shapes/quadric.h"

namespace povwall::trace {
namespace {

// The unit sphere x^2 + y^2 + z^2 - 1 as a poly of order `order` (higher terms 0).
Poly unit_sphere(int order) {
    Poly p;
    p.order = order;
    p.coeffs.assign(size_t(poly_term_count(order)), 0.0);
    p.coeffs[size_t(poly_term_index(order, 2, 0, 0))] = 1;
    p.coeffs[size_t(poly_term_index(order, 0, 2, 0))] = 1;
    p.coeffs[size_t(poly_term_index(order, 0, 0, 2))] = 1;
    p.coeffs[size_t(poly_term_index(order, 0, 0, 0))] = -1;
    return p;
}

TEST(ShapePoly, TermIndexMatchesTheEnumeration) {
    for (int n = 2; n <= 11; ++n) {
        int term = 0;
        for (int i = n; i >= 0; --i)
            for (int j = n - i; j >= 0; --j)
                for (int k = n - i - j; k >= 0; --k)
                    EXPECT_EQ(poly_term_index(n, i, j, k), term++) << n;
        EXPECT_EQ(term, poly_term_count(n));
    }
    EXPECT_EQ(poly_term_count(35), 8436);
}

TEST(ShapePoly, SphereHitsAtEveryOrder) {
    for (int order : {2, 3, 4, 5, 6}) {
        Poly p = unit_sphere(order);
        p.sturm = order > 3;
        ShapeHits hits;
        // World direction of length 2: the world distances are half the object ones.
        shape_hits(p, untransformed_ray({0, 0, -3}, {0, 0, 2}), hits);
        // Along z the terms above z^2 add exactly 0: the solver gets the quadratic.
        ASSERT_EQ(hits.size(), 2u) << order;
        EXPECT_DOUBLE_EQ(hits[0].t, 1.0) << order;
        EXPECT_DOUBLE_EQ(hits[1].t, 2.0) << order;
        EXPECT_TRUE(hits[0].own_point);
        EXPECT_DOUBLE_EQ(hits[0].p.z, -1.0);
        const Vector3 n = shape_normal(p, hits[0]);
        EXPECT_DOUBLE_EQ(n.x, 0.0);
        EXPECT_DOUBLE_EQ(n.z, -2.0) << order;
        EXPECT_TRUE(shape_inside(p, {0.5, 0, 0}));
        EXPECT_FALSE(shape_inside(p, {1.5, 0, 0}));
        // F < 1e-4: a point just outside the surface is still inside.
        EXPECT_TRUE(shape_inside(p, {1 + 4e-5, 0, 0}));
    }
}

TEST(ShapePoly, LinearAlongTheRayIsNoHit) {
    // x^3 + y = 0 seen along y: the t^3 and t^2 terms vanish exactly, no hit at all.
    Poly c;
    c.order = 3;
    c.coeffs.assign(20, 0.0);
    c.coeffs[0] = 1;
    c.coeffs[15] = 1;
    ShapeHits hits;
    shape_hits(c, untransformed_ray({0.5, 3, 0}, {0, -1, 0}), hits);
    EXPECT_TRUE(hits.empty());
    // Tilted, the cubic is met.
    shape_hits(c, untransformed_ray({0.5, 3, 0}, {0.001, -1, 0}), hits);
    EXPECT_FALSE(hits.empty());
}

TEST(ShapePoly, DepthToleranceInObjectUnits) {
    Poly p = unit_sphere(2);
    ShapeHits hits;
    shape_hits(p, untransformed_ray({0, 0, -1 - 5e-5}, {0, 0, 1}),
               hits);  // first root 5e-5: dropped
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 2 + 5e-5, 1e-12);
}

TEST(ShapeQuadric, HitsNormalsInsideAndTransform) {
    Quadric q;  // unit sphere
    quadric_transform(q, Transform::translate({2, 0, 0}));
    ShapeHits hits;
    shape_hits(q, untransformed_ray({2, 0, -3}, {0, 0, 1}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_DOUBLE_EQ(hits[0].t, 2.0);
    EXPECT_DOUBLE_EQ(hits[1].t, 4.0);
    const Vector3 n = shape_normal(q, hits[0]);
    EXPECT_DOUBLE_EQ(n.z, -2.0);
    EXPECT_TRUE(shape_inside(q, {2, 0.5, 0}));
    EXPECT_TRUE(shape_inside(q, {3, 0, 0}));  // on the surface: Q = 0 is inside
    EXPECT_FALSE(shape_inside(q, {0, 0, 0}));
    // A tangent ray misses (no single-root case).
    hits.clear();
    shape_hits(q, untransformed_ray({3, 0, -3}, {0, 0, 1}), hits);
    EXPECT_TRUE(hits.empty());
}

TEST(ShapeQuadric, PovRayBoxBugs) {
    // Paraboloid x^2 + z^2 - y = 0 moved down by 1: POV-Ray centres it at y = +1
    // (its wrong sign), so within a clip range of -2..2 the box is the slab y in [1, 2].
    Quadric p;
    p.square = {1, 0, 1};
    p.linear = {0, -1, 0};
    p.constant = 0;
    quadric_transform(p, Transform::translate({0, -1, 0}));
    quadric_compute_bbox(p, Vector3(-2), Vector3(2));
    EXPECT_EQ(p.box_lo[1], 1.0f);
    EXPECT_EQ(p.box_len[1], 1.0f);
    EXPECT_EQ(p.box_lo[0], -1.0f);
    // Hyperboloid x^2 - y^2 + z^2 - 9 within y in [-1, 1]: radius sqrt(2), not 3+.
    Quadric h;
    h.square = {1, -1, 1};
    h.constant = -9;
    quadric_compute_bbox(h, {-5, -1, -5}, {5, 1, 5});
    EXPECT_EQ(h.box_lo[0], float(-std::sqrt(2.0)));
}

}  // namespace
}  // namespace povwall::trace
