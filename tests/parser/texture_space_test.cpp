// uv_mapping, mesh texture coordinates, material_map, image_pattern and the object
// pattern as parsed: the scene model they build, and the located errors where POV-Ray
// stops or povwall refuses.
#include <gtest/gtest.h>

#include <optional>
#include <sstream>

#include "output/image_io.h"
#include "parser/parser.h"

namespace povwall::parser {
namespace {

Scene parse_in_golden_folder(const std::string& text) {
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.image_reader = output::read_stored_image;
    // A scene in scenes/golden, so that "images/..." is found.
    return parse_scene_text(text,
                            std::string(POVWALL_SOURCE_DIR) + "/scenes/golden/t.pov", o);
}

std::optional<ParseError> parse_error_in_golden_folder(const std::string& text) {
    try {
        parse_in_golden_folder(text);
    } catch (const ParseError& e) {
        return e;
    }
    return std::nullopt;
}

TEST(UvMapping, PigmentTakesTheRestOfTheBlockAsItsEntry) {
    const Scene s = parse_in_golden_folder(
        "sphere { 0, 1 pigment { uv_mapping checker rgb 1 rgb 0 scale 0.5 } "
        "scale 2 }");
    const Pigment& p = s.objects.at(0).texture.at(0).pigment;
    ASSERT_EQ(p.pattern->kind, PatternKind::UvMapping);
    ASSERT_EQ(p.maps->list.size(), 1u);
    const Pigment& inner = p.maps->list[0];
    EXPECT_EQ(inner.pattern->kind, PatternKind::Checker);
    // Its own scale is kept; the object's lands on the outer pattern only.
    EXPECT_NEAR(inner.pattern->transform.get().inverse_point({1, 1, 0}).x, 2.0, 1e-12);
    EXPECT_FALSE(p.pattern->transform.is_identity());
}

TEST(UvMapping, ObjectModifierKeepsTexturesFromTransforms) {
    const Scene s = parse_in_golden_folder(
        "sphere { 0, 1 uv_mapping pigment { checker rgb 1 rgb 0 } scale 3 }");
    const Object& o = s.objects.at(0);
    EXPECT_TRUE(o.uv_mapping);
    EXPECT_TRUE(o.texture.at(0).pigment.pattern->transform.is_identity());
}

TEST(UvMapping, ComesDownToChildrenWithTheTexture) {
    const Scene s = parse_in_golden_folder(
        "union { sphere { 0, 1 } box { 0, 1 pigment { rgb 1 } } uv_mapping "
        "pigment { checker } }");
    const Csg& u = std::get<Csg>(s.objects.at(0).shape);
    EXPECT_TRUE(u.children.at(0).uv_mapping);
    // POV-Ray passes it on with the (empty) interior texture as well.
    EXPECT_TRUE(u.children.at(1).uv_mapping);
}

TEST(UvMapping, AfterATextureIsAnError) {
    const auto e =
        parse_error_in_golden_folder("sphere { 0, 1 pigment { rgb 1 } uv_mapping }");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->kind(), ParseError::Kind::Syntax);
    EXPECT_EQ(e->loc().line, 1);
    EXPECT_EQ(e->loc().column, 33);
}

TEST(UvMapping, InAPigmentFunctionOrADensityIsAnError) {
    auto e = parse_error_in_golden_folder(
        "#declare F = function { pigment { uv_mapping checker } }");
    ASSERT_TRUE(e);
    EXPECT_NE(e->message().find("uv_mapping"), std::string::npos);
    EXPECT_EQ(e->loc().column, 25);
    e = parse_error_in_golden_folder(
        "sphere { 0, 1 hollow interior { media { density { uv_mapping bozo } } } }");
    ASSERT_TRUE(e);
    EXPECT_NE(e->message().find("uv_mapping"), std::string::npos);
}

// POV-Ray moves and scales a box's corners until its first rotate, matrix or transform
// (Box::Translate, Box::Scale, a negative scale swapping them), and orders the corners it
// reads: the box keeps only what comes from the first turn on as its transform, so a
// mirror before the turn is known (a uv_mapped box mirrored and then turned is mapped).
TEST(BoxCorners, MovedAndScaledUntilTheFirstTurn) {
    Scene s = parse_in_golden_folder(
        "box { <0, 1, 2>, <1, 3, 5> scale <-2, 1, 1> translate <1, 0, 0> rotate 30 * y "
        "scale 2 }\n"
        "box { <1, 1, 1>, <0, -1, 0> }\n"
        "box { -1, 1 pigment { uv_mapping checker } scale <-1, 1, 1> rotate 30 * y }\n"
        "union { box { -1, 1 scale <-1, 1, 1> rotate 30 * y } sphere { 0, 1 } "
        "uv_mapping pigment { checker } }");
    ASSERT_EQ(s.objects.size(), 4u);
    const Box& turned = std::get<Box>(s.objects[0].shape);
    EXPECT_EQ(turned.corner1, (Point3{-1, 1, 2}));
    EXPECT_EQ(turned.corner2, (Point3{1, 3, 5}));
    const Transform expected =
        Transform::rotate({0, 30, 0}).then(Transform::scale({2, 2, 2}));
    EXPECT_EQ(s.objects[0].transform.forward().m[0][0], expected.forward().m[0][0]);
    EXPECT_EQ(s.objects[0].transform.forward().m[0][2], expected.forward().m[0][2]);
    EXPECT_EQ(s.objects[0].transform.forward().m[1][1], 2.0);
    const Box& ordered = std::get<Box>(s.objects[1].shape);
    EXPECT_EQ(ordered.corner1, (Point3{0, -1, 0}));
    EXPECT_EQ(ordered.corner2, (Point3{1, 1, 1}));
    EXPECT_TRUE(s.objects[1].transform.is_identity());
    // The mirror went into the corners: only the turn is a transform, with no mirror.
    const Matrix34& m = s.objects[2].transform.forward();
    const Real det = m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
                     m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
                     m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
    EXPECT_GT(det, 0);
}

TEST(MeshUv, Mesh2IndicesAndDefaults) {
    Scene s = parse_in_golden_folder(
        "mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 2, <0, 0>, <1, 0.5> } "
        "face_indices { 1, <0, 1, 2> } uv_indices { 1, <1, 0, 1> } }");
    const MeshData& m = *std::get<Mesh>(s.objects.at(0).shape).data;
    ASSERT_EQ(m.uvs.size(), 2u);
    ASSERT_EQ(m.uv_faces.size(), 1u);
    EXPECT_EQ(m.uv_faces[0][0], 1u);
    EXPECT_EQ(m.uv_faces[0][1], 0u);
    EXPECT_EQ(m.uvs[1][1], 0.5);
    // As many coordinates as vertices: indexed like them.
    s = parse_in_golden_folder(
        "mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 3, 0, 1, 2 } "
        "face_indices { 1, <2, 1, 0> } }");
    EXPECT_EQ(std::get<Mesh>(s.objects.at(0).shape).data->uv_faces.at(0)[0], 2u);
    // Otherwise POV-Ray wants the indices.
    const auto e = parse_error_in_golden_folder(
        "mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 2, 0, 1 } "
        "face_indices { 1, <0, 1, 2> } }");
    ASSERT_TRUE(e);
    EXPECT_NE(e->message().find("uv_indices"), std::string::npos);
}

TEST(MeshUv, TriangleUvVectors) {
    const Scene s = parse_in_golden_folder(
        "mesh { triangle { 0, x, y uv_vectors <0, 0>, <1, 0>, <0, 1> } "
        "triangle { 0, y, z } }");
    const MeshData& m = *std::get<Mesh>(s.objects.at(0).shape).data;
    ASSERT_EQ(m.uv_faces.size(), 2u);
    EXPECT_EQ(m.uvs[m.uv_faces[0][2]][1], 1.0);
    EXPECT_EQ(m.uvs[m.uv_faces[1][2]][1], 0.0);  // none given: (0, 0)
}

TEST(MaterialMap, ImageAndTextures) {
    const Scene s = parse_in_golden_folder(
        "sphere { 0, 1 texture { material_map { png \"images/palette.png\" once "
        "texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } scale 2 } }");
    const Texture& t = s.objects.at(0).texture.at(0);
    ASSERT_TRUE(t.map_pattern);
    EXPECT_EQ(t.map_pattern->kind, PatternKind::MaterialMap);
    ASSERT_TRUE(t.map_pattern->image);
    EXPECT_TRUE(t.map_pattern->image->once);
    EXPECT_EQ(t.map->entries.size(), 2u);
    EXPECT_FALSE(t.map_pattern->transform.is_identity());
}

// Interpolated indices are POV-Ray's (golden material_map_interpolate); any number is
// kept, as POV-Ray's material_map takes any.
TEST(MaterialMap, InterpolationIsKept) {
    Scene s = parse_in_golden_folder(
        "sphere { 0, 1 texture { material_map { png \"images/palette.png\" interpolate 3 "
        "texture { pigment { rgb 1 } } } } }");
    EXPECT_EQ(s.objects.at(0).texture.at(0).map_pattern->image->interpolate, 3);
}

TEST(ImagePattern, UseAlphaReadsTransmitOrRed) {
    Scene s = parse_in_golden_folder(
        "plane { z, 0 pigment { image_pattern { png \"images/card_alpha.png\" use_alpha "
        "} } }");
    EXPECT_EQ(s.objects.at(0).texture.at(0).pigment.pattern->image->image_value, 1);
    s = parse_in_golden_folder(
        "plane { z, 0 pigment { image_pattern { png \"images/card.png\" use_alpha } } }");
    EXPECT_EQ(s.objects.at(0).texture.at(0).pigment.pattern->image->image_value, 2);
}

TEST(ObjectPattern, ObjectTransformsAndEntries) {
    const Scene s = parse_in_golden_folder(
        "#declare O = sphere { 0, 1 }\n"
        "plane { z, 0 pigment { object { O translate x rgb 1, rgb 0 } } }");
    const Pigment& p = s.objects.at(0).texture.at(0).pigment;
    ASSERT_EQ(p.pattern->kind, PatternKind::ObjectInside);
    ASSERT_TRUE(p.pattern->object);
    EXPECT_FALSE(p.pattern->object->transform.is_identity());
    EXPECT_EQ(p.maps->list.size(), 2u);
    const auto e = parse_error_in_golden_folder(
        "plane { z, 0 pigment { object { sphere { 0, 1 } box { 0, 1 } } } }");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->loc().column, 24);
}

}  // namespace
}  // namespace povwall::parser
