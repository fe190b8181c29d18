// POV-Ray 3.7's optional commas (notes/parser-rules.md §1): optional exactly where 3.7
// reads them with Parse_Comma, required where it loops on a comma. The #debug outputs
// below are what POV-Ray 3.7.0.10 prints for the same lines.
// Repeated blocks (§2): a second pigment, normal, finish or interior block edits the
// first; scenes/golden/repeated_blocks.pov checks the same against POV-Ray's image.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "parser/parser.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::parse;

std::string debug_of(const std::string& text) {
    std::string out;
    parse(text, &out);
    return out;
}

// The first line of the error a scene stops with.

void expect_vec(const Vector3& v, double x, double y, double z) {
    EXPECT_DOUBLE_EQ(v.x, x);
    EXPECT_DOUBLE_EQ(v.y, y);
    EXPECT_DOUBLE_EQ(v.z, z);
}

TEST(Commas, MacroParametersAndArguments) {
    const std::string m =
        "#macro M(A B) #debug concat(str(A,0,1), \" \", str(B,0,1), \";\") #end\n"
        "#macro T(A, B,) #debug concat(str(A,0,1), \" \", str(B,0,1), \";\") #end\n";
    EXPECT_EQ(debug_of(m + "M(1 2) M(1, 2) M(1,2,) T(3 4) T(5, 6,)"),
              "1.0 2.0;1.0 2.0;1.0 2.0;3.0 4.0;5.0 6.0;");
    // Arguments are sums: `-` after a term subtracts, and `<` after a number starts the
    // next argument (a vector).
    EXPECT_EQ(debug_of(m + "M(1 (-2)) M(0 <1, 2, 3>.y) M(2*3 4/2)"),
              "1.0 -2.0;0.0 2.0;6.0 2.0;");
    // An identifier alone is passed by reference, also without a comma after it.
    EXPECT_EQ(debug_of("#declare K = 5;\n#macro Add(P Q) #declare P = P + Q; #end\n"
                       "Add(K 2) Add(K, 3) #debug str(K, 0, 0)"),
              "10");
    EXPECT_EQ(debug_of("#declare K = 5;\n#macro Add(P Q) #declare P = P + 10; #end\n"
                       "Add(K -2 3) #debug str(K, 0, 0)"),
              "5");  // K - 2 is an expression: passed by value
    // #local of such a parameter in its own macro writes through too (macro4.pov), also
    // from a macro it is passed on to; a #local of another name stays local.
    EXPECT_EQ(debug_of("#declare K = 5;\n#macro Inc(V) #local V = V + 1; #end\n"
                       "Inc(K) Inc(K + 0) Inc(+K) #debug str(K, 0, 0)"),
              "6");
    EXPECT_EQ(
        debug_of("#declare K = 0;\n#macro Inc(V) #while (V < 3) #local V = V + 1; "
                 "#end #end\n#macro Outer(W) Inc(W) #end\n#macro SetL(P) #local Q = "
                 "P; #local Q = 9; #end\nOuter(K) SetL(K) #debug str(K, 0, 0)"),
        "3");
    EXPECT_EQ(error_of(m + "M(1 -2)"),
              "test.pov:3:7: error: macro 'M' expects 2 parameters but only 1 was found");
    EXPECT_EQ(error_of(m + "M(1,,2)"),
              "test.pov:3:5: error: macro 'M' expects 2 parameters but only 1 was found");
    EXPECT_EQ(
        error_of(m + "M(1, 2, 3)"),
        "test.pov:3:9: error: expected ')' after the arguments of 'M' but found '3'");
    EXPECT_EQ(error_of("#macro M(A,,B) #end"),
              "test.pov:1:12: error: expected a parameter name but found ','");
    // `optional` is no keyword in 3.7: it names a parameter.
    EXPECT_EQ(debug_of("#macro O(optional A) #debug str(optional + A, 0, 0) #end O(1 2)"),
              "3");
}

TEST(Commas, ArrayInitialisers) {
    EXPECT_EQ(debug_of("#declare A = array[3] {1 2 3}\n"
                       "#declare B = array[3] {1, 2, 3,}\n"
                       "#declare C = array[2][2] {{1 2}{3 4}}\n"
                       "#declare D = array[2][3] {{1, 2, 3}, {4, 5, 6},}\n"
                       "#debug concat(str(A[2],0,0), str(B[0],0,0), str(C[1][0],0,0), "
                       "str(D[1][2],0,0), str(D[0][1],0,0))"),
              "31362");
    // Elements are sums: `{1 -2 3}` is two elements.
    EXPECT_EQ(debug_of("#declare A = array[2] {1 -2 3} #debug str(A[0] + A[1], 0, 0)"),
              "2");
    EXPECT_EQ(error_of("#declare A = array[3] {1, 2}"),
              "test.pov:1:28: error: too few elements in array initializer");
    EXPECT_EQ(error_of("#declare A = array[2] {1, 2, 3}"),
              "test.pov:1:30: error: too many elements in array initializer");
    EXPECT_EQ(error_of("#declare A = array[3] {1,, 2, 3}"),
              "test.pov:1:26: error: expected an array element but found ','");
    EXPECT_EQ(error_of("#declare A = array[2][2] {{1 2}}"),
              "test.pov:1:32: error: too few elements in array initializer");
}

