// POV-Ray 3.7's optional commas (notes/parser-rules.md §1): optional exactly where 3.7
// reads them with Parse_Comma, required where it loops on a comma. The #debug outputs
// below are what POV-Ray 3.7.0.10 prints for the same lines.
#include <gtest/gtest.h>

#include <sstream>

#include "parser/parser.h"

namespace povwall::parser {
namespace {

Scene parse(const std::string& text, std::string* debug = nullptr) {
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    Scene s = parse_scene_text(text, "test.pov", o);
    if (debug) *debug = messages.str();
    return s;
}

std::string debug_of(const std::string& text) {
    std::string out;
    parse(text, &out);
    return out;
}

// The first line of the error a scene stops with.
std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        const std::string what = e.what();
        return what.substr(0, what.find('\n'));
    }
    return "(no error)";
}

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
        const Cone& cone = std::get<Cone>(s.objects[2].shape);
        EXPECT_EQ(cone.base_radius, 1);
        EXPECT_EQ(cone.cap_radius, 0.5);
        expect_vec(cone.cap, 0, 1, 0);
        EXPECT_EQ(std::get<Cylinder>(s.objects[3].shape).radius, 2);
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
        const Mesh& mesh = std::get<Mesh>(s.objects[0].shape);
        ASSERT_EQ(mesh.faces.size(), 2u) << faces;
        EXPECT_EQ(mesh.faces[0].texture, 1) << faces;
        EXPECT_EQ(mesh.faces[1].texture, 0) << faces;
    }
    // An index may be any float expression.
    Scene s = parse("#declare T = 1;\n" + head + "<0 1 2> T <0,1,2>, T-1 } }");
    EXPECT_EQ(std::get<Mesh>(s.objects[0].shape).faces[0].texture, 1);
    EXPECT_EQ(std::get<Mesh>(s.objects[0].shape).faces[1].texture, 0);
    EXPECT_EQ(error_of(head + "<0 1 2> 0 2 <0 1 2> } }"),
              "test.pov:1:142: error: mesh2 texture index out of range");
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

}  // namespace
}  // namespace povwall::parser
