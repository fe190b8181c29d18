// What POV-Ray's parser does to an object once it is placed, and keywords it checks: a
// CSG's interior shared by the children without their own, object{} copies apart, the old
// finish { ior refraction caustics } moved into the interior (the last sharer wins),
// hollow passed down, the textures cutaway_textures leaves out, light types and their
// items, finish details.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "parser/parser.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::full_error_of;
using test::parse;

const Object& child(const Object& o, size_t i) {
    return std::get<Csg>(o.shape).children[i];
}

TEST(PostProcess, CsgChildrenShareItsInteriorObjectCopiesDoNot) {
    Scene s = parse(R"(
#declare S = sphere { 0, 1 interior { ior 1.3 } }
union { sphere { 0, 1 } sphere { x, 1 } sphere { y, 1 interior { ior 2 } } interior { ior 1.5 } }
object { S }
object { S }
sphere { 0, 1 }
)");
    const Object& u = s.objects[0];
    EXPECT_EQ(child(u, 0).interior->id, u.interior->id);
    EXPECT_EQ(child(u, 1).interior->id, u.interior->id);
    EXPECT_NE(child(u, 2).interior->id, u.interior->id);
    EXPECT_FLOAT_EQ(child(u, 1).interior->ior, 1.5f);
    EXPECT_FLOAT_EQ(child(u, 2).interior->ior, 2.0f);
    // Each copy of a declared object has its own interior; an object without one gets
    // a new one too.
    EXPECT_NE(s.objects[1].interior->id, s.objects[2].interior->id);
    EXPECT_NE(s.objects[3].interior->id, 0u);
    EXPECT_NE(s.objects[3].interior->id, s.objects[2].interior->id);
}

TEST(PostProcess, InteriorTextureComesDownAndNeedsAnExteriorTexture) {
    Scene s = parse(R"(
#declare M = material { texture { pigment { rgb 1 } } interior_texture { pigment { rgb x } } }
union { sphere { 0, 1 } sphere { x, 1 texture { pigment { rgb y } } }
        texture { pigment { rgb z } } interior_texture { pigment { rgb 0.5 } } }
sphere { 0, 1 material { M } }
)");
    const Object& u = s.objects[0];
    // Each child takes the union's interior texture, with or without its own texture.
    ASSERT_EQ(child(u, 0).interior_texture->size(), 1u);
    ASSERT_EQ(child(u, 1).interior_texture->size(), 1u);
    EXPECT_FLOAT_EQ(child(u, 1).interior_texture->front().pigment.colour.rgb.r, 0.5f);
    EXPECT_FLOAT_EQ(child(u, 1).texture.front().pigment.colour.rgb.g, 1.0f);
    // A declared material carries its interior texture.
    ASSERT_EQ(s.objects[1].interior_texture->size(), 1u);
    EXPECT_FLOAT_EQ(s.objects[1].interior_texture->front().pigment.colour.rgb.g, 0.0f);
    EXPECT_EQ(full_error_of("sphere { 0, 1 interior_texture { pigment { rgb 1 } } }"),
              "test.pov:1:54: error: interior texture requires an exterior texture\n"
              "sphere { 0, 1 interior_texture { pigment { rgb 1 } } }\n"
              "                                                     ^");
}

// cutaway_textures (POV-Ray's Post_Process): the flag comes down to every CSG inside;
// a part without a texture gets no default one when its parent is an intersection or
// difference with the flag, nor does such a CSG with a texture given in a part; a CSG
// without any texture gets the default (which comes down to all), and one with a texture
// gives it to its parts.
TEST(PostProcess, CutawayTexturesLeaveUntexturedPartsBare) {
    Scene s = parse(R"(
difference { sphere { 0, 1 pigment { rgb 1 } } box { 0, 2 } cutaway_textures }
intersection { sphere { 0, 1 } box { 0, 2 } cutaway_textures }
intersection { sphere { 0, 1 pigment { rgb 1 } } union { box { 0, 2 } sphere { x, 1 } }
               difference { box { 0, 2 } sphere { x, 1 } } cutaway_textures }
difference { sphere { 0, 1 } box { 0, 2 } pigment { rgb x } cutaway_textures }
difference { sphere { 0, 1 pigment { rgb 1 } } box { 0, 2 } }
)");
    const Object& cut = s.objects[0];
    EXPECT_TRUE(cut.texture.empty());
    EXPECT_FALSE(child(cut, 0).texture.empty());
    EXPECT_TRUE(child(cut, 1).texture.empty());
    const Object& bare = s.objects[1];
    EXPECT_EQ(bare.texture.size(), 1u);
    EXPECT_EQ(child(bare, 0).texture.size(), 1u);
    EXPECT_EQ(child(bare, 1).texture.size(), 1u);
    const Object& nested = s.objects[2];
    EXPECT_TRUE(child(nested, 1).texture.empty());
    EXPECT_TRUE(std::get<Csg>(child(nested, 1).shape).cutaway_textures);
    // A union's parts get the default texture each.
    EXPECT_EQ(child(child(nested, 1), 0).texture.size(), 1u);
    EXPECT_TRUE(child(nested, 2).texture.empty());
    EXPECT_TRUE(std::get<Csg>(child(nested, 2).shape).cutaway_textures);
    EXPECT_TRUE(child(child(nested, 2), 0).texture.empty());
    EXPECT_TRUE(child(child(nested, 2), 1).texture.empty());
    const Object& textured = s.objects[3];
    EXPECT_EQ(child(textured, 0).texture.size(), 1u);
    EXPECT_EQ(child(textured, 1).texture.size(), 1u);
    EXPECT_FALSE(std::get<Csg>(s.objects[4].shape).cutaway_textures);
    EXPECT_EQ(child(s.objects[4], 1).texture.size(), 1u);
}

