// The render plan leaves out what a scene cannot use, and leaving it out changes no
// pixel: every scene is rendered with the plan and with the plan forced on ("everything
// on"), in one process and in black boxes, and the images must be bit-identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "distrib/distribution_plan.h"
#include "distrib/space_render.h"
#include "parser/parser.h"
#include "trace/render.h"
#include "trace/render_plan.h"

namespace povwall::distrib {
namespace {

// Diffuse only: no reflection, no transparency, a spotlight and a point light.
const char* kDiffuse = R"(
camera { location <0, 3, -8> look_at <0, 0.5, 0> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <3, 6, -2> color rgb 0.8 spotlight point_at <1, 0, 0> radius 10 falloff 20 }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.3 } }
#declare I = 0;
#while (I < 40)
  sphere { <mod(I, 8) - 3.5, 0.4, div(I, 8) - 1>, 0.35 pigment { color rgb <0.8, 0.5, 0.2> } }
  #declare I = I + 1;
#end
)";

// Glass, a reflection exponent (non-linear), no_shadow objects.
const char* kGlass = R"(
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> }
light_source { <-3, 7, -5> color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } finish { reflection { 0.3 exponent 0.7 } } }
sphere { <0, 1, 0>, 0.9 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } }
box { <1, 0, -1>, <2, 1, 0> pigment { color rgb <0.2, 0.4, 1> } no_shadow }
)";

// One flat object: nothing can stand between its points and the light.
const char* kLoneDisc = R"(
camera { location <0, 0, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
light_source { <-5, 1, -1> color rgb 0.5 }
disc { 0, <0.2, 0.3, -1>, 1.5 pigment { color rgb <1, 0.6, 0.3> } finish { phong 0.6 }
       normal { bumps 0.8 scale 0.2 } scale <1, 0.7, 1.2> }
)";

// One convex solid: a bumped normal turned toward a light behind its face, or a camera
// inside it, sees that light through the solid itself.
const char* kLoneSphere = R"(
camera { location <0, 0, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { 0, 1 pigment { color rgb <1, 0.6, 0.3> } normal { bumps 1 scale 0.2 } }
)";

// Every object no_shadow: no shadow ray can be blocked.
const char* kNoShadow = R"(
camera { location <0, 2, -6> look_at 0 }
light_source { <2, 5, -3> color rgb 1 }
plane { y, -1 pigment { color rgb 0.8 } no_shadow }
sphere { 0, 1 pigment { color rgb <0.3, 0.6, 1> } no_shadow }
)";

Scene parse_plan_scene(const char* text) {
    return parser::parse_scene_text(text, "plan.pov", {});
}

trace::RenderSettings settings(bool everything_on) {
    trace::RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.threads = 2;
    s.plan_everything_on = everything_on;
    return s;
}

// Forward contributions sum a pixel in another order than parents combining children.
float max_difference(const Image& a, const Image& b) {
    float m = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i)
        m = std::max(m, std::fabs(a.rgba[i] - b.rgba[i]));
    return m;
}

bool identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

TEST(RenderPlan, DiffuseSceneHasNoReflectionRefractionOrParentTable) {
    Scene scene = parse_plan_scene(kDiffuse);
    trace::RenderPlan plan = trace::make_render_plan(scene);
    EXPECT_FALSE(plan.reflection_rays);
    EXPECT_FALSE(plan.transmission_rays);
    EXPECT_FALSE(plan.refraction_rays);
    EXPECT_FALSE(plan.parent_tracking);
    ASSERT_EQ(plan.lights.size(), 2u);
    EXPECT_TRUE(plan.lights[0].shadow_rays);
    EXPECT_EQ(plan.finite_primitives, 40u);
    EXPECT_EQ(plan.infinite_primitives, 1u);

    trace::RenderStats stats;
    trace::render_scene(scene, settings(false), &stats);
    EXPECT_EQ(stats.rays.camera, 64u * 48u);
    EXPECT_EQ(stats.rays.reflected, 0u);
    EXPECT_EQ(stats.rays.refracted, 0u);
    EXPECT_GT(stats.rays.shadow, 0u);

    SpaceOptions o;
    o.boxes = {2, 2, 2};
    SpaceStats space;
    render_space(scene, settings(false), o, &space);
    EXPECT_FALSE(space.parent_tracking);
    for (const BoxStats& b : space.boxes) {
        EXPECT_EQ(b.rays.reflected, 0u);
        EXPECT_EQ(b.rays.refracted, 0u);
        EXPECT_EQ(b.peak_parents, 0u);
        EXPECT_EQ(b.results_received, 0u);
    }
}

