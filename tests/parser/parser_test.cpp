#include "parser/parser.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::full_error_of;
using test::parse;

TEST(Random, MatchesPovRay37Sequence) {
    // Reference values printed by POV-Ray 3.7.0.10 for the same #debug lines
    // (povray +Ir.pov -D -F; see tests/parser/README.md).
    std::string out;
    parse(R"(
#declare S = seed(0);
#declare T = seed(-7);
#declare U = seed(123456789);
#debug concat(str(rand(S),0,10), " ", str(rand(S),0,10), " ", str(rand(S),0,10), "\n")
#debug concat(str(rand(T),0,10), " ", str(rand(T),0,10), "\n")
#debug concat(str(rand(U),0,10), " ", str(rand(U),0,10), "\n")
#declare V = seed(5.9);
#debug concat(str(rand(V),0,10), "\n")
)",
          &out);
    EXPECT_EQ(out,
              "0.0000028743 0.4665636845 0.2490702288\n"
              "0.0460728682 0.3226610886\n"
              "0.4982198781 0.0969679065\n"
              "0.1099528787\n");
}

TEST(Random, IllegalStreamIsLocatedError) {
    EXPECT_EQ(full_error_of("#declare A = rand(3);"),
              "test.pov:1:19: error: illegal random number generator\n"
              "#declare A = rand(3);\n"
              "                  ^");
}

TEST(Directives, WhileLoopBuildsObjects) {
    Scene s = parse(R"(
#declare I = 0;
#while (I < 5)
  sphere { <I, 0, 0>, 0.5 }
  #declare I = I + 1;
#end
)");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(std::get<Sphere>(s.objects[4].shape).centre, (Vector3{4, 0, 0}));
}

TEST(Directives, IfElseifElseAndNesting) {
    Scene s = parse(R"(
#declare A = 2;
#if (A = 1) sphere { 0, 1 }
#elseif (A = 2)
  #if (A > 5) box { 0, 1 } #else sphere { 0, 2 } #end
#else sphere { 0, 3 }
#end
)");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).radius, 2);
}

TEST(Directives, ForSwitchAndIfdef) {
    std::string out;
    parse(R"(
#for (I, 1, 7, 2)
  #switch (I)
    #case (1) #debug "one " #break
    #range (2, 5) #debug "mid " #break
    #else #debug "other "
  #end
#end
#ifdef (I) #debug "defined" #end
#ifndef (Nope) #debug "!" #end
)",
          &out);
    EXPECT_EQ(out, "one mid mid other defined!");
}

TEST(Directives, MacroParametersAreByReferenceAndLocalsScoped) {
    std::string out;
    parse(R"(
#macro Bump(V, Amount)
  #local Tmp = V + Amount;
  #declare V = Tmp;
#end
#macro Twice(X) (2 * X) #end
#declare Count = 1;
Bump(Count, 4)
#declare Y = Twice(Count) + 1;
#debug concat(str(Count, 0, 0), " ", str(Y, 0, 0))
#ifndef (Tmp) #debug " no-leak" #end
)",
          &out);
    EXPECT_EQ(out, "5 11 no-leak");
}

TEST(Directives, DirectivesInsideObjectsAndDeclares) {
    Scene s = parse(R"(
#declare Fancy = 1;
#declare O = #if (Fancy) sphere { 0, 1 #if (Fancy) translate x #end } #else box { 0, 1 } #end
object { O }
)");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}), (Vector3{1, 0, 0}));
}

TEST(Expressions, OperatorsFunctionsAndMembers) {
    std::string out;
    parse(R"(
#declare V = <1, 2, 3> * 2 - <0, 0, 1>;
#declare C = rgb <0.5, 0.25, 1> filter 0.5;
#debug concat(str(V.x, 0, 1), ",", str(V.y, 0, 1), ",", str(V.z, 0, 1))
#debug concat(" ", str(vlength(<3, 4, 0>), 0, 1), " ", str(C.filter, 0, 2))
#debug concat(" ", str(mod(7, 3), 0, 0), " ", str(pow(2, 10), 0, 0), " ", str(int(-2.7), 0, 0))
#debug concat(" ", str((1 < 2 ? 10 : 20), 0, 0), " ", str(select(-1, 4, 5), 0, 0))
#debug concat(" ", strupr("ab"), substr("hello", 2, 3), str(strlen("four"), 0, 0))
#declare A = array[3] {1, 4, 9}
#debug concat(" ", str(A[2], 0, 0), " ", str(dimension_size(A, 1), 0, 0))
)",
          &out);
    EXPECT_EQ(out, "2.0,4.0,5.0 5.0 0.50 1 1024 -2 10 4 ABell4 9 3");
}

TEST(Colours, ColorsIncAndColourForms) {
    ParseOptions o;
    Scene s = parse_scene_text(R"(
#include "colors.inc"
background { color Red }
sphere { 0, 1 pigment { color red 0.5 green 0.25 } }
sphere { 0, 1 pigment { rgbt <0.1, 0.2, 0.3, 0.4> } }
)",
                               "test.pov", o);
    EXPECT_EQ(s.background.rgb, (Rgb{1, 0, 0}));
    EXPECT_EQ(s.objects[0].texture[0].pigment.colour.rgb, (Rgb{0.5f, 0.25f, 0}));
    EXPECT_FLOAT_EQ(s.objects[1].texture[0].pigment.colour.transmit, 0.4f);
}

TEST(Camera, LookAtAngleAndDefaults) {
    Scene d = parse("sphere { 0, 1 }");
    EXPECT_EQ(d.camera.right, (Vector3{1.33, 0, 0}));
    EXPECT_EQ(d.camera.direction, (Vector3{0, 0, 1}));
    Scene s = parse("camera { location <0, 0, -5> look_at <0, 0, 0> angle 90 }");
    // |direction| = |right| / (2 tan(45 deg)) = 0.665
    EXPECT_NEAR(s.camera.direction.z, 0.665, 1e-12);
    EXPECT_NEAR(s.camera.right.x, 1.33, 1e-12);
    EXPECT_NEAR(s.camera.up.y, 1.0, 1e-12);
    Scene t = parse("camera { location <0, 0, -5> look_at <5, 0, -5> }");
    EXPECT_NEAR(t.camera.direction.x, 1.0, 1e-12);
    EXPECT_NEAR(t.camera.right.z, -1.33, 1e-12);  // left-handed: right = sky x direction
}

TEST(Camera, ProjectionKindsKeepTheirAngleAndCylinderNeedsATypeFrom1To4) {
    Scene f = parse("camera { fisheye angle 200 location <0, 0, -5> look_at 0 }");
    EXPECT_EQ(f.camera.kind, Camera::Kind::Fisheye);
    EXPECT_EQ(f.camera.angle, 200);
    EXPECT_NEAR(f.camera.direction.z, 1.0,
                1e-12);  // angle does not rescale direction here
    EXPECT_EQ(parse("camera { panoramic }").camera.angle, 90);  // POV-Ray's default
    EXPECT_EQ(parse("camera { ultra_wide_angle }").camera.kind,
              Camera::Kind::UltraWideAngle);
    EXPECT_EQ(parse("camera { cylinder 1 }").camera.kind, Camera::Kind::Cylinder1);
    EXPECT_EQ(parse("camera { cylinder 4 angle 30 }").camera.kind,
              Camera::Kind::Cylinder4);
    EXPECT_EQ(full_error_of("camera { cylinder 5 angle 90 }"),
              "test.pov:1:19: error: cylinder camera type must be 1, 2, 3 or 4\n"
              "camera { cylinder 5 angle 90 }\n"
              "                  ^");
}

