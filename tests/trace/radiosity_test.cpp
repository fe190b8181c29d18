// Radiosity's parts on their own: the sample direction set (cosine-weighted about +y,
// evenly spread, also in short runs), the derived per-bounce settings (POV-Ray 3.7's),
// the irradiance cache's reuse rule, the pretrace step sizes, and the pretrace's number
// of gathers against POV-Ray's.
#include <gtest/gtest.h>

#include <cmath>

#include "parser/parser.h"
#include "trace/camera_interiors.h"
#include "trace/prepared_scene.h"
#include "trace/radiosity/irradiance_cache.h"
#include "trace/radiosity/pretrace.h"
#include "trace/radiosity/recursion_settings.h"
#include "trace/radiosity/sample_directions.h"
#include "trace/render.h"

namespace {

using namespace povwall;
using namespace povwall::trace::radiosity;

struct Moments {
    double x = 0, y = 0, z = 0, xx = 0, yy = 0, zz = 0;
};

Moments moments(const SampleDirections& d, size_t start, size_t n) {
    Moments m;
    for (size_t i = start; i < start + n; ++i) {
        const Vector3& v = d[i];
        m.x += v.x;
        m.y += v.y;
        m.z += v.z;
        m.xx += v.x * v.x;
        m.yy += v.y * v.y;
        m.zz += v.z * v.z;
    }
    for (double* p : {&m.x, &m.y, &m.z, &m.xx, &m.yy, &m.zz}) *p /= double(n);
    return m;
}

// A cosine-weighted hemisphere about +y: E[y] = 2/3, E[y^2] = 1/2, E[x^2] = E[z^2] =
// 1/4, E[x] = E[z] = 0.
TEST(RadiositySampleDirections, PoolHasTheCosineDistributionsMoments) {
    const SampleDirections d(1600);
    ASSERT_EQ(d.size(), 1600u);
    for (size_t i = 0; i < d.size(); ++i) {
        EXPECT_NEAR(length(d[i]), 1.0, 1e-12);
        EXPECT_GT(d[i].y, 0.0);
    }
    const Moments m = moments(d, 0, 1600);
    EXPECT_NEAR(m.y, 2.0 / 3.0, 0.002);
    EXPECT_NEAR(m.yy, 0.5, 0.002);
    EXPECT_NEAR(m.xx, 0.25, 0.002);
    EXPECT_NEAR(m.zz, 0.25, 0.002);
    EXPECT_NEAR(m.x, 0.0, 0.003);
    EXPECT_NEAR(m.z, 0.0, 0.003);
}

// A gather takes `count` consecutive directions from anywhere in the pool: runs of
// POV-Ray's default count (35) are spread nearly as evenly as the whole (a random set
// of 35 misses E[y] by 0.04 typically, and by 0.1 at worst over 229 runs; these stay
// within 0.035 at worst).
TEST(RadiositySampleDirections, ShortRunsAreEvenlySpread) {
    const SampleDirections d(1600);
    double worst_y = 0, worst_x = 0;
    for (size_t start = 0; start < 1600; start += 7) {
        const Moments m = moments(d, start, 35);
        worst_y = std::max(worst_y, std::fabs(m.y - 2.0 / 3.0));
        worst_x = std::max(worst_x, std::fabs(m.x));
    }
    EXPECT_LT(worst_y, 0.035);
    EXPECT_LT(worst_x, 0.06);
}

TEST(RadiosityRecursionSettings, ArePovRays) {
    RadiositySettings s;  // count 35, nearest_count 5, error_bound 1.8, limit 2
    s.recursion_limit = 4;
    const std::vector<RecursionSettings> r = recursion_settings(s);
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r[0].rays_per_sample, 35);
    EXPECT_EQ(r[1].rays_per_sample, 17);
    EXPECT_EQ(r[2].rays_per_sample, 8);
    EXPECT_EQ(r[3].rays_per_sample, 5);
    EXPECT_EQ(r[0].reuse_count, 5);
    EXPECT_EQ(r[1].reuse_count, 2);
    EXPECT_EQ(r[2].reuse_count, 1);
    EXPECT_EQ(r[0].trace_level, 1);
    EXPECT_EQ(r[1].trace_level, 3);
    EXPECT_EQ(r[2].trace_level, 4);
    EXPECT_DOUBLE_EQ(r[1].weight, 0.25);
    EXPECT_DOUBLE_EQ(r[1].max_error_bound, 3.6);
    EXPECT_DOUBLE_EQ(r[1].overfill_factor, 8);
}

