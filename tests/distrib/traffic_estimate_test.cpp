// The pilot's ray segments and the wall crossings they predict, which --boxes auto over
// several workers minimises.
#include "distrib/traffic_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "distrib/distribution_plan.h"
#include "parser/parser.h"
#include "trace/prepared_scene.h"

namespace povwall::distrib {
namespace {

Scene parse(const std::string& text) {
    return parser::parse_scene_text(text, "test.pov", parser::ParseOptions{});
}

TEST(TrafficEstimate, EveryGridOfEightBoxes) {
    const std::vector<std::array<int, 3>> expected{
        {1, 1, 8}, {1, 2, 4}, {1, 4, 2}, {1, 8, 1}, {2, 1, 4},
        {2, 2, 2}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}, {8, 1, 1}};
    EXPECT_EQ(box_grids(8), expected);
    EXPECT_EQ(box_grids(1), (std::vector<std::array<int, 3>>{{1, 1, 1}}));
    EXPECT_EQ(box_grids(7).size(), 3u);  // 1x1x7, 1x7x1, 7x1x1
}

// Two spheres either side of a wall at x = 0. A crossing is a box met after the first
// one: only where the segment can meet what the next box holds.
TEST(TrafficEstimate, CrossingsCountOnlyBoxesWhoseObjectsTheSegmentCanMeet) {
    const Scene scene = parse("sphere { <-2, 0, 0>, 0.5 } sphere { <2, 0, 0>, 0.5 }");
    const std::vector<ObjectExtent> extents = object_extents(scene);
    const VirtualWalls two({std::vector<Real>{0}, {}, {}});
    const std::vector<PilotSegment> across{{{-2, 0, 0}, {2, 0, 0}, false}};
    const std::vector<PilotSegment> up_and_over{{{-2, 0, 0}, {2, 5, 0}, false}};
    const std::vector<PilotSegment> above{{{-1, 3, 0}, {1, 3, 0}, true}};
    EXPECT_EQ(estimated_crossings(across, two, extents), 1u);
    // Past the wall (x >= 0) it runs at y >= 2.5, above the right sphere's bounds.
    EXPECT_EQ(estimated_crossings(up_and_over, two, extents), 0u);
    EXPECT_EQ(estimated_crossings(above, two, extents), 0u);
    const VirtualWalls one({std::vector<Real>{}, {}, {}});
    EXPECT_EQ(estimated_crossings(across, one, extents), 0u);
    // Three boxes: the middle one (x in [-1, 1]) holds nothing and costs nothing.
    const VirtualWalls three({std::vector<Real>{-1, 1}, {}, {}});
    EXPECT_EQ(estimated_crossings(across, three, extents), 1u);
}

// 16 camera rays on a 4 x 4 grid of an 8 x 8 image; those that hit the sphere end on its
// surface and add one shadow segment to the light; nothing reflects, so no bounce.
TEST(TrafficEstimate, PilotTracesCameraRaysAndAShadowRayPerLight) {
    const Scene scene = parse(R"(
camera { location <0, 0, -5> look_at <0, 0, 0> }
light_source { <3, 4, -5> color rgb 1 }
sphere { 0, 1.5 pigment { rgb 1 } }
)");
    const std::vector<PilotSegment> segments = pilot_segments(scene, 8, 8, 16);
    int camera = 0, hits = 0, shadows = 0;
    for (const PilotSegment& s : segments) {
        if (s.camera) {
            ++camera;
            const Real r = length(s.to - Point3{0, 0, 0});
            if (std::fabs(r - 1.5) < 1e-6) ++hits;
            EXPECT_EQ(s.from.z, -5);
        } else {
            ++shadows;
            EXPECT_NEAR(length(s.from - Point3{0, 0, 0}), 1.5, 1e-6);
            EXPECT_EQ(s.to.x, 3);
            EXPECT_EQ(s.to.y, 4);
        }
    }
    EXPECT_EQ(camera, 16);
    EXPECT_GT(hits, 0);
    EXPECT_LT(hits, 16);  // the corners miss the sphere
    EXPECT_EQ(shadows, hits);
}

// The demo scene at 120x120 in space subdivision over 8 local processes.
DistributionRequest demo_request(const char* boxes) {
    DistributionRequest r;
    r.mode = RenderMode::Space;
    r.boxes = boxes;
    r.procs = 8;
    r.width = 120;
    r.height = 120;
    r.pixels = 120 * 120;
    return r;
}

// On the demo scene (spheres over a mirror floor, lights high up in front) cutting along
// y is crossed by every shadow and floor reflection; the planner avoids it and states
// why.
TEST(TrafficEstimate, AutoWallsOverWorkersAvoidTheMostCrossedCuts) {
    const Scene scene =
        parser::parse_scene_file(POVWALL_DEMO_SCENE, parser::ParseOptions{});
    DistributionRequest r = demo_request("auto");
    const DistributionPlan plan = plan_distribution(scene, r);
    ASSERT_FALSE(plan.reasons.empty());
    EXPECT_NE(plan.reasons.back().find("walls cut across the least ray traffic"),
              std::string::npos)
        << plan.reasons.back();
    EXPECT_EQ(plan.space.boxes[0] * plan.space.boxes[1] * plan.space.boxes[2], 8);
    // Not 2x2x2 here, so the reason gives the equal cuts' count for comparison.
    EXPECT_NE(plan.space.boxes, (std::array<int, 3>{2, 2, 2}));
    EXPECT_NE(plan.reasons.back().find("with equal cuts)"), std::string::npos);
    EXPECT_TRUE(plan.space.balanced);
    // The chosen grid has the fewest estimated crossings of all, and fewer than 1x8x1.
    const std::vector<PilotSegment> segments =
        pilot_segments(scene, 120, 120, kTrafficPilotRays);
    const std::vector<ObjectExtent> extents = object_extents(scene);
    std::vector<Bounds3> finite;
    for (const Object& o : scene.objects) {
        const Bounds3 b = trace::object_world_bounds(o);
        if (!b.infinite()) finite.push_back(b);
    }
    auto crossings = [&](std::array<int, 3> g) {
        return estimated_crossings(
            segments, VirtualWalls::balanced(finite, g[0], g[1], g[2]), extents);
    };
    const uint64_t chosen = crossings(plan.space.boxes);
    for (const auto& g : box_grids(8)) EXPECT_LE(chosen, crossings(g));
    EXPECT_LT(chosen, crossings({1, 8, 1}));
    // No workers: --boxes auto keeps its equal cuts.
    r.procs = 0;
    const DistributionPlan in_process = plan_distribution(scene, r);
    EXPECT_EQ(in_process.space.boxes[0], in_process.space.boxes[1]);
    EXPECT_EQ(in_process.space.boxes[1], in_process.space.boxes[2]);
}

// With the boxes given (4x4x4 over 8 processes on 2 cores) the walls stay; the planner
// chooses which blocks of boxes each process hosts, by the crossings between processes.
// On the demo scene the blocks keep all of y (its cuts carry every shadow ray). 2x2x2
// over 8 has no choice and runs no pilot; processes that each have a core keep the cuts
// across the view.
TEST(TrafficEstimate, GivenBoxesGoToProcessesInBlocksCrossedLeast) {
    const Scene scene =
        parser::parse_scene_file(POVWALL_DEMO_SCENE, parser::ParseOptions{});
    DistributionRequest r = demo_request("4x4x4");
    r.cores = 2;
    const DistributionPlan plan = plan_distribution(scene, r);
    const std::array<int, 3> grid = plan.space.process_grid;
    EXPECT_EQ(grid[0] * grid[1] * grid[2], 8);
    EXPECT_EQ(grid[1], 1) << plan.reasons.back();
    EXPECT_EQ(plan.space.boxes, (std::array<int, 3>{4, 4, 4}));
    EXPECT_NE(plan.reasons.back().find("processes), cut across the least ray traffic"),
              std::string::npos)
        << plan.reasons.back();
    // The chosen grid's walls between processes are crossed least of all the grids.
    const std::vector<PilotSegment> segments =
        pilot_segments(scene, 120, 120, kTrafficPilotRays);
    const std::vector<ObjectExtent> extents = object_extents(scene);
    Bounds3 world;
    for (const Object& o : scene.objects) {
        const Bounds3 b = trace::object_world_bounds(o);
        if (!b.infinite()) world.extend(b);
    }
    const VirtualWalls boxes = VirtualWalls::uniform(world, 4, 4, 4);
    auto crossings = [&](std::array<int, 3> g) {
        std::array<std::vector<Real>, 3> w;
        for (int a = 0; a < 3; ++a) {
            for (int i = 1; i < g[a]; ++i)
                w[a].push_back(boxes.walls(a)[4 / g[a] * i - 1]);
        }
        return estimated_crossings(segments, VirtualWalls(w), extents);
    };
    for (const auto& g : box_grids(8)) {
        if (g[0] <= 4 && g[1] <= 4 && g[2] <= 4) {
            EXPECT_LE(crossings(grid), crossings(g));
        }
    }
    EXPECT_LT(crossings(grid), crossings({2, 2, 2}));
    // The owners follow the grid: process (x, y, z) of the grid hosts its block.
    const std::vector<int> owner =
        box_owners(plan.space.boxes, 8, scene.camera.direction, grid);
    for (int b = 0; b < 64; ++b) {
        const int x = b % 4, y = b / 4 % 4, z = b / 16;
        EXPECT_EQ(
            owner[size_t(b)],
            ((z * grid[2] / 4) * grid[1] + y * grid[1] / 4) * grid[0] + x * grid[0] / 4);
    }
    // One candidate: no pilot, no grid.
    r.boxes = "2x2x2";
    EXPECT_EQ(plan_distribution(scene, r).space.process_grid,
              (std::array<int, 3>{0, 0, 0}));
    // As many cores as processes, or running workers: no grid.
    r.boxes = "4x4x4";
    r.cores = 8;
    EXPECT_EQ(plan_distribution(scene, r).space.process_grid,
              (std::array<int, 3>{0, 0, 0}));
    r.cores = 2;
    r.procs = 0;
    r.workers = 8;
    EXPECT_EQ(plan_distribution(scene, r).space.process_grid,
              (std::array<int, 3>{0, 0, 0}));
}

// The plan has the coordinator keep 8 local processes on the 2 cores, and says so; not
// with running workers, with a core per process, with more processes than the search
// takes, or when asked not to.
TEST(TrafficEstimate, CrowdedLocalProcessesAreKeptOnCores) {
    const Scene scene =
        parser::parse_scene_file(POVWALL_DEMO_SCENE, parser::ParseOptions{});
    DistributionRequest r = demo_request("2x2x2");
    r.cores = 2;
    const DistributionPlan plan = plan_distribution(scene, r);
    EXPECT_EQ(plan.space.keep_on_cores, 2);
    EXPECT_NE(plan.reasons.back().find("each process is kept on one of the 2 cores"),
              std::string::npos)
        << plan.reasons.back();
    r.keep_on_cores = false;
    EXPECT_EQ(plan_distribution(scene, r).space.keep_on_cores, 0);
    r.keep_on_cores = true;
    r.cores = 8;
    EXPECT_EQ(plan_distribution(scene, r).space.keep_on_cores, 0);
    r.cores = 2;
    r.procs = kMaxProcessesOnCores + 1;
    EXPECT_EQ(plan_distribution(scene, r).space.keep_on_cores, 0);
    r.procs = 0;
    r.workers = 8;
    EXPECT_EQ(plan_distribution(scene, r).space.keep_on_cores, 0);
}

}  // namespace
}  // namespace povwall::distrib
