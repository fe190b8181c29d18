// The bounds of CSG made of planes (trace/convex_region.h): a prism of planes is finite,
// so it goes into the octree and rays far from it never test it. A twisted column of
// 2,000 such slices (codavex/povray lib/fountain) had every ray test every slice.
#include "trace/convex_region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "parser/parser.h"
#include "trace/prepared_scene.h"

namespace povwall::trace {
namespace {

constexpr Real kPi = 3.14159265358979323846;

// The six sides of a hexagon 1 from its axis (y), faces at 0, 60, ... degrees.
std::vector<HalfSpace> hexagon_sides() {
    std::vector<HalfSpace> sides;
    for (int k = 0; k < 6; ++k) {
        const Real a = k * kPi / 3;
        sides.push_back({{std::cos(a), 0, std::sin(a)}, 1});
    }
    return sides;
}

TEST(ConvexRegion, HexagonalPrismOfPlanes) {
    std::vector<HalfSpace> cuts = hexagon_sides();
    cuts.push_back({{0, 1, 0}, 1});
    cuts.push_back({{0, -1, 0}, 0});
    const Bounds3 b = convex_region_bounds(Bounds3::everything(), cuts);
    ASSERT_FALSE(b.infinite());
    // Corners at 1 / cos 30 from the axis, at 30, 90, ... degrees.
    const Real corner = 1 / std::cos(kPi / 6);
    EXPECT_NEAR(b.lo.x, -1, 1e-6);
    EXPECT_NEAR(b.hi.x, 1, 1e-6);
    EXPECT_NEAR(b.lo.z, -corner, 1e-6);
    EXPECT_NEAR(b.hi.z, corner, 1e-6);
    EXPECT_NEAR(b.lo.y, 0, 1e-6);
    EXPECT_NEAR(b.hi.y, 1, 1e-6);
    // Never inside the exact region.
    EXPECT_LE(b.lo.x, -1);
    EXPECT_GE(b.hi.z, corner);
    EXPECT_LE(b.lo.y, 0);
}

TEST(ConvexRegion, OpenWhereNoCutClosesIt) {
    // Without the caps the prism runs along y for ever.
    const Bounds3 b = convex_region_bounds(Bounds3::everything(), hexagon_sides());
    EXPECT_TRUE(std::isinf(b.lo.y) && std::isinf(b.hi.y));
    EXPECT_NEAR(b.hi.x, 1, 1e-6);
    EXPECT_NEAR(b.lo.z, -1 / std::cos(kPi / 6), 1e-6);
    // One half-space alone leaves everything open.
    const HalfSpace one[] = {{{1, 1, 0}, 3}};
    EXPECT_TRUE(convex_region_bounds(Bounds3::everything(), one).infinite());
}

TEST(ConvexRegion, CutsAFiniteBox) {
    const Bounds3 box{{-1, -1, -1}, {1, 1, 1}};
    const HalfSpace cut[] = {{{1, 0, 0}, -0.5}};
    const Bounds3 b = convex_region_bounds(box, cut);
    EXPECT_NEAR(b.hi.x, -0.5, 1e-6);
    EXPECT_EQ(b.lo.x, -1);
    EXPECT_EQ(b.lo.y, -1);
    EXPECT_EQ(b.hi.z, 1);
    // A slanted cut through the corner: x + y <= 0 leaves x up to 1 (at y = -1).
    const HalfSpace slant[] = {{{1, 1, 0}, 0}};
    const Bounds3 s = convex_region_bounds(box, slant);
    EXPECT_EQ(s.hi.x, 1);
    EXPECT_EQ(s.hi.y, 1);
}

TEST(ConvexRegion, UnsureAnswersKeepTheBox) {
    const Bounds3 box{{-1, -1, -1}, {1, 1, 1}};
    // Nothing of the box is left: the box (the caller's bounds) rather than a guess.
    const HalfSpace away[] = {{{1, 0, 0}, -2}};
    const Bounds3 e = convex_region_bounds(box, away);
    EXPECT_EQ(e.lo.x, -1);
    EXPECT_EQ(e.hi.x, 1);
    std::vector<HalfSpace> many(kMaxConvexCuts + 1, HalfSpace{{1, 0, 0}, 0});
    EXPECT_EQ(convex_region_bounds(box, many).hi.x, 1);
}

// The column's slice: POV-Ray's twisted_column.inc Hexagon, a CSG intersection of eight
// planes with a bounded_by.
const char* const kHexagon =
    "#declare Hexagon = intersection {\n"
    "  plane {x, 1} plane {x, 1 rotate <0, 60, 0>} plane {x, 1 rotate <0, 120, 0>}\n"
    "  plane {x, 1 rotate <0, 180, 0>} plane {x, 1 rotate <0, 240, 0>}\n"
    "  plane {x, 1 rotate <0, 300, 0>} plane { y, 1} plane {-y, 0}\n"
    "  bounded_by {sphere{0, 1.5}}\n"
    "}\n";

TEST(ConvexRegion, IntersectionOfPlanesHasFiniteWorldBounds) {
    parser::ParseOptions po;
    const Scene scene = parser::parse_scene_text(
        std::string(kHexagon) +
            "object { Hexagon scale <0.2, 0.01, 0.2> rotate y * 17 translate <1, 2, 3> "
            "}\n"
            // An inverted plane in a difference closes the other side.
            "difference { plane { y, 1 } plane { y, 0 } }\n",
        "hexagon.pov", po);
    ASSERT_EQ(scene.objects.size(), 2u);
    const Bounds3 b = object_world_bounds(scene.objects[0]);
    ASSERT_FALSE(b.infinite());
    const Real corner = 0.2 / std::cos(kPi / 6);
    EXPECT_LE(b.lo.y, 2);
    EXPECT_GE(b.hi.y, 2.01);
    EXPECT_NEAR(b.lo.y, 2, 1e-6);
    EXPECT_NEAR(b.hi.y, 2.01, 1e-6);
    // Every corner of the slice, turned and moved as the object is, lies inside.
    const Real turn = 17 * kPi / 180;
    for (int k = 0; k < 6; ++k) {
        const Real a = (30 + 60 * k) * kPi / 180;
        // POV-Ray's rotate y: x' = x cos + z sin, z' = -x sin + z cos.
        const Real x = corner * std::cos(a), z = corner * std::sin(a);
        const Real wx = 1 + x * std::cos(turn) + z * std::sin(turn),
                   wz = 3 - x * std::sin(turn) + z * std::cos(turn);
        EXPECT_LE(b.lo.x, wx);
        EXPECT_GE(b.hi.x, wx);
        EXPECT_LE(b.lo.z, wz);
        EXPECT_GE(b.hi.z, wz);
    }
    EXPECT_GT(b.lo.x, 1 - corner - 1e-6);
    EXPECT_LT(b.hi.x, 1 + corner + 1e-6);
    EXPECT_GT(b.lo.z, 3 - corner - 1e-6);
    EXPECT_LT(b.hi.z, 3 + corner + 1e-6);
    // A slab between two planes: finite in y, open across.
    const Bounds3 slab = object_world_bounds(scene.objects[1]);
    EXPECT_NEAR(slab.lo.y, 0, 1e-6);
    EXPECT_NEAR(slab.hi.y, 1, 1e-6);
    EXPECT_TRUE(std::isinf(slab.lo.x) && std::isinf(slab.hi.z));
}

// How many objects a ray tests among 400 stacked slices: before the slices had finite
// bounds, every ray tested all of them. (An octree cannot cut a stack of wide slices as
// finely as a ray through it would like: each split copies them into four children, and
// its reference budget stops the splits at about a hundred slices a leaf here.)
TEST(ConvexRegion, RaysTestOnlyTheSlicesNearThem) {
    parser::ParseOptions po;
    const Scene scene = parser::parse_scene_text(
        std::string(kHexagon) +
            "#declare I = 0;\n"
            "#while (I < 400)\n"
            "  object { Hexagon scale <0.2, 0.0025, 0.2> rotate y * I * 0.45\n"
            "           translate y * I * 0.0025 }\n"
            "  #declare I = I + 1;\n"
            "#end\n",
        "column.pov", po);
    ASSERT_EQ(scene.objects.size(), 400u);
    PreparedScene prepared(scene);
    RayContext ctx;
    prepared.init_context(ctx);
    Hit hit;
    // Beside the column: nothing to test.
    EXPECT_FALSE(prepared.closest_hit(Ray{{3, 0.5, -5}, {0, 0, 1}}, 0, kInfinity,
                                      RayUse::Camera, hit, ctx));
    EXPECT_EQ(ctx.tests, 0u);
    // Into the column's side, level: the slices at that height.
    ctx.tests = 0;
    ASSERT_TRUE(prepared.closest_hit(Ray{{0, 0.50125, -5}, {0, 0, 1}}, 0, kInfinity,
                                     RayUse::Camera, hit, ctx));
    EXPECT_NEAR(hit.t, 5 - 0.2 / std::cos(kPi / 6), 0.05);
    EXPECT_LT(ctx.tests, 200u);
    // Down the column's axis from above: the top slice's cap.
    ctx.tests = 0;
    ASSERT_TRUE(prepared.closest_hit(Ray{{0, 3, 0}, {0, -1, 0}}, 0, kInfinity,
                                     RayUse::Camera, hit, ctx));
    EXPECT_NEAR(hit.t, 2, 1e-6);
    EXPECT_LT(ctx.tests, 200u);
}

}  // namespace
}  // namespace povwall::trace