CacheEntry entry_at(const Point3& p, const Vector3& n, float hmd, Rgb c) {
    CacheEntry e;
    e.point = p;
    e.normal = n;
    e.to_nearest = Vector3{0, 1, 0};
    e.illuminance = c;
    e.harmonic_mean = hmd;
    e.nearest = hmd;
    e.quality = 1;
    return e;
}

TEST(RadiosityCache, ReusesNearbyEntriesWithPovRaysWeights) {
    IrradianceCache cache({1.8});
    cache.insert(entry_at({0, 0, 0}, {0, 1, 0}, 1, Rgb(1, 0, 0)));
    cache.insert(entry_at({0.5, 0, 0}, {0, 1, 0}, 1, Rgb(0, 1, 0)));
    cache.insert(entry_at({10, 0, 0}, {0, 1, 0}, 1, Rgb(0, 0, 1)));  // too far
    cache.insert(entry_at({0, 0, 0}, {0, -1, 0}, 1, Rgb(0, 0, 1)));  // facing away
    Reuse r;
    cache.accumulate({0, 0, 0}, {0, 1, 0}, 1.8, 0, false, r);
    // The first: error 0, weight 1; the second: error 0.5 / 1, weight 1 - 0.5 / 1.8.
    EXPECT_NEAR(r.weights, 1 + (1 - 0.5 / 1.8), 1e-6);
    EXPECT_NEAR(r.weighted_sum.r, 1, 1e-6);
    EXPECT_NEAR(r.weighted_sum.g, 1 - 0.5 / 1.8, 1e-6);
    EXPECT_EQ(r.weighted_sum.b, 0);
    // Final top-level lookups weigh with POV-Ray's pseudo-sigmoid: t = 0.5 / 1.8.
    Reuse f;
    cache.accumulate({0, 0, 0}, {0, 1, 0}, 1.8, 0, true, f);
    const double t = 0.5 / 1.8;
    EXPECT_NEAR(f.weights, 1 + (1 - (2 * t) * (2 * t) / 2), 1e-6);
    // Entries of another recursion depth are not seen.
    Reuse d;
    cache.accumulate({0, 0, 0}, {0, 1, 0}, 1.8, 1, false, d);
    EXPECT_EQ(d.weights, 0);
}

// Which entries a lookup sees at all is POV-Ray's octree rule: an entry of depth 1 with
// harmonic mean 1 is filed by radius 1 x 3.6 / 8 = 0.45 (diameter 0.9: side 0.5, whose
// widened box [-0.25, 0.75] does not hold [-0.45, 0.45], so its parent, side 1, around
// [0, 1]); a lookup sees it from (-0.5, 1.5) on each axis only, although the reuse rule
// (error bound 3.6) would take it from 3.6 away.
TEST(RadiosityCache, SeesDeeperEntriesThroughPovRaysOctreeNodes) {
    IrradianceCache cache({1.8, 3.6 / 8});
    CacheEntry e = entry_at({0, 0, 0}, {0, 1, 0}, 1, Rgb(1, 0, 0));
    e.depth = 1;
    cache.insert(e);
    auto weight_at = [&](double x) {
        Reuse r;
        cache.accumulate({x, 0, 0}, {0, 1, 0}, 3.6, 1, false, r);
        return r.weights;
    };
    EXPECT_NEAR(weight_at(1.4), 1 - 1.4 / 3.6, 1e-9);
    EXPECT_NEAR(weight_at(-0.4), 1 - 0.4 / 3.6, 1e-9);
    EXPECT_EQ(weight_at(-0.6), 0);  // within the error bound, outside the node
    EXPECT_EQ(weight_at(1.6), 0);
    // At the top level (address factor 1.8, no overfill) every entry within the error
    // bound is seen: radius 1.8, side 2 (widened box [-1, 3]) is too small, side 4 holds.
    IrradianceCache top({1.8});
    top.insert(entry_at({0, 0, 0}, {0, 1, 0}, 1, Rgb(1, 0, 0)));
    for (double x : {-1.7, 1.7}) {
        Reuse r;
        top.accumulate({x, 0, 0}, {0, 1, 0}, 1.8, 0, false, r);
        EXPECT_NEAR(r.weights, 1 - 1.7 / 1.8, 1e-9) << x;
    }
}