TEST(Camera, SphericalAngleIsAcrossThenUpWithHalfOfItByDefault) {
    Scene a = parse("camera { spherical angle 200 }");
    EXPECT_EQ(a.camera.kind, Camera::Kind::Spherical);
    EXPECT_EQ(a.camera.h_angle, 200);
    EXPECT_EQ(a.camera.v_angle, 100);
    Scene b = parse("camera { spherical angle 120, 60 }");
    EXPECT_EQ(b.camera.h_angle, 120);
    EXPECT_EQ(b.camera.v_angle, 60);
    EXPECT_EQ(b.camera.angle, 90);  // the other kinds' angle is untouched
    Scene c = parse("camera { spherical }");
    EXPECT_EQ(c.camera.h_angle, 360);
    EXPECT_EQ(c.camera.v_angle, 180);
    EXPECT_EQ(parse("camera { omnimax }").camera.kind, Camera::Kind::Omnimax);
    EXPECT_TRUE(parse("camera { normal { bumps 0.3 } }").camera.normal.has_value());
}

TEST(Camera, BlurSamplesAndTheFocalDistanceAsPovRayReadsThem) {
    Scene one = parse("camera { aperture 0.5 blur_samples 20 }");
    EXPECT_EQ(one.camera.blur_samples, 20);
    EXPECT_EQ(one.camera.blur_samples_min, 0);
    Scene two = parse("camera { aperture 0.5 blur_samples 5, 30 confidence 0.95 }");
    EXPECT_EQ(two.camera.blur_samples, 30);
    EXPECT_EQ(two.camera.blur_samples_min, 5);
    EXPECT_EQ(two.camera.confidence, 0.95);
    EXPECT_EQ(two.camera.variance, 1.0 / 10000);
    // No focal point: POV-Ray's Direction_Length, 1 unless angle or look_at set it.
    EXPECT_EQ(parse("camera { direction 2 * z aperture 1 blur_samples 4 }")
                  .camera.focal_distance,
              1);
    EXPECT_NEAR(parse("camera { location -z direction 2 * z look_at 5 * z }")
                    .camera.focal_distance,
                2, 1e-12);
    EXPECT_NEAR(parse("camera { location <0, 0, -1> focal_point <0, 3, 3> translate x }")
                    .camera.focal_distance,
                5, 1e-12);
    EXPECT_EQ(full_error_of("camera { blur_samples 10, 5 }"),
              "test.pov:1:23: error: focal blur samples minimum must not be larger than "
              "maximum\n"
              "camera { blur_samples 10, 5 }\n"
              "                      ^~");
}

TEST(Degenerate, ExporterShapesAsPovRay) {
    // Coincident ends: POV-Ray stops with a parse error too.
    EXPECT_EQ(full_error_of("cylinder { <1, 1, 0>, <1, 1, 0>, 0.5 }"),
              "test.pov:1:1: error: degenerate cylinder, base point = cap point\n"
              "cylinder { <1, 1, 0>, <1, 1, 0>, 0.5 }\n"
              "^~~~~~~~");
    EXPECT_EQ(full_error_of("cone { 0, 0.5, 0, 0.3 }"),
              "test.pov:1:1: error: degenerate cone, base point = cap point\n"
              "cone { 0, 0.5, 0, 0.3 }\n"
              "^~~~");
    // Degenerate triangles are warned about (and never hit); zero radii and flat boxes
    // parse.
    std::string messages;
    Scene s = parse(
        "triangle { 0, 0, x }\nsmooth_triangle { 0, y, x, y, 2*x, y }\n"
        "cylinder { 0, y, 0 } box { 0, <1, 1, 0> } sphere { 0, 0 }",
        &messages);
    EXPECT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(messages,
              "test.pov:1:1: warning: degenerate triangle, never hit; please remove\n"
              "triangle { 0, 0, x }\n"
              "^~~~~~~~\n"
              "test.pov:2:1: warning: degenerate triangle, never hit; please remove\n"
              "smooth_triangle { 0, y, x, y, 2*x, y }\n"
              "^~~~~~~~~~~~~~~\n");
    // In meshes they are dropped silently, as POV-Ray does.
    std::string quiet;
    Scene m = parse(
        "mesh { triangle { 0, 0, x } triangle { 0, x, y } }\n"
        "mesh2 { vertex_vectors { 3, 0, x, 2*x } face_indices { 1, <0, 1, 2> } }",
        &quiet);
    EXPECT_EQ(std::get<Mesh>(m.objects[0].shape).data->faces.size(), 1u);
    EXPECT_EQ(std::get<Mesh>(m.objects[1].shape).data->faces.size(), 0u);
    EXPECT_EQ(quiet, "");
}

TEST(Textures, ObjectTransformsMoveTexturesAndCsgPushesTextureDown) {
    Scene s = parse(R"(
sphere { 0, 1 pigment { checker } scale 2 }
union { sphere { 0, 1 } sphere { x, 1 pigment { rgb 1 } } pigment { rgb <1, 0, 0> } }
)");
    const PatternSpec& p = s.objects[0].texture[0].pigment.pattern.get();
    EXPECT_EQ(p.kind, PatternKind::Checker);
    EXPECT_EQ(p.transform.point({1, 1, 1}), (Vector3{2, 2, 2}));
    const Csg& u = std::get<Csg>(s.objects[1].shape);
    EXPECT_EQ(u.children[0].texture.back().pigment.colour.rgb, (Rgb{1, 0, 0}));
    EXPECT_EQ(u.children[1].texture.back().pigment.colour.rgb, (Rgb{1, 1, 1}));
}

// no_bump_scale (POV-Ray's DONT_SCALE_BUMPS_FLAG) ends on the normal patterns the tracer
// reads it from: written in a normal, in a texture (after its transforms, handed to its
// normal when the texture ends, to a texture_map's pattern and its entries' top layers),
// and on its own layer only.
TEST(Textures, NoBumpScaleReachesTheNormalPatterns) {
    Scene s = parse(
        "sphere { 0, 1 normal { bumps no_bump_scale scale 2 } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } no_bump_scale normal { dents } } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } normal { wrinkles } scale 2 "
        "no_bump_scale } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } scale 2 no_bump_scale } }\n"
        "sphere { 0, 1 normal { gradient x normal_map { [0 bumps] [1 ripples] } "
        "no_bump_scale } }\n"
        "#declare T = texture { pigment { rgb 1 } normal { bumps } };\n"
        "sphere { 0, 1 texture { gradient x texture_map { [0 T] [1 T] } scale 2 "
        "no_bump_scale } }\n"
        "sphere { 0, 1 texture { T } texture { T no_bump_scale } }\n"
        "sphere { 0, 1 texture { T } pigment { rgb 1 no_bump_scale } }\n");
    ASSERT_EQ(s.objects.size(), 8u);
    auto flagged = [&](size_t object, size_t layer = 0) {
        const Texture& t = s.objects[object].texture.at(layer);
        return t.normal && t.normal->pattern->no_bump_scale;
    };
    EXPECT_TRUE(flagged(0));
    EXPECT_TRUE(flagged(1));
    EXPECT_TRUE(flagged(2));
    EXPECT_FALSE(s.objects[3].texture[0].normal);  // nothing to hand it to
    const Normal& mapped = *s.objects[4].texture[0].normal;
    ASSERT_EQ(mapped.list.size(), 2u);
    EXPECT_TRUE(mapped.pattern->no_bump_scale);
    EXPECT_TRUE(mapped.list[0].pattern->no_bump_scale);
    EXPECT_TRUE(mapped.list[1].pattern->no_bump_scale);
    const Texture& map = s.objects[5].texture[0];
    ASSERT_TRUE(map.map_pattern);
    EXPECT_TRUE(map.map_pattern->no_bump_scale);
    ASSERT_EQ(map.map->entries.size(), 2u);
    for (const LayeredTexture& entry : map.map->entries)
        EXPECT_TRUE(entry.back().normal->pattern->no_bump_scale);
    EXPECT_FALSE(flagged(6, 0));  // the bottom layer keeps none
    EXPECT_TRUE(flagged(6, 1));
    EXPECT_FALSE(flagged(7));  // a pigment's pattern keeps it to itself
}