TEST(PostProcess, BoundsAndClipsLinkAsPovRays) {
    Scene s = parse(R"(
sphere { 0, 1 bounded_by { box { -1, 0.5 } } clipped_by { bounded_by } translate x }
intersection { sphere { 0, 1 } sphere { x, 1 } clipped_by { plane { y, 0 } }
               bounded_by { clipped_by } }
union { sphere { 0, 1 } sphere { x, 1 } split_union off }
)");
    ASSERT_EQ(s.objects[0].clipped_by->size(), 1u);
    ASSERT_EQ(s.objects[0].bounded_by->size(), 1u);
    // The clip is the bound, moved with the object (a box moves its corners, as
    // POV-Ray's Box::Translate).
    const Box& clip = std::get<Box>(s.objects[0].clipped_by->front().shape);
    EXPECT_EQ(clip.corner1.x, 0.0);
    EXPECT_EQ(clip.corner2.x, 1.5);
    EXPECT_TRUE(s.objects[0].clipped_by->front().transform.is_identity());
    ASSERT_EQ(s.objects[1].bounded_by->size(), 1u);
    EXPECT_TRUE(std::holds_alternative<Plane>(s.objects[1].bounded_by->front().shape));
    EXPECT_FALSE(s.objects[2].split_union);
    EXPECT_FALSE(pov_splits_union(s.objects[2]));
    EXPECT_TRUE(pov_keeps_bound(s.objects[1]));
    EXPECT_FALSE(pov_keeps_bound(s.objects[0]));  // a shape's bound is removed
    EXPECT_NE(full_error_of("sphere { 0, 1 clipped_by { box { -1, 1 } } "
                            "clipped_by { bounded_by } }")
                  .find("error: cannot link bounds with previous clips"),
              std::string::npos);
    EXPECT_NE(full_error_of("sphere { 0, 1 bounded_by { box { -1, 1 } } "
                            "clipped_by { bounded_by } bounded_by { sphere { 0, 1 } } }")
                  .find("error: cannot add bounds after linking bounds and clips"),
              std::string::npos);
    EXPECT_NE(full_error_of("sphere { 0, 1 split_union off }")
                  .find("error: split_union found in non-union object"),
              std::string::npos);
}

TEST(PostProcess, FractalColouringOnMandelOnly) {
    Scene s =
        parse("plane { z, 0 pigment { mandel 30 exterior 6, 0.5 interior 4 0.25 } }");
    const PatternSpec& p = *s.objects[0].texture.front().pigment.pattern;
    EXPECT_EQ(p.fractal.exterior_type, 6);
    EXPECT_EQ(p.fractal.exterior_factor, 0.5);
    EXPECT_EQ(p.fractal.interior_type, 4);
    EXPECT_EQ(p.fractal.interior_factor, 0.25);
    // A new mandel starts from POV-Ray's defaults.
    s = parse(
        "#declare P = pigment { mandel 30 exterior 6, 0.5 }\n"
        "plane { z, 0 pigment { P mandel 20 } }");
    EXPECT_EQ(s.objects[0].texture.front().pigment.pattern->fractal.exterior_type, 1);
    EXPECT_NE(full_error_of("plane { z, 0 pigment { bozo exterior 1, 1 } }")
                  .find("error: Keyword 'exterior' can only be used in a mandel"),
              std::string::npos);
    EXPECT_NE(full_error_of("plane { z, 0 pigment { mandel 9 interior 7, 1 } }")
                  .find("error: invalid fractal pattern interior type (0 to 6)"),
              std::string::npos);
    EXPECT_NE(full_error_of("plane { z, 0 pigment { mandel 9 exterior 9, 1 } }")
                  .find("error: invalid fractal pattern exterior type (0 to 8)"),
              std::string::npos);
}