TEST(Commas, VectorLiterals) {
    const std::string show = "#debug vstr(5, V, \",\", 0, 0)";
    EXPECT_EQ(debug_of("#declare V = <1 2 3>;" + show), "1,2,3,0,0");
    EXPECT_EQ(debug_of("#declare V = <1, 2,>;" + show), "1,2,0,0,0");
    EXPECT_EQ(debug_of("#declare V = <1, 2, 3, 4,>;" + show), "1,2,3,4,0");
    // `-` after a term subtracts: two components.
    EXPECT_EQ(debug_of("#declare V = <1 -2 3>;" + show), "-1,3,0,0,0");
    EXPECT_EQ(debug_of("#declare V = <1 (-2) 3>;" + show), "1,-2,3,0,0");
    // Components after the fifth overwrite it.
    EXPECT_EQ(debug_of("#declare V = <1, 2, 3, 4, 5 6>;" + show), "1,2,3,4,6");
    EXPECT_EQ(error_of("#declare V = <1, 2, 3, 4, 5,>;"),
              "test.pov:1:28: error: expected '>' to close the vector but found ','");
    EXPECT_EQ(error_of("#declare V = <1, 2 }"),
              "test.pov:1:20: error: expected '>' to close the vector but found '}'");
    // The same inside a loop, where expressions are compiled.
    EXPECT_EQ(debug_of("#for (I, 1, 2) #declare V = <I 2 -I 3, 4, 5 6 7>;"
                       "#debug concat(vstr(5, V, \",\", 0, 0), \";\") #end"),
              "1,1,3,4,7;2,0,3,4,7;");
}

TEST(Commas, UserFunctionCalls) {
    EXPECT_EQ(debug_of("#declare F = function(a, b) { a - b }\n"
                       "#debug concat(str(F(1 2), 0, 0), str(F(5, 1), 0, 0))"),
              "-14");
    EXPECT_EQ(error_of("#declare F = function(a, b) { a - b }\n#declare X = F(1, 2,);"),
              "test.pov:2:20: error: expected ')' after the 2 arguments of 'F' but "
              "found ','");
    EXPECT_EQ(error_of("#declare F = function(a, b) { a - b }\n#declare X = F(1 -2);"),
              "test.pov:2:14: error: 'F' takes 2 arguments, not 1");
    // Inside function { } commas are required.
    EXPECT_EQ(error_of("#declare G = function(a, b) { a + b }\n"
                       "#declare F = function { G(x 2) }"),
              "test.pov:2:29: error: expected ',' between the arguments of 'G' but found "
              "'2'");
    EXPECT_EQ(error_of("#declare F = function { max(x 2) }"),
              "test.pov:1:31: error: expected ',' between the arguments of 'max' but "
              "found '2'");
}

TEST(Commas, BuiltInFunctions) {
    EXPECT_EQ(debug_of("#debug concat(str(atan2(1 2), 0, 4), \" \", str(div(7 2), 0, 0), "
                       "\" \", str(mod(7 2), 0, 0), \" \", str(pow(2 3), 0, 0))"),
              "0.4636 3 1 8");
    EXPECT_EQ(debug_of("#debug concat(str(vdot(<1,2,3> <1,1,1>), 0, 0), \" \", "
                       "vstr(3, vcross(x y), \",\", 0, 0), \" \", "
                       "vstr(3, vrotate(x <0,0,90>), \",\", 0, 0), \" \", "
                       "vstr(3, vaxis_rotate(x z 90), \",\", 0, 0))"),
              "6 0,0,1 0,1,0 0,1,0");
    EXPECT_EQ(debug_of("#debug vstr(3, vturbulence(2 0.5 6 <1,2,3>,), \",\", 0, 3)"),
              "-0.381,-0.538,0.422");
    EXPECT_EQ(debug_of("#debug concat(str(strcmp(\"abc\" \"abd\"), 0, 0), \" \", "
                       "str(strcmp(\"b\", \"a\"), 0, 0), \" \", "
                       "str(strcmp(\"ab\", \"abc\"), 0, 0), \" \", "
                       "str(strcmp(\"x\", \"x\"), 0, 0))"),
              "-1 1 -99 0");
    EXPECT_EQ(debug_of("#debug concat(substr(\"abcdef\" 2 3), str(3.14159 0 2), "
                       "\"x\" \"y\", vstr(3 <1,2,3> \",\" 0 0), datetime(0 \"%Y\"), "
                       "\" \", datetime(0,))"),
              "bcd3.14xy1,2,32000 2000-01-01 00:00:00Z");
    EXPECT_EQ(
        debug_of("#declare D = array[2][5]\n"
                 "#debug concat(str(select(1 2 3), 0, 0), str(select(-1 2 3), 0, 0), "
                 "str(select(0, 2, 3, 4), 0, 0), str(dimension_size(D 2), 0, 0))"),
        "3235");
    // Required commas.
    EXPECT_EQ(error_of("#declare X = max(1 2);"),
              "test.pov:1:20: error: expected ')' but found '2'");
    EXPECT_EQ(error_of("#declare X = min(1 2);"),
              "test.pov:1:20: error: expected ')' but found '2'");
    EXPECT_EQ(error_of("#declare X = bitwise_or(1 2);"),
              "test.pov:1:27: error: expected ')' but found '2'");
    EXPECT_EQ(error_of("#declare X = select(1, 2, 3 4);"),
              "test.pov:1:29: error: expected ')' but found '4'");
    EXPECT_EQ(error_of("#declare S = spline { linear_spline 0, <0,0>, 1, <1,1> }\n"
                       "#declare X = S(0.5 linear_spline);"),
              "test.pov:2:20: error: expected ')' to close the spline call but found "
              "'linear_spline'");
    EXPECT_EQ(debug_of("#declare S = spline { linear_spline 0 <0,0> 1 <1,1>, }\n"
                       "#debug vstr(2, S(0.5, linear_spline), \",\", 0, 2)"),
              "0.50,0.50");
}