TEST(Settings, VersionAndGlobalSettings) {
    Scene s =
        parse("#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 300 }");
    EXPECT_EQ(s.language_version, 370);
    EXPECT_TRUE(s.gamma_handling());
    EXPECT_EQ(s.settings.max_trace_level, 256);
    Scene legacy = parse("sphere { 0, 1 }");
    EXPECT_EQ(legacy.language_version, 362);
    EXPECT_FALSE(legacy.gamma_handling());
}

TEST(Errors, ExactLocationsAndCarets) {
    EXPECT_EQ(full_error_of("sphere { 0, 1\n  pigment { colr Red }\n}"),
              "test.pov:2:13: error: expected a pigment item or '}' but found 'colr'\n"
              "  pigment { colr Red }\n"
              "            ^~~~");
    // Commas are optional in POV-Ray (`<0, 0, 0> 1` is a sphere); a missing value is not.
    EXPECT_EQ(full_error_of("sphere { <0, 0, 0>, }"),
              "test.pov:1:21: error: expected the sphere's radius but found '}'\n"
              "sphere { <0, 0, 0>, }\n"
              "                    ^");
    EXPECT_EQ(full_error_of("#declare X = Undefined_Thing + 1;"),
              "test.pov:1:14: error: undeclared identifier 'Undefined_Thing'\n"
              "#declare X = Undefined_Thing + 1;\n"
              "             ^~~~~~~~~~~~~~~");
    EXPECT_EQ(full_error_of("#include \"no_such_file.inc\""),
              "test.pov:1:10: error: cannot find include file \"no_such_file.inc\"\n"
              "#include \"no_such_file.inc\"\n"
              "         ^~~~~~~~~~~~~~~~~~");
    EXPECT_EQ(full_error_of("#while (1)\nsphere { 0, 1 }"),
              "test.pov:1:1: error: #while has no matching #end\n"
              "#while (1)\n"
              "^~~~~~");
    EXPECT_EQ(full_error_of("\tbox { 0, 1 } @"),
              "test.pov:1:15: error: unexpected character '@'\n"
              "        box { 0, 1 } @\n"
              "                     ^");
}

TEST(Errors, InsideMacroPointsAtCallSite) {
    EXPECT_EQ(full_error_of("#macro M()\n  sphere { 0 }\n#end\nM()"),
              "test.pov:2:14: error: expected the sphere's radius but found '}'\n"
              "  sphere { 0 }\n"
              "             ^\n"
              "test.pov:4:1: note: in macro 'M' called from here\n"
              "M()\n"
              "^");
}

// Runaway recursion: the 5 innermost and 5 outermost of the 1000 call sites, the rest
// counted, as clang elides template instantiation contexts.
TEST(Errors, DeepMacroRecursionElidesMiddleNotes) {
    std::string inner =
        "test.pov:2:3: note: in macro 'M' called from here\n"
        "  M()\n"
        "  ^\n";
    std::string expected =
        "test.pov:2:3: error: macro 'M' nested too deeply (limit 1000): runaway "
        "recursion?\n"
        "  M()\n"
        "  ^\n";
    for (int i = 0; i < 5; ++i) expected += inner;
    expected += "note: (990 more macro contexts not shown)\n";
    for (int i = 0; i < 4; ++i) expected += inner;
    expected +=
        "test.pov:4:1: note: in macro 'M' called from here\n"
        "M()\n"
        "^";
    EXPECT_EQ(full_error_of("#macro M()\n  M()\n#end\nM()"), expected);
}

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

// Deep nesting is recursion on the stack: a located error at level 257, not a crash (the
// scene fuzzer's stack overflows: parentheses, CSG, pigment maps, and an object inside a
// vector through a #while whose #end lands in the middle of it).
TEST(Errors, DeepNestingIsALocatedErrorNotAStackOverflow) {
    EXPECT_EQ(parse("#declare X = " + repeat("(", 255) + "1" + repeat(")", 255) + ";")
                  .objects.size(),
              0u);
    EXPECT_EQ(error_of("#declare X = " + repeat("(", 300) + "1" + repeat(")", 300) + ";"),
              "test.pov:1:270: error: expressions, objects or patterns nested too deeply "
              "(limit 256)");
    EXPECT_EQ(
        error_of(repeat("union { ", 300) + "sphere { 0, 1 }" + repeat(" }", 300)),
        "test.pov:1:2049: error: expressions, objects or patterns nested too deeply "
        "(limit 256)");
    EXPECT_EQ(
        error_of("#declare P = pigment { " +
                 repeat("gradient x pigment_map { [0 ", 3000) + "rgb 1" +
                 repeat(" ] }", 3000) + " };"),
        "test.pov:1:7145: error: expressions, objects or patterns nested too deeply "
        "(limit 256)");
    // (After a third component a vector reads on only what can start an expression, as
    // POV-Ray does, so the object comes in as an operand of `+`.)
    EXPECT_EQ(error_of("mesh {\n#declare I = 0;\n#while (I < 24)\n"
                       "  triangle { <0, 0, 0>, <1, 0, 0>, <cos(I), 1, 0 + #end\n"),
              "test.pov:4:14: error: expressions, objects or patterns nested too deeply "
              "(limit 256)");
    EXPECT_EQ(
        error_of("mesh {\n#declare I = 0;\n#while (I < 24)\n"
                 "  triangle { <0, 0, 0>, <1, 0, 0>, <cos(I), 1, 0 #end\n"),
        "test.pov:4:3: error: expected '>' to close the vector but found 'triangle'");
}

