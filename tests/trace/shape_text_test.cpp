// The glyph shape (text): exact hits, normals and inside tests of POV-Ray's extruded
// outlines, its even-odd rule and its tangent-blind quadratic solver.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "tests/trace/local_rays.h"
#include "trace/shapes/text.h"

namespace povwall::trace {
namespace {

GlyphSegment line(Real x0, Real y0, Real x1, Real y1) {
    return {{x0, x1, 0}, {y0, y1, 0}, false};
}

// A clockwise square from (x0, y0) to (x1, y1), as TrueType draws outer contours.
void add_square(GlyphOutline& g, Real x0, Real y0, Real x1, Real y1) {
    g.segments.push_back(line(x0, y0, x0, y1));
    g.segments.push_back(line(x0, y1, x1, y1));
    g.segments.push_back(line(x1, y1, x1, y0));
    g.segments.push_back(line(x1, y0, x0, y0));
}

Glyph square_glyph(Real depth) {
    auto g = std::make_shared<GlyphOutline>();
    add_square(*g, 0, 0, 1, 1);
    g->xmax = g->ymax = 1;
    return {g, depth};
}

TEST(GlyphShape, RayAlongZMeetsOnlyTheFaces) {
    ShapeHits hits;
    shape_hits(square_glyph(0.5), transformed_ray({0.5, 0.5, -1}, {0, 0, 1}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].t, 1.0);
    EXPECT_EQ(hits[1].t, 1.5);
    EXPECT_EQ(shape_normal(square_glyph(0.5), hits[0]), Vector3(0, 0, -1));
    EXPECT_EQ(shape_normal(square_glyph(0.5), hits[1]), Vector3(0, 0, 1));
}

TEST(GlyphShape, RayInThePlaneMeetsTheSidesInSegmentOrder) {
    const Glyph g = square_glyph(0.5);
    ShapeHits hits;
    // The direction is not normalised: t stays the world parameter.
    shape_hits(g, transformed_ray({-1, 0.5, 0.25}, {2, 0, 0}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].t, 0.5);
    EXPECT_EQ(hits[1].t, 1.0);
    // Side normals point into the solid for clockwise contours, as POV-Ray's.
    EXPECT_EQ(shape_normal(g, hits[0]), Vector3(1, 0, 0));
    EXPECT_EQ(shape_normal(g, hits[1]), Vector3(-1, 0, 0));
    // Outside the slab 0 <= z <= depth the sides are not hit.
    hits.clear();
    shape_hits(g, transformed_ray({-1, 0.5, 0.75}, {1, 0, 0}), hits);
    EXPECT_TRUE(hits.empty());
}

TEST(GlyphShape, HitsBehindTheToleranceAreDropped) {
    ShapeHits hits;
    shape_hits(square_glyph(0.5), transformed_ray({0.5, 0.5, -1e-7}, {0, 0, 1}), hits);
    ASSERT_EQ(hits.size(), 1u);  // the front face at 1e-7 < 1e-6 is not taken
    EXPECT_EQ(hits[0].t, 0.5 + 1e-7);
}

TEST(GlyphShape, InsideIsEvenOddOverAllContours) {
    const Glyph g = square_glyph(0.5);
    EXPECT_TRUE(shape_inside(g, {0.5, 0.5, 0.25}));
    EXPECT_TRUE(shape_inside(g, {0.5, 0.5, 0.5}));
    EXPECT_FALSE(shape_inside(g, {0.5, 0.5, 0.6}));
    EXPECT_FALSE(shape_inside(g, {1.5, 0.5, 0.25}));
    GlyphOutline two = *g.outline;
    add_square(two, 0.5, 0.5, 1.5, 1.5);  // overlapping, same direction
    EXPECT_TRUE(inside_glyph_outline(two, 0.25, 0.25));
    EXPECT_FALSE(inside_glyph_outline(two, 0.75, 0.75));  // a hole, unlike nonzero
    EXPECT_TRUE(inside_glyph_outline(two, 1.25, 1.25));
}

TEST(GlyphShape, CurveSideHitAndNormal) {
    auto outline = std::make_shared<GlyphOutline>();
    outline->segments.push_back(
        {{0, 1, 2}, {0, 1, 0}, true});  // y = 2 s (1 - s), x = 2 s
    outline->segments.push_back(line(2, 0, 0, 0));
    const Glyph g{outline, 1};
    ShapeHits hits;
    shape_hits(g, transformed_ray({1, -1, 0.25}, {0, 1, 0}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].t, 1.5);  // the arch's top at s = 0.5
    EXPECT_EQ(hits[1].t, 1.0);  // the base line
    const Vector3 n = shape_normal(g, hits[0]);
    EXPECT_NEAR(n.x, 0, 1e-15);
    EXPECT_EQ(n.y, -2);
    EXPECT_TRUE(inside_glyph_outline(*outline, 1, 0.25));
    EXPECT_FALSE(inside_glyph_outline(*outline, 1, 0.75));
}

TEST(GlyphShape, SolverMissesTangents) {
    Real r[2];
    EXPECT_EQ(glyph_solve_quad(1, -2, 1, r), 0);  // (s - 1)^2: a double root
    ASSERT_EQ(glyph_solve_quad(1, -1, 0, r), 2);  // s (s - 1)
    EXPECT_EQ(r[0], 1);
    EXPECT_EQ(r[1], 0);
    ASSERT_EQ(glyph_solve_quad(0, 2, -1, r), 1);  // linear
    EXPECT_EQ(r[0], 0.5);
}

TEST(GlyphShape, ClosestHitQueryStopsAtTheFirstCap) {
    const Glyph g = square_glyph(0.5);
    LocalRay r = transformed_ray({0.5, 0.5, -1}, {0, 0, 1});
    r.nearest_only = true;
    ShapeHits hits;
    shape_hits(g, r, hits);
    ASSERT_EQ(hits.size(), 1u);  // the back face is not searched
    EXPECT_EQ(hits[0].t, 1.0);
    EXPECT_EQ(shape_normal(g, hits[0]), Vector3(0, 0, -1));
    // From behind, the back face is met first.
    r = transformed_ray({0.5, 0.5, 2}, {0, 0, -1});
    r.nearest_only = true;
    hits.clear();
    shape_hits(g, r, hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].t, 1.5);
    EXPECT_EQ(shape_normal(g, hits[0]), Vector3(0, 0, 1));
    // Nothing is wanted past want_hi.
    r.want_hi = 1.4;
    hits.clear();
    shape_hits(g, r, hits);
    EXPECT_TRUE(hits.empty());
}

// A closest-hit query's nearest crossing (the last of equal depths, as the caller keeps)
// is the full list's, on rays through an outline of lines and curves.
TEST(GlyphShape, ClosestHitQueryKeepsTheNearestCrossing) {
    auto outline = std::make_shared<GlyphOutline>();
    add_square(*outline, 0, 0, 1, 1);
    outline->segments.push_back({{0.2, 0.5, 0.8}, {0.2, 0.9, 0.2}, true});
    outline->segments.push_back(line(0.8, 0.2, 0.2, 0.2));
    outline->xmax = outline->ymax = 1;
    outline->index();
    const Glyph g{outline, 0.3};
    auto nearest = [](const ShapeHits& hits, Real lo, Real hi) {
        const ShapeHit* best = nullptr;
        for (const ShapeHit& h : hits)
            if (h.t >= lo && h.t < hi && (!best || h.t <= best->t)) best = &h;
        return best;
    };
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<Real> u(-1, 2);
    int hit_count = 0;
    for (int i = 0; i < 20000; ++i) {
        const Point3 o{u(rng), u(rng), u(rng) * 2 - 1};
        const Point3 target{u(rng) * 0.6 + 0.2, u(rng) * 0.6 + 0.2, u(rng) * 0.2};
        LocalRay r = transformed_ray(o, target - o);
        const Real hi = i % 3 == 0 ? 2.0 * u(rng) + 2 : kInfinity;
        ShapeHits all, kept;
        shape_hits(g, r, all);
        r.nearest_only = true;
        r.want_hi = hi;
        shape_hits(g, r, kept);
        const ShapeHit* a = nearest(all, 0, hi);
        const ShapeHit* k = nearest(kept, 0, hi);
        ASSERT_EQ(a == nullptr, k == nullptr) << i;
        if (!a) continue;
        ++hit_count;
        EXPECT_EQ(a->t, k->t) << i;
        EXPECT_EQ(a->face, k->face) << i;
    }
    EXPECT_GT(hit_count, 5000);
}

TEST(GlyphShape, PovBoxIsTheHeaderBoxPaddedInZ) {
    const PovBBox b = shape_pov_bbox(square_glyph(0.5), CompactTransform());
    EXPECT_EQ(b.lo[0], 0.0f);
    EXPECT_EQ(b.lo[2], float(-1e-6));
    EXPECT_EQ(b.len[0], 1.0f);
    EXPECT_EQ(b.len[2], float(0.5 + 2e-6));
}

}  // namespace
}  // namespace povwall::trace
