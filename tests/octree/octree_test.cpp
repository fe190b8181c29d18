#include "octree/octree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "octree/overlap.h"
#include "octree/spatial_order.h"

namespace povwall::octree {
namespace {

struct Sphere {
    Point3 c;
    Real r;
};
struct Tri {
    Point3 a, b, c;
};

Real hit_sphere(const Sphere& s, const Ray& ray) {
    Vector3 oc = s.c - ray.origin;
    Real dd = dot(ray.direction, ray.direction);
    Real tca = dot(oc, ray.direction) / dd;
    Real d2 = s.r * s.r / dd - (dot(oc, oc) / dd - tca * tca);
    if (d2 < 0) return kInfinity;
    Real th = std::sqrt(d2);
    if (tca - th > 1e-9) return tca - th;
    if (tca + th > 1e-9) return tca + th;
    return kInfinity;
}

// Moller-Trumbore; the same code serves brute force and octree, so hits compare exactly.
Real hit_tri(const Tri& t, const Ray& ray) {
    Vector3 e1 = t.b - t.a, e2 = t.c - t.a;
    Vector3 p = cross(ray.direction, e2);
    Real det = dot(e1, p);
    if (det == 0) return kInfinity;
    Real inv = 1 / det;
    Vector3 s = ray.origin - t.a;
    Real u = dot(s, p) * inv;
    if (u < 0 || u > 1) return kInfinity;
    Vector3 q = cross(s, e1);
    Real v = dot(ray.direction, q) * inv;
    if (v < 0 || u + v > 1) return kInfinity;
    Real d = dot(e2, q) * inv;
    return d > 1e-9 ? d : kInfinity;
}

std::vector<Sphere> random_spheres(int n, Real spread, std::mt19937& rng,
                                   Real scale = 1) {
    std::uniform_real_distribution<Real> pos(-spread, spread), rad(0.05, 0.6);
    std::vector<Sphere> s;
    for (int i = 0; i < n; ++i) {
        s.push_back({Point3{pos(rng), pos(rng), pos(rng)} * scale, rad(rng) * scale});
    }
    return s;
}

BuildInput sphere_input(const std::vector<Sphere>& spheres, bool exact = true) {
    BuildInput in;
    for (const auto& s : spheres)
        in.bounds.push_back({s.c - Vector3(s.r), s.c + Vector3(s.r)});
    if (exact) {
        in.overlaps = [&spheres](uint32_t id, const Bounds3& cell) {
            return sphere_overlaps(spheres[id].c, spheres[id].r, cell);
        };
    }
    return in;
}

Octree build_spheres(const std::vector<Sphere>& spheres, BuildOptions opt = {}) {
    Octree t;
    t.build(sphere_input(spheres), opt);
    return t;
}

// Closest hit through the octree with a mailbox; also checks leaf order and counts tests.
template <class Hit>
Real octree_closest(const Octree& tree, const Ray& ray, Mailbox& mb, Hit hit, int* tests,
                    bool* ordered) {
    Real best = kInfinity;
    Real last_entry = -kInfinity;
    mb.next_ray();
    tree.traverse_with_entry(ray, 0, best,
                             [&](const uint32_t* ids, size_t n, Real& t_max, Real entry) {
                                 if (entry < last_entry || entry > t_max)
                                     *ordered = false;
                                 last_entry = entry;
                                 for (size_t i = 0; i < n; ++i) {
                                     if (!mb.first_visit(ids[i])) continue;
                                     ++*tests;
                                     t_max = std::min(t_max, hit(ids[i]));
                                 }
                                 return false;
                             });
    return best;
}

// The octree's closest sphere hit along `ray` equals the brute-force one.
void expect_closest_as_brute(const Octree& tree, const std::vector<Sphere>& spheres,
                             const Ray& ray, Mailbox& mb, int* tests, bool* ordered) {
    Real brute = kInfinity;
    for (const auto& sp : spheres) brute = std::min(brute, hit_sphere(sp, ray));
    ASSERT_EQ(
        octree_closest(
            tree, ray, mb, [&](uint32_t id) { return hit_sphere(spheres[id], ray); },
            tests, ordered),
        brute);
}

Ray random_ray(std::mt19937& rng, Real spread, int n) {
    std::uniform_real_distribution<Real> u(-1, 1), p(-1.5 * spread, 1.5 * spread);
    Ray ray{{p(rng), p(rng), p(rng)}, {u(rng), u(rng), u(rng)}};
    if (n % 7 == 0) ray.direction = {0, 0, n % 2 ? 1.0 : -1.0};  // along an axis
    if (n % 13 == 0) ray.direction = {1, -1, 0};                 // parallel to a plane
    return ray;
}

TEST(Octree, ClosestHitEqualsBruteForceOnRandomSpheres) {
    std::mt19937 rng(11);
    std::vector<Sphere> spheres = random_spheres(3000, 10, rng);
    Octree tree = build_spheres(spheres);
    EXPECT_FALSE(tree.stats().flat);
    EXPECT_GT(tree.stats().leaves, 500);
    EXPECT_GE(tree.top_level(), 2);  // most rays step through the dense top
    Mailbox mb;
    mb.resize(spheres.size());
    int hits = 0, tests = 0;
    bool ordered = true;
    for (int n = 0; n < 20000; ++n) {
        Ray ray = random_ray(rng, 10, n);
        if (n % 11 == 0)
            ray.origin.x = tree.bounds().centre().x;  // on the root mid-plane
        Real brute = kInfinity;
        for (const auto& s : spheres) brute = std::min(brute, hit_sphere(s, ray));
        Real best = octree_closest(
            tree, ray, mb, [&](uint32_t id) { return hit_sphere(spheres[id], ray); },
            &tests, &ordered);
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_TRUE(ordered);
    EXPECT_GT(hits, 5000);
    // The octree must prune: far fewer than 3000 tests per ray on average.
    EXPECT_LT(tests / 20000, 60);
}

TEST(Octree, ClosestHitEqualsBruteForceOnRandomTriangles) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> pos(-10, 10), off(-1.5, 1.5);
    std::vector<Tri> tris;
    for (int i = 0; i < 3000; ++i) {
        Point3 a{pos(rng), pos(rng), pos(rng)};
        tris.push_back({a, a + Vector3{off(rng), off(rng), off(rng)},
                        a + Vector3{off(rng), off(rng), off(rng)}});
    }
    BuildInput in;
    for (const Tri& t : tris) {
        Bounds3 b;
        b.extend(t.a);
        b.extend(t.b);
        b.extend(t.c);
        in.bounds.push_back(b);
    }
    in.overlaps = [&](uint32_t id, const Bounds3& cell) {
        return triangle_overlaps(tris[id].a, tris[id].b, tris[id].c, cell);
    };
    Octree tree;
    tree.build(in);
    EXPECT_GT(tree.stats().exact_rejected, 0u);
    Mailbox mb;
    mb.resize(tris.size());
    int hits = 0, tests = 0;
    bool ordered = true;
    for (int n = 0; n < 10000; ++n) {
        Ray ray = random_ray(rng, 10, n);
        Real brute = kInfinity;
        for (const auto& t : tris) brute = std::min(brute, hit_tri(t, ray));
        Real best = octree_closest(
            tree, ray, mb, [&](uint32_t id) { return hit_tri(tris[id], ray); }, &tests,
            &ordered);
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_TRUE(ordered);
    EXPECT_GT(hits, 2000);
}

// Rays running exactly inside cell planes of several levels, in all axis directions.
TEST(Octree, RaysAlongCellBoundaries) {
    std::mt19937 rng(7);
    std::vector<Sphere> spheres = random_spheres(4000, 8, rng);
    Octree tree = build_spheres(spheres);
    ASSERT_GE(tree.stats().depth, 3);
    const Bounds3 root = tree.bounds();
    // Plane coordinates as the builder makes them: repeated halving.
    std::vector<Real> planes[3];
    for (int a = 0; a < 3; ++a) {
        std::vector<std::pair<Real, Real>> cells{{root.lo[a], root.hi[a]}};
        for (int level = 0; level < 3; ++level) {
            std::vector<std::pair<Real, Real>> next;
            for (auto [lo, hi] : cells) {
                Real mid = (lo + hi) * 0.5;
                planes[a].push_back(mid);
                next.push_back({lo, mid});
                next.push_back({mid, hi});
            }
            cells = next;
        }
    }
    Mailbox mb;
    mb.resize(spheres.size());
    int tests = 0, hits = 0;
    bool ordered = true;
    std::uniform_real_distribution<Real> p(-12, 12);
    for (int n = 0; n < 6000; ++n) {
        int axis = n % 3;
        Vector3 d(0);
        d[axis] = (n / 3) % 2 ? 1 : -1;
        if (n % 5 == 0) d[(axis + 1) % 3] = 0.5;  // diagonal inside the plane
        Point3 o{p(rng), p(rng), p(rng)};
        // Pin the two coordinates across the travel axis to cell planes.
        for (int k = 1; k < 3; ++k) {
            int a = (axis + k) % 3;
            if (d[a] == 0 || k == 2) o[a] = planes[a][rng() % planes[a].size()];
        }
        Ray ray{o, d};
        Real brute = kInfinity;
        for (const auto& s : spheres) brute = std::min(brute, hit_sphere(s, ray));
        Real best = octree_closest(
            tree, ray, mb, [&](uint32_t id) { return hit_sphere(spheres[id], ray); },
            &tests, &ordered);
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_TRUE(ordered);
    EXPECT_GT(hits, 1000);
}

TEST(Octree, HugeTinyAndFlatScenes) {
    for (Real scale : {1e-9, 1e12}) {
        std::mt19937 rng(9);
        std::vector<Sphere> spheres = random_spheres(2000, 10, rng, scale);
        Octree tree = build_spheres(spheres);
        EXPECT_GE(tree.stats().depth, 3) << scale;
        Mailbox mb;
        mb.resize(spheres.size());
        int tests = 0;
        bool ordered = true;
        for (int n = 0; n < 3000; ++n) {
            Ray ray = random_ray(rng, 10, n);
            ray.origin *= scale;
            Real brute = kInfinity;
            for (const auto& s : spheres) brute = std::min(brute, hit_sphere(s, ray));
            Real best = octree_closest(
                tree, ray, mb, [&](uint32_t id) { return hit_sphere(spheres[id], ray); },
                &tests, &ordered);
            ASSERT_EQ(best, brute) << "scale " << scale << " ray " << n;
        }
        EXPECT_TRUE(ordered);
    }
    // All triangles in the plane z = 3: the root is flat and must be padded.
    std::mt19937 rng(2);
    std::uniform_real_distribution<Real> pos(-10, 10), off(-1, 1);
    std::vector<Tri> tris;
    BuildInput in;
    for (int i = 0; i < 2000; ++i) {
        Point3 a{pos(rng), pos(rng), 3};
        tris.push_back(
            {a, a + Vector3{off(rng), off(rng), 0}, a + Vector3{off(rng), off(rng), 0}});
        Bounds3 b;
        b.extend(tris.back().a);
        b.extend(tris.back().b);
        b.extend(tris.back().c);
        in.bounds.push_back(b);
    }
    in.overlaps = [&](uint32_t id, const Bounds3& cell) {
        return triangle_overlaps(tris[id].a, tris[id].b, tris[id].c, cell);
    };
    Octree tree;
    tree.build(in);
    EXPECT_GT(tree.bounds().hi.z, tree.bounds().lo.z);
    EXPECT_GT(tree.stats().leaves, 100);
    Mailbox mb;
    mb.resize(tris.size());
    int tests = 0, hits = 0;
    bool ordered = true;
    for (int n = 0; n < 3000; ++n) {
        Ray ray = random_ray(rng, 10, n);
        Real brute = kInfinity;
        for (const auto& t : tris) brute = std::min(brute, hit_tri(t, ray));
        Real best = octree_closest(
            tree, ray, mb, [&](uint32_t id) { return hit_tri(tris[id], ray); }, &tests,
            &ordered);
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_GT(hits, 150);
}

TEST(Octree, LeavesComeFrontToBackAndStopEarly) {
    // Spheres in a row along x: the first leaf visited must hold the nearest one.
    std::vector<Sphere> row;
    for (int i = 0; i < 200; ++i) row.push_back({{Real(i), 0, 0}, 0.3});
    Octree tree = build_spheres(row);
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
    // A closest hit at t = 4.7 ends traversal: no leaf starting beyond it is visited.
    int visits = 0;
    t_max = kInfinity;
    tree.traverse_with_entry(ray, 0, t_max,
                             [&](const uint32_t*, size_t, Real& t, Real entry) {
                                 EXPECT_LE(entry, 4.7);
                                 ++visits;
                                 t = 4.7;
                                 return false;
                             });
    EXPECT_GE(visits, 1);
    EXPECT_LE(visits, 3);
}

TEST(Octree, RayStartingInsideSkipsCellsBehindIt) {
    std::vector<Sphere> row;
    for (int i = 0; i < 200; ++i) row.push_back({{Real(i), 0, 0}, 0.3});
    Octree tree = build_spheres(row);
    Ray ray{{100, 0, 0}, {1, 0, 0}};
    Real t_max = kInfinity;
    uint32_t lowest = 1000;
    tree.traverse(ray, 0, t_max, [&](const uint32_t* ids, size_t count, Real&) {
        for (size_t i = 0; i < count; ++i) lowest = std::min(lowest, ids[i]);
        return false;
    });
    EXPECT_GE(lowest, 98u);  // cells wholly behind the origin are never visited
    EXPECT_LE(lowest, 100u);
}

// Secondary-ray style queries: only hits beyond t_min count, cells behind are skipped.
TEST(Octree, ClosestHitBeyondTMinEqualsBruteForce) {
    std::mt19937 rng(17);
    std::vector<Sphere> spheres = random_spheres(3000, 10, rng);
    Octree tree = build_spheres(spheres);
    EXPECT_GE(tree.top_level(), 2);
    std::uniform_real_distribution<Real> tm(0, 20);
    auto hit_after = [&](const Sphere& s, const Ray& ray, Real t_min) {
        Vector3 oc = s.c - ray.origin;
        Real dd = dot(ray.direction, ray.direction);
        Real tca = dot(oc, ray.direction) / dd;
        Real d2 = s.r * s.r / dd - (dot(oc, oc) / dd - tca * tca);
        if (d2 < 0) return kInfinity;
        Real th = std::sqrt(d2);
        if (tca - th > t_min) return tca - th;
        if (tca + th > t_min) return tca + th;
        return kInfinity;
    };
    Mailbox mb;
    mb.resize(spheres.size());
    int hits = 0;
    for (int n = 0; n < 10000; ++n) {
        Ray ray = random_ray(rng, 10, n);
        const Real t_min = tm(rng);
        Real brute = kInfinity;
        for (const auto& s : spheres) brute = std::min(brute, hit_after(s, ray, t_min));
        Real best = kInfinity;
        mb.next_ray();
        tree.traverse_with_entry(
            ray, t_min, best,
            [&](const uint32_t* ids, size_t k, Real& t_max, Real entry) {
                EXPECT_LE(entry, t_max);
                for (size_t i = 0; i < k; ++i) {
                    if (mb.first_visit(ids[i])) {
                        t_max = std::min(t_max, hit_after(spheres[ids[i]], ray, t_min));
                    }
                }
                return false;
            });
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_GT(hits, 1000);
}

// The dense top only changes how the first levels are walked: every ray visits the same
// leaves in the same order as the walk from the root, from outside and from inside
// (t_min > 0), and a tree that is not complete two levels down keeps the plain walk.
TEST(Octree, DenseTopVisitsTheLeavesOfTheWalkFromTheRoot) {
    std::mt19937 rng(23);
    std::vector<Sphere> spheres = random_spheres(30000, 20, rng);
    BuildOptions plain_options;
    plain_options.dense_top_max = 0;
    const Octree dense = build_spheres(spheres),
                 plain = build_spheres(spheres, plain_options);
    ASSERT_EQ(dense.top_level(), 4);  // complete down to 4,096 cells
    EXPECT_EQ(dense.stats().dense_top, 4);
    EXPECT_EQ(plain.top_level(), 0);
    ASSERT_EQ(dense.nodes().size(), plain.nodes().size());
    auto leaves = [](const Octree& tree, const Ray& ray, Real t_min) {
        std::vector<const uint32_t*> seen;
        Real t_max = kInfinity;
        tree.traverse(ray, t_min, t_max, [&](const uint32_t* ids, size_t, Real&) {
            seen.push_back(ids);
            return false;
        });
        return seen;
    };
    std::uniform_real_distribution<Real> u(-1, 1), p(-40, 40), tm(0, 30);
    size_t visited = 0;
    for (int n = 0; n < 5000; ++n) {
        const Ray ray{{p(rng), p(rng), p(rng)}, {u(rng), u(rng), u(rng)}};
        const Real t_min = n % 2 ? tm(rng) : 0;
        const auto a = leaves(dense, ray, t_min);
        const auto b = leaves(plain, ray, t_min);
        // Same leaves: pointers into the same ids (the two trees are built alike).
        ASSERT_EQ(a.size(), b.size()) << "ray " << n;
        for (size_t i = 0; i < a.size(); ++i) {
            ASSERT_EQ(a[i] - dense.ids().data(), b[i] - plain.ids().data())
                << "ray " << n << " leaf " << i;
        }
        visited += a.size();
    }
    EXPECT_GT(visited, 5000u * 3);
    // A cluster and one far sphere leave six of the root's children empty leaves.
    std::vector<Sphere> cluster = random_spheres(2000, 5, rng);
    cluster.push_back({{1000, 1000, 1000}, 1});
    EXPECT_EQ(build_spheres(cluster).top_level(), 0);
}

// A field 100 wide and 1.5 high under a root 25 high (no axis shorter than a quarter):
// the upper cells are empty leaves, copied into the dense top, and rays walk only their
// stretch inside the spheres' own box. Closest hits, from outside and from inside
// (t_min > 0), and with an axis-parallel direction, stay the brute force's.
TEST(Octree, FlatFieldWalksInsideThePrimitivesBox) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<Real> across(0, 100), up(0.3, 1.2), rad(0.1, 0.5);
    std::vector<Sphere> field;
    for (int i = 0; i < 20000; ++i)
        field.push_back({{across(rng), up(rng), across(rng)}, rad(rng)});
    const Octree tree = build_spheres(field);
    EXPECT_GE(tree.bounds().diagonal().y, 24.0);
    EXPECT_GE(tree.top_level(), 3);
    Mailbox mb;
    mb.resize(field.size());
    std::uniform_real_distribution<Real> u(-1, 1), high(-5, 40), tm(0, 30);
    int hits = 0, tests = 0, in_box_visits = 0, visits = 0;
    bool ordered = true;
    for (int n = 0; n < 10000; ++n) {
        Ray ray{{across(rng), high(rng), across(rng)}, {u(rng), u(rng), u(rng)}};
        if (n % 7 == 0) ray.direction = {u(rng), 0, u(rng)};  // level with the field
        if (n % 11 == 0) ray.direction = {0, n % 2 ? 1.0 : -1.0, 0};
        const Real t_min = n % 3 == 0 ? tm(rng) : 0;
        Real brute = kInfinity;
        for (const auto& s : field) {
            const Real t =
                hit_sphere(s, {ray.origin + ray.direction * t_min, ray.direction});
            if (t < kInfinity) brute = std::min(brute, t + t_min);
        }
        Real best = kInfinity;
        Real last_entry = -kInfinity;
        mb.next_ray();
        tree.traverse_with_entry(
            ray, t_min, best,
            [&](const uint32_t* ids, size_t k, Real& t_max, Real entry) {
                if (entry < last_entry || entry > t_max) ordered = false;
                last_entry = entry;
                ++visits;
                for (size_t i = 0; i < k; ++i) {
                    if (!mb.first_visit(ids[i])) continue;
                    ++tests;
                    const Sphere& s = field[ids[i]];
                    const Real t = hit_sphere(
                        s, {ray.origin + ray.direction * t_min, ray.direction});
                    if (t < kInfinity) t_max = std::min(t_max, t + t_min);
                }
                in_box_visits += k > 0;
                return false;
            });
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_TRUE(ordered);
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(in_box_visits, visits);  // empty leaves are never handed out
    EXPECT_LT(tests / 10000, 100);
}

TEST(Octree, NanAndInfiniteRaysVisitNothing) {
    std::mt19937 rng(3);
    std::vector<Sphere> spheres = random_spheres(500, 10, rng);
    Octree tree = build_spheres(spheres);
    const Real nan = std::nan("");
    // Every NaN/Inf position: std::max drops a NaN unless it comes first.
    std::vector<Ray> bad = {{{0, 0, 0}, {0, 0, 0}}, {{0, 0, 0}, {-0.0, 0.0, -0.0}}};
    for (Real v : {nan, kInfinity, -kInfinity}) {
        for (int a = 0; a < 3; ++a) {
            Ray r{{0.5, -0.25, 0.125}, {0.3, 0.4, 0.5}};
            r.direction[a] = v;
            bad.push_back(r);
            r = {{0.5, -0.25, 0.125}, {0.3, 0.4, 0.5}};
            r.origin[a] = v;
            bad.push_back(r);
        }
    }
    // The same rays without the bad component do visit leaves.
    Real t_ok = kInfinity;
    int ok_visits = 0;
    tree.traverse({{0.5, -0.25, 0.125}, {0.3, 0.4, 0.5}}, 0, t_ok,
                  [&](auto, auto, auto&) { return ++ok_visits, false; });
    EXPECT_GT(ok_visits, 0);
    int visits = 0;
    for (const Ray& r : bad) {
        Real t = kInfinity;
        tree.traverse(r, 0, t, [&](auto, auto, auto&) { return ++visits, false; });
        Real t_nan = nan;
        tree.traverse({{0, 0, -20}, {0, 0, 1}}, 0, t_nan,
                      [&](auto, auto, auto&) { return ++visits, false; });
    }
    EXPECT_EQ(visits, 0);
}

TEST(Octree, FlatThresholdBuildsNoTree) {
    std::mt19937 rng(5);
    std::vector<Sphere> few = random_spheres(BuildOptions{}.flat_threshold - 1, 10, rng);
    Octree tree = build_spheres(few);
    EXPECT_TRUE(tree.stats().flat);
    EXPECT_EQ(tree.stats().nodes, 1);
    EXPECT_EQ(tree.stats().leaves, 1);
    EXPECT_EQ(tree.stats().references, few.size());
    std::vector<Sphere> more = random_spheres(BuildOptions{}.flat_threshold, 10, rng);
    EXPECT_FALSE(build_spheres(more).stats().flat);
}

TEST(Octree, StatsCountLeavesReferencesAndExactSavings) {
    std::mt19937 rng(21);
    std::vector<Sphere> spheres = random_spheres(5000, 10, rng);
    Octree exact = build_spheres(spheres);
    Octree loose;
    loose.build(sphere_input(spheres, false));
    const BuildStats& s = exact.stats();
    // Stats agree with the arrays.
    int leaves = 0;
    uint64_t refs = 0;
    for (const Octree::Node& n : exact.nodes()) {
        if (n.count != Octree::kInner) ++leaves, refs += n.count;
    }
    EXPECT_EQ(s.nodes, int(exact.nodes().size()));
    EXPECT_EQ(s.leaves, leaves);
    EXPECT_EQ(s.references, refs);
    EXPECT_EQ(refs, exact.ids().size());
    EXPECT_EQ((s.nodes - 1) % 8, 0);
    EXPECT_EQ(s.leaves, s.nodes - (s.nodes - 1) / 8);
    EXPECT_GT(s.exact_tests, s.exact_rejected);
    EXPECT_GT(s.exact_rejected, 0u);
    EXPECT_EQ(loose.stats().exact_tests, 0u);
    // Exact tests keep fewer references than bounds overlap alone.
    EXPECT_LT(double(s.references) / double(s.leaves),
              double(loose.stats().references) / double(loose.stats().leaves));
    EXPECT_LE(s.depth, BuildOptions{}.max_depth);
    EXPECT_GT(s.seconds, 0);
}

TEST(Octree, ParallelBuildEqualsSerialBuild) {
    std::mt19937 rng(8);
    std::vector<Sphere> spheres = random_spheres(6000, 10, rng);
    BuildOptions one, four;
    one.threads = 1;
    four.threads = 4;
    Octree a = build_spheres(spheres, one), b = build_spheres(spheres, four);
    ASSERT_EQ(a.nodes().size(), b.nodes().size());
    ASSERT_EQ(a.ids().size(), b.ids().size());
    // Node order differs (subtrees are stitched in task order); compare by walking.
    std::vector<std::pair<uint32_t, uint32_t>> stack{{0, 0}};
    while (!stack.empty()) {
        auto [x, y] = stack.back();
        stack.pop_back();
        const Octree::Node &nx = a.nodes()[x], &ny = b.nodes()[y];
        ASSERT_EQ(nx.count, ny.count);
        if (nx.count == Octree::kInner) {
            for (uint32_t c = 0; c < 8; ++c)
                stack.push_back({nx.first + c, ny.first + c});
        } else {
            for (uint32_t i = 0; i < nx.count; ++i) {
                ASSERT_EQ(a.ids()[nx.first + i], b.ids()[ny.first + i]);
            }
        }
    }
    EXPECT_EQ(a.stats().depth, b.stats().depth);
    EXPECT_EQ(a.stats().exact_tests, b.stats().exact_tests);
}

TEST(Octree, UnboundedAndEmptyBoundsAreLeftOut) {
    BuildInput in;
    in.bounds = {Bounds3::everything(), Bounds3{}, {{0, 0, 0}, {1, 1, 1}}};
    Octree tree;
    tree.build(in);
    EXPECT_EQ(tree.stats().references, 1u);
    // The one finite box, grown by a few ulps (a ray touching the root must reach it).
    EXPECT_LE(tree.bounds().lo.x, 0);
    EXPECT_GT(tree.bounds().lo.x, -1e-12);
    EXPECT_GE(tree.bounds().hi.x, 1);
    EXPECT_LT(tree.bounds().hi.x, 1 + 1e-12);
}

// Thin boxes standing for triangles (bounds only, no exact test): `kinds` different ones
// in a 10-unit cluster, each repeated `copies` times at identical bounds, as a model of
// one part placed many times at one transform.
BuildInput copied_slabs(int kinds, int copies, std::vector<Bounds3>& shapes) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<Real> pos(-5, 5), size(0.5, 4);
    shapes.clear();
    for (int k = 0; k < kinds; ++k) {
        Point3 lo{pos(rng), pos(rng), pos(rng)};
        Vector3 d{size(rng), size(rng), size(rng)};
        d[k % 3] = 1e-3;  // flat along one axis
        shapes.push_back({lo, lo + d});
    }
    BuildInput in;
    for (int c = 0; c < copies; ++c)
        for (int k = 0; k < kinds; ++k) in.bounds.push_back(shapes[size_t(k)]);
    return in;
}

Real hit_box(const Bounds3& b, const Ray& ray) {
    Real t0 = 1e-9, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0) {
            if (ray.origin[a] < b.lo[a] || ray.origin[a] > b.hi[a]) return kInfinity;
            continue;
        }
        Real u = (b.lo[a] - ray.origin[a]) / ray.direction[a];
        Real v = (b.hi[a] - ray.origin[a]) / ray.direction[a];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
    }
    return t0 <= t1 ? t0 : kInfinity;
}

// 150 copies of 40 parts (the bricks of scenes/stress/coincident_bricks.pov in small):
// cells stop splitting once they hold copies of at most leaf_primitives parts, so the
// tree stays shallow and its references a small multiple of the primitives. Before,
// splitting went on around every part's edges to the deepest level.
TEST(OctreeBounded, CopiesAtOneTransformStopSplitting) {
    std::vector<Bounds3> shapes;
    BuildInput in = copied_slabs(40, 150, shapes);
    BuildOptions one;
    one.threads = 1;
    Octree tree;
    tree.build(in, one);
    const BuildStats& s = tree.stats();
    EXPECT_GT(s.inseparable_leaves, 0u);
    EXPECT_EQ(s.budget_leaves, 0u);
    EXPECT_EQ(s.threads, 1);
    EXPECT_LE(s.depth, 4);
    EXPECT_LE(s.references, 8 * in.bounds.size());
    // Copies of one part sit in the same leaves: the tree for 150 copies has the shape of
    // the tree for 3.
    BuildInput few = copied_slabs(40, 3, shapes);
    Octree small;
    small.build(few, one);
    EXPECT_EQ(small.stats().nodes, s.nodes);
    EXPECT_EQ(small.stats().references * 50, s.references);
    // Still exact: closest hits equal brute force.
    std::mt19937 rng(3);
    Mailbox mb;
    mb.resize(in.bounds.size());
    int tests = 0, hits = 0;
    bool ordered = true;
    for (int n = 0; n < 2000; ++n) {
        Ray ray = random_ray(rng, 6, n);
        Real brute = kInfinity;
        for (const Bounds3& b : shapes) brute = std::min(brute, hit_box(b, ray));
        Real best = octree_closest(
            tree, ray, mb, [&](uint32_t id) { return hit_box(in.bounds[id], ray); },
            &tests, &ordered);
        ASSERT_EQ(best, brute) << "ray " << n;
        hits += best < kInfinity;
    }
    EXPECT_TRUE(ordered);
    EXPECT_GT(hits, 150);
}

// Two quads of two triangles each share their bounds in pairs: pairs are not copies (the
// exact test separates them), so such cells still split.
TEST(OctreeBounded, PairsWithEqualBoundsStillSplit) {
    std::vector<Bounds3> shapes;
    BuildInput in = copied_slabs(300, 2, shapes);
    Octree tree;
    tree.build(in);
    EXPECT_EQ(tree.stats().inseparable_leaves, 0u);
    EXPECT_GE(tree.stats().depth, 2);
}

// 40 nested boxes in the low octant of the scene (a box at the far corner makes the
// scene): in that octant's cell they fill exactly the two low-x, low-y children. The area
// estimate says splitting pays (each box in 2 of 8 children), but both children would get
// all 40: the cell stays a leaf (before: two leaves of 40, 80 references).
TEST(OctreeBounded, SplitsThatCopyEverythingAreNotTaken) {
    BuildInput in;
    for (int i = 0; i < 40; ++i) {
        const Real e = 1e-3 * i;
        in.bounds.push_back({{-1, -1, -1}, {-0.51 - e, -0.51 - e, -0.001 - e}});
    }
    in.bounds.push_back({{0.9, 0.9, 0.9}, {1, 1, 1}});
    Octree tree;
    tree.build(in);
    const BuildStats& s = tree.stats();
    EXPECT_EQ(s.inseparable_leaves, 1u);
    EXPECT_EQ(s.leaves, 8);
    EXPECT_EQ(s.references, 41u);
}

// The budget of references is a hard cap: one reference per primitive and no slack leaves
// overlapping spheres unsplit where copying them would exceed it, and hits stay exact.
TEST(OctreeBounded, ReferenceBudgetCapsTheTree) {
    std::mt19937 rng(4);
    std::vector<Sphere> spheres = random_spheres(4000, 10, rng);
    BuildOptions tight;
    tight.max_references_per_primitive = 1.2;
    tight.reference_slack = 0;
    tight.threads = 1;
    Octree tree = build_spheres(spheres, tight);
    EXPECT_GT(tree.stats().budget_leaves, 0u);
    EXPECT_LE(tree.stats().references, uint64_t(1.2 * 4000));
    Octree free = build_spheres(spheres, BuildOptions{});
    EXPECT_GT(free.stats().references, uint64_t(1.2 * 4000));
    Mailbox mb;
    mb.resize(spheres.size());
    int tests = 0;
    bool ordered = true;
    for (int n = 0; n < 2000; ++n)
        expect_closest_as_brute(tree, spheres, random_ray(rng, 10, n), mb, &tests,
                                &ordered);
}

// The budget is shared out by each split in proportion to the children's references: a
// crowded region that spends its share stops splitting without starving the others (a
// sky sphere around two detailed trees: one spent it all, the other stayed leaves of
// thousands of parts, 465 M tests against 0.13 M), and the tree is the same however many
// threads build it.
TEST(OctreeBounded, ACrowdedRegionDoesNotSpendTheOthersBudget) {
    std::mt19937 rng(21);
    // Low x, built first: large spheres piled on each other. High x: small ones apart.
    std::vector<Sphere> spheres = random_spheres(1500, 2, rng, 1.0);
    for (Sphere& s : spheres) {
        s.c.x -= 8;
        s.r *= 3;
    }
    const std::vector<Sphere> sparse = random_spheres(3000, 2, rng, 0.25);
    for (Sphere s : sparse) {
        s.c.x += 8;
        s.r *= 0.2;
        spheres.push_back(s);
    }
    BuildOptions tight;
    tight.max_references_per_primitive = 3;
    tight.reference_slack = 0;
    tight.threads = 1;
    const Octree tree = build_spheres(spheres, tight);
    EXPECT_GT(tree.stats().budget_leaves, 0u);
    EXPECT_LE(tree.stats().references, uint64_t(3 * spheres.size()));
    tight.threads = 2;
    const Octree threaded = build_spheres(spheres, tight);
    EXPECT_EQ(threaded.stats().references, tree.stats().references);
    EXPECT_EQ(threaded.stats().nodes, tree.stats().nodes);
    // Rays through the sparse region only meet its few spheres near them.
    Mailbox mb;
    mb.resize(spheres.size());
    std::uniform_real_distribution<Real> across(-0.5, 0.5);
    int tests = 0;
    bool ordered = true;
    for (int n = 0; n < 500; ++n) {
        const Ray ray{{8 + across(rng), across(rng), -5}, {0, 0, 1}};
        expect_closest_as_brute(tree, spheres, ray, mb, &tests, &ordered);
    }
    EXPECT_TRUE(ordered);
    EXPECT_LT(tests, 500 * 60);  // 26,450 (before: 373,386)
}

TEST(OctreeBounded, BuildThreadsAsAsked) {
    std::mt19937 rng(9);
    std::vector<Sphere> spheres = random_spheres(6000, 10, rng);
    BuildOptions one, two;
    one.threads = 1;
    two.threads = 2;
    EXPECT_EQ(build_spheres(spheres, one).stats().threads, 1);
    EXPECT_EQ(build_spheres(spheres, two).stats().threads, 2);
}

TEST(Mailbox, FirstVisitPerRay) {
    Mailbox m;
    m.resize(4);
    m.next_ray();
    EXPECT_TRUE(m.first_visit(2));
    EXPECT_FALSE(m.first_visit(2));
    EXPECT_TRUE(m.first_visit(3));
    m.next_ray();
    EXPECT_TRUE(m.first_visit(2));
}

TEST(Mailbox, LargeScenesShareSlotsAndNeverSkip) {
    Mailbox m;
    m.resize(Mailbox::kSlots * 1000);
    const uint32_t a = 5, b = a + Mailbox::kSlots;  // same slot
    m.next_ray();
    EXPECT_TRUE(m.first_visit(a));
    EXPECT_FALSE(m.first_visit(a));
    EXPECT_TRUE(m.first_visit(b));
    EXPECT_FALSE(m.first_visit(b));
    // The clash forgot `a`: it is tested again rather than skipped.
    EXPECT_TRUE(m.first_visit(a));
    EXPECT_TRUE(m.first_visit(uint32_t(Mailbox::kSlots * 1000 - 1)));
    m.next_ray();
    EXPECT_TRUE(m.first_visit(a));
}

}  // namespace
}  // namespace povwall::octree

namespace povwall::octree {
namespace {

TEST(MortonOrder, CornersInZOrderTiesStableInfiniteLast) {
    auto box = [](Real x, Real y, Real z) {
        return Bounds3{{x - 0.1, y - 0.1, z - 0.1}, {x + 0.1, y + 0.1, z + 0.1}};
    };
    // Input: the 8 corners of a cube in reverse Z order, an unbounded plane, and a copy
    // of corner (0,0,0) that must stay after the first one.
    std::vector<Bounds3> b;
    for (int i = 7; i >= 0; --i) b.push_back(box(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    b.push_back(Bounds3::everything());
    b.push_back(box(0, 0, 0));
    std::vector<uint32_t> order = morton_order(b);
    // x is the lowest bit of the code, then y, then z: corner i comes i-th.
    EXPECT_EQ(order, (std::vector<uint32_t>{7, 9, 6, 5, 4, 3, 2, 1, 0, 8}));
    EXPECT_TRUE(morton_order({}).empty());
}

}  // namespace
}  // namespace povwall::octree