TEST(RenderPlan, GlassSceneNeedsEverything) {
    trace::RenderPlan plan = trace::make_render_plan(parse_plan_scene(kGlass));
    EXPECT_TRUE(plan.reflection_rays);
    EXPECT_TRUE(plan.transmission_rays);
    EXPECT_TRUE(plan.refraction_rays);
    EXPECT_TRUE(plan.parent_tracking);  // reflection exponent
    ASSERT_EQ(plan.lights.size(), 1u);
    EXPECT_TRUE(plan.lights[0].shadow_rays);
}

TEST(RenderPlan, UnblockableShadowRaysAreLeftOut) {
    for (const char* text : {kLoneDisc, kNoShadow}) {
        Scene scene = parse_plan_scene(text);
        trace::RenderPlan plan = trace::make_render_plan(scene);
        for (const auto& l : plan.lights) {
            EXPECT_FALSE(l.shadow_rays) << l.reason;
            EXPECT_TRUE(l.unoccluded);
        }
        trace::RenderStats left_out, forced;
        trace::render_scene(scene, settings(false), &left_out);
        trace::render_scene(scene, settings(true), &forced);
        EXPECT_EQ(left_out.rays.shadow, 0u);
        EXPECT_GT(forced.rays.shadow, 0u);
    }
    // A second object that casts shadows brings them back; so does a lone solid.
    std::string two = std::string(kLoneDisc) + "sphere { <1, 2, -1>, 0.3 }\n";
    for (const auto& l : trace::make_render_plan(parse_plan_scene(two.c_str())).lights)
        EXPECT_TRUE(l.shadow_rays);
    for (const auto& l : trace::make_render_plan(parse_plan_scene(kLoneSphere)).lights)
        EXPECT_TRUE(l.shadow_rays);
}

TEST(RenderPlan, ForcedOnPlanChangesNoPixel) {
    for (const char* text : {kDiffuse, kGlass, kLoneDisc, kLoneSphere, kNoShadow}) {
        Scene scene = parse_plan_scene(text);
        // The plan on forces parent tracking: colours combine as the ray tree returns
        // instead of as forward contributions (trace/forward_sum.h), the same sums in
        // another order.
        Image planned = trace::render_scene(scene, settings(false));
        Image forced = trace::render_scene(scene, settings(true));
        EXPECT_LE(max_difference(planned, forced), 1e-6f) << text;
        // In boxes, with the same way of returning colours: bit-identical.
        SpaceOptions o;
        o.boxes = {2, 2, 2};
        o.results = SpaceOptions::Results::Parents;
        Image boxes_planned = render_space(scene, settings(false), o);
        Image boxes_forced = render_space(scene, settings(true), o);
        EXPECT_TRUE(identical(boxes_planned, boxes_forced)) << text;
        EXPECT_TRUE(identical(boxes_forced, forced)) << text;
        // The plan's own choice (forward contributions when linear) in boxes: the
        // one-process image bit for bit.
        o.results = SpaceOptions::Results::Auto;
        EXPECT_TRUE(identical(render_space(scene, settings(false), o), planned)) << text;
    }
}

TEST(RenderPlan, ForcedOnBuildsTheOctreeEvenForFewObjects) {
    Scene scene = parse_plan_scene(kGlass);
    trace::RenderStats planned, forced;
    trace::render_scene(scene, settings(false), &planned);
    trace::render_scene(scene, settings(true), &forced);
    EXPECT_TRUE(planned.octree_flat);
    EXPECT_FALSE(forced.octree_flat);
}