TEST(Commas, ObjectHeadersWithAndWithoutCommas) {
    for (const char* comma : {"", ","}) {
        const std::string c = comma;
        Scene s = parse("sphere { <1 2 3>" + c + " 4 }\n" +                  //
                        "box { <0 0 0>" + c + " <1 2 3> }\n" +               //
                        "cone { 0" + c + " 1" + c + " y" + c + " 0.5 }\n" +  //
                        "cylinder { 0" + c + " x" + c + " 2 }\n" +           //
                        "disc { 0" + c + " y" + c + " 2" + c + " 1 }\n" +    //
                        "plane { z" + c + " 3 }\n" +                         //
                        "torus { 2" + c + " 0.5 }\n" +                       //
                        "triangle { 0" + c + " x" + c + " y }\n" +           //
                        "polygon { 4" + c + " <0,0>" + c + " <1,0>" + c +    //
                        " <1,1>" + c + " <0,0> }\n" +                        //
                        "light_source { <1 2 3>" + c +
                        " rgb <0.5 0.25 1> "  //
                        "area_light x" +
                        c + " y" + c + " 3" + c + " 2 }\n");
        ASSERT_EQ(s.objects.size(), 9u) << "comma '" << c << "'";
        const Sphere& sp = std::get<Sphere>(s.objects[0].shape);
        expect_vec(sp.centre, 1, 2, 3);
        EXPECT_EQ(sp.radius, 4);
        expect_vec(std::get<Box>(s.objects[1].shape).corner2, 1, 2, 3);
        // The unit cone in POV-Ray's frame: its full cone's tip at z = 0, the wider end
        // (radius 1 at the origin) at z = 1, the narrower (0.5 at y) at z = 0.5.
        const Cone& cone = std::get<Cone>(s.objects[2].shape);
        EXPECT_EQ(cone.base_radius, 0.5);
        EXPECT_EQ(cone.cap_radius, 1);
        const CompactTransform& cone_frame = s.objects[2].transform;
        EXPECT_NEAR(length(cone_frame.point({0, 0, 1}) - Point3{0, 0, 0}), 0, 1e-12);
        EXPECT_NEAR(length(cone_frame.point({0, 0, 0.5}) - Point3{0, 1, 0}), 0, 1e-12);
        EXPECT_NEAR(length(cone_frame.point({1, 0, 1}) - cone_frame.point({0, 0, 1})), 1,
                    1e-12);
        // (The unit cylinder in POV-Ray's frame: the radius is the frame's scale.)
        const CompactTransform& frame = s.objects[3].transform;
        EXPECT_NEAR(length(frame.point({1, 0, 0}) - frame.point({0, 0, 0})), 2, 1e-12);
        const Disc& d = std::get<Disc>(s.objects[4].shape);
        EXPECT_EQ(d.radius, 2);
        EXPECT_EQ(d.hole_radius, 1);
        EXPECT_EQ(std::get<Plane>(s.objects[5].shape).distance, 3);
        EXPECT_EQ(std::get<Torus>(s.objects[6].shape).minor, 0.5);
        expect_vec(std::get<Triangle>(s.objects[7].shape).p[2], 0, 1, 0);
        EXPECT_EQ(std::get<Polygon>(s.objects[8].shape).points.size(), 4u);
        ASSERT_EQ(s.lights.size(), 1u);
        EXPECT_EQ(s.lights[0].location.z, 3);
        EXPECT_EQ(s.lights[0].colour.g, 0.25f);
        ASSERT_TRUE(s.lights[0].area);
        EXPECT_EQ(s.lights[0].area->size1, 3);
        EXPECT_EQ(s.lights[0].area->size2, 2);
    }
    // A comma after the disc radius, with no hole radius.
    EXPECT_EQ(std::get<Disc>(parse("disc { 0, y, 2, }").objects[0].shape).hole_radius, 0);
    // No comma after the last fixed argument of other objects.
    EXPECT_EQ(error_of("sphere { 0, 1, }"),
              "test.pov:1:14: error: expected an object modifier or '}' but found ','");
    // `angle h, v` is the spherical camera's only.
    EXPECT_EQ(error_of("camera { angle 60, 40 }"),
              "test.pov:1:18: error: expected a camera item or '}' but found ','");
}

TEST(Commas, Mesh2TextureIndices) {
    const std::string head =
        "mesh2 { vertex_vectors { 3 0 x y } texture_list { 2 texture { pigment { rgb 1 } "
        "} texture { pigment { rgb 0 } } } face_indices { 2 ";
    for (const char* faces : {"<0 1 2> 1 <0 1 2> 0 1 1", "<0,1,2>, 1, <0,1,2>, 0, 1, 1,",
                              "<0 1 2>, 1 <0, 1, 2> 0, 1 1"}) {
        Scene s = parse(head + faces + " } }");
        const MeshData& mesh = *std::get<Mesh>(s.objects[0].shape).data;
        ASSERT_EQ(mesh.faces.size(), 2u) << faces;
        EXPECT_EQ(mesh.faces[0].texture, 1) << faces;
        // Three indices: a texture per corner, blended by the hit's barycentrics.
        EXPECT_EQ(mesh.faces[1].texture, -2) << faces;
        ASSERT_EQ(mesh.texture_triples.size(), 1u) << faces;
        EXPECT_EQ(mesh.texture_triples[0], (std::array<int32_t, 3>{0, 1, 1})) << faces;
    }
    // An index may be any float expression.
    Scene s = parse("#declare T = 1;\n" + head + "<0 1 2> T <0,1,2>, T-1 } }");
    EXPECT_EQ(std::get<Mesh>(s.objects[0].shape).data->faces[0].texture, 1);
    EXPECT_EQ(std::get<Mesh>(s.objects[0].shape).data->faces[1].texture, 0);
    EXPECT_EQ(error_of(head + "<0 1 2> 0 2 <0 1 2> } }"),
              "test.pov:1:142: error: mesh2 texture index out of range");
    // Two indices: POV-Ray reads the third from a texture written before the list.
    EXPECT_EQ(error_of(head + "<0 1 2> 0 1 <0 1 2> 1 } }"),
              "test.pov:1:142: error: unsupported: mesh2 face with two texture indices");
}