// A #declare whose value runs into the loop's #end: every turn nests another #declare on
// the stack (found by the scene fuzzer). The stack check stops it before the stack ends.
TEST(Errors, DirectivesNestedPastTheStackAreALocatedError) {
    // Which token meets the limit first depends on the build's frame sizes: line 2.
    const std::string e = error_of("#declare I = 0;\n#while (I < 3) #declare I = #end\n");
    EXPECT_EQ(e.rfind("test.pov:2:", 0), 0u) << e;
    EXPECT_NE(
        e.find(": error: directives, macros and expressions nested too deeply for the "
               "stack"),
        std::string::npos)
        << e;
    // Deep but legitimate recursion still parses: 400 macro levels, each with a #local.
    // (`#local R = #if (N > 0) ... #else 0 #end;` is POV-Ray's missing-';' error: the
    // value ends at the #else.)
    Scene s = parse(
        "#macro F(N) #local R = 0; #if (N > 0) #local R = F(N - 1) + 1; #end R #end\n"
        "sphere { 0, F(400) }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).radius, 400);
}

// A loop that makes objects without end stops at the memory limit, long before its
// iteration limit (the scene fuzzer's tori ate 15 GB in a minute).
TEST(Errors, LoopThatMakesObjectsWithoutEndStopsAtTheMemoryLimit) {
    ParseOptions options;
    options.max_parse_memory = 64 << 20;
    try {
        parse_scene_text("#declare I = 0;\n#while (I < 1)\n  sphere { I, 1 }\n#end\n",
                         "test.pov", options);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        const std::string text = e.what();
        // The token the limit meets varies: any of the loop's lines.
        EXPECT_NE(text.substr(0, text.find('\n'))
                      .find(": error: the scene outgrew the parse memory limit of 64 MB "
                            "(set by the caller; a loop without end?)"),
                  std::string::npos)
            << text;
        EXPECT_EQ(text.rfind("test.pov:", 0), 0u) << text;
    }
}

// Floats read as ints saturate instead of overflowing; vstr's component count is 2..5 (a
// fuzzed vstr(9, ...) wrote past a 5-component vector).
TEST(Errors, HugeIntegerArgumentsAreSafe) {
    EXPECT_EQ(error_of("#declare V = vstr(9, <1,2,3>, \",\", 0, 1);"),
              "test.pov:1:19: error: vstr: the number of components must be 2 to 5");
    EXPECT_EQ(error_of("#declare R = rand(1e30);"),
              "test.pov:1:19: error: illegal random number generator");
    EXPECT_EQ(error_of("#declare S = substr(\"abc\", 2e10, 2e10);"),
              "test.pov:1:14: error: substr arguments out of range");
    // A width past the buffer is cut to 500 characters, zero-padded.
    Scene s = parse("#declare S = str(1.5, -3e12, 2);\nsphere { 0, strlen(S) }");
    EXPECT_EQ(std::get<Sphere>(s.objects.at(0).shape).radius, 500);
}

// Indices past the lists (and past int) are located errors, not undefined conversions.
TEST(Errors, Mesh2IndicesOutOfRangeAreLocated) {
    const std::string head =
        "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } "
        "normal_vectors { 1, <0,0,1> } texture_list { 1, texture { pigment { rgb 1 } } "
        "} ";
    EXPECT_EQ(error_of(head + "face_indices { 1, <0,1,2>, 2e113 } }"),
              "test.pov:1:164: error: mesh2 texture index out of range");
    EXPECT_EQ(error_of(head + "face_indices { 1, <0,1,2>, 0 } normal_indices { 1, "
                              "<0,0,5e9> } }"),
              "test.pov:1:188: error: mesh2 normal index out of range");
    // NaN passes `v < 0 || v >= n`; it must be out of range, not converted to an index.
    EXPECT_EQ(error_of(head + "face_indices { 1, <0, 1, sqrt(-1)> } }"),
              "test.pov:1:155: error: mesh2 face index out of range");
}

// mesh2's normals as Parse_Mesh2 takes them. Without normal_indices, as many normals as
// vertices are indexed like the vertices, and any other count is an error (the fuzzer's
// heap overflow: povwall indexed 2 normals by 4 vertices); faces past the normal_indices
// are flat; a second vertex or normal block replaces the first; the index sections
// follow face_indices, which every mesh2 has.
TEST(Errors, Mesh2NormalsWithoutTheirIndicesFollowPovRay) {
    const std::string verts = "mesh2 { vertex_vectors { 4, 0, x, y, x+y } ";
    EXPECT_EQ(error_of(verts + "normal_vectors { 2, z, y } face_indices { 2, <0,1,2>, "
                               "<1,3,2> } }"),
              "test.pov:1:108: error: missing normal_indices section in mesh2");
    const Scene s = parse(verts +
                          "normal_vectors { 4, z, y, x, -z } face_indices { 2, <0,1,2>, "
                          "<1,3,2> } }\n" +
                          verts +
                          "normal_vectors { 2, z, y } face_indices { 2, <0,1,2>, <1,3,2> "
                          "} normal_indices { 1, <0,1,1> } }");
    const MeshData& by_vertex = *std::get<Mesh>(s.objects.at(0).shape).data;
    EXPECT_EQ(by_vertex.faces[1].n[0], 1);
    EXPECT_EQ(by_vertex.faces[1].n[1], 3);
    EXPECT_EQ(by_vertex.faces[1].n[2], 2);
    const MeshData& fewer = *std::get<Mesh>(s.objects.at(1).shape).data;
    EXPECT_EQ(fewer.faces[0].n[1], 1);
    EXPECT_EQ(fewer.faces[1].n[0], -1);  // flat
    EXPECT_EQ(error_of(verts + "face_indices { 1, <0,1,2> } normal_vectors { 1, z } }"),
              "test.pov:1:72: error: expected uv_indices, normal_indices or the end of "
              "mesh2 but found 'normal_vectors'");
    EXPECT_EQ(error_of(verts + "normal_vectors { 1, z } normal_indices { 1, <0,0,0> } }"),
              "test.pov:1:68: error: expected face_indices but found 'normal_indices'");
    EXPECT_EQ(error_of(verts + "}"),
              "test.pov:1:44: error: expected face_indices but found '}'");
    EXPECT_EQ(
        error_of(verts + "face_indices { 1, <0,1,2> } normal_vectors { 4, z, z, z, z } "
                         "face_indices { 1, <0,1,2> } }"),
        "test.pov:1:72: error: expected uv_indices, normal_indices or the end of "
        "mesh2 but found 'normal_vectors'");
    std::string messages;
    const Scene twice = parse(
        "mesh2 { vertex_vectors { 1, 5*x } vertex_vectors { 3, 0, x, y } face_indices { "
        "1, <0,1,2> } }",
        &messages);
    EXPECT_EQ(std::get<Mesh>(twice.objects.at(0).shape).data->vertices.size(), 3u);
    EXPECT_EQ(messages.substr(0, messages.find('\n')),
              "test.pov:1:35: warning: duplicate vertex_vectors block; ignoring previous "
              "block");
}

// A macro call whose arguments run past the end of the macro body that contains it: the
// look-ahead after `N` ends that body and frees its scope, where `N` was bound. Found by
// the scene fuzzer (a heap-use-after-free); now `N` is looked up again, outside the body
// (so no "called from" note: the call has returned).
// The argument `N` is read as the value it had when met (as POV-Ray reads identifiers),
// so the calls nest until the closing parentheses run out.
TEST(Errors, MacroArgumentsRunningPastTheirBodysEndAreALocatedError) {
    EXPECT_EQ(
        full_error_of("#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N #end #end\n"
                      "#declare F = Fact(3));\n"),
        "test.pov:2:22: error: expected ')' after the arguments of 'Fact' but found "
        "';'\n"
        "#declare F = Fact(3));\n"
        "                     ^");
}

// trace() writes its normal argument: a #declare of it cannot wait until the value is
// used (the scene would test the unchanged normal and go on as if nothing was hit).
TEST(Errors, TraceInADeclareStopsAtOnce) {
    EXPECT_EQ(full_error_of("#declare S = sphere { 0, 1 }\n"
                            "#declare N = <0, 0, 0>;\n"
                            "#declare P = trace(S, <0, 0, -5>, z, N);\n"),
              "test.pov:3:14: error: unsupported: trace\n"
              "#declare P = trace(S, <0, 0, -5>, z, N);\n"
              "             ^~~~~");
}

TEST(Errors, UnsupportedFeatureIsNamed) {
    try {
        parse("atmosphere { }");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.kind(), ParseError::Kind::Unsupported);
        EXPECT_EQ(e.message(), "unsupported: atmosphere");
    }
}

