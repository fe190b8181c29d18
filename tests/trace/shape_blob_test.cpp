// blob kernels: exact hit distances for rays through single and merged components, the
// 1e-2 depth tolerance, only the positive components in POV-Ray's box, the field, the
// inside margin and normals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "trace/shapes/blob.h"

namespace povwall::trace {
namespace {

// A ray in blob space; a direction of length other than 1 stands for a transformed one
// (an untransformed blob takes the world's unit direction as it is).
LocalRay ray_transformed_if_scaled(Point3 o, Vector3 d) {
    const Real len = length(d);
    return {o, d, d * (1.0 / len), len, len != 1};
}

BlobElement sphere(Point3 c, Real r, Real s) {
    BlobElement e;
    e.origin = c;
    e.rad2 = r * r;
    e.c[2] = s;
    return e;
}

Blob blob_of(Real threshold, std::vector<BlobElement> comps) {
    Blob b;
    b.data = std::make_shared<BlobData>(make_blob(threshold, comps));
    return b;
}

TEST(ShapeBlob, SingleSphereHitsAtTheThresholdRadius) {
    // s (1 - r^2)^2 = t: r^2 = 1 - sqrt(t / s); s = 1, t = 0.25: r = sqrt(0.5).
    const Blob b = blob_of(0.25, {sphere({0, 0, 0}, 1, 1)});
    ShapeHits hits;
    shape_hits(b, ray_transformed_if_scaled({0, 0, -3}, {0, 0, 1}), hits);
    // One element: one interval holding both roots.
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 3 - std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(hits[1].t, 3 + std::sqrt(0.5), 1e-12);
    const Vector3 n = shape_normal(b, hits[0]);
    EXPECT_NEAR(n.z, -1.0, 1e-15);
    EXPECT_NEAR(n.x, 0.0, 1e-15);
}

TEST(ShapeBlob, EveryIntervalsHitsOutsideCsgToo) {
    // Two separate spheres along the ray: their intervals do not overlap. POV-Ray stops
    // after the first outside CSG and finds the others from restarted rays; povwall's one
    // ray keeps them all.
    const Blob b = blob_of(0.25, {sphere({0, 0, 0}, 1, 1), sphere({0, 0, 4}, 1, 1)});
    for (bool csg : {false, true}) {
        LocalRay r = ray_transformed_if_scaled({0, 0, -3}, {0, 0, 1});
        r.csg_child = csg;
        ShapeHits hits;
        shape_hits(b, r, hits);
        ASSERT_EQ(hits.size(), 4u);
        EXPECT_NEAR(hits[1].t, 3 + std::sqrt(0.5), 1e-12);
        EXPECT_NEAR(hits[3].t, 7 + std::sqrt(0.5), 1e-12);
    }
}

TEST(ShapeBlob, TwoSpheresMergeAndTheDepthTolerance) {
    // Two unit spheres 1 apart, strength 1, threshold 0.5: at the midpoint each gives
    // (1 - 0.25)^2 = 0.5625, 1.125 in all, so the gap is bridged.
    const Blob b = blob_of(0.5, {sphere({-0.5, 0, 0}, 1, 1), sphere({0.5, 0, 0}, 1, 1)});
    EXPECT_TRUE(shape_inside(b, {0, 0, 0}));
    EXPECT_NEAR(blob_field(*b.data, {0, 0, 0}), 1.125, 1e-15);
    // On the y axis: 2 (1 - (0.25 + y^2))^2 = 0.5, y^2 = 0.25.
    ShapeHits hits;
    shape_hits(b, ray_transformed_if_scaled({0, 4, 0}, {0, -2, 0}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 1.75, 1e-12);  // world distance along a length-2 direction
    EXPECT_NEAR(hits[1].t, 2.25, 1e-12);
    // A hit closer than 1e-2 is dropped: from just inside the surface only the far one.
    LocalRay r = ray_transformed_if_scaled({0, 0.5 - 0.005, 0}, {0, -1, 0});
    r.csg_child = true;
    hits.clear();
    shape_hits(b, r, hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 0.995, 1e-12);
    // The inside margin: field > threshold - 1e-6.
    const Real edge = std::sqrt(1 - std::sqrt(0.5));  // one sphere alone: field 0.5
    const Blob one = blob_of(0.5 + 5e-7, {sphere({0, 0, 0}, 1, 1)});
    EXPECT_TRUE(shape_inside(one, {edge, 0, 0}));
    EXPECT_FALSE(
        shape_inside(blob_of(0.5 + 2e-6, {sphere({0, 0, 0}, 1, 1)}), {edge, 0, 0}));
}

TEST(ShapeBlob, NegativeComponentsCarveAndDoNotBound) {
    const Blob b = blob_of(0.5, {sphere({0, 0, 0}, 1, 1), sphere({0, 0, -1}, 1, -2)});
    // On the z axis the negative sphere cancels the near side: the hit moves in.
    ShapeHits hits;
    shape_hits(b, ray_transformed_if_scaled({0, 0, -5}, {0, 0, 1}), hits);
    ASSERT_EQ(hits.size(), 2u);  // in and out
    const Real z = hits[0].t - 5;
    EXPECT_NEAR(hits[1].t - 5, std::sqrt(1 - std::sqrt(0.5)), 1e-12);
    EXPECT_GT(z, -std::sqrt(1 - std::sqrt(0.5)));
    EXPECT_NEAR(blob_field(*b.data, {0, 0, z}), 0.5, 1e-9);
    // POV-Ray's box: the positive sphere only, in single precision.
    const PovBBox box = shape_pov_bbox(b, CompactTransform{});
    EXPECT_EQ(box.lo[2], -1.0f);
    EXPECT_EQ(box.len[2], 2.0f);
    EXPECT_EQ(box.lo[0], -1.0f);
}

TEST(ShapeBlob, CylinderFieldAndBoxes) {
    BlobElement c;
    c.kind = BlobElementKind::Cylinder;
    c.len = 2;
    c.rad2 = 1;
    c.c[2] = 1;
    c.transform = Transform::translate({0, 0, -1});  // z from -1 to 1 in blob space
    const Blob b = blob_of(0.25, {c});
    ASSERT_EQ(b.data->elements.size(), 3u);
    // Across the body: r = sqrt(0.5) as for the sphere.
    ShapeHits hits;
    shape_hits(b, ray_transformed_if_scaled({-3, 0, 0.3}, {1, 0, 0}), hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 3 - std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(shape_normal(b, hits[0]).x, -1.0, 1e-15);
    // Along the axis: through the base hemisphere's cap.
    hits.clear();
    shape_hits(b, ray_transformed_if_scaled({0, 0, -4}, {0, 0, 1}), hits);
    ASSERT_GE(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 3 - std::sqrt(0.5), 1e-12);
    // The body's bounding sphere: centre at half its length, r^2 = rad2 + (len/2)^2,
    // then the box [0, r]^3 through its matrix (a translation: r^2 + 1e-10).
    Point3 centre;
    Real r2;
    blob_element_sphere(b.data->elements[0], centre, r2);
    EXPECT_EQ(centre.z, 0.0);
    EXPECT_NEAR(r2, 2.0, 1e-6);
    EXPECT_EQ(float(r2), float(Real(float(std::sqrt(2.0))) * float(std::sqrt(2.0))));
}

// Components at random: spheres, ellipsoids and cylinders turned every way, some
// negative.
std::vector<BlobElement> random_components(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(-1, 1);
    std::vector<BlobElement> comps;
    for (int i = 0; i < n; ++i) {
        const Point3 at{4 * u(rng), 4 * u(rng), 4 * u(rng)};
        const Real r = 0.3 + 0.4 * std::fabs(u(rng));
        const Real strength = i % 7 == 3 ? -1.0 : 1.5 + u(rng);
        const Vector3 turn{180 * u(rng), 180 * u(rng), 180 * u(rng)};
        BlobElement e = sphere(at, r, strength);
        if (i % 3 == 1) {
            e.kind = BlobElementKind::Ellipsoid;
            e.origin = {0, 0, 0};
            e.transform = Transform::scale({1, 0.5 + std::fabs(u(rng)), 1.5})
                              .then(Transform::rotate(turn))
                              .then(Transform::translate(at));
        } else if (i % 3 == 2) {
            e.kind = BlobElementKind::Cylinder;
            e.len = 0.5 + 2 * std::fabs(u(rng));
            e.transform = Transform::rotate(turn).then(Transform::translate(at));
        }
        comps.push_back(e);
    }
    return comps;
}

TEST(ShapeBlob, TheTreeFindsWhatVisitingEveryElementFinds) {
    // The hierarchy only leaves out elements the line or point cannot reach: the same
    // bits as the blob without it, for hits, normals, the field and the nearest-only
    // queries (which stop after the first interval giving a wanted hit).
    const Blob with_tree = blob_of(0.6, random_components(300, 7));
    ASSERT_FALSE(with_tree.data->tree.empty());
    Blob without = with_tree;
    auto plain = std::make_shared<BlobData>(*with_tree.data);
    plain->tree = BoxTree{};
    without.data = plain;
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-1, 1);
    int hit_rays = 0;
    for (int k = 0; k < 3000; ++k) {
        // Origins outside and inside the cloud; directions of other lengths too.
        const Real reach = k % 2 ? 12 : 4;
        const Point3 o{reach * u(rng), reach * u(rng), reach * u(rng)};
        const Point3 aim{3 * u(rng), 3 * u(rng), 3 * u(rng)};
        const Vector3 d = (aim - o) * (k % 3 ? 1.0 : 0.37 / length(aim - o));
        LocalRay r = ray_transformed_if_scaled(o, d);
        ShapeHits a, b;
        shape_hits(with_tree, r, a);
        shape_hits(without, r, b);
        ASSERT_EQ(a.size(), b.size()) << k;
        for (size_t i = 0; i < a.size(); ++i) {
            ASSERT_EQ(a[i].t, b[i].t) << k;
            ASSERT_EQ(shape_normal(with_tree, a[i]).x, shape_normal(without, b[i]).x);
        }
        hit_rays += !a.empty();
        if (a.empty()) continue;
        r.nearest_only = true;
        r.want_lo = a[0].t + 1e-9;
        const auto wanted = std::find_if(
            a.begin(), a.end(), [&](const ShapeHit& h) { return h.t >= r.want_lo; });
        ShapeHits nearest;
        shape_hits(with_tree, r, nearest);
        Real best = kInfinity;
        for (const ShapeHit& h : nearest)
            if (h.t >= r.want_lo && h.t < r.want_hi) best = std::min(best, h.t);
        ASSERT_EQ(best, wanted == a.end() ? kInfinity : wanted->t) << k;
    }
    EXPECT_GT(hit_rays, 500);
    for (int k = 0; k < 3000; ++k) {
        const Point3 p{5 * u(rng), 5 * u(rng), 5 * u(rng)};
        EXPECT_EQ(blob_field(*with_tree.data, p), blob_field(*without.data, p));
        EXPECT_EQ(shape_inside(with_tree, p), shape_inside(without, p));
    }
}

}  // namespace
}  // namespace povwall::trace