TEST(Commas, MapsListsSplinesAndDirectives) {
    for (const char* comma : {"", ","}) {
        const std::string c = comma;
        Scene s = parse("sphere { 0 1 pigment { gradient x color_map { [0" + c +
                        " rgb 0.25] [1" + c + " rgb 1] } } }\n" +
                        "sphere { 0 1 pigment { checker rgb 0.5" + c + " rgb 1 } }\n" +
                        "sphere { 0 1 matrix <1" + c + " 0" + c + " 0" + c + " 0" + c +
                        " 2" + c + " 0" + c + " 0" + c + " 0" + c + " 1" + c + " 0" + c +
                        " 0" + c + " 3> }\n");
        ASSERT_EQ(s.objects.size(), 3u);
        const ColourMap& map = s.objects[0].texture[0].pigment.maps->colour_map;
        ASSERT_EQ(map.size(), 2u);
        EXPECT_EQ(map[0].colour.rgb.r, 0.25f);
        EXPECT_EQ(map[1].value, 1.0f);
        ASSERT_EQ(s.objects[1].texture[0].pigment.maps->list.size(), 2u);
        EXPECT_EQ(s.objects[1].texture[0].pigment.maps->list[0].colour.rgb.r, 0.5f);
        const Point3 p = s.objects[2].transform.point(Point3(1, 1, 1));
        EXPECT_EQ(p.y, 2);
        EXPECT_EQ(p.z, 4);
    }
    EXPECT_EQ(debug_of("#for (I 0 4 2) #debug str(I, 0, 0) #end "
                       "#for (I, 0, 2,) #debug str(I, 0, 0) #end "
                       "#switch (3) #range (1 5) #debug \"in\" #break #end"),
              "024012in");
    EXPECT_EQ(error_of("#for (I, 0, 4, 2,) #end"),
              "test.pov:1:17: error: expected ')' but found ','");
    EXPECT_EQ(error_of("#switch (3) #range (1, 5,) #end"),
              "test.pov:1:25: error: expected ')' but found ','");
}

// A list pattern's entries each take an optional comma after them, the last one too
// (POV-Ray's Parse_Blend_List): exporters and hand-written scenes end lists with one.
size_t top_layer_map_entries(const Scene& s, size_t object) {
    const Texture& t = s.objects.at(object).texture.back();
    return t.map.allocated() ? t.map->entries.size() : 0;
}

TEST(Commas, AfterTheLastEntryOfAListPattern) {
    Scene s = parse(
        "plane { y, 0 pigment { checker rgb 1, rgb <0.8, 0.6, 0.4>, } }\n"
        "plane { y, 0 pigment { hexagon pigment { rgb 1 }, pigment { rgb 0.5 }, "
        "pigment { rgb 0.2 }, } }\n"
        "plane { y, 0 normal { brick normal { bumps }, normal { dents }, 0.4 } }\n"
        "plane { y, 0 texture { checker texture { pigment { rgb 1 } }, texture { "
        "pigment { rgb 0 } }, } }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    const auto& colours = s.objects[0].texture[0].pigment.maps->list;
    ASSERT_EQ(colours.size(), 2u);
    EXPECT_EQ(colours[1].colour.rgb.g, 0.6f);
    EXPECT_EQ(s.objects[1].texture[0].pigment.maps->list.size(), 3u);
    ASSERT_TRUE(s.objects[2].texture[0].normal);
    EXPECT_EQ(s.objects[2].texture[0].normal->list.size(), 2u);
    EXPECT_EQ(s.objects[2].texture[0].normal->amount, double(0.4f));  // a single
    EXPECT_EQ(top_layer_map_entries(s, 3), 2u);
}

// #read and #write: commas between the items optional (the #debug output is POV-Ray
// 3.7.0.10's for the same scene).
TEST(Commas, ReadAndWriteArguments) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "povwall_syntax_test_rw";
    fs::create_directories(dir);
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.output_dir = dir.string();
    parse_scene_text(
        "#fopen F \"rw1.txt\" write\n"
        "#write (F \"1, 2,\" 3 \",\\n\")\n"
        "#write (F, \"\\\"a\\\"\", \",\", 4, \"\\n\")\n"
        "#fclose F\n"
        "#fopen F \"rw1.txt\" read\n"
        "#read (F A B C)\n"
        "#read (F, S, D)\n"
        "#fclose F\n"
        "#debug concat(str(A + B + C, 0, 0), S, str(D, 0, 0))\n",
        (dir / "rw.pov").string(), o);
    EXPECT_EQ(messages.str(), "6a4");
    std::ifstream in(dir / "rw1.txt");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "1, 2,3,\n\"a\",4\n");
}

const Texture& top_layer(const Scene& s, size_t object) {
    return s.objects.at(object).texture.back();
}