// The patterns of textures II: material_map outside a texture is refused by name; the
// misuses POV-Ray rejects are errors with its messages; proportion and
// gradient_map (no pattern in any POV-Ray) are plain words.
TEST(Errors, PatternRefusalsAndMisuses) {
    auto refusal = [](const std::string& text) {
        try {
            parse(text);
        } catch (const ParseError& e) {
            return e.kind() == ParseError::Kind::Unsupported ? e.message() : "(an error)";
        }
        return std::string("(no error)");
    };
    auto message = [](const std::string& text) {
        try {
            parse(text);
        } catch (const ParseError& e) {
            return e.message();
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(message("plane { y, 0 pigment { tiling 0 } }"),
              "Tiling number must be between 1 and 27.");
    EXPECT_EQ(message("plane { y, 0 pigment { tiling 28 } }"),
              "Tiling number must be between 1 and 27.");
    EXPECT_EQ(
        message("plane { y, 0 normal { checker normal { bumps } } }"),
        "give all 2 normals of 'checker' (POV-Ray 3.7 crashes on the missing ones)");
    EXPECT_EQ(refusal("plane { y, 0 pigment { material_map } }"),
              "unsupported: material_map");
    EXPECT_EQ(refusal("plane { y, 0 pigment { proportion } }"), "(an error)");
    EXPECT_EQ(refusal("plane { y, 0 pigment { gradient_map } }"), "(an error)");
    EXPECT_EQ(
        message("plane { y, 0 pigment { square colour_map { [0 rgb 0] [1 rgb 1] } } }"),
        "Cannot use color_map with this pattern type.");
    EXPECT_EQ(message("plane { y, 0 pigment { checker pigment_map { [0 rgb 0] } } }"),
              "Keyword 'pigment_map' cannot be used with this pigment type.");
    EXPECT_EQ(message("plane { y, 0 pigment { facets } }"),
              "Keyword 'facets' can only be used in a normal statement.");
    EXPECT_EQ(message("plane { y, 0 pigment { magnet 3 mandel 20 } }"),
              "Invalid magnet-mandel pattern type found. Valid types are 1 and 2.");
    EXPECT_EQ(message("plane { y, 0 pigment { magnet 1 mandel 20 exponent 3 } }"),
              "Keyword 'exponent' can only be used in a mandel or julia statement.");
    EXPECT_EQ(message("plane { y, 0 normal { bumps size 0.3 } }"),
              "Keyword 'size' can only be used in a facets statement.");
    EXPECT_EQ(message("plane { y, 0 texture { tiles { tile2 texture { } } } }"),
              "First texture missing from tiles");
}

// POV-Ray keeps a pattern's frequency, phase, wave exponent, agate_turb, quilted
// controls, turbulence omega and lambda, and a normal's amount and accuracy in single
// precision (SNGL): 0.1 is stored as 0.100000001490116...
TEST(Parser, PatternSettingsInSinglePrecision) {
    Scene s = parse(R"(
plane { y, 0 pigment { agate phase 0.1 frequency 0.3 agate_turb 0.7 poly_wave 1.1
                       turbulence 0.2 omega 0.6 lambda 2.1 } }
plane { y, 0 pigment { quilted control0 0.3 control1 0.9 }
             normal { bumps 0.3 accuracy 0.01 } }
)");
    auto single = [](double v) { return double(float(v)); };
    const PatternSpec& a = *s.objects[0].texture[0].pigment.pattern;
    EXPECT_EQ(a.phase, single(0.1));
    EXPECT_NE(a.phase, 0.1);
    EXPECT_EQ(a.frequency, single(0.3));
    EXPECT_EQ(a.scalar, single(0.7));
    EXPECT_EQ(a.wave_exponent, single(1.1));
    ASSERT_EQ(a.warps.size(), 1u);
    EXPECT_EQ(a.warps[0].omega, single(0.6));
    EXPECT_EQ(a.warps[0].lambda, single(2.1));
    EXPECT_EQ(a.warps[0].turbulence.x, 0.2);  // a vector: double
    const Texture& q = s.objects[1].texture[0];
    EXPECT_EQ(q.pigment.pattern->vector.x, single(0.3));
    EXPECT_EQ(q.pigment.pattern->vector.y, single(0.9));
    ASSERT_TRUE(q.normal);
    EXPECT_EQ(q.normal->amount, single(0.3));
    EXPECT_EQ(q.normal->accuracy, single(0.01));
}

// POV-Ray reads a pigment's pattern only as its first item (after an identifier): one
// after a modifier or another pattern ends the block, and its closing brace (a
// pigment_map entry's ']') is missing there (its messages, same place).
TEST(Errors, PigmentPatternAfterAModifier) {
    auto located = [](const std::string& text) {
        try {
            parse(text);
        } catch (const ParseError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(located("sphere { 0, 1 pigment { phase 0.4 quilted } }"),
              "test.pov:1:35: error: No matching } in 'pigment', quilted found instead\n"
              "sphere { 0, 1 pigment { phase 0.4 quilted } }\n"
              "                                  ^~~~~~~");
    EXPECT_EQ(located("sphere { 0, 1 pigment { checker quilted } }"),
              "test.pov:1:33: error: No matching } in 'pigment', quilted found instead\n"
              "sphere { 0, 1 pigment { checker quilted } }\n"
              "                                ^~~~~~~");
    EXPECT_EQ(located("sphere { 0, 1 pigment { gradient x pigment_map { [0 phase 0.4 "
                      "quilted] [1 rgb 1] } } }"),
              "test.pov:1:63: error: Expected ']', quilted found instead\n"
              "sphere { 0, 1 pigment { gradient x pigment_map { [0 phase 0.4 quilted] [1 "
              "rgb 1] } } }\n"
              "                                                              ^~~~~~~");
    // After an identifier the pattern is still the first item.
    EXPECT_EQ(located("#declare P = pigment { rgb 1 }\n"
                      "sphere { 0, 1 pigment { P quilted phase 0.4 } }"),
              "(no error)");
}

}  // namespace
}  // namespace povwall::parser

namespace povwall::parser {
namespace {

TEST(Lights, LightsInsideCsgMoveWithIt) {
    Scene s = parse(R"(
#declare L = light_source { <1, 0, 0> color rgb 1 }
union {
  light_source { <0, 1, 0> color rgb 1 }
  object { L translate <0, 0, 1> }
  sphere { 0, 0.1 }
  translate <10, 0, 0>
  rotate y * 90
}
)");
    ASSERT_EQ(s.lights.size(), 2u);
    // <0,1,0> + 10x = <10,1,0>; rotate 90 about y: x -> -z.
    EXPECT_NEAR(s.lights[0].location.x, 0, 1e-12);
    EXPECT_NEAR(s.lights[0].location.y, 1, 1e-12);
    EXPECT_NEAR(s.lights[0].location.z, -10, 1e-12);
    // <1,0,0> + z + 10x = <11,0,1> -> rotate: <1, 0, -11>.
    EXPECT_NEAR(s.lights[1].location.x, 1, 1e-12);
    EXPECT_NEAR(s.lights[1].location.z, -11, 1e-12);
}

// VMD-style scenes wrap a light in object { }; its transforms move it.
TEST(Lights, ALightWrittenInsideObjectIsALight) {
    Scene s = parse(R"(
object { light_source { <1, 2, 3> color rgb 0.5 } translate <1, 0, 0> }
sphere { 0, 1 }
)");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].location, (Point3{2, 2, 3}));
    EXPECT_FLOAT_EQ(s.lights[0].colour.r, 0.5f);
    ASSERT_EQ(s.objects.size(), 2u);  // the light's empty holder and the sphere
}

// POV-Ray's own qtvr/qtvrpanorama.pov writes `looks_like { LightShape }`.
TEST(Lights, LooksLikeTakesAnObjectIdentifier) {
    Scene s = parse(R"(
#declare LightShape = sphere { 0, 6 pigment { rgb <1, 0.8, 0.2> } }
light_source {
  0*x color rgb 1
  looks_like { LightShape }
  translate <-100, 50, -50>
}
)");
    ASSERT_EQ(s.lights.size(), 1u);
    ASSERT_EQ(s.lights[0].looks_like.size(), 1u);
    const Object& o = s.lights[0].looks_like[0];
    const Sphere* sp = std::get_if<Sphere>(&o.shape);
    ASSERT_NE(sp, nullptr);
    EXPECT_EQ(sp->radius, 6);
    EXPECT_TRUE(o.no_shadow);
    const Point3 c = o.transform.point(sp->centre);
    EXPECT_NEAR(c.x, -100, 1e-12);
    EXPECT_NEAR(c.y, 50, 1e-12);
    EXPECT_NEAR(c.z, -50, 1e-12);
    ASSERT_EQ(o.texture.size(), 1u);
    EXPECT_NEAR(o.texture[0].pigment.colour.rgb.g, 0.8, 1e-6);
}

// projected_through (POV-Ray 3.7's Parse_Light_Source and Post_Process): the object
// stays where it is written, is moved by the light's later transforms (a copy of a
// declared light moves its own), is not in the scene and loses a texture with a warning.
TEST(Lights, ProjectedThroughIsTheLightsOwnObject) {
    std::string messages;
    Scene s = parse(R"(
#declare Lamp = light_source { <0, 5, 0> rgb 1
  projected_through { sphere { <0, 1, 0>, 0.5 pigment { rgb 1 } } } }
light_source { Lamp translate <2, 0, 0> }
light_source { Lamp }
)",
                    &messages);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_TRUE(s.objects.empty());
    for (size_t l = 0; l < 2; ++l) {
        ASSERT_TRUE(s.lights[l].projected_through);
        const Object& o = *s.lights[l].projected_through;
        const Point3 c = o.transform.point(std::get<Sphere>(o.shape).centre);
        EXPECT_EQ(c.x, l == 0 ? 2.0 : 0.0);
        EXPECT_EQ(c.y, 1.0);
        EXPECT_TRUE(o.texture.empty());
    }
    EXPECT_EQ(messages.substr(0, messages.find('\n')),
              "test.pov:3:3: warning: Projected through objects can not have "
              "texture/interior");
    EXPECT_EQ(
        error_of("light_source { 0 rgb 1 projected_through { sphere { 0, 1 } }\n"
                 "  projected_through { sphere { 0, 1 } } }"),
        "test.pov:2:3: error: Only one projected through allowed per light_source.");
    // What POV-Ray does beyond one test per light ray is refused where it is asked for.
    EXPECT_EQ(error_of("light_source { 0 rgb 1 projected_through { sphere { 0, 1 } }\n"
                       "  area_light x, z, 2, 2 }"),
              "test.pov:1:24: error: unsupported: projected_through on an area_light");
    EXPECT_EQ(
        error_of("light_source { 0 rgb 1 media_attenuation on\n"
                 "  projected_through { sphere { 0, 1 } } }"),
        "test.pov:2:3: error: unsupported: projected_through with media_attenuation");
    EXPECT_EQ(error_of("light_source { 0 rgb 1 projected_through { sphere { 0, 1 } } }\n"
                       "global_settings { photons { spacing 0.1 } }"),
              "test.pov:1:24: error: unsupported: projected_through with photons");
}

}  // namespace
}  // namespace povwall::parser

