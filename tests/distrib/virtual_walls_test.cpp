#include "distrib/virtual_walls.h"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

namespace povwall::distrib {
namespace {

TEST(VirtualWalls, UniformWallsAndInfiniteOuterBoxes) {
    VirtualWalls w = VirtualWalls::uniform({{0, 0, 0}, {4, 2, 1}}, 4, 2, 1);
    EXPECT_EQ(w.box_count(), 8);
    EXPECT_EQ(w.walls(0), (std::vector<Real>{1, 2, 3}));
    EXPECT_EQ(w.walls(1), (std::vector<Real>{1}));
    EXPECT_TRUE(w.walls(2).empty());
    Bounds3 b = w.box_bounds(w.box_index({1, 0, 0}));
    EXPECT_EQ(b.lo.x, 1);
    EXPECT_EQ(b.hi.x, 2);
    EXPECT_EQ(b.lo.y, -kInfinity);
    EXPECT_EQ(b.hi.y, 1);
    // Far outside the scene still belongs to an outer box.
    EXPECT_EQ(w.locate({-100, 50, 7}), w.box_index({0, 1, 0}));
}

TEST(VirtualWalls, PointOnWallBelongsToHighSide) {
    VirtualWalls w = VirtualWalls::uniform({{0, 0, 0}, {2, 2, 2}}, 2, 2, 2);
    EXPECT_EQ(w.locate({1, 1, 1}), w.box_index({1, 1, 1}));
    EXPECT_EQ(w.locate({0.999, 1, 0}), w.box_index({0, 1, 0}));
}

TEST(VirtualWalls, OverlapCountsTouchingBoxes) {
    VirtualWalls w = VirtualWalls::uniform({{0, 0, 0}, {2, 2, 2}}, 2, 2, 2);
    // A sphere centred on the central corner touches all eight boxes.
    EXPECT_EQ(w.boxes_overlapping({{0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}}).size(), 8u);
    // Touching the wall x=1 from below still counts for the box above (shared object).
    EXPECT_EQ(w.boxes_overlapping({{0.2, 0.2, 0.2}, {1.0, 0.4, 0.4}}),
              (std::vector<int>{w.box_index({0, 0, 0}), w.box_index({1, 0, 0})}));
    EXPECT_EQ(w.boxes_overlapping(Bounds3::everything()).size(), 8u);
}

TEST(VirtualWalls, BalancedWallsSplitPrimitiveCountsEvenly) {
    std::vector<Bounds3> prims;
    // 90 primitives crowded near x=0, 10 spread to x=100: a uniform cut would be
    // lopsided.
    for (int i = 0; i < 90; ++i)
        prims.push_back({{i * 0.01, 0, 0}, {i * 0.01 + 0.001, 1, 1}});
    for (int i = 0; i < 10; ++i)
        prims.push_back({{10.0 + i * 10, 0, 0}, {10.0 + i * 10, 1, 1}});
    VirtualWalls w = VirtualWalls::balanced(prims, 2, 1, 1);
    ASSERT_EQ(w.walls(0).size(), 1u);
    int below = 0;
    for (const auto& b : prims) below += w.locate(b.centre()) == w.box_index({0, 0, 0});
    EXPECT_EQ(below, 50);
}

TEST(VirtualWalls, WalkVisitsContiguousSegmentsInOrder) {
    VirtualWalls w = VirtualWalls::uniform({{-1, -1, -1}, {1, 1, 1}}, 3, 4, 5);
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-2, 2);
    for (int n = 0; n < 2000; ++n) {
        Ray ray{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
        if (n % 10 == 0) ray.direction.y = 0;  // along axes and walls
        if (n % 17 == 0) ray.origin.x = w.walls(0)[0];
        Real t = 0;
        int segments = 0;
        w.walk(ray, 0, 10, [&](const VirtualWalls::Segment& s) {
            EXPECT_EQ(s.t_enter, t);
            EXPECT_GE(s.t_exit, s.t_enter);
            if (s.t_exit > s.t_enter) {
                // The middle of the segment lies in the box the walk claims.
                EXPECT_EQ(w.locate(ray.at((s.t_enter + s.t_exit) / 2)), s.box);
            }
            t = s.t_exit;
            ++segments;
            return false;
        });
        EXPECT_EQ(t, 10);
        EXPECT_LE(segments, 3 + 4 + 5);
    }
}

// A walk stopped by its visitor and continued later (as a box does with the walk a ray
// carries in) visits exactly the segments of one uninterrupted walk, with the same
// distances. Many walls on an axis (a binary search) and few (a count) start alike.
TEST(VirtualWalls, ContinuedWalkEqualsOneWalk) {
    std::array<std::vector<Real>, 3> many;
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 20; ++k) many[size_t(a)].push_back(-1 + 0.1 * k);
    for (const VirtualWalls& w :
         {VirtualWalls::uniform({{-1, -1, -1}, {1, 1, 1}}, 3, 4, 5),
          VirtualWalls(many)}) {
        std::mt19937 rng(11);
        std::uniform_real_distribution<Real> u(-2, 2);
        for (int n = 0; n < 1000; ++n) {
            Ray ray{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
            if (n % 7 == 0) ray.direction.z = 0;
            if (n % 13 == 0) ray.origin.y = w.walls(1)[1];  // starting on a wall
            std::vector<VirtualWalls::Segment> whole, pieces;
            w.walk(ray, 0, kInfinity, [&](const VirtualWalls::Segment& s) {
                whole.push_back(s);
                return false;
            });
            VirtualWalls::WalkState at;
            ASSERT_TRUE(w.start_walk(ray, 0, kInfinity, at));
            for (int stops = 0; stops < 100; ++stops) {
                // Take one segment, stop at the next; go on from there.
                bool took = false, stopped = false;
                w.continue_walk(ray, at, kInfinity, [&](const VirtualWalls::Segment& s) {
                    if (took) return stopped = true;
                    pieces.push_back(s);
                    took = true;
                    return false;
                });
                if (!stopped) break;
            }
            ASSERT_EQ(pieces.size(), whole.size()) << n;
            for (size_t i = 0; i < whole.size(); ++i) {
                EXPECT_EQ(pieces[i].box, whole[i].box);
                EXPECT_EQ(pieces[i].t_enter, whole[i].t_enter);
                EXPECT_EQ(pieces[i].t_exit, whole[i].t_exit);
            }
            // The first box is the box of the start point, on a wall the side the ray
            // moves into.
            const Point3 p = ray.at(1e-9);
            EXPECT_EQ(whole.front().box, w.locate(p)) << n;
        }
    }
}

TEST(VirtualWalls, NanRayVisitsNothing) {
    VirtualWalls w = VirtualWalls::uniform({{-1, -1, -1}, {1, 1, 1}}, 2, 2, 2);
    int visits = 0;
    w.walk({{0, 0, 0}, {std::nan(""), 1, 0}}, 0, 10,
           [&](auto) { return ++visits, false; });
    EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace povwall::distrib