TEST(RepeatedBlocks, ASecondFinishContinuesFromTheFirst) {
    Scene s = parse(
        "sphere { 0, 1 texture { pigment { rgb 1 } finish { ambient 0.3 diffuse 0.4 }\n"
        "  finish { phong 0.8 reflection 0.2 } } }\n"
        "#declare F = finish { ambient 0.5 phong 0.3 phong_size 20 };\n"
        "sphere { 0, 1 finish { F phong 1 } }\n"
        "sphere { 0, 1 finish { phong 0.5 } finish { F } }\n"
        "sphere { 0, 1 finish { diffuse albedo 0.6 brilliance 3 phong albedo 0.5 } }\n");
    const Finish& a = *top_layer(s, 0).finish;
    EXPECT_FLOAT_EQ(a.ambient.r, 0.3f);
    EXPECT_FLOAT_EQ(a.diffuse, 0.4f);
    EXPECT_FLOAT_EQ(a.phong, 0.8f);
    EXPECT_FLOAT_EQ(a.reflection_max.g, 0.2f);
    const Finish& b = *top_layer(s, 1).finish;
    EXPECT_FLOAT_EQ(b.ambient.r, 0.5f);
    EXPECT_FLOAT_EQ(b.phong, 1.0f);
    EXPECT_FLOAT_EQ(b.phong_size, 20.0f);
    // An identifier first replaces what the block edits.
    EXPECT_FLOAT_EQ(top_layer(s, 2).finish->phong, 0.3f);
    // Albedo scales by the values the block ends with: 0.6 * (3 + 1) / 2, 0.5 * 41 / 2.
    EXPECT_FLOAT_EQ(top_layer(s, 3).finish->diffuse, 1.2f);
    EXPECT_FLOAT_EQ(top_layer(s, 3).finish->phong, 10.25f);
    // The identifier only as the first item.
    EXPECT_EQ(
        error_of(
            "#declare F = finish { phong 1 };\nsphere { 0, 1 finish { ambient 1 F } }"),
        "test.pov:2:34: error: expected a finish item or '}' but found 'F'");
}

TEST(RepeatedBlocks, ASecondPigmentEditsTheFirst) {
    Scene s = parse(
        "sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [1 rgb <0, 0, 1>] } "
        "scale 2 } pigment { gradient y } }\n"
        "sphere { 0, 1 pigment { rgb <1, 0, 0> } pigment { translate x } }\n"
        "sphere { 0, 1 pigment { checker rgb 1 rgb 0 } pigment { checker rgb 0.5 } }\n"
        "sphere { 0, 1 pigment { brick brick_size <1, 2, 3> mortar 0.1 } "
        "pigment { brick } }\n"
        "sphere { 0, 1 pigment { spiral1 5 } pigment { brick } }\n"
        "sphere { 0, 1 pigment { bozo color_map { [0 rgb 1] [1 rgb 0] } } "
        "pigment { checker } }\n");
    const Pigment& g = top_layer(s, 0).pigment;
    EXPECT_EQ(g.pattern->kind, PatternKind::Gradient);
    expect_vec(g.pattern->vector, 0, 1, 0);
    ASSERT_EQ(g.maps->colour_map.size(), 2u);  // the map stays
    EXPECT_FLOAT_EQ(g.maps->colour_map[1].colour.rgb.b, 1.0f);
    EXPECT_DOUBLE_EQ(g.pattern->transform.point(Point3(1, 1, 1)).y,
                     2);  // so does the scale
    const Pigment& red = top_layer(s, 1).pigment;
    EXPECT_EQ(red.pattern->kind, PatternKind::Solid);
    EXPECT_FLOAT_EQ(red.colour.rgb.r, 1.0f);
    // A blend list replaces the earlier one (the missing entry is the default's).
    ASSERT_EQ(top_layer(s, 2).pigment.maps->list.size(), 1u);
    EXPECT_FLOAT_EQ(top_layer(s, 2).pigment.maps->list[0].colour.rgb.r, 0.5f);
    // brick keeps its size and mortar when it was brick already; other parameters are
    // the new pattern's own.
    expect_vec(top_layer(s, 3).pigment.pattern->vector2, 1, 2, 3);
    EXPECT_DOUBLE_EQ(top_layer(s, 3).pigment.pattern->scalar, 0.1);
    expect_vec(top_layer(s, 4).pigment.pattern->vector2, 0, 0, 0);
    EXPECT_DOUBLE_EQ(top_layer(s, 4).pigment.pattern->scalar, 0);
    EXPECT_TRUE(top_layer(s, 5).pigment.maps->colour_map.empty());
}

TEST(RepeatedBlocks, NormalsAndInteriors) {
    Scene s = parse(
        "#declare N = normal { dents 0.7 };\n"
        "sphere { 0, 1 normal { bumps 0.6 scale 0.2 } normal { scale 2 } }\n"
        "sphere { 0, 1 normal { N 0.3 } }\n"
        "sphere { 0, 1 interior { ior 1.5 } interior { fade_distance 2 } }\n"
        "#declare I = interior { caustics 0.5 };\n"
        "sphere { 0, 1 interior { ior 1.5 } interior { I fade_power 3 } }\n");
    const Normal& n = *top_layer(s, 0).normal;
    EXPECT_EQ(n.pattern->kind, PatternKind::Bumps);
    EXPECT_EQ(n.amount, double(0.6f));  // single precision, as POV-Ray keeps it
    EXPECT_NEAR(n.pattern->transform.point(Point3(1, 0, 0)).x, 0.4, 1e-15);
    EXPECT_EQ(top_layer(s, 1).normal->pattern->kind, PatternKind::Dents);
    EXPECT_DOUBLE_EQ(top_layer(s, 1).normal->amount, 0.3);
    ASSERT_TRUE(s.objects[2].interior);
    EXPECT_FLOAT_EQ(s.objects[2].interior->ior, 1.5f);
    EXPECT_FLOAT_EQ(s.objects[2].interior->fade_distance, 2.0f);
    // An identifier first replaces the interior.
    EXPECT_FLOAT_EQ(s.objects[3].interior->ior, 1.0f);
    EXPECT_FLOAT_EQ(s.objects[3].interior->caustics, 0.5f * 45);
    EXPECT_FLOAT_EQ(s.objects[3].interior->fade_power, 3.0f);
}