TEST(RenderPlan, ExplainsInPlainWords) {
    Scene scene = parse_plan_scene(kDiffuse);
    auto lines = trace::explain_plan(trace::make_render_plan(scene), scene);
    std::vector<std::string> expected = {
        "no reflective materials: reflection rays off",
        "no transparent materials: transmission and refraction rays off",
        "light 1 (point light): shadow rays",
        "light 2 (spotlight): shadow rays; none outside its 20-degree falloff cone",
        "points a light does not reach (back faces, outside spot cones): no shadow ray",
        "40 bounded primitives: octree",
        "1 unbounded primitives (planes, unbounded CSG): tested by every ray",
        "shading is linear: contributions go straight to the pixel, no parent table",
    };
    EXPECT_EQ(lines, expected);
    Scene lone = parse_plan_scene(kLoneDisc);
    auto lone_lines = trace::explain_plan(trace::make_render_plan(lone), lone);
    EXPECT_EQ(lone_lines[2],
              "light 1 (point light): the only object is flat and cannot shadow itself: "
              "no shadow rays");
    EXPECT_EQ(lone_lines[5], "1 bounded primitives (< 24): no octree, a flat list");
}

TEST(DistributionPlan, FitsInOneProcessOrSplitsSpaceToTheBudget) {
    Scene scene = parse_plan_scene(kDiffuse);
    DistributionRequest request;
    request.worker_memory = size_t(1) << 30;
    DistributionPlan fits = plan_distribution(scene, request);
    EXPECT_EQ(fits.mode, RenderMode::Single);
    EXPECT_GT(fits.scene_bytes, 40u * 100);

    request.worker_memory = fits.scene_bytes / 3;
    DistributionPlan split = plan_distribution(scene, request);
    ASSERT_EQ(split.mode, RenderMode::Space);
    EXPECT_LE(split.largest_box_bytes, request.worker_memory);
    EXPECT_GT(split.space.boxes[0], 1);
    // The boxes really hold no more than the budget once prepared, and the image is the
    // single-process one.
    SpaceStats stats;
    Image boxes = render_space(scene, settings(false), split.space, &stats);
    for (const BoxStats& b : stats.boxes)
        EXPECT_LE(b.resident_bytes, request.worker_memory);
    EXPECT_LE(max_difference(boxes, trace::render_scene(scene, settings(false))), 1e-6f);
}

TEST(DistributionPlan, EstimateIsCloseToThePreparedSize) {
    Scene scene = parse_plan_scene(kDiffuse);
    DistributionRequest request;
    const DistributionPlan plan = plan_distribution(scene, request);
    // The whole scene's memory is the parsed model plus the prepared form.
    EXPECT_GT(plan.scene_bytes,
              plan.prepared_bytes + scene.objects.size() * sizeof(Object));
    size_t estimate = plan.prepared_bytes;
    trace::RenderStats stats;
    trace::render_scene(scene, settings(false), &stats);
    EXPECT_GT(double(estimate), 0.7 * double(stats.resident_bytes));
    EXPECT_LT(double(estimate), 1.3 * double(stats.resident_bytes));
}