TEST(RadiosityPretrace, StepSizesArePovRays) {
    RadiositySettings s;  // 0.08 .. 0.04
    EXPECT_EQ(pretrace_sizes(s, 160, 120), (std::vector<double>{12.8, 6.4}));
    s.pretrace_end = 0.01;
    EXPECT_EQ(pretrace_sizes(s, 160, 120).size(), 4u);
    s.pretrace_end = 0.001;  // below a pixel: stops at one pixel
    const std::vector<double> sizes = pretrace_sizes(s, 160, 120);
    EXPECT_EQ(sizes.back(), 1.0);
    EXPECT_EQ(sizes.size(), 5u);
}

// POV-Ray's high-reproducibility pretrace: pass p deals the blocks to 2^p chains, so the
// first pass reads every entry it made (one chain), and the chains never outnumber the
// blocks.
TEST(RadiosityPretrace, ChainsDoublePerPass) {
    EXPECT_EQ(pretrace_groups(0, 20), 1u);
    EXPECT_EQ(pretrace_groups(1, 20), 2u);
    EXPECT_EQ(pretrace_groups(3, 20), 8u);
    EXPECT_EQ(pretrace_groups(5, 20), 20u);
    EXPECT_EQ(pretrace_groups(200, 20), 20u);
    EXPECT_EQ(pretrace_groups(0, 0), 1u);
}

// The pretrace's gathers on the golden Cornell box at 160x120 (default radiosity, 20
// render blocks): POV-Ray 3.7.0.10 (+WT1 -A) takes 354 samples in its pretrace (184
// top-level, 170 one bounce down). When a block read only its own entries of the pass,
// every block gathered the bounce samples again (1276 gathers, 1079 of them one bounce
// down); with POV-Ray's chains, 364 for any thread count.
TEST(RadiosityPretrace, GathersAboutAsOftenAsPovRay) {
    const Scene scene = parser::parse_scene_text(R"(#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
camera { location <0, 1, -0.98> look_at <0, 0.9, 0> angle 75 }
light_source { <0, 1.9, -0.3> color rgb 1 }
#declare White = finish { diffuse 0.8 ambient 0.3 };
box { <-1, 0, -1>, <1, 2, 1> inverse pigment { rgb 0.9 } finish { White } }
box { <-1.01, -0.01, -1>, <-0.999, 2.01, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { White } }
box { <0.999, -0.01, -1>, <1.01, 2.01, 1> pigment { rgb <0.1, 0.7, 0.1> } finish { White } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.3>
      pigment { rgb 0.9 } finish { White } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y * -20 translate <0.4, 0, -0.3>
      pigment { rgb 0.9 } finish { White } }
)",
                                                 "cornell.pov", {});
    trace::PreparedScene prepared(scene);
    const trace::CameraInteriors interiors(scene);
    trace::RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    uint64_t one_thread = 0;
    for (int threads : {1, 2}) {
        const auto render = run_pretrace(prepared, interiors, settings, threads);
        ASSERT_TRUE(render);
        EXPECT_EQ(render->passes, 2);
        EXPECT_LT(render->gathers, 400u) << threads;
        EXPECT_GT(render->gathers, 300u) << threads;
        if (threads == 1) one_thread = render->gathers;
        EXPECT_EQ(render->gathers, one_thread);
    }
}

}  // namespace