TEST(RepeatedBlocks, LoosePartsEditTheTopLayer) {
    Scene s = parse(
        "sphere { 0, 1 texture { pigment { rgb 1 } }\n"
        "  texture { pigment { rgbt <0, 0, 1, 0.5> } finish { phong 1 } }\n"
        "  pigment { rgbt <0, 1, 0, 0.5> } }\n"
        "#declare T = texture { pigment { rgb <1, 0, 0> } finish { diffuse 0.2 } };\n"
        "sphere { 0, 1 texture { T } finish { ambient 0.5 } }\n"
        "sphere { 0, 1 pigment { gradient x } pigment { scale 2 } finish { phong 1 } }\n"
        "sphere { 0, 1 material { texture { pigment { rgb 1 } } scale 3 } }\n");
    ASSERT_EQ(s.objects[0].texture.size(), 2u);
    EXPECT_FLOAT_EQ(s.objects[0].texture[0].pigment.colour.rgb.r, 1.0f);
    EXPECT_FLOAT_EQ(top_layer(s, 0).pigment.colour.rgb.g, 1.0f);
    EXPECT_FLOAT_EQ(top_layer(s, 0).pigment.colour.rgb.b, 0.0f);
    EXPECT_FLOAT_EQ(top_layer(s, 0).finish->phong, 1.0f);
    EXPECT_FLOAT_EQ(top_layer(s, 1).pigment.colour.rgb.r, 1.0f);
    EXPECT_FLOAT_EQ(top_layer(s, 1).finish->diffuse, 0.2f);
    EXPECT_FLOAT_EQ(top_layer(s, 1).finish->ambient.r, 0.5f);
    EXPECT_EQ(top_layer(s, 2).pigment.pattern->kind, PatternKind::Gradient);
    EXPECT_DOUBLE_EQ(top_layer(s, 2).pigment.pattern->transform.point(Point3(1, 0, 0)).x,
                     2);
    // A material's transform moves its textures, not the object.
    EXPECT_DOUBLE_EQ(s.objects[3].transform.point(Point3(1, 0, 0)).x, 1);
    EXPECT_DOUBLE_EQ(top_layer(s, 3).pigment.pattern->transform.point(Point3(1, 0, 0)).x,
                     3);
    // Nothing layers over a patterned texture.
    const std::string checker =
        "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } "
        "texture { pigment { rgb 0 } } }";
    EXPECT_EQ(error_of(checker + " pigment { rgb 1 } }"),
              "test.pov:1:95: error: cannot layer over a patterned texture");
    EXPECT_EQ(error_of(checker + " texture { pigment { rgb 1 } } }"),
              "test.pov:1:95: error: cannot layer over a patterned texture");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { rgb 1 } texture { checker } }"),
              "test.pov:1:33: error: cannot layer a patterned texture over another");
}

TEST(RepeatedBlocks, DefaultsAccumulateAndDeclarationsStartFromThem) {
    Scene s = parse(
        "#default { finish { ambient 0.4 } }\n"
        "#default { finish { diffuse 0.3 } }\n"
        "sphere { 0, 1 }\n"
        "#default { pigment { rgb <1, 0, 0> } }\n"
        "#default { pigment { scale 2 } }\n"
        "#declare P = pigment { translate x };\n"
        "sphere { 0, 1 pigment { P } }\n"
        "#default { texture { finish { phong 1 } } }\n"
        "#default { texture { normal { bumps 0.4 } } }\n"
        "sphere { 0, 1 }\n");
    const Finish& f = *top_layer(s, 0).finish;
    EXPECT_FLOAT_EQ(f.ambient.r, 0.4f);
    EXPECT_FLOAT_EQ(f.diffuse, 0.3f);
    const Pigment& p = top_layer(s, 1).pigment;
    EXPECT_FLOAT_EQ(p.colour.rgb.r, 1.0f);
    EXPECT_DOUBLE_EQ(p.pattern->transform.point(Point3(1, 0, 0)).x, 3);  // scale, move
    const Texture& t = top_layer(s, 2);
    EXPECT_FLOAT_EQ(t.finish->phong, 1.0f);
    EXPECT_FLOAT_EQ(t.finish->ambient.r, 0.4f);
    ASSERT_TRUE(t.normal);
    EXPECT_EQ(t.normal->amount, double(0.4f));  // single precision
    EXPECT_EQ(error_of("#default { texture { pigment { rgb 1 } } texture { } }"),
              "(no error)");
    EXPECT_EQ(error_of("#declare T = texture { pigment { rgb 1 } } texture { };\n"
                       "#default { texture { T } }"),
              "test.pov:2:12: error: the default texture cannot be layered");
    EXPECT_EQ(error_of("#default { texture { checker } }"),
              "test.pov:1:12: error: the default texture cannot be patterned");
}

}  // namespace
}  // namespace povwall::parser

namespace povwall::parser {
namespace {

// Forms real scenes write that POV-Ray 3.7 reads (found in public scenes).
TEST(RealSceneForms, NoColourIsBlack) {
    // POV-Ray's Parse_Colour leaves the colour black when none follows.
    const Scene s =
        parse("light_source { <1, 20, -5> }\nsphere { 0, 1 pigment { color } }");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].colour.r, 0.0f);
    EXPECT_EQ(s.lights[0].colour.g, 0.0f);
    EXPECT_EQ(s.lights[0].colour.b, 0.0f);
}