namespace povwall::parser {
namespace {

TEST(Expressions, VturbulenceMatchesPovRay) {
    // Values printed by POV-Ray 3.7.0.10 for the same #debug lines.
    std::string out;
    parse(R"(
#debug concat(vstr(3, vturbulence(2, 0.5, 6, <0.3, 0.7, 1.1>), ",", 0, 6), "\n")
#debug concat(vstr(3, vturbulence(2.5, 0.4, 3, <-12.5, 3.25, 100>), ",", 0, 6), "\n")
)",
          &out);
    EXPECT_EQ(out, "0.344564,-0.261187,-0.078804\n-0.116862,-0.399384,0.198307\n");
}

// A forked black-box worker takes its objects from the coordinator's whole parse; it must
// number them as a worker whose parse left the others out (interior stacks cross the
// wire as those numbers).
TEST(KeepObjects, TakenFromAWholeParseNumbersObjectsAsAFilteredParse) {
    const std::string text = R"(
sphere { <-3, 0, 0>, 1 }
union { sphere { <3, 0, 0>, 1 } box { <2, -1, -1>, <4, 1, 1> } }
difference { box { -1, 1 } sphere { 0, 1.2 } translate <-3, 2, 0> }
sphere { <3, 2, 0>, 0.5 }
light_source { <0, 10, 0> rgb 1 looks_like { sphere { 0, 0.1 } } }
)";
    // Keeps what lies right of the origin: the union and the last sphere.
    auto right = [](const Object& o) {
        if (auto s = std::get_if<Sphere>(&o.shape)) return s->centre.x > 0;
        return std::holds_alternative<Csg>(o.shape) &&
               std::get<Csg>(o.shape).children.size() == 2 &&
               std::holds_alternative<Sphere>(std::get<Csg>(o.shape).children[0].shape) &&
               std::get<Sphere>(std::get<Csg>(o.shape).children[0].shape).centre.x > 0;
    };
    ParseOptions o;
    o.keep_object = right;
    const Scene filtered = parse_scene_text(text, "test.pov", o);
    Scene whole = parse_scene_text(text, "test.pov", ParseOptions{});
    ASSERT_EQ(whole.objects.size(), 4u);
    EXPECT_FALSE(whole.objects_filtered());
    const Object* first = whole.objects.data();
    const Scene taken = take_scene_keeping(std::move(whole), {1, 3});
    // Nodes: sphere 0; union 1 (children 2, 3); difference 4 (5, 6); sphere 7.
    EXPECT_EQ(filtered.object_first_node, (std::vector<uint32_t>{1, 7}));
    EXPECT_EQ(taken.object_first_node, filtered.object_first_node);
    EXPECT_EQ(taken.object_nodes_total, 8u);
    EXPECT_EQ(taken.object_nodes_total, filtered.object_nodes_total);
    EXPECT_EQ(taken.objects_left_out, 2u);
    EXPECT_EQ(taken.objects_left_out, filtered.objects_left_out);
    ASSERT_EQ(taken.objects.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<Csg>(taken.objects[0].shape));
    EXPECT_EQ(std::get<Sphere>(taken.objects[1].shape).radius, 0.5);
    EXPECT_EQ(taken.lights.size(), 1u);
    // `whole` keeps its object list, in place (a forked worker writes none of its
    // pages), and nothing else.
    ASSERT_EQ(whole.objects.size(), 4u);
    EXPECT_EQ(whole.objects.data(), first);
    EXPECT_EQ(std::get<Sphere>(whole.objects[0].shape).centre.x, -3);
    EXPECT_TRUE(whole.lights.empty());
    // Keeping everything still numbers as a filtered parse: every object has its first
    // node.
    Scene again = parse_scene_text(text, "test.pov", ParseOptions{});
    const Scene all = take_scene_keeping(std::move(again), {0, 1, 2, 3});
    EXPECT_EQ(all.object_first_node, (std::vector<uint32_t>{0, 1, 4, 7}));
    EXPECT_EQ(all.objects_left_out, 0u);
    EXPECT_TRUE(all.objects_filtered());
}