TEST(PostProcess, OldFinishIorGoesIntoTheSharedInteriorAndTheLastSharerWins) {
    Scene s = parse(R"(
union { sphere { 0, 1 } sphere { x, 1 finish { ior 1.2 refraction 0.5 } } interior { ior 1.5 } }
sphere { 0, 1 finish { caustics 0.4 } interior { caustics 1 refraction 0.3 } }
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
         interior { refraction 0.3 } }
)");
    const Object& u = s.objects[0];
    // The second child's plain texture rewrites the interior it shares with the union
    // and its sibling.
    for (const Object* o : {&u, &child(u, 0), &child(u, 1)}) {
        EXPECT_FLOAT_EQ(o->interior->ior, 1.2f);
        EXPECT_FLOAT_EQ(o->interior->old_refract, 0.5f);
    }
    // finish caustics are moved unscaled (interior caustics are x45); a plain texture's
    // finish refraction (1 when not given) replaces interior { refraction }.
    EXPECT_FLOAT_EQ(s.objects[1].interior->caustics, 0.4f);
    EXPECT_FLOAT_EQ(s.objects[1].interior->old_refract, 1.0f);
    // A patterned texture (of textures) is not plain: the interior keeps its refraction.
    EXPECT_FLOAT_EQ(s.objects[2].interior->old_refract, 0.3f);
    EXPECT_FLOAT_EQ(
        parse("sphere { 0, 1 interior { caustics 0.5 } }").objects[0].interior->caustics,
        22.5f);
}

// POV-Ray's difference is an intersection (CSGIntersection with isDifference): `hollow`
// goes down through it too (golden media_difference_hollow).
TEST(PostProcess, HollowGoesDownToChildrenThatDidNotSayThroughEveryCsg) {
    Scene s = parse(R"(
union { sphere { 0, 1 } sphere { x, 1 hollow off interior { } } union { sphere { y, 1 } }
        hollow }
difference { sphere { 0, 1 } sphere { x, 1 } hollow }
)");
    const Object& u = s.objects[0];
    EXPECT_TRUE(child(u, 0).hollow);
    EXPECT_FALSE(child(u, 1).hollow);
    EXPECT_FALSE(child(u, 2).hollow);  // a nested union passes it on, keeping its own
    EXPECT_TRUE(child(child(u, 2), 0).hollow);
    // The interior holds the flag of the last object placed with it: the union's is
    // shared with the leaves, which are hollow; the second sphere has its own.
    EXPECT_TRUE(child(u, 0).interior->hollow);
    EXPECT_FALSE(child(u, 1).interior->hollow);
    const Object& d = s.objects[1];
    EXPECT_TRUE(child(d, 0).hollow);
    EXPECT_TRUE(child(d, 1).hollow);
    EXPECT_TRUE(child(d, 0).interior->hollow);
}

TEST(Lights, ParallelIsAFlagAndTheTypeResetsItsCone) {
    Scene s = parse(R"(
light_source { <0, 5, 0> rgb 1 parallel point_at 0 }
light_source { <0, 5, 0> rgb 1 parallel spotlight point_at 0 }
light_source { <0, 5, 0> rgb 1 spotlight radius 10 falloff 20 spotlight }
light_source { <0, 5, 0> rgb 1 cylinder point_at 0 }
)");
    EXPECT_EQ(s.lights[0].kind, Light::Kind::Parallel);
    EXPECT_EQ(s.lights[1].kind, Light::Kind::Spot);
    EXPECT_TRUE(s.lights[1].parallel);
    EXPECT_DOUBLE_EQ(s.lights[2].radius, 30);
    EXPECT_DOUBLE_EQ(s.lights[2].falloff, 45);
    EXPECT_EQ(s.lights[3].kind, Light::Kind::Cylinder);
    EXPECT_FALSE(s.lights[3].parallel);
    EXPECT_EQ(
        full_error_of("light_source { 0, 1 radius 10 }"),
        "test.pov:1:21: error: 'radius' cannot be used with a standard light source\n"
        "light_source { 0, 1 radius 10 }\n"
        "                    ^~~~~~");
    EXPECT_EQ(full_error_of("light_source { 0, 1 point_at x }"),
              "test.pov:1:21: error: 'point_at' cannot be used with a standard light "
              "source\n"
              "light_source { 0, 1 point_at x }\n"
              "                    ^~~~~~~~");
}

