// povwall's octree against Embree 3 (Debian's libembree-dev, a benchmark reference only)
// on the same rays: camera rays of the seed scene's 5000 spheres and, for each hit, one
// shadow ray toward a light, one thread. Issue 6 asks for >= 0.5x Embree's rate. Run:
// build/bench/povwall_bench_embree --benchmark_repetitions=5
//      --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <cstdio>
#include <cstdlib>

#include "bench/scene.h"
#include "octree/overlap.h"

namespace povwall::bench {
namespace {

constexpr size_t kCameraRays = 8192;

struct Scene {
    Spheres spheres;
    Real half = 0;
    std::vector<Ray> camera;
    Point3 light;
    octree::Octree tree;
    LaneOctree lanes;  // what trace/ does
    RTCDevice device = nullptr;
    RTCScene embree = nullptr;
};

Scene& scene() {
    static Scene instance = [] {
        Scene s;
        s.half = make_spheres(5000, 1997, s.spheres);
        // Camera rays only: the pinhole in front of the cube (make_rays' even rays).
        for (const Ray& r : make_rays(2 * kCameraRays, s.half, 42)) {
            if (s.camera.size() < kCameraRays && r.origin.z < -s.half)
                s.camera.push_back(r);
        }
        s.light = {-2 * s.half, 3 * s.half, -3 * s.half};
        octree::BuildInput in;
        for (size_t i = 0; i < s.spheres.size(); ++i)
            in.bounds.push_back(s.spheres.bounds(i));
        const Spheres& sp = s.spheres;
        in.overlaps = [&sp](uint32_t id, const Bounds3& cell) {
            return octree::sphere_overlaps({sp[id].x, sp[id].y, sp[id].z}, sp[id].r,
                                           cell);
        };
        s.tree.build(in);
        octree::BuildOptions lane_options;
        lane_options.traversal_cost = 12;
        s.lanes.build(s.spheres, in, lane_options);
        s.device = rtcNewDevice("threads=1");
        s.embree = rtcNewScene(s.device);
        RTCGeometry g = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                    4 * sizeof(float), sp.size()));
        for (size_t i = 0; i < sp.size(); ++i) {
            v[4 * i] = float(sp[i].x);
            v[4 * i + 1] = float(sp[i].y);
            v[4 * i + 2] = float(sp[i].z);
            v[4 * i + 3] = float(sp[i].r);
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(s.embree, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(s.embree);
        return s;
    }();
    return instance;
}

bool octree_any_hit(const Scene& s, const Ray& ray, Real t_max, octree::Mailbox& mb) {
    mb.next_ray();
    bool hit = false;
    Real limit = t_max;
    s.tree.traverse(ray, 0, limit, [&](const uint32_t* ids, size_t n, Real&) {
        for (size_t k = 0; k < n; ++k) {
            if (!mb.first_visit(ids[k])) continue;
            Real t = t_max;
            if (hit_sphere(s.spheres, ids[k], ray, t)) return hit = true;
        }
        return false;
    });
    return hit;
}

// Camera rays, and one shadow ray toward the light from each hit: closest(ray) gives the
// hit distance (kInfinity: none), shadowed(ray, distance) whether anything blocks it.
template <class Closest, class Shadowed>
void primary_and_shadow(benchmark::State& state, const Scene& s, Closest closest,
                        Shadowed shadowed_by) {
    uint64_t rays = 0, shadowed = 0, shadow_rays = 0;
    size_t i = 0;
    for (auto _ : state) {
        const Ray& ray = s.camera[i];
        i = (i + 1) % s.camera.size();
        ++rays;
        Real t = closest(ray);
        if (t == kInfinity) continue;
        Point3 p = ray.at(t);
        Vector3 to = s.light - p;
        Real d = length(to);
        ++rays;
        ++shadow_rays;
        shadowed += shadowed_by(Ray{p, to / d}, d);
    }
    state.SetItemsProcessed(int64_t(rays));
    // Same rays, so the engines must agree on these fractions (a correctness check).
    state.counters["hit_fraction"] = double(shadow_rays) / double(rays - shadow_rays);
    state.counters["shadowed_fraction"] = double(shadowed) / double(shadow_rays);
}

void BM_PrimaryAndShadow_Octree(benchmark::State& state) {
    Scene& s = scene();
    octree::Mailbox mb;
    mb.resize(s.spheres.size());
    uint64_t tests = 0;
    primary_and_shadow(
        state, s,
        [&](const Ray& ray) { return octree_closest(s.tree, s.spheres, ray, mb, tests); },
        [&](const Ray& ray, Real d) { return octree_any_hit(s, ray, d, mb); });
}

// The same rays through trace/'s engine: the leaves' spheres tested 4 or 8 at a time
// with POV-Ray's sphere test (tangent rays miss, 1e-6 tolerance).
void BM_PrimaryAndShadow_Lanes(benchmark::State& state) {
    Scene& s = scene();
    uint64_t tests = 0;
    primary_and_shadow(
        state, s, [&](const Ray& ray) { return s.lanes.closest(ray, tests); },
        [&](const Ray& ray, Real d) { return s.lanes.any_hit(ray, d); });
}

void BM_PrimaryAndShadow_Embree(benchmark::State& state) {
    Scene& s = scene();
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    uint64_t rays = 0, shadowed = 0, shadow_rays = 0;
    size_t i = 0;
    for (auto _ : state) {
        const Ray& ray = s.camera[i];
        i = (i + 1) % s.camera.size();
        ++rays;
        RTCRayHit rh{};
        rh.ray.org_x = float(ray.origin.x);
        rh.ray.org_y = float(ray.origin.y);
        rh.ray.org_z = float(ray.origin.z);
        rh.ray.dir_x = float(ray.direction.x);
        rh.ray.dir_y = float(ray.direction.y);
        rh.ray.dir_z = float(ray.direction.z);
        rh.ray.tnear = 1e-6f;
        rh.ray.tfar = 1e30f;
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(s.embree, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        Point3 p = ray.at(rh.ray.tfar);
        Vector3 to = s.light - p;
        Real d = length(to);
        Vector3 dir = to / d;
        RTCRay sr{};
        sr.org_x = float(p.x);
        sr.org_y = float(p.y);
        sr.org_z = float(p.z);
        sr.dir_x = float(dir.x);
        sr.dir_y = float(dir.y);
        sr.dir_z = float(dir.z);
        sr.tnear = 1e-4f;  // float hit points need a larger offset than the double octree
        sr.tfar = float(d);
        sr.mask = ~0u;
        ++rays;
        ++shadow_rays;
        rtcOccluded1(s.embree, &ctx, &sr);
        shadowed += sr.tfar < 0;
    }
    state.SetItemsProcessed(int64_t(rays));
    // Same rays, so both engines must agree on these fractions (a correctness check).
    state.counters["hit_fraction"] = double(shadow_rays) / double(rays - shadow_rays);
    state.counters["shadowed_fraction"] = double(shadowed) / double(shadow_rays);
}

BENCHMARK(BM_PrimaryAndShadow_Octree);
BENCHMARK(BM_PrimaryAndShadow_Lanes);
BENCHMARK(BM_PrimaryAndShadow_Embree);

}  // namespace
}  // namespace povwall::bench

BENCHMARK_MAIN();
