// POV-Ray's object order for exact ties (trace/pov_order.h) and the tie probe
// (trace/ties.h).
#include "trace/pov_order.h"

#include <gtest/gtest.h>

#include <string>

#include "parser/parser.h"
#include "trace/ties.h"

namespace povwall::trace {
namespace {

Scene parse(std::string text) {
    parser::ParseOptions po;
    return parser::parse_scene_text(std::move(text), "order.pov", po);
}

TEST(PovOrder, FrameListOpensPlainUnionsAndPlacesLightObjects) {
    const Scene scene = parse(
        "sphere { 0, 1 }\n"                                                   // 0
        "union { sphere { x, 1 } union { box { 0, 1 } sphere { y, 1 } } }\n"  // 1, 2, 3
        "light_source { 0, 1 looks_like { sphere { 0, 0.1 } } }\n"            // 4
        "merge { sphere { 0, 1 } sphere { x, 1 } }\n"                         // 5
        "union { sphere { 0, 1 } sphere { x, 1 } clipped_by { plane { y, 0 } } }\n"  // 6
        "union { sphere { 0, 1 } sphere { x, 1 } split_union off }\n"                // 7
        "light_source { 0, 1 }\n");  // no object
    const PovFrameList list = pov_frame_list(scene);
    ASSERT_EQ(list.objects.size(), 8u);
    EXPECT_EQ(list.first_of_object, (std::vector<uint32_t>{0, 1, 5, 6, 7}));
    EXPECT_EQ(list.of_light, (std::vector<uint32_t>{4, ~0u}));
    EXPECT_TRUE(std::holds_alternative<Box>(list.objects[2]->shape));
    EXPECT_TRUE(list.slab_tree);
    // Below POV-Ray's Bounding_Threshold (3) or with bounding off: no tree.
    EXPECT_FALSE(pov_frame_list(parse("sphere { 0, 1 } sphere { x, 1 }")).slab_tree);
    EXPECT_FALSE(pov_frame_list(scene, kPovBoundingOff).slab_tree);
}

TEST(PovOrder, InfiniteObjectsFirstThenBoxesInTheOrderTheRayEntersThem) {
    // Written: a far box, a near box, a plane.
    const Scene scene = parse(
        "box { <-1, -1, 5>, <1, 1, 6> }\n"
        "box { <-1, -1, 2>, <1, 1, 3> }\n"
        "plane { y, -2 }\n");
    const PovFrameList list = pov_frame_list(scene);
    ASSERT_TRUE(list.slab_tree);
    const PovTestOrder order(list);
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_EQ(order.order(ray), (std::vector<uint32_t>{2, 1, 0}));
    EXPECT_TRUE(order.tests_first(ray, 2, 0));
    EXPECT_TRUE(order.tests_first(ray, 1, 0));
    EXPECT_FALSE(order.tests_first(ray, 0, 1));
    // A box the ray misses is never tested: it comes last.
    const Ray up{{0, 0, 0}, {0, 1, 0}};
    EXPECT_TRUE(order.tests_first(up, 2, 0));
    // Without the tree POV-Ray tests its list in order.
    const PovTestOrder listed(pov_frame_list(scene, kPovBoundingOff));
    EXPECT_TRUE(listed.order(ray).empty());
    EXPECT_TRUE(listed.tests_first(ray, 0, 2));
}

// A worker's parse keeps some objects: the list it records of the whole scene as it
// parses gives the same boxes, places and lights as the whole scene's own list.
TEST(PovOrder, WholeSceneRecordedByAFilteredParseGivesTheWholeList) {
    const std::string text =
        "sphere { 0, 1 }\n"
        "union { sphere { x, 1 } union { box { 0, 1 } sphere { y, 1 } } }\n"
        "light_source { 0, 1 looks_like { sphere { 0, 0.1 } } }\n"
        "merge { sphere { 0, 1 } sphere { x, 1 } }\n"
        "box { -2, 3 }\n"
        "light_source { 0, 1 looks_like { box { -0.1, 0.1 } } }\n"
        "sphere { 7*x, 2 }\n";
    const Scene scene = parse(text);
    const PovFrameList all = pov_frame_list(scene);
    PovWholeScene whole;
    size_t index = 0;
    parser::ParseOptions po;
    po.keep_object = [&](const Object& o) {
        const bool kept = index++ % 2 == 1;  // objects 1 and 3 of 0..4
        whole.add(o, kept);
        return kept;
    };
    const Scene part = parser::parse_scene_text(text, "order.pov", po);
    ASSERT_EQ(part.objects.size(), 2u);
    ASSERT_TRUE(part.objects_filtered());
    const PovFrameList list = pov_frame_list(part, kPovBoundingThreshold, &whole);
    ASSERT_EQ(list.size(), all.size());
    for (size_t f = 0; f < all.size(); ++f) {
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(list.box(f).lo[a], all.box(f).lo[a]);
            EXPECT_EQ(list.box(f).len[a], all.box(f).len[a]);
        }
    }
    EXPECT_EQ(list.first_of_object,
              (std::vector<uint32_t>{all.first_of_object[1], all.first_of_object[3]}));
    EXPECT_EQ(list.of_light, all.of_light);
    EXPECT_EQ(list.slab_tree, all.slab_tree);
    EXPECT_EQ(pov_frame_objects(part, &whole), pov_frame_objects(scene));
    PovBBox a, b;
    ASSERT_TRUE(pov_slab_root(scene, a));
    ASSERT_TRUE(pov_slab_root(part, b, &whole));
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a.lo[k], b.lo[k]);
        EXPECT_EQ(a.len[k], b.len[k]);
    }
    EXPECT_FALSE(pov_slab_root(part, b));  // without the record: unknown
}

// A disc lying in a plane: every pixel on it is a tie the two renderers' rounding
// decides; a pixel on the sky and one on the plane alone are not.
TEST(TieProbe, FindsCoincidentSurfacesOnly) {
    const Scene scene = parse(
        "camera { location <0, 4, -4> look_at 0 angle 40 }\n"
        "light_source { <0, 5, -2> color rgb 1 }\n"
        "plane { y, 0 pigment { rgb 0.8 } }\n"
        "disc { 0, y, 0.5 pigment { rgb <1, 0, 0> } }\n"
        "sphere { <1.2, 0.5, 0>, 0.5 pigment { rgb 1 } }\n");
    RenderSettings settings;
    settings.width = 40;
    settings.height = 30;
    TieProbe probe(scene, settings);
    EXPECT_EQ(probe.pixel(20, 15), TieProbe::Kind::Surface);  // the disc's centre
    EXPECT_EQ(probe.pixel(20, 0), TieProbe::Kind::None);      // the plane, far
    EXPECT_EQ(probe.pixel(3, 27), TieProbe::Kind::None);      // the plane, near
    EXPECT_EQ(probe.pixel(32, 10), TieProbe::Kind::None);     // the sphere
}

}  // namespace
}  // namespace povwall::trace