TEST(RealSceneForms, BareObjectIdentifierInCsg) {
    // A declared object named bare inside a CSG is a child (POV-Ray's Parse_Object).
    const Scene s = parse(
        "#declare S = sphere { <0, 0, -1>, 0.8 }\n"
        "#declare B = box { -1, 1 }\n"
        "difference { box { -1, 1 } S }\n"
        "union { light_source { 0, 1 } S B }\n"
        "object { S bounded_by { B } clipped_by { B S } }\n");
    ASSERT_EQ(s.objects.size(), 3u);
    const Csg* a = std::get_if<Csg>(&s.objects[0].shape);
    ASSERT_NE(a, nullptr);
    ASSERT_EQ(a->children.size(), 2u);
    EXPECT_NE(std::get_if<Sphere>(&a->children[1].shape), nullptr);
    const Csg* b = std::get_if<Csg>(&s.objects[1].shape);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->children.size(), 2u);
    // In bounded_by and clipped_by too.
    ASSERT_EQ(s.objects[2].bounded_by->size(), 1u);
    EXPECT_NE(std::get_if<Box>(&(*s.objects[2].bounded_by)[0].shape), nullptr);
    ASSERT_EQ(s.objects[2].clipped_by->size(), 2u);
    EXPECT_NE(std::get_if<Sphere>(&(*s.objects[2].clipped_by)[1].shape), nullptr);
}

TEST(RealSceneForms, ObjectIdentifierFirstInCsgIsTheResult) {
    // POV-Ray's Parse_Object_Id: first in the braces, a declared object is copied as the
    // result, whatever its kind, and only modifiers may follow.
    const Scene s = parse(
        "#declare S = sphere { <0, 0, -1>, 0.8 }\n"
        "#declare U = union { box { -1, 1 } sphere { 0, 1.2 } }\n"
        "intersection { S pigment { rgb <1, 0, 0> } translate x }\n"
        "union { U }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const Sphere* sphere = std::get_if<Sphere>(&s.objects[0].shape);
    ASSERT_NE(sphere, nullptr);
    ASSERT_EQ(s.objects[0].texture.size(), 1u);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}).x, 1.0);
    const Csg* u = std::get_if<Csg>(&s.objects[1].shape);
    ASSERT_NE(u, nullptr);
    EXPECT_EQ(u->children.size(), 2u);
    // POV-Ray: "No matching } in 'difference', object found".
    EXPECT_EQ(error_of("#declare S = sphere { 0, 1 }\n"
                       "#declare D = difference { box { -1, 1 } S }\n"
                       "difference { D S }"),
              "test.pov:3:16: error: expected an object modifier or '}' but found 'S'");
}

// String relational operators (POV-Ray 3.7's Parse_Rel_String_Term; the values are in
// tests/lang/string_relations.pov): a string can only be the left side of a comparison
// with one string, and nothing tighter than `&` or `|` may follow that comparison. The
// mixes POV-Ray 3.7 rejects are errors with its reason (its messages, in our form).
TEST(StringRelations, MixesPovRayRejects) {
    const std::string v = "#version 3.7;\n";
    // POV-Ray: "Expected 'string comparison operator', ) found instead".
    EXPECT_EQ(error_of(v + "#if (\"a\") #end"),
              "test.pov:2:9: error: expected a string comparison operator but found ')'");
    EXPECT_EQ(
        error_of(v + "#if (\"a\" + \"b\") #end"),
        "test.pov:2:10: error: expected a string comparison operator but found '+'");
    EXPECT_EQ(
        error_of(v + "#declare X = (\"a\" & 1);"),
        "test.pov:2:19: error: expected a string comparison operator but found '&'");
    EXPECT_EQ(
        error_of(v + "#if ((\"a\") = \"a\") #end"),
        "test.pov:2:10: error: expected a string comparison operator but found ')'");
    EXPECT_EQ(
        error_of(v + "#if (1 & \"a\") #end"),
        "test.pov:2:13: error: expected a string comparison operator but found ')'");
    EXPECT_EQ(
        error_of(v + "#if (1 ? \"a\" : \"b\") #end"),
        "test.pov:2:14: error: expected a string comparison operator but found ':'");
    EXPECT_EQ(
        error_of(v + "#declare X = sin(\"a\");"),
        "test.pov:2:21: error: expected a string comparison operator but found ')'");
    // POV-Ray: "Expected 'string expression', float function 'float constant' found".
    EXPECT_EQ(error_of(v + "#if (\"a\" < 1) #end"),
              "test.pov:2:12: error: expected a string but found '1'");
    EXPECT_EQ(error_of(v + "#if (\"a\" = (\"a\")) #end"),
              "test.pov:2:12: error: expected a string but found '('");
    // POV-Ray: "Expected 'numeric expression', string literal found instead".
    EXPECT_EQ(error_of(v + "#if (1 < \"a\") #end"),
              "test.pov:2:6: error: expected a numeric expression but found string");
    EXPECT_EQ(error_of(v + "#if (1 + \"a\" = \"b\") #end"),
              "test.pov:2:6: error: expected a numeric expression but found string");
    EXPECT_EQ(error_of(v + "#if (-\"a\" < \"b\") #end"),
              "test.pov:2:6: error: expected a numeric expression but found string");
    // POV-Ray: "Expected ')', < found instead": the comparison is the whole term.
    EXPECT_EQ(error_of(v + "#if (\"a\" < \"b\" < \"c\") #end"),
              "test.pov:2:16: error: expected ')' to close the condition but found '<'");
    EXPECT_EQ(error_of(v + "#if (\"a\" < \"b\" + 1) #end"),
              "test.pov:2:16: error: expected ')' to close the condition but found '+'");
    EXPECT_EQ(error_of(v + "#if (1 & \"a\" = \"a\" = 1) #end"),
              "test.pov:2:20: error: expected ')' to close the condition but found '='");
    // A declared string is the string alone (POV-Ray's Parse_RValue): "Expected
    // 'object or directive', < found instead".
    EXPECT_NE(error_of(v + "#declare X = \"a\" < \"b\";"), "(no error)");
    // Float and vector positions read sums only, as for numbers: `str("a" < "b", 0, 0)`
    // is an error in POV-Ray too; parenthesised, the comparison is a float.
    EXPECT_NE(error_of(v + "#debug str(\"a\" < \"b\", 0, 0)"), "(no error)");
    EXPECT_EQ(debug_of(v + "#debug str((\"a\" < \"b\"), 0, 0)"), "1");
}