// Workers get compact blocks of boxes, cut across the view first.
TEST(DistributionPlan, BoxOwnersAreCompactBlocksCutAcrossTheView) {
    // 4x4x4 over 8: each worker a 2x2x2 block.
    const std::vector<int> owner = box_owners({4, 4, 4}, 8, {0.1, 0.2, 1});
    ASSERT_EQ(owner.size(), 64u);
    for (int w = 0; w < 8; ++w) {
        int lo[3] = {4, 4, 4}, hi[3] = {-1, -1, -1}, count = 0;
        for (int b = 0; b < 64; ++b) {
            if (owner[size_t(b)] != w) continue;
            const int cell[3] = {b % 4, b / 4 % 4, b / 16};
            for (int a = 0; a < 3; ++a)
                lo[a] = std::min(lo[a], cell[a]), hi[a] = std::max(hi[a], cell[a]);
            ++count;
        }
        EXPECT_EQ(count, 8) << "worker " << w;
        for (int a = 0; a < 3; ++a) EXPECT_EQ(hi[a] - lo[a], 1) << "worker " << w;
    }
    // 2x2x2 over 2, camera along z: cut at the x wall (x is more across the view than
    // y here), so each worker has front and back boxes.
    EXPECT_EQ(box_owners({2, 2, 2}, 2, {0.1, 0.3, 1}),
              (std::vector<int>{0, 1, 0, 1, 0, 1, 0, 1}));
    // Camera along x: the cut is at the y wall.
    EXPECT_EQ(box_owners({2, 2, 2}, 2, {1, 0.1, 0.3}),
              (std::vector<int>{0, 0, 1, 1, 0, 0, 1, 1}));
    // Uneven shares and more workers than boxes.
    EXPECT_EQ(box_owners({3, 1, 1}, 3, {0, 0, 1}), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(box_owners({5, 1, 1}, 2, {0, 0, 1}), (std::vector<int>{0, 0, 0, 1, 1}));
    EXPECT_EQ(box_owners({2, 1, 1}, 4, {0, 0, 1}), (std::vector<int>{0, 2}));
    // A grid of processes: its blocks, numbered x first.
    EXPECT_EQ(box_owners({4, 1, 2}, 4, {0, 0, 1}, {2, 1, 2}),
              (std::vector<int>{0, 0, 1, 1, 2, 2, 3, 3}));
    EXPECT_EQ(box_owners({3, 1, 1}, 2, {0, 0, 1}, {2, 1, 1}),
              (std::vector<int>{0, 0, 1}));
    // A grid that does not fit (too many processes on an axis, or another count): the
    // cuts above.
    EXPECT_EQ(box_owners({2, 2, 2}, 2, {0.1, 0.3, 1}, {1, 1, 3}),
              box_owners({2, 2, 2}, 2, {0.1, 0.3, 1}));
    EXPECT_EQ(box_owners({2, 2, 2}, 2, {0.1, 0.3, 1}, {4, 1, 1}),
              box_owners({2, 2, 2}, 2, {0.1, 0.3, 1}));
}

TEST(DistributionPlan, ParsesMemorySizesAndBoxes) {
    EXPECT_EQ(parse_memory_size("512M"), size_t(512) << 20);
    EXPECT_EQ(parse_memory_size("2G"), size_t(2) << 30);
    EXPECT_EQ(parse_memory_size("1.5G"), size_t(3) << 29);
    EXPECT_EQ(parse_memory_size("64KB"), size_t(64) << 10);
    EXPECT_EQ(parse_memory_size("1000"), 1000u);
    for (const char* bad : {"", "0", "-5M", "12Q", "abc", "5MX"}) {
        EXPECT_THROW(parse_memory_size(bad), DistributionError) << bad;
    }
    EXPECT_EQ(parse_boxes("3x1x5").boxes, (std::array<int, 3>{3, 1, 5}));
    EXPECT_FALSE(parse_boxes("3x1x5").balanced);
    EXPECT_TRUE(parse_boxes("4").balanced);
    try {
        parse_boxes("4x4");
        FAIL();
    } catch (const DistributionError& e) {
        EXPECT_STREQ(e.what(), "bad --boxes value '4x4' (expected NxNxN, N or auto)");
    }
}

// Processes on cores: the work balanced first, then the fewest crossings between the
// cores; none where the processes do not outnumber the cores.
TEST(DistributionPlan, CoreGroupsBalanceTheWorkThenCutTheLeastTraffic) {
    // Two heavy processes (0, 1) and two light ones; 0 trades with 2, 1 with 3.
    std::vector<double> work = {100, 100, 10, 10};
    std::vector<std::vector<uint64_t>> crossings = {
        {0, 1, 50, 0}, {1, 0, 0, 50}, {50, 0, 0, 1}, {0, 50, 1, 0}};
    std::vector<int> g = core_groups(work, crossings, 2);
    ASSERT_EQ(g.size(), 4u);
    EXPECT_NE(g[0], g[1]);  // the heavy ones apart
    EXPECT_EQ(g[0], g[2]);  // each with its partner
    EXPECT_EQ(g[1], g[3]);
    // The partners heavy together would leave one core idle: balance comes first.
    crossings = {{0, 50, 1, 1}, {50, 0, 1, 1}, {1, 1, 0, 50}, {1, 1, 50, 0}};
    g = core_groups(work, crossings, 2);
    EXPECT_NE(g[0], g[1]);
    // Uneven work: three light processes share a core against one heavy one.
    g = core_groups({90, 30, 30, 30}, crossings, 2);
    EXPECT_EQ(g[1], g[2]);
    EXPECT_EQ(g[2], g[3]);
    EXPECT_NE(g[0], g[1]);
    // Four cores and eight processes: two per core, partners together.
    std::vector<std::vector<uint64_t>> pairs(8, std::vector<uint64_t>(8, 1));
    for (int p = 0; p < 8; p += 2) pairs[size_t(p)][size_t(p + 1)] = 40;
    g = core_groups(std::vector<double>(8, 10), pairs, 4);
    ASSERT_EQ(g.size(), 8u);
    std::vector<int> per_core(4, 0);
    for (int p = 0; p < 8; ++p) {
        ASSERT_GE(g[size_t(p)], 0);
        ASSERT_LT(g[size_t(p)], 4);
        ++per_core[size_t(g[size_t(p)])];
    }
    EXPECT_EQ(per_core, (std::vector<int>{2, 2, 2, 2}));
    for (int p = 0; p < 8; p += 2) EXPECT_EQ(g[size_t(p)], g[size_t(p + 1)]) << p;
    // No more processes than cores, one core, a crossings table of another size, or too
    // many processes to search: none.
    EXPECT_TRUE(core_groups(work, crossings, 4).empty());
    EXPECT_TRUE(core_groups(work, crossings, 1).empty());
    EXPECT_TRUE(core_groups(std::vector<double>(5, 1), crossings, 2).empty());
    const size_t many = size_t(kMaxProcessesOnCores + 1);
    EXPECT_TRUE(
        core_groups(
            std::vector<double>(many, 1),
            std::vector<std::vector<uint64_t>>(many, std::vector<uint64_t>(many, 0)), 2)
            .empty());
}

// --teams auto: the most teams of 2 or more workers whose largest worker fits the budget.
TEST(DistributionPlan, TeamsAutoTakesTheMostTeamsWhoseWorkersFit) {
    Scene scene = parse_plan_scene(R"(
camera { location <0, 2, -30> look_at <0, 0, 0> }
light_source { <0, 30, -30> color rgb 1 }
#declare I = 0;
#while (I < 4000)
  sphere { <-20 + mod(I, 400) * 0.1, int(I / 400) * 0.5, 0>, 0.05 pigment { rgb 1 } }
  #declare I = I + 1;
#end
)");
    DistributionRequest request;
    request.boxes = "8x1x1";
    request.workers = 8;  // running workers: no core placement, no machine total
    request.worker_memory = size_t(1) << 34;
    auto planned = [&](int teams, size_t memory) {
        request.teams = teams;
        request.worker_memory = memory;
        return plan_distribution(scene, request);
    };
    const DistributionPlan four = planned(4, size_t(1) << 34);
    const DistributionPlan two = planned(2, size_t(1) << 34);
    const DistributionPlan one = planned(1, size_t(1) << 34);
    EXPECT_EQ(four.space.teams, 4);
    EXPECT_EQ(one.space.teams, 1);
    // A worker of a team of 2 holds half the spheres, of 4 a quarter, of 8 an eighth.
    ASSERT_GT(four.largest_worker_bytes, two.largest_worker_bytes);
    ASSERT_GT(two.largest_worker_bytes, one.largest_worker_bytes);

    EXPECT_EQ(planned(0, size_t(1) << 34).space.teams, 4);
    EXPECT_EQ(planned(0, four.largest_worker_bytes).space.teams, 4);
    EXPECT_EQ(planned(0, four.largest_worker_bytes - 1).space.teams, 2);
    EXPECT_EQ(planned(0, two.largest_worker_bytes - 1).space.teams, 1);
    const DistributionPlan tight = planned(0, one.largest_worker_bytes - 1);
    EXPECT_EQ(tight.space.teams, 1);  // none fits: one team, said over budget
    ASSERT_FALSE(tight.reasons.empty());
    EXPECT_NE(tight.reasons.back().find("over budget"), std::string::npos)
        << tight.reasons.back();
    const DistributionPlan chosen = planned(0, two.largest_worker_bytes);
    EXPECT_EQ(chosen.space.teams, 2);
    EXPECT_NE(
        chosen.reasons.back().find("over 8 running worker processes in 2 teams of 4 "
                                   "(each team hosts every box)"),
        std::string::npos)
        << chosen.reasons.back();

    // Fewer workers than two teams of 2, or none: one team.
    request.workers = 3;
    EXPECT_EQ(planned(0, size_t(1) << 34).space.teams, 1);
    request.workers = 0;
    request.procs = 0;
    EXPECT_EQ(planned(0, size_t(1) << 34).space.teams, 1);
    // A count that does not divide the workers, or no workers to make teams of.
    request.workers = 8;
    EXPECT_THROW(planned(3, size_t(1) << 34), DistributionError);
    request.workers = 0;
    EXPECT_THROW(planned(2, size_t(1) << 34), DistributionError);
}

}  // namespace
}  // namespace povwall::distrib