// What a filtered parse keeps of the objects it leaves out: for each node whose interior
// is not a default one, or that is hollow, that interior (one for the sharers in a CSG)
// and the hollow flag, so that a ray counted as inside a left-out object keeps its ior
// and media (wire/items.h, ObjectNumbers). A forked worker's take_scene_keeping agrees.
TEST(KeepObjects, LeftOutObjectsKeepWhatInteriorStacksNeed) {
    const std::string text = R"(
sphere { <-3, 0, 0>, 1 hollow }
union { sphere { <3, 0, 0>, 1 } box { <2, -1, -1>, <4, 1, 1> } }
difference { box { -1, 1 } sphere { 0, 1.2 interior { ior 1.3 } }
  interior { ior 1.5 media { absorption 1 } } translate <-3, 2, 0> }
sphere { <3, 2, 0>, 0.5 interior { ior 2 } }
sphere { <-3, -2, 0>, 0.5 }
)";
    auto right = [](const Object& o) {
        if (auto sp = std::get_if<Sphere>(&o.shape)) return sp->centre.x > 0;
        return std::holds_alternative<Csg>(o.shape) &&
               std::get<Csg>(o.shape).kind == CsgKind::Union;
    };
    ParseOptions o;
    o.keep_object = right;
    const Scene filtered = parse_scene_text(text, "test.pov", o);
    const Scene taken =
        take_scene_keeping(parse_scene_text(text, "test.pov", ParseOptions{}), {1, 3});
    for (const Scene* s : {&filtered, &taken}) {
        SCOPED_TRACE(s == &filtered ? "filtered parse" : "taken from a whole parse");
        // Nodes: sphere 0; union 1 (2, 3); difference 4 (5, 6); sphere 7; sphere 8.
        ASSERT_EQ(s->left_out_nodes.size(), 4u);
        const LeftOutNode* sphere = s->left_out_node(0);
        ASSERT_TRUE(sphere);
        EXPECT_TRUE(sphere->hollow);
        EXPECT_EQ(sphere->interior, nullptr);  // a default interior
        const LeftOutNode* difference = s->left_out_node(4);
        const LeftOutNode* box = s->left_out_node(5);
        const LeftOutNode* inner = s->left_out_node(6);
        ASSERT_TRUE(difference && box && inner);
        ASSERT_TRUE(difference->interior && inner->interior);
        EXPECT_EQ(box->interior, difference->interior);  // shared, held once
        EXPECT_FLOAT_EQ(difference->interior->ior, 1.5f);
        EXPECT_EQ(difference->interior->media.size(), 1u);
        EXPECT_FALSE(difference->hollow);
        EXPECT_FLOAT_EQ(inner->interior->ior, 1.3f);
        EXPECT_EQ(s->left_out_interiors.size(), 2u);
        // Kept objects and default left-out ones have no record.
        for (uint32_t n : {1u, 2u, 3u, 7u, 8u})
            EXPECT_EQ(s->left_out_node(n), nullptr) << n;
    }
}

TEST(Prism, PointCountsAndClosureAsPovRay) {
    EXPECT_EQ(full_error_of("prism { 0, 1, 2, <0,0>, <1,0> }"),
              "test.pov:1:15: error: Prism with linear splines must have at least three "
              "points.\n"
              "prism { 0, 1, 2, <0,0>, <1,0> }\n"
              "              ^");
    EXPECT_EQ(full_error_of("prism { bezier_spline 0, 1, 6, 0,0,0,0,0,0 }").substr(0, 82),
              "test.pov:1:29: error: Prism with Bezier splines must have four points per "
              "segment.");
    EXPECT_EQ(full_error_of("prism { 0, 1, 3, <0, 0, 1>, <1,0>, <0,1> }").substr(0, 78),
              "test.pov:1:18: error: UV_Vector expected but vector or color expression "
              "found.");
    // A linear outline left open is closed with a warning; other splines are ignored.
    std::string messages;
    Scene s = parse("prism { 1, 0, 3, <0,0>, <1,0>, <0,1> }", &messages);
    const Prism& p = std::get<Prism>(s.objects.at(0).shape);
    EXPECT_EQ(p.segments.size(), 3u);
    EXPECT_EQ(p.height1, 0);  // heights given high first are swapped
    EXPECT_EQ(p.height2, 1);
    EXPECT_FALSE(p.degenerate);
    EXPECT_NE(messages.find("warning: Linear prism not closed. Closing it."),
              std::string::npos);
    s = parse("prism { bezier_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }", &messages);
    EXPECT_TRUE(std::get<Prism>(s.objects.at(0).shape).degenerate);
    EXPECT_NE(messages.find("warning: Prism not closed. Ignoring it."),
              std::string::npos);
    EXPECT_EQ(
        full_error_of("prism { quadratic_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>, "
                      "<2,2> }")
            .substr(0, 45),
        "test.pov:1:1: error: Too few points in prism.");
    // sturm is an object modifier of prisms; open only directly after the points.
    s = parse(
        "prism { cubic_spline 0, 1, 7, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, "
        "<0,1> "
        "open sturm }");
    EXPECT_TRUE(std::get<Prism>(s.objects.at(0).shape).sturm);
    EXPECT_TRUE(std::get<Prism>(s.objects.at(0).shape).open);
    EXPECT_EQ(full_error_of("sphere { 0, 1 sturm }").substr(0, 61),
              "test.pov:1:15: error: 'sturm' cannot be used with this object");
}

}  // namespace
}  // namespace povwall::parser

namespace povwall::parser {
namespace {

// A colour read on its own takes any vector expression, as POV-Ray's Parse_Colour
// (CASE_VECTOR): x, y, z, u, v, vector and float functions, unary '+' and '!'. A colour
// map entry takes a colour keyword or identifier, or a float expression: not `x`.
TEST(Parser, ColourTakesAnyVectorExpression) {
    Scene s = parse(R"(
global_settings { ambient_light y + 0.5 * x }
background { z * 0.3 }
light_source { <0, 5, 0> x + y }
light_source { <0, 5, 0> color vnormalize(<3, 0, 4>) }
light_source { <0, 5, 0> color sqrt(0.25) }
light_source { <0, 5, 0> color +y }
sphere { 0, 1 hollow interior { media { emission y * 2 } } finish { ambient !0 * 0.1 } }
)");
    EXPECT_EQ(s.settings.ambient_light.r, 0.5f);
    EXPECT_EQ(s.settings.ambient_light.g, 1.0f);
    EXPECT_EQ(s.background.rgb.b, 0.3f);
    EXPECT_EQ(s.background.rgb.r, 0.0f);
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(s.lights[0].colour.r, 1.0f);
    EXPECT_EQ(s.lights[0].colour.b, 0.0f);
    EXPECT_EQ(s.lights[1].colour.r, 0.6f);
    EXPECT_EQ(s.lights[1].colour.b, 0.8f);
    EXPECT_EQ(s.lights[2].colour.g, 0.5f);
    EXPECT_EQ(s.lights[3].colour.r, 0.0f);
    EXPECT_EQ(s.lights[3].colour.g, 1.0f);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].interior->media.at(0).emission.g, 2.0f);
    EXPECT_EQ(s.objects[0].interior->media.at(0).emission.r, 0.0f);
    EXPECT_EQ(full_error_of("sphere { 0, 1 pigment { gradient y color_map { [0 x] } } }"),
              "test.pov:1:51: error: expected ']' to close the color_map entry but found "
              "'x'\n"
              "sphere { 0, 1 pigment { gradient y color_map { [0 x] } } }\n"
              "                                                  ^");
}

