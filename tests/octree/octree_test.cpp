#include "octree/octree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace povwall::octree {
namespace {

struct Sphere {
    Point3 c;
    Real r;
};

Real hit_sphere(const Sphere& s, const Ray& ray) {
    Vector3 oc = s.c - ray.origin;
    Real tca = dot(oc, ray.direction);
    Real d2 = s.r * s.r - dot(oc, oc) + tca * tca;
    if (d2 < 0) return kInfinity;
    Real th = std::sqrt(d2);
    if (tca - th > 1e-9) return tca - th;
    if (tca + th > 1e-9) return tca + th;
    return kInfinity;
}

std::vector<Sphere> random_spheres(int n, std::mt19937& rng) {
    std::uniform_real_distribution<Real> pos(-10, 10), rad(0.05, 0.6);
    std::vector<Sphere> s;
    for (int i = 0; i < n; ++i) s.push_back({{pos(rng), pos(rng), pos(rng)}, rad(rng)});
    return s;
}

Octree build_for(const std::vector<Sphere>& spheres) {
    BuildInput in;
    for (const auto& s : spheres) in.bounds.push_back({s.c - Vector3(s.r), s.c + Vector3(s.r)});
    Octree t;
    t.build(in);
    return t;
}

TEST(Octree, ClosestHitEqualsBruteForceOnRandomScenes) {
    std::mt19937 rng(11);
    std::vector<Sphere> spheres = random_spheres(3000, rng);
    Octree tree = build_for(spheres);
    EXPECT_GT(tree.stats().leaves, 64);
    std::uniform_real_distribution<Real> u(-1, 1), p(-15, 15);
    int hits = 0;
    for (int n = 0; n < 20000; ++n) {
        Ray ray{{p(rng), p(rng), p(rng)}, normalize(Vector3{u(rng), u(rng), u(rng)})};
        if (n % 7 == 0) ray.direction = {0, 0, n % 2 ? 1.0 : -1.0};  // along an axis
        if (n % 11 == 0) ray.origin.x = 0;                            // on a cell plane
        Real brute = kInfinity;
        for (const auto& s : spheres) brute = std::min(brute, hit_sphere(s, ray));
        Real best = kInfinity;
        Real last_leaf_entry = -kInfinity;
        tree.traverse(ray, 0, best, [&](const uint32_t* ids, size_t count, Real& t_max) {
            for (size_t i = 0; i < count; ++i) t_max = std::min(t_max, hit_sphere(spheres[ids[i]], ray));
            return false;
        });
        (void)last_leaf_entry;
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_GT(hits, 1000);
}

TEST(Octree, LeavesComeFrontToBackAndStopEarly) {
    // Spheres in a row along x: the first leaf visited must hold the nearest one.
    std::vector<Sphere> row;
    for (int i = 0; i < 200; ++i) row.push_back({{Real(i), 0, 0}, 0.3});
    Octree tree = build_for(row);
    Ray ray{{-5, 0.01, 0.02}, {1, 0, 0}};
    std::vector<uint32_t> order;
    Real t_max = kInfinity;
    tree.traverse(ray, 0, t_max, [&](const uint32_t* ids, size_t count, Real&) {
        uint32_t lo = ids[0];
        for (size_t i = 0; i < count; ++i) lo = std::min(lo, ids[i]);
        order.push_back(lo);
        return order.size() == 3;  // any-hit style early stop
    });
    ASSERT_EQ(order.size(), 3u);
    EXPECT_EQ(order[0], 0u);
    EXPECT_LT(order[0], order[1]);
    EXPECT_LT(order[1], order[2]);
}

TEST(Octree, NanAndDegenerateRaysAreHarmless) {
    std::mt19937 rng(3);
    Octree tree = build_for(random_spheres(500, rng));
    int visits = 0;
    Real t = kInfinity;
    tree.traverse({{0, 0, 0}, {std::nan(""), 0, 1}}, 0, t, [&](auto, auto, auto&) {
        return ++visits, false;
    });
    tree.traverse({{0, 0, 0}, {0, 0, 0}}, 0, t, [&](auto, auto, auto&) { return ++visits, false; });
    EXPECT_EQ(visits, 0);
}

TEST(Octree, FlatThresholdBuildsNoTree) {
    std::mt19937 rng(5);
    Octree tree = build_for(random_spheres(10, rng));
    EXPECT_EQ(tree.stats().nodes, 1);
    EXPECT_EQ(tree.stats().leaves, 1);
}

TEST(Mailbox, FirstVisitPerRay) {
    Mailbox m;
    m.resize(4);
    m.next_ray();
    EXPECT_TRUE(m.first_visit(2));
    EXPECT_FALSE(m.first_visit(2));
    m.next_ray();
    EXPECT_TRUE(m.first_visit(2));
}

}  // namespace
}  // namespace povwall::octree
