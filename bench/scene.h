// Benchmark fixtures: random sphere scenes at the seed scene's density, ray sets, and
// three closest-hit engines (octree, brute force, naive uniform grid) over the same SoA
// spheres.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/math.h"
#include "octree/octree.h"
#include "octree/spatial_order.h"
#include "trace/sphere_lanes.h"

namespace povwall::bench {

/// Spheres as trace/ keeps them: one 32-byte record each, aligned (a candidate test
/// touches one cache line), numbered along a Morton curve.
using trace::SphereRecord;
struct Spheres {
    std::vector<SphereRecord> records;
    size_t size() const { return records.size(); }
    const SphereRecord& operator[](size_t i) const { return records[i]; }
    Bounds3 bounds(size_t i) const {
        const SphereRecord& s = records[i];
        Point3 c{s.x, s.y, s.z};
        return {c - Vector3(s.r), c + Vector3(s.r)};
    }
};

/// N spheres (radius 0.25..0.6) in a cube sized so the density equals
/// scenes/demo/walls.pov's (5000 spheres in a 20-unit cube). Returns the cube half-size.
inline Real make_spheres(size_t n, uint32_t seed, Spheres& s) {
    const Real half = 10 * std::cbrt(Real(n) / 5000);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> pos(-half, half), rad(0.25, 0.6);
    Spheres raw;
    for (size_t i = 0; i < n; ++i) {
        SphereRecord r;
        r.x = pos(rng);
        r.y = pos(rng);
        r.z = pos(rng);
        r.r = rad(rng);
        raw.records.push_back(r);
    }
    // Numbered along a Morton curve, as trace/ numbers a scene's spheres.
    std::vector<Bounds3> b;
    for (size_t i = 0; i < n; ++i) b.push_back(raw.bounds(i));
    s = {};
    for (uint32_t i : octree::morton_order(b)) s.records.push_back(raw.records[i]);
    return half;
}

/// Half camera rays (pinhole in front of the cube, 48 degree view, as walls.pov), half
/// secondary rays (random origins inside the cube, random directions).
inline std::vector<Ray> make_rays(size_t count, Real half, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(-1, 1), in(-half, half);
    std::vector<Ray> rays;
    const Point3 eye{0, 0, -2.2 * half};
    const Real tan_half = std::tan(24 * kPi / 180);
    for (size_t i = 0; i < count; ++i) {
        if (i % 2 == 0) {
            rays.push_back(
                {eye, normalize(Vector3{u(rng) * tan_half, u(rng) * tan_half, 1})});
        } else {
            Vector3 d;
            do d = {u(rng), u(rng), u(rng)};
            while (dot(d, d) > 1 || dot(d, d) < 1e-4);
            rays.push_back({{in(rng), in(rng), in(rng)}, normalize(d)});
        }
    }
    return rays;
}

/// Nearest sphere intersection beyond 1e-6 (unit direction assumed).
inline bool hit_sphere(const Spheres& s, uint32_t i, const Ray& ray, Real& t_max) {
    const Real ox = s[i].x - ray.origin.x, oy = s[i].y - ray.origin.y,
               oz = s[i].z - ray.origin.z;
    const Real b = ox * ray.direction.x + oy * ray.direction.y + oz * ray.direction.z;
    const Real disc = b * b - (ox * ox + oy * oy + oz * oz) + s[i].r * s[i].r;
    if (disc < 0) return false;
    const Real root = std::sqrt(disc);
    Real t = b - root;
    if (t <= 1e-6) t = b + root;
    if (t <= 1e-6 || t >= t_max) return false;
    t_max = t;
    return true;
}

inline Real brute_closest(const Spheres& s, const Ray& ray, uint64_t& tests) {
    Real t = kInfinity;
    for (uint32_t i = 0; i < s.size(); ++i) hit_sphere(s, i, ray, t);
    tests += s.size();
    return t;
}

inline Real octree_closest(const octree::Octree& tree, const Spheres& s, const Ray& ray,
                           octree::Mailbox& mb, uint64_t& tests) {
    Real best = kInfinity;
    mb.next_ray();
    tree.traverse(ray, 0, best, [&](const uint32_t* ids, size_t n, Real& t_max) {
        for (size_t k = 0; k < n; ++k) {
            if (!mb.first_visit(ids[k])) continue;
            ++tests;
            hit_sphere(s, ids[k], ray, t_max);
        }
        return false;
    });
    return best;
}

// What trace/ does: a node step worth 12 tests, each leaf's spheres copied side by side
// (four parallel arrays over the tree's references) and tested 4 or 8 at a time by
// trace::sphere_distances, POV-Ray's sphere test. Checked against brute force with the
// same test first.
struct LaneOctree {
    octree::Octree tree;
    trace::SphereLanes lanes;
    // `in`: the spheres' bounds and exact overlap test; `opt`: as trace/ sets it for
    // sphere scenes (traversal_cost 12) unless a tuning run says otherwise.
    void build(const Spheres& s, const octree::BuildInput& in, octree::BuildOptions opt) {
        tree.build(in, opt);
        lanes.build(tree.ids(), s.records.data(), uint32_t(s.size()));
    }
    // `hit`, when given, receives the nearest sphere's number (left alone on a miss).
    Real closest(const Ray& ray, uint64_t& tests, uint32_t* hit = nullptr) const {
        Real best = kInfinity;
        const uint32_t* refs = tree.ids().data();
        tree.traverse(
            ray, 0, best,
            [&](const uint32_t* ids, size_t n, Real& t_max) {
                Real t[trace::kMaxSphereRun];
                for (size_t done = 0; done < n; done += trace::kMaxSphereRun) {
                    const size_t m = std::min(trace::kMaxSphereRun, n - done);
                    const size_t p = size_t(ids - refs) + done;
                    uint64_t nearer =
                        trace::sphere_distances(lanes.run(p), m, ray, 0, t_max, t);
                    tests += m;
                    for (; nearer; nearer &= nearer - 1) {
                        const size_t i = size_t(__builtin_ctzll(nearer));
                        if (t[i] < t_max) {
                            t_max = t[i];
                            if (hit) *hit = ids[done + i];
                        }
                    }
                }
                return false;
            },
            [&](uint32_t first) { lanes.prefetch(first); });
        return best;
    }
    // Any sphere hit in [1e-6, t_max) (shadow rays).
    bool any_hit(const Ray& ray, Real t_max) const {
        bool hit = false;
        Real limit = t_max;
        const uint32_t* refs = tree.ids().data();
        tree.traverse(
            ray, 0, limit,
            [&](const uint32_t* ids, size_t n, Real&) {
                Real t[trace::kMaxSphereRun];
                for (size_t done = 0; done < n; done += trace::kMaxSphereRun) {
                    const size_t m = std::min(trace::kMaxSphereRun, n - done);
                    const size_t p = size_t(ids - refs) + done;
                    if (trace::sphere_distances(lanes.run(p), m, ray, 0, t_max, t))
                        return hit = true;
                }
                return false;
            },
            [&](uint32_t first) { lanes.prefetch(first); });
        return hit;
    }
};

/// The naive alternative: a uniform grid of about one cell per sphere, references by
/// bounds overlap, 3D-DDA (Amanatides and Woo) with a mailbox and early exit.
class UniformGrid {
  public:
    void build(const Spheres& s);
    Real closest(const Spheres& s, const Ray& ray, octree::Mailbox& mb,
                 uint64_t& tests) const;

  private:
    Bounds3 box_;
    int res_[3] = {1, 1, 1};
    Vector3 cell_;
    std::vector<uint32_t> start_, ids_;
};

}  // namespace povwall::bench
