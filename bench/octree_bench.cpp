// Closest-hit throughput of the octree against brute force and a naive uniform grid on
// random sphere scenes at the seed scene's density, build times, and the flat-list
// crossover. Rays are half camera rays, half secondary rays from inside the scene.
// Run: build/bench/povwall_bench --benchmark_repetitions=5
// --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include "bench/scene.h"
#include "octree/overlap.h"

namespace povwall::bench {
namespace {

constexpr size_t kRays = 4096;

struct Fixture {
    Spheres spheres;
    Real half = 0;
    std::vector<Ray> rays;
    octree::Octree tree, loose;  // exact overlap / bounds overlap only
    UniformGrid grid;
    bool has_loose = false, has_grid = false;
};

// POVWALL_BENCH_LEAF / POVWALL_BENCH_TRAV / POVWALL_BENCH_TOP override the build options
// (tuning runs).
octree::BuildOptions options() {
    octree::BuildOptions opt;
    if (const char* v = std::getenv("POVWALL_BENCH_LEAF"))
        opt.leaf_primitives = std::atoi(v);
    if (const char* v = std::getenv("POVWALL_BENCH_TRAV"))
        opt.traversal_cost = std::atof(v);
    if (const char* v = std::getenv("POVWALL_BENCH_TOP"))
        opt.dense_top_max = std::atoi(v);
    return opt;
}

octree::BuildInput input_for(const Spheres& s, bool exact) {
    octree::BuildInput in;
    in.bounds.reserve(s.size());
    for (size_t i = 0; i < s.size(); ++i) in.bounds.push_back(s.bounds(i));
    if (exact) {
        in.overlaps = [&s](uint32_t id, const Bounds3& cell) {
            return octree::sphere_overlaps({s[id].x, s[id].y, s[id].z}, s[id].r, cell);
        };
    }
    return in;
}

// Scenes are built once per size and shared by every engine.
Fixture& fixture(size_t n) {
    static std::map<size_t, std::unique_ptr<Fixture>> cache;
    auto& f = cache[n];
    if (!f) {
        f = std::make_unique<Fixture>();
        f->half = make_spheres(n, 1997, f->spheres);
        f->rays = make_rays(kRays, f->half, 42);
        f->tree.build(input_for(f->spheres, true), options());
        // The octree must agree with brute force before it is timed.
        octree::Mailbox mb;
        mb.resize(n);
        uint64_t tests = 0;
        for (size_t i = 0; i < 256; ++i) {
            Real a = octree_closest(f->tree, f->spheres, f->rays[i], mb, tests);
            Real b = brute_closest(f->spheres, f->rays[i], tests);
            if (a != b) {
                std::fprintf(stderr, "octree/brute mismatch, n=%zu ray %zu\n", n, i);
                std::abort();
            }
        }
    }
    return *f;
}

template <class Closest>
void run_rays(benchmark::State& state, const Fixture& f, Closest closest) {
    uint64_t tests = 0, rays = 0, hits = 0;
    size_t i = 0;
    for (auto _ : state) {
        const Ray& ray = f.rays[i];
        i = (i + 1) % f.rays.size();
        Real t = closest(ray, tests);
        hits += t < kInfinity;
        ++rays;
        benchmark::DoNotOptimize(t);
    }
    state.SetItemsProcessed(int64_t(rays));
    state.counters["tests_per_ray"] = double(tests) / double(std::max<uint64_t>(rays, 1));
    state.counters["hit_fraction"] = double(hits) / double(std::max<uint64_t>(rays, 1));
}

void BM_Octree(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    octree::Mailbox mb;
    mb.resize(f.spheres.size());
    run_rays(state, f, [&](const Ray& r, uint64_t& tests) {
        return octree_closest(f.tree, f.spheres, r, mb, tests);
    });
    state.counters["leaves"] = f.tree.stats().leaves;
    state.counters["refs_per_prim"] =
        double(f.tree.stats().references) / double(f.spheres.size());
}

void BM_OctreeBoundsOnly(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    if (!f.has_loose)
        f.loose.build(input_for(f.spheres, false), options()), f.has_loose = true;
    octree::Mailbox mb;
    mb.resize(f.spheres.size());
    run_rays(state, f, [&](const Ray& r, uint64_t& tests) {
        return octree_closest(f.loose, f.spheres, r, mb, tests);
    });
    state.counters["refs_per_prim"] =
        double(f.loose.stats().references) / double(f.spheres.size());
}

void BM_Grid(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    if (!f.has_grid) f.grid.build(f.spheres), f.has_grid = true;
    octree::Mailbox mb;
    mb.resize(f.spheres.size());
    run_rays(state, f, [&](const Ray& r, uint64_t& tests) {
        return f.grid.closest(f.spheres, r, mb, tests);
    });
}

void BM_Brute(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    run_rays(state, f, [&](const Ray& r, uint64_t& tests) {
        return brute_closest(f.spheres, r, tests);
    });
}

// NaN rays must cost no more than ordinary ones (they are rejected up front).
void BM_OctreeNanRays(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    Fixture bad;
    bad.rays = f.rays;
    for (size_t i = 0; i < bad.rays.size(); ++i)
        bad.rays[i].direction[i % 3] = std::nan("");
    octree::Mailbox mb;
    mb.resize(f.spheres.size());
    run_rays(state, bad, [&](const Ray& r, uint64_t& tests) {
        return octree_closest(f.tree, f.spheres, r, mb, tests);
    });
}

void BM_Build(benchmark::State& state) {
    Spheres s;
    make_spheres(size_t(state.range(0)), 1997, s);
    octree::BuildInput in = input_for(s, true);
    octree::BuildOptions opt = options();
    opt.threads = int(state.range(1));
    for (auto _ : state) {
        octree::Octree t;
        t.build(in, opt);
        benchmark::DoNotOptimize(t.stats().nodes);
        state.counters["exact_tests"] = double(t.stats().exact_tests);
        state.counters["exact_rejected"] = double(t.stats().exact_rejected);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Flat list (one leaf) against a tree for small scenes: where flat_threshold should sit.
void BM_Small(benchmark::State& state) {
    const size_t n = size_t(state.range(0));
    Fixture f;
    f.half = make_spheres(n, 7, f.spheres);
    f.rays = make_rays(kRays, f.half, 8);
    octree::BuildOptions opt = options();
    opt.flat_threshold = state.range(1) ? INT_MAX : 0;
    f.tree.build(input_for(f.spheres, true), opt);
    octree::Mailbox mb;
    mb.resize(n);
    run_rays(state, f, [&](const Ray& r, uint64_t& tests) {
        return octree_closest(f.tree, f.spheres, r, mb, tests);
    });
}

// The lane engine over fixture `f`, built once and checked against brute force.
LaneOctree& lane_octree(Fixture& f) {
    static std::map<size_t, std::unique_ptr<LaneOctree>> cache;
    auto& lanes = cache[f.spheres.size()];
    if (!lanes) {
        lanes = std::make_unique<LaneOctree>();
        octree::BuildOptions opt = options();
        if (!std::getenv("POVWALL_BENCH_TRAV")) opt.traversal_cost = 12;
        lanes->build(f.spheres, input_for(f.spheres, true), opt);
        for (size_t i = 0; i < 256; ++i) {
            const Ray& ray = f.rays[i];
            Real want = kInfinity;
            for (const SphereRecord& sp : f.spheres.records) {
                want = std::min(want,
                                trace::sphere_distance(sp.x, sp.y, sp.z, sp.r, ray, 0));
            }
            uint64_t tests = 0;
            if (lanes->closest(ray, tests) != want) {
                std::fprintf(stderr, "lane octree/brute mismatch, ray %zu\n", i);
                std::abort();
            }
        }
    }
    return *lanes;
}

void BM_OctreeLanes(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    LaneOctree& lanes = lane_octree(f);
    run_rays(state, f,
             [&](const Ray& r, uint64_t& tests) { return lanes.closest(r, tests); });
    state.counters["leaves"] = lanes.tree.stats().leaves;
    state.counters["refs_per_prim"] =
        double(lanes.tree.stats().references) / double(f.spheres.size());
}

// The rays a render traces, in the order it traces them: a 256x256 image's camera rays
// scanline by scanline (the pinhole and view of make_rays), and from each hit a shadow
// ray toward a light; with the second argument 2, also the mirror ray, which gets its own
// shadow ray. Argument 1 is issue 6's "primary + shadow rays". BM_OctreeLanes' random
// rays from anywhere in the volume are the worst case for the caches; these are the case
// a render meets, where neighbouring pixels walk the same nodes.
void BM_ImageLanes(benchmark::State& state) {
    Fixture& f = fixture(size_t(state.range(0)));
    const LaneOctree& lanes = lane_octree(f);
    constexpr int kSide = 256;
    const Point3 eye{0, 0, -2.2 * f.half};
    const Point3 light{-2 * f.half, 3 * f.half, -3 * f.half};
    const Real tan_half = std::tan(24 * kPi / 180);
    uint64_t tests = 0, rays = 0, camera_hits = 0, shadowed = 0, shadow_rays = 0;
    // The shadow ray from the hit at distance t along `ray` on sphere `id`; returns the
    // mirror ray from there.
    auto shade = [&](const Ray& ray, Real t, uint32_t id) {
        const Point3 p = ray.at(t);
        const SphereRecord& sp = f.spheres[id];
        const Vector3 n = normalize(p - Point3{sp.x, sp.y, sp.z});
        const Vector3 to = light - p;
        const Real d = length(to);
        ++rays;
        ++shadow_rays;
        shadowed += lanes.any_hit(Ray{p, to / d}, d);
        return Ray{p, ray.direction - 2 * dot(ray.direction, n) * n};
    };
    const bool mirrors = state.range(1) == 2;
    int pixel = 0;
    for (auto _ : state) {
        const int x = pixel % kSide, y = pixel / kSide;
        pixel = (pixel + 1) % (kSide * kSide);
        const Ray camera{eye,
                         normalize(Vector3{(2 * (x + 0.5) / kSide - 1) * tan_half,
                                           (1 - 2 * (y + 0.5) / kSide) * tan_half, 1})};
        ++rays;
        uint32_t id = 0;
        const Real t = lanes.closest(camera, tests, &id);
        if (t == kInfinity) continue;
        ++camera_hits;
        const Ray mirror = shade(camera, t, id);
        if (!mirrors) continue;
        ++rays;
        const Real t2 = lanes.closest(mirror, tests, &id);
        if (t2 != kInfinity) shade(mirror, t2, id);
    }
    state.SetItemsProcessed(int64_t(rays));
    state.counters["rays_per_pixel"] =
        double(rays) / double(std::max<size_t>(state.iterations(), 1));
    state.counters["camera_hit_fraction"] =
        double(camera_hits) / double(std::max<size_t>(state.iterations(), 1));
    state.counters["shadowed_fraction"] =
        double(shadowed) / double(std::max<uint64_t>(shadow_rays, 1));
    state.counters["tests_per_ray"] = double(tests) / double(std::max<uint64_t>(rays, 1));
    state.counters["dense_top"] = lanes.tree.top_level();
    state.counters["depth"] = lanes.tree.stats().depth;
}

BENCHMARK(BM_Octree)->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK(BM_OctreeLanes)->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK(BM_ImageLanes)->ArgsProduct({{1000, 10000, 100000, 1000000}, {1, 2}});
BENCHMARK(BM_OctreeBoundsOnly)->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_Grid)->RangeMultiplier(10)->Range(1000, 1000000);
BENCHMARK(BM_Brute)->RangeMultiplier(10)->Range(1000, 100000);
BENCHMARK(BM_OctreeNanRays)->Arg(10000);
BENCHMARK(BM_Build)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Small)->ArgsProduct({{4, 8, 16, 24, 32, 64}, {0, 1}});

}  // namespace
}  // namespace povwall::bench

BENCHMARK_MAIN();