// One light type, the last written: shadowless after a spotlight makes a shadowless point
// light (then point_at is POV-Ray's error); a spotlight or cylinder after shadowless
// casts shadows; a copied parallel light keeps its flag.
TEST(Lights, ShadowlessIsALightTypeLikeSpotlight) {
    Scene s = parse(R"(
light_source { <0, 5, 0> rgb 1 shadowless spotlight point_at 0 }
light_source { <0, 5, 0> rgb 1 spotlight shadowless }
light_source { <0, 5, 0> rgb 1 shadowless cylinder point_at 0 }
#declare P = light_source { <0, 5, 0> rgb 1 parallel point_at 0 }
light_source { P point_at x }
)");
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(s.lights[0].kind, Light::Kind::Spot);
    EXPECT_FALSE(s.lights[0].shadowless);
    EXPECT_EQ(s.lights[1].kind, Light::Kind::Point);
    EXPECT_TRUE(s.lights[1].shadowless);
    EXPECT_EQ(s.lights[2].kind, Light::Kind::Cylinder);
    EXPECT_FALSE(s.lights[2].shadowless);
    EXPECT_EQ(s.lights[3].kind, Light::Kind::Parallel);
    EXPECT_EQ(s.lights[3].point_at, (Vector3{1, 0, 0}));
    EXPECT_EQ(full_error_of("light_source { 0, 1 spotlight shadowless point_at x }"),
              "test.pov:1:42: error: 'point_at' cannot be used with a standard light "
              "source\n"
              "light_source { 0, 1 spotlight shadowless point_at x }\n"
              "                                         ^~~~~~~~");
}

// area_illumination is an area light's item, before or after area_light; a copy keeps it
// (and the other area items) unless it says otherwise, even with a grid of its own.
TEST(Lights, AreaIlluminationIsAnAreaLightItem) {
    Scene s = parse(R"(
#declare L = light_source { 0, 1 area_light x, y, 3, 3 adaptive 1 jitter area_illumination }
light_source { 0, 1 area_illumination area_light x, y, 2, 2 }
light_source { 0, 1 area_light x, y, 2, 2 area_illumination on area_illumination off }
light_source { L }
light_source { L area_light x, z, 5, 5 }
light_source { L area_illumination off }
)");
    ASSERT_EQ(s.lights.size(), 5u);
    for (const Light& l : s.lights) ASSERT_TRUE(l.area);
    EXPECT_TRUE(s.lights[0].area->illumination);
    EXPECT_FALSE(s.lights[1].area->illumination);
    EXPECT_TRUE(s.lights[2].area->illumination);
    EXPECT_TRUE(s.lights[3].area->illumination);
    EXPECT_EQ(s.lights[3].area->size1, 5);
    EXPECT_EQ(s.lights[3].area->adaptive, 1);
    EXPECT_TRUE(s.lights[3].area->jitter);
    EXPECT_FALSE(s.lights[4].area->illumination);
}

TEST(Finishes, DiffuseBackAndAlbedoAtTheEndOfTheBlock) {
    Scene s = parse(R"(
sphere { 0, 1 finish { diffuse 0.6, 0.4 } }
sphere { 0, 1 finish { diffuse albedo 0.6 brilliance 3 phong albedo 0.5 phong_size 9 } }
sphere { 0, 1 finish { specular albedo 0.5 roughness 0.05 } }
)");
    const Finish& a = *s.objects[0].texture[0].finish;
    EXPECT_FLOAT_EQ(a.diffuse, 0.6f);
    EXPECT_FLOAT_EQ(a.diffuse_back, 0.4f);
    const Finish& b = *s.objects[1].texture[0].finish;
    EXPECT_FLOAT_EQ(b.diffuse, 0.6f * 2);  // (brilliance + 1) / 2 with the later 3
    EXPECT_FLOAT_EQ(b.phong, 0.5f * 5);    // (phong_size + 1) / 2 with the later 9
    // roughness 0.05 is R = 20: (R + 2) / (4 (2 - 2^-10)).
    EXPECT_FLOAT_EQ(s.objects[2].texture[0].finish->specular,
                    float(0.5 * 22 / (4 * (2 - std::pow(2.0, -10)))));
}