// Media take POV-Ray's defaults by the language version at each block (3.5 and later:
// method 3, one interval, 10 samples; before: method 1, 10 intervals, 1 sample), a
// declared media is copied whole, and transforms move the densities given so far.
TEST(Media, DefaultsFollowTheVersionAndDeclaredMediaAreCopied) {
    Scene s = parse(R"(
#declare M = media { emission 0.5 }
sphere { 0, 1 hollow interior { media { absorption 1 } media { M samples 4 } } }
#version 3.1;
sphere { 0, 1 hollow interior { media { emission 1 density { gradient x } translate x
                                        density { rgb 0.5 } } } }
media { absorption <0.1, 0.2, 0.3> }
)");
    ASSERT_EQ(s.objects.size(), 2u);
    const std::vector<Media>& a = s.objects[0].interior->media;
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].method, 3);
    EXPECT_EQ(a[0].intervals, 1);
    EXPECT_EQ(a[0].samples_min, 10);
    EXPECT_EQ(a[0].absorption.g, 1.0f);
    EXPECT_EQ(a[1].emission.r, 0.5f);
    EXPECT_EQ(a[1].samples_min, 4);
    EXPECT_EQ(a[1].samples_max, 4);
    const Media& b = s.objects[1].interior->media.at(0);
    EXPECT_EQ(b.method, 1);
    EXPECT_EQ(b.intervals, 10);
    EXPECT_EQ(b.samples_min, 1);
    ASSERT_EQ(b.density.size(), 2u);
    EXPECT_EQ(b.density[0].pattern->transform.point({0, 0, 0}).x, 1.0);  // moved
    EXPECT_EQ(b.density[1].pattern->transform.point({0, 0, 0}).x, 0.0);  // given after
    ASSERT_EQ(s.atmosphere_media.size(), 1u);
    EXPECT_EQ(s.atmosphere_media[0].absorption.b, 0.3f);
}

TEST(Media, BadValuesAreLocatedAndMissingFeaturesUnsupported) {
    EXPECT_EQ(full_error_of("sphere { 0, 1 interior { media { method 4 } } }"),
              "test.pov:1:41: error: media method must be 1, 2 or 3\n"
              "sphere { 0, 1 interior { media { method 4 } } }\n"
              "                                        ^");
    EXPECT_EQ(error_of("media { samples 5, 2 }"),
              "test.pov:1:20: error: maximum samples must not be below the minimum");
    EXPECT_EQ(error_of("media { scattering { 1, 0.5 eccentricity 0.3 } }"),
              "test.pov:1:29: error: eccentricity only applies to scattering type 5");
    EXPECT_EQ(error_of("media { density { density_map { [0 rgb 1] } } }"),
              "test.pov:1:19: error: a density_map cannot be used with this pattern "
              "type");
    EXPECT_EQ(error_of("light_source { 0, 1 area_light x, y, 2, 2 media_attenuation }\n"
                       "media { emission 1 }"),
              "test.pov:2:1: error: unsupported: atmospheric media with an area light's "
              "media_attenuation");
    EXPECT_EQ(
        error_of("media { emission 1 }\n"
                 "light_source { 0, 1 media_attenuation area_light x, y, 2, 2 }"),
        "test.pov:2:21: error: unsupported: media_attenuation of an area light with "
        "atmospheric media");
}

// POV-Ray's Parse_Bound_Clip: the objects of clipped_by/bounded_by, then transforms that
// move each of them; an object after a transform is an error. A smooth_triangle a shear
// turns degenerate stays so (SmoothTriangle::Transform).
TEST(Errors, ClipListTakesTransformsAfterItsObjects) {
    const Scene s = parse(
        "sphere { 0, 1 clipped_by { box { -1, 1 } sphere { x, 1 } "
        "translate <0, 2, 0> scale 2 } }");
    const std::vector<Object>& clips = *s.objects.at(0).clipped_by;
    ASSERT_EQ(clips.size(), 2u);
    // Each moved: the box's corner and the sphere's centre, where they end up.
    const Box& box = std::get<Box>(clips[0].shape);
    EXPECT_EQ(clips[0].transform.point(min(box.corner1, box.corner2)),
              (Point3{-2, 2, -2}));
    const Sphere& ball = std::get<Sphere>(clips[1].shape);
    EXPECT_EQ(clips[1].transform.point(ball.centre), (Point3{2, 4, 0}));
    EXPECT_EQ(
        error_of("sphere { 0, 1 clipped_by { box { -1, 1 } scale 2 sphere { 0, 1 } } }"),
        "test.pov:1:50: error: expected a transformation or '}' but found 'sphere'");
    const char* face =
        "smooth_triangle { <0.816, -0.899, -0.668>, <0.033, 0.619, -0.042>, "
        "<0.685, 0.037, 0.93>, <0.304, 0.349, 0.126>, <-0.8, 0.604, 0.042>, "
        "<-0.983, 0.169, -0.988> ";
    const std::string shear = "matrix <1, 0, 0, 0.196, 1, 0, -0.444, 0, 1, 0, 0, 0> ";
    auto degenerate = [](const Scene& scene) {
        return (*std::get<SmoothTriangle>(scene.objects.at(0).shape).n)[0] ==
               Vector3{0, 0, 0};
    };
    EXPECT_FALSE(degenerate(parse(std::string(face) + "}")));
    EXPECT_TRUE(degenerate(parse(std::string(face) + shear + "}")));
    EXPECT_TRUE(degenerate(
        parse(std::string(face) + shear + "transform { " + shear + "inverse } }")));
}

}  // namespace
TEST(Parser, SubsurfaceSettingsAndFinish) {
    const Scene s = parse(
        "global_settings { mm_per_unit 2.5 subsurface { samples 12 7 } }\n"
        "#declare F = finish { subsurface { anisotropy 0.5 translucency <3, 1.5, 0.8> } "
        "}\n"
        "sphere { 0, 1 finish { F diffuse 0.7 } }\n"
        "sphere { 0, 1 finish { subsurface { translucency 2 translucency 0.5 } } }");
    EXPECT_EQ(s.settings.mm_per_unit, 2.5);
    ASSERT_TRUE(s.settings.subsurface.has_value());
    EXPECT_EQ(s.settings.subsurface->samples_diffuse, 12);
    EXPECT_EQ(s.settings.subsurface->samples_single, 7);
    const Finish& a = *s.objects.at(0).texture.at(0).finish;
    EXPECT_TRUE(a.subsurface);
    EXPECT_EQ(a.translucency, (Rgb{3, 1.5f, 0.8f}));
    EXPECT_EQ(a.anisotropy, Rgb(0.5f));
    EXPECT_EQ(a.raw_diffuse, 0.7f);
    // The last translucency wins; a float is grey.
    EXPECT_EQ(s.objects.at(1).texture.at(0).finish->translucency, Rgb(0.5f));
    // Defaults: 10 mm a unit, 50 and 50 samples (the block alone turns it on).
    const Scene d = parse("global_settings { subsurface { } }");
    EXPECT_EQ(d.settings.mm_per_unit, 10.0);
    EXPECT_EQ(d.settings.subsurface->samples_diffuse, 50);
    EXPECT_EQ(d.settings.subsurface->samples_single, 50);
    EXPECT_FALSE(d.settings.subsurface->radiosity);
    EXPECT_FALSE(parse("sphere { 0, 1 }").settings.subsurface.has_value());
    const Scene r = parse(
        "global_settings { subsurface { radiosity on samples 3, 4 } radiosity { "
        "subsurface "
        "on } }");
    EXPECT_TRUE(r.settings.subsurface->radiosity);
    EXPECT_EQ(r.settings.subsurface->samples_single, 4);
    EXPECT_TRUE(r.settings.radiosity->subsurface);
}

TEST(Errors, SubsurfaceValuesThatDivideByZero) {
    EXPECT_EQ(error_of("sphere { 0, 1 finish { subsurface { } } }"),
              "test.pov:1:24: error: subsurface needs a translucency above 0 in every "
              "channel");
    EXPECT_EQ(
        error_of("sphere { 0, 1 finish { subsurface { translucency <1, 0, 1> } } }"),
        "test.pov:1:24: error: subsurface needs a translucency above 0 in every "
        "channel");
    EXPECT_EQ(error_of("global_settings { mm_per_unit 0 }"),
              "test.pov:1:31: error: mm_per_unit must be positive");
    EXPECT_EQ(error_of("global_settings { subsurface { samples -1, 3 } }"),
              "test.pov:1:40: error: subsurface samples must not be negative");
}

}  // namespace povwall::parser
