// Sphere distances for runs of spheres kept as structure of arrays: an octree leaf's
// spheres side by side, so that they are tested four or eight at a time.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/math.h"
#include "core/memory.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

// POV-Ray's sphere test for a unit-length direction: the nearer root beyond the
// tolerances and before MAX_DISTANCE (1e7), else the farther one; tangent rays miss.
// kInfinity when there is no hit at or beyond `lo`.
inline Real sphere_distance(Real cx, Real cy, Real cz, Real r, const Ray& ray, Real lo) {
    const Real ocx = cx - ray.origin.x, ocy = cy - ray.origin.y, ocz = cz - ray.origin.z;
    const Real tca =
        ocx * ray.direction.x + ocy * ray.direction.y + ocz * ray.direction.z;
    const Real t2hc = r * r - (ocx * ocx + ocy * ocy + ocz * ocz) + tca * tca;
    if (!(t2hc > kPovEpsilon)) return kInfinity;
    const Real th = std::sqrt(t2hc);
    Real t = tca - th;
    if (!(t > kSphereTolerance && t >= lo)) {
        t = tca + th;
        if (!(t > kSphereTolerance && t >= lo)) return kInfinity;
    }
    return t < kMaxDistance ? t : kInfinity;
}

// A sphere in world space: 32 bytes, aligned so that a record never straddles two cache
// lines (unaligned, half of them did: most of the cache misses of large sphere scenes).
struct alignas(32) SphereRecord {
    Real x, y, z, r;
};

// A run of spheres as four parallel arrays. Reading up to seven entries past a run's end
// must be allowed (the arrays are padded), since lanes are read eight at a time.
struct SphereRun {
    const Real *x, *y, *z, *r;
};

// Up to 64 spheres at a time: t[i] = sphere_distance(sphere i of `run`, ray, lo) for
// i < n <= 64, and bit i of the result set when t[i] < below. `t` needs room for n
// rounded up to a multiple of 8 (the extra entries are scratch). Four lanes (AVX) or
// eight (AVX-512) do the scalar function's exact operations in its order (no fused
// multiply-add), so every width gives the same bits.
constexpr size_t kMaxSphereRun = 64;
uint64_t sphere_distances(const SphereRun& run, size_t n, const Ray& ray, Real lo,
                          Real below, Real* t);

// The spheres of a list of octree references as four parallel arrays: entry p is the
// sphere of refs[p] (NaN where refs[p] >= sphere_count: another primitive), so a leaf's
// spheres are side by side. Seven entries of padding at the end.
struct SphereLanes {
    std::vector<Real> x, y, z, r;
    void build(const std::vector<uint32_t>& refs, const SphereRecord* records,
               uint32_t sphere_count) {
        const size_t n = sphere_count ? refs.size() + 7 : 0;
        for (auto* lane : {&x, &y, &z, &r}) {
            // Read at random by large scenes: 2 MB pages spare the TLB (a
            // 1,000,000-sphere tree's 96 MB of lanes: 660 -> 578 ns per ray in
            // BM_OctreeLanes).
            lane->clear();
            lane->reserve(n);
            advise_huge_pages(lane->data(), n * sizeof(Real));
            lane->assign(n, std::numeric_limits<Real>::quiet_NaN());
        }
        for (size_t p = 0; sphere_count && p < refs.size(); ++p) {
            if (refs[p] >= sphere_count) continue;
            const SphereRecord& s = records[refs[p]];
            x[p] = s.x;
            y[p] = s.y;
            z[p] = s.z;
            r[p] = s.r;
        }
    }
    SphereRun run(size_t p) const { return {&x[p], &y[p], &z[p], &r[p]}; }
    size_t bytes() const { return 4 * x.capacity() * sizeof(Real); }
    // Large trees: the octree asks for a leaf's lanes ahead of its visit.
    void prefetch(size_t p) const {
        if (p < x.size()) {
            __builtin_prefetch(&x[p]);
            __builtin_prefetch(&y[p]);
            __builtin_prefetch(&z[p]);
            __builtin_prefetch(&r[p]);
        }
    }
};

enum class LaneWidth { One, Four, Eight };
// The widest this CPU runs; sphere_distances() uses it.
LaneWidth widest_lanes();
// With a given width, at most widest_lanes() (for tests).
uint64_t sphere_distances(LaneWidth width, const SphereRun& run, size_t n, const Ray& ray,
                          Real lo, Real below, Real* t);

}  // namespace povwall::trace