TEST(Keywords, RefusedOrCheckedWhereTheyStand) {
    EXPECT_EQ(full_error_of("sphere { 0, 1 sturm }"),
              "test.pov:1:15: error: 'sturm' cannot be used with this object\n"
              "sphere { 0, 1 sturm }\n"
              "              ^~~~~");
    EXPECT_EQ(full_error_of("box { 0, 1 open }"),
              "test.pov:1:12: error: 'open' cannot be used with this object\n"
              "box { 0, 1 open }\n"
              "           ^~~~");
    EXPECT_EQ(full_error_of("union { sphere { 0, 1 } sphere { x, 1 } cutaway_textures }"),
              "test.pov:1:41: error: cutaway_textures can only be used with intersection "
              "and difference\n"
              "union { sphere { 0, 1 } sphere { x, 1 } cutaway_textures }\n"
              "                                        ^~~~~~~~~~~~~~~~");
    // A frequency wraps a block pattern's entry number, as POV-Ray's (golden
    // block_pattern_frequency).
    EXPECT_EQ(full_error_of("plane { y, 0 pigment { hexagon frequency 2 } }"),
              "(no error)");
    // area_illumination renders on an area light; on another light POV-Ray lights the
    // side facing away from it.
    EXPECT_EQ(full_error_of("light_source { 0, 1 area_illumination }"),
              "test.pov:1:21: error: unsupported: area_illumination without area_light\n"
              "light_source { 0, 1 area_illumination }\n"
              "                    ^~~~~~~~~~~~~~~~~");
    EXPECT_EQ(
        full_error_of("light_source { 0, 1 area_illumination on area_illumination off }"),
        "(no error)");
    // Dispersion renders; without an `ior` it is dropped (POV-Ray takes the
    // atmosphere's index and dispersion), with one kept; a finish's old `ior` replaces
    // the interior's index and drops it.
    {
        Scene s = parse(
            "sphere { 0, 1 interior { dispersion 1.02 } }"
            "sphere { 0, 1 interior { dispersion 1.02 ior 1.5 } }"
            "sphere { 0, 1 interior { ior 1.5 dispersion 1.02 } "
            "  finish { ior 1.3 } }");
        ASSERT_EQ(s.objects.size(), 3u);
        EXPECT_EQ(s.objects[0].interior->dispersion, 1.0f);
        EXPECT_EQ(s.objects[1].interior->dispersion, 1.02f);
        EXPECT_EQ(s.objects[2].interior->dispersion, 1.0f);  // the finish's ior wins
        EXPECT_EQ(s.objects[2].interior->ior, 1.3f);
    }
    // Off, they change nothing and are accepted.
    EXPECT_EQ(
        full_error_of("light_source { 0, 1 area_light x, y, 2, 2 area_illumination off }"
                      "sphere { 0, 1 interior { dispersion 1 } no_radiosity }"
                      "mesh { triangle { 0, x, y } hierarchy off }"),
        "(no error)");
}

// double_illuminate on a CSG is set on every node below when read, on or off (POV-Ray's
// Set_CSG_Tree_Flag); the ray flags come down when the object is placed, never off.
TEST(PostProcess, DoubleIlluminateSetsTheTreeRayFlagsComeDown) {
    Scene s = parse(R"(
union { sphere { 0, 1 double_illuminate } union { sphere { x, 1 double_illuminate } }
        double_illuminate off }
merge { sphere { 0, 1 } intersection { sphere { x, 1 } sphere { y, 1 } } double_illuminate 1 }
sphere { 0, 1 double_illuminate 0 }
union { sphere { 0, 1 no_image off } merge { sphere { x, 1 } } no_image no_shadow }
)");
    const Object& off = s.objects[0];
    EXPECT_FALSE(off.double_illuminate);
    EXPECT_FALSE(child(off, 0).double_illuminate);
    EXPECT_FALSE(child(child(off, 1), 0).double_illuminate);
    const Object& on = s.objects[1];
    EXPECT_TRUE(child(on, 0).double_illuminate);
    EXPECT_TRUE(child(child(on, 1), 1).double_illuminate);
    EXPECT_FALSE(s.objects[2].double_illuminate);
    const Object& flags = s.objects[3];
    EXPECT_TRUE(child(flags, 0).no_image);
    EXPECT_TRUE(child(flags, 0).no_shadow);
    EXPECT_TRUE(child(child(flags, 1), 0).no_image);
    EXPECT_FALSE(child(flags, 0).no_reflection);
}

}  // namespace
}  // namespace povwall::parser
