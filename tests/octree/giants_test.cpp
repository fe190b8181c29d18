#include "octree/giants.h"

#include <gtest/gtest.h>

namespace povwall::octree {
namespace {

Bounds3 cube(Point3 centre, Real half) {
    return {centre - Vector3(half), centre + Vector3(half)};
}

TEST(Giants, ASkySphereAroundASmallSceneIsOne) {
    // Twenty unit boxes within 40 units, a sky sphere of radius 1e6 and two cloud shells
    // of radius 5e4: the three shells, not the scene.
    std::vector<Bounds3> b;
    for (int i = 0; i < 20; ++i) b.push_back(cube({Real(2 * i), 0, 0}, 0.5));
    b.insert(b.begin() + 3, cube({0, 0, 0}, 1e6));
    b.push_back(cube({0, 0, 0}, 5e4));
    b.push_back(cube({10, 0, 0}, 5e4 - 1.5e4));
    EXPECT_EQ(giant_primitives(b), (std::vector<uint32_t>{3, 21, 22}));
}

TEST(Giants, NoneWhereSizesGrowGradually) {
    // Each box 8x the one before: none is 64x all the smaller ones together.
    std::vector<Bounds3> b;
    Real half = 1;
    for (int i = 0; i < 8; ++i, half *= 8) b.push_back(cube({0, 0, 0}, half));
    EXPECT_TRUE(giant_primitives(b).empty());
}

TEST(Giants, TheRatioIsStrictAndInfiniteOrEmptyBoxesNeverCount) {
    // Flat boxes along x: diagonals of exactly 1 and 64.
    std::vector<Bounds3> b{{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {64, 0, 0}}};
    EXPECT_TRUE(giant_primitives(b).empty());  // exactly 64 times the diagonal
    b[1].hi.x = 64.001;
    EXPECT_EQ(giant_primitives(b), (std::vector<uint32_t>{1}));
    // An infinite box (a plane) is neither a giant nor part of the others' union, and
    // neither is an empty one.
    b.push_back(Bounds3::everything());
    b.push_back(Bounds3{});
    EXPECT_EQ(giant_primitives(b), (std::vector<uint32_t>{1}));
    // One bounded box alone: nothing to compare with.
    EXPECT_TRUE(giant_primitives(std::vector<Bounds3>{cube({0, 0, 0}, 1e9)}).empty());
}

TEST(Giants, AtMostSixteenEvenWhenMoreDwarfTheRest) {
    std::vector<Bounds3> b{cube({0, 0, 0}, 1)};
    for (int i = 0; i < 20; ++i) b.push_back(cube({0, 0, 0}, 1e6 + i));
    // The 16 largest of the 20 shells; the other four are in "the rest", which the
    // largest 16 do not dwarf: none. With the limit above the count they would be found.
    EXPECT_TRUE(giant_primitives(b).empty());
    b.resize(1 + kMaxGiants);
    const std::vector<uint32_t> g = giant_primitives(b);
    ASSERT_EQ(g.size(), kMaxGiants);
    EXPECT_EQ(g.front(), 1u);
    EXPECT_EQ(g.back(), uint32_t(kMaxGiants));
}

}  // namespace
}  // namespace povwall::octree
