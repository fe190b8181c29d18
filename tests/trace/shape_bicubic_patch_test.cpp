// bicubic_patch: the pieces POV-Ray cuts (counts by steps and flatness), exact crossings
// and interpolated normals, transforms that move the control points.
#include <gtest/gtest.h>

#include "parser/parser.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

Object parse_one_patch(const std::string& text, std::string* messages = nullptr) {
    std::ostringstream out;
    parser::ParseOptions o;
    o.messages = &out;
    Scene s = parser::parse_scene_text(text, "test.pov", o);
    if (messages) *messages = out.str();
    EXPECT_EQ(s.objects.size(), 1u);
    return s.objects.empty() ? Object{} : s.objects[0];
}

// A flat patch in y = 0 over [0, 3] x [0, 3], then `extra` (steps, transforms).
std::string flat(const std::string& keywords, const std::string& extra = "") {
    return "bicubic_patch { " + keywords +
           " <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,0,1>, <1,0,1>, <2,0,1>, <3,0,1>,"
           " <0,0,2>, <1,0,2>, <2,0,2>, <3,0,2>, <0,0,3>, <1,0,3>, <2,0,3>, <3,0,3> " +
           extra + " }";
}

TEST(BicubicPatch, StepsAndFlatnessDecideThePieces) {
    const Object full = parse_one_patch(flat("type 1 flatness 0 u_steps 2 v_steps 3"));
    const BicubicPatchData& d = *std::get<BicubicPatch>(full.shape).data;
    EXPECT_EQ(d.leaves.size(), 4u * 8u);  // 2 levels in u, 3 in v
    // A flat patch is flatter than any positive flatness: one piece.
    const Object flat_enough =
        parse_one_patch(flat("type 1 flatness 0.01 u_steps 4 v_steps 4"));
    EXPECT_EQ(std::get<BicubicPatch>(flat_enough.shape).data->leaves.size(), 1u);
}

TEST(BicubicPatch, CrossingsAndNormalsOfAFlatPatch) {
    const Object o = parse_one_patch(flat("type 0 flatness 0 u_steps 1 v_steps 1"));
    ShapeHits hits;
    leaf_hits(o, leaf_ray(o, Ray{{1.3, 2, 0.7}, {0, -1, 0}}), hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_DOUBLE_EQ(hits[0].t, 2);
    // dP/du x dP/dv: u runs along z (the rows), v along x: z x x = +y.
    const Vector3 n = leaf_normal(o, hits[0]);
    EXPECT_DOUBLE_EQ(n.y, 1);
    EXPECT_FALSE(leaf_inside(o, {1, -1, 1}));
    // Outside the patch, nothing.
    hits.clear();
    leaf_hits(o, leaf_ray(o, Ray{{3.5, 2, 1}, {0, -1, 0}}), hits);
    EXPECT_TRUE(hits.empty());
}

TEST(BicubicPatch, TransformsMoveTheControlPoints) {
    const Object o = parse_one_patch(
        flat("type 1 flatness 0 u_steps 1 v_steps 1", "scale 2 translate <0, 1, 0>"));
    EXPECT_TRUE(o.transform.is_identity());
    const BicubicPatchData& d = *std::get<BicubicPatch>(o.shape).data;
    EXPECT_EQ(d.control[15].x, 6);
    EXPECT_EQ(d.control[15].y, 1);
    ShapeHits hits;
    leaf_hits(o, leaf_ray(o, Ray{{5, 4, 4.5}, {0, -1, 0}}), hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_DOUBLE_EQ(hits[0].t, 3);
}

TEST(BicubicPatch, ParserRulesAsPovRay) {
    std::string messages;
    parse_one_patch(flat("type 2 u_steps 1 v_steps 1"), &messages);
    EXPECT_NE(messages.find("warning: Patch type no longer supported. Using type 1."),
              std::string::npos);
    parse_one_patch(flat("type 1", "inverse"), &messages);
    EXPECT_NE(messages.find("warning: Cannot invert a patch object."), std::string::npos);
    parse_one_patch(flat("1 3 2"), &messages);  // the old form: type, u_steps, v_steps
    EXPECT_NE(messages.find("warning: Should use keywords for bicubic parameters."),
              std::string::npos);
    try {
        parse_one_patch(flat("flatness 0.1"));
        ADD_FAILURE() << "no error";
    } catch (const parser::ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("error: Undefined bicubic patch type."),
                  std::string::npos);
    }
    // clipped_by is kept: POV-Ray shrinks the patch's box by it and never tests it (the
    // golden bicubic_patch_clipped shows both).
    const Object clipped =
        parse_one_patch(flat("type 1", "clipped_by { plane { y, 0 } }"));
    EXPECT_EQ(clipped.clipped_by->size(), 1u);
}

}  // namespace
}  // namespace povwall::trace