// A declared float, vector or colour without its ';' (POV-Ray 3.7's Parse_Semi_Colon):
// the value ends at the next directive or macro call, which runs after the identifier
// is declared; from #version 3.5 on a missing ';' is POV-Ray's error, from 3.1 its
// "possible parse error" (a warning), before 3.1 nothing (values:
// tests/lang/legacy_semicolons.pov, with POV-Ray's output).
TEST(LegacySemicolons, WhenPovRayAcceptsThem) {
    const std::string body =
        "#declare X = 1\n#declare Y = X + 1\n"
        "#debug concat(str(X, 0, 0), str(Y, 0, 0))\n";
    const std::string warning =
        "warning: All #version and #declares of float, vector, and color require "
        "semi-colon ';' at end.";
    std::string out;
    parse("#version 3.0;\n" + body, &out);
    EXPECT_EQ(out, "12");
    parse("#version 3.1;\n" + body, &out);
    EXPECT_EQ(out, "test.pov:2:1: " + warning + "\n#declare X = 1\n^~~~~~~~\n" +
                       "test.pov:3:1: " + warning + "\n#declare Y = X + 1\n^~~~~~~~\n12");
    const std::string error =
        "error: All #declares of float, vector, and color require semi-colon ';' at "
        "end if the language version is set to 3.5 or higher. Either add the "
        "semi-colon or set the language version to 3.1 or lower.";
    EXPECT_EQ(error_of("#version 3.5;\n" + body), "test.pov:2:1: " + error);
    EXPECT_EQ(error_of(body), "test.pov:1:1: " + error);  // no #version: 3.7
    EXPECT_EQ(error_of("#declare C = rgb <1, 0, 0>\nsphere { 0, 1 }"),
              "test.pov:1:1: " + error);
    // POV-Ray 3.7 rejects these too: the value ends at the #else.
    EXPECT_EQ(error_of("#declare N = 1;\n#declare R = #if (N > 0) N #else 0 #end;"),
              "test.pov:2:1: " + error);
    EXPECT_EQ(error_of("#macro Mx(A, B) #if (A > B) A #else B #end #end\n"
                       "#declare R = Mx(3, 2);"),
              "test.pov:2:1: " + error);
    // Other values only allow a ';'.
    EXPECT_EQ(debug_of("#declare S = \"a\"\n#declare P = pigment { rgb 1 }\n#debug S"),
              "a");
    // #version itself: the warning from 3.1 on, never the error.
    parse("#version 3.0\n#declare X = 1\n#debug str(X, 0, 0)", &out);
    EXPECT_EQ(out, "1");
    parse("#version 3.6\n#declare X = 1;\n#debug str(X, 0, 0)", &out);
    EXPECT_EQ(out, "test.pov:1:1: " + warning + "\n#version 3.6\n^~~~~~~~\n1");
}

TEST(LegacySemicolons, MacroCallsAndLocals) {
    // #version 3.1 (macros need it): what POV-Ray 3.7 prints, besides its 4 warnings
    // (X, M, the #local L, K).
    std::string out;
    parse(
        "#version 3.1;\n"
        "#macro Twice(A) (2 * A) #end\n"
        "#macro Note(T) #debug concat(\"note \", T, \"\\n\") #end\n"
        "#macro Inner() #local L = 10 #debug concat(\"L=\", str(L, 0, 0), \"\\n\") L "
        "#end\n"
        "#declare X = 1\n"
        "#declare M = Twice(X)\n"
        "Note(str(M, 0, 0))\n"
        "#declare K = Inner()\n"
        "#debug concat(\"K=\", str(K, 0, 0), \"\\n\")\n",
        &out);
    std::string lines;
    int warnings = 0;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
        if (line.find(": warning: All #version and #declares") != std::string::npos)
            ++warnings;
        if (line == "note 2" || line == "L=10" || line == "K=10") lines += line + " ";
    }
    EXPECT_EQ(lines, "note 2 L=10 K=10 ") << out;
    EXPECT_EQ(warnings, 4) << out;
    EXPECT_EQ(out.find("error"), std::string::npos) << out;
}

// A carriage return alone ends a line (classic Mac files, a PoseRay export), as POV-Ray
// reads it: a // comment stops there, and errors name the right line; CR LF is one break.
TEST(LineEndings, CarriageReturnAloneEndsALine) {
    EXPECT_EQ(debug_of("// comment\r#debug \"a\"\r// more\r#debug \"b\""), "ab");
    EXPECT_EQ(error_of("#declare A = 1;\r// c\rsphere { 0, 1 foo }"),
              "test.pov:3:15: error: expected an object modifier or '}' but found 'foo'");
    EXPECT_EQ(error_of("#declare A = 1;\r\n// c\r\nsphere { 0, 1 foo }"),
              "test.pov:3:15: error: expected an object modifier or '}' but found 'foo'");
}

}  // namespace
}  // namespace povwall::parser
