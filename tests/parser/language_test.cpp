// Scene-language behaviour that real scenes and include files rely on: optional commas,
// expression levels, identifiers of every kind, tolerance of unused unsupported features.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "parser/parser.h"
#include "parser/source.h"
#include "tests/parser/parse_helpers.h"
#include "tests/scratch_folder.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::full_error_of;
using test::parse;

void expect_vec_near(const Vector3& v, double x, double y, double z) {
    EXPECT_NEAR(v.x, x, 1e-9);
    EXPECT_NEAR(v.y, y, 1e-9);
    EXPECT_NEAR(v.z, z, 1e-9);
}

TEST(Syntax, CommasAreOptionalAndTrailingCommasAccepted) {
    Scene s = parse(
        "box { <-0.5, 0, -0.5> <0.5, 10, 0.5> }\n"
        "sphere { < -1 0 0 > 2 }\n"
        "cylinder { 0 y 0.5 }\n"
        "sphere { 0, 1 pigment { color rgb <0.2, 0.1, 0.5,> } }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    const Box& b = std::get<Box>(s.objects[0].shape);
    expect_vec_near(b.corner1, -0.5, 0, -0.5);
    expect_vec_near(b.corner2, 0.5, 10, 0.5);
    const Sphere& sp = std::get<Sphere>(s.objects[1].shape);
    expect_vec_near(sp.centre, -1, 0, 0);
    EXPECT_EQ(sp.radius, 2);
    // A cylinder is the unit cylinder in POV-Ray's frame: from its second point (z = 0)
    // to its first (z = 1), radius 1 scaled to its own.
    const Cylinder& c = std::get<Cylinder>(s.objects[2].shape);
    EXPECT_EQ(c.radius, 1);
    const CompactTransform& frame = s.objects[2].transform;
    expect_vec_near(frame.point({0, 0, 0}), 0, 1, 0);
    expect_vec_near(frame.point({0, 0, 1}), 0, 0, 0);
    EXPECT_NEAR(length(frame.point({1, 0, 0}) - frame.point({0, 0, 0})), 0.5, 1e-12);
    EXPECT_FLOAT_EQ(s.objects[3].texture[0].pigment.colour.rgb.b, 0.5f);
}

TEST(Syntax, ComparisonsNeedParenthesesInFloatPositions) {
    // POV-Ray's Parse_Float reads sums only; `<` after a vector starts the next vector.
    std::string out;
    parse("#declare A = 2 < 3;\n#debug str(A, 0, 0)\n#debug str((1 > 2) + 5, 0, 0)\n",
          &out);
    EXPECT_EQ(out, "15");
}

TEST(Identifiers, ArrayElementsStandWhereIdentifiersDo) {
    Scene s = parse(
        "#declare T = array[2]\n"
        "#declare T[0] = texture { pigment { rgb <1, 0, 0> } }\n"
        "#declare T[1] = texture { pigment { rgb <0, 0, 1> } }\n"
        "#declare O = array[1] { sphere { 0, 3 } }\n"
        "object { O[0] texture { T[1] } }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).radius, 3);
    EXPECT_FLOAT_EQ(s.objects[0].texture[0].pigment.colour.rgb.b, 1.0f);
    EXPECT_EQ(full_error_of("#declare A = array[3]\n#declare B = A[1] + 1;"),
              "test.pov:2:14: error: array element 'A[1]' used before it was set\n"
              "#declare B = A[1] + 1;\n"
              "             ^~~~");
}

// As in POV-Ray 3.7 (its output: "1 5 7 1"): assigning an array copies it, while a
// macro's identifier argument still refers to the caller's array. A shared array also let
// `#declare C[0] = C;` make a cycle that was never freed (the scene fuzzer's leak; the
// sanitizer build's leak check sees it).
TEST(Identifiers, ArrayAssignmentCopiesAndMacroArgumentsRefer) {
    std::string out;
    parse(
        "#declare A = array[2] {1, 2};\n#declare B = A;\n#declare B[0] = 5;\n"
        "#macro Set(P) #declare P[1] = 7; #end\nSet(A)\n"
        "#declare C = array[1];\n#declare C[0] = C;\n"
        "#debug concat(str(A[0], 0, 0), \" \", str(B[0], 0, 0), \" \", "
        "str(A[1], 0, 0), \" \", str(defined(C[0]), 0, 0))\n",
        &out);
    EXPECT_EQ(out, "1 5 7 1");
}

TEST(Identifiers, LayeredTextureDeclarationAndBareObjectStatement) {
    Scene s = parse(
        "#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt <0, 0, 0, "
        "0.5> } }\n"
        "#declare Ball = sphere { 0, 1 texture { L } }\n"
        "Ball\n");
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.objects[0].texture.size(), 2u);
    EXPECT_FLOAT_EQ(s.objects[0].texture[1].pigment.colour.transmit, 0.5f);
}

TEST(Tolerance, UnusedUnsupportedDeclarationsDoNotStopTheParse) {
    std::string out;
    Scene s = parse(
        "#declare F = function { x * y }\n"
        "#declare Q = quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }\n"
        "#declare deprecated once \"old\" D = 4;\n"
        "#debug str(D, 0, 0)\n"
        "sphere { 0, 1 }\n",
        &out);
    EXPECT_EQ(out, "4");
    EXPECT_EQ(s.objects.size(), 1u);
    try {
        parse(
            "#declare Q = lemon { <0, 0, 0>, <0, 1, 0>, 1, 0.5, 0.5 }\nobject { Q "
            "}\n");
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.kind(), ParseError::Kind::Unsupported);
        EXPECT_EQ(std::string(e.what()),
                  "test.pov:2:10: error: unsupported: lemon\nobject { Q }\n         ^");
    }
}

TEST(Textures, TextureMapAndCheckerTextures) {
    Scene s = parse(
        "sphere { 0, 1 texture { gradient x texture_map {\n"
        "  [0.2 pigment { rgb 1 } finish { ambient 0.2 }]\n"
        "  [0.8 texture { pigment { rgb <1, 0, 0> } }] } scale 2 } }\n"
        "box { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { "
        "rgb 0 } } } }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const Texture& t = s.objects[0].texture[0];
    ASSERT_TRUE(t.map_pattern.has_value());
    EXPECT_EQ(t.map_pattern->kind, PatternKind::Gradient);
    ASSERT_EQ(t.map->entries.size(), 2u);
    EXPECT_EQ(t.map->values[0], 0.2f);
    EXPECT_EQ(t.map->entries[0][0].finish->ambient.r, 0.2f);
    EXPECT_FLOAT_EQ(t.map->entries[1][0].pigment.colour.rgb.r, 1.0f);
    // `scale 2` after the map moves the pattern; the entries, evaluated in its space
    // (as POV-Ray's), keep their own transforms.
    EXPECT_NEAR(t.map_pattern->transform.point({1, 1, 1}).x, 2, 1e-12);
    EXPECT_TRUE(t.map->entries[1][0].pigment.pattern->transform.is_identity());
    EXPECT_EQ(s.objects[1].texture[0].map->entries.size(), 2u);
    EXPECT_EQ(s.objects[1].texture[0].map_pattern->kind, PatternKind::Checker);
}

TEST(Textures, PigmentMapEntriesAreBodies) {
    Scene s = parse(
        "#declare P = pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } }\n"
        "sphere { 0, 1 pigment { gradient y pigment_map { [0.01 rgb <1, 0, 0>] [0.5 P "
        "scale 2] } } }\n");
    const Pigment& p = s.objects[0].texture[0].pigment;
    ASSERT_EQ(p.maps->list.size(), 2u);
    EXPECT_FLOAT_EQ(p.maps->list[0].colour.rgb.r, 1.0f);
    EXPECT_EQ(p.maps->list[1].pattern->kind, PatternKind::Bozo);
    EXPECT_NEAR(p.maps->list[1].pattern->transform.point({1, 0, 0}).x, 2, 1e-12);
}

TEST(Textures, DefaultFinishAppliesToLaterTextures) {
    Scene s = parse(
        "sphere { 0, 1 pigment { rgb 1 } }\n"
        "#default { finish { ambient 0.3 diffuse 0.5 } }\n"
        "sphere { 0, 1 pigment { rgb 1 } }\n"
        "sphere { 0, 1 texture { finish { phong 1 } } }\n");
    EXPECT_FLOAT_EQ(s.objects[0].texture[0].finish->ambient.r, 0.1f);
    EXPECT_FLOAT_EQ(s.objects[1].texture[0].finish->ambient.r, 0.3f);
    EXPECT_FLOAT_EQ(s.objects[1].texture[0].finish->diffuse, 0.5f);
    EXPECT_FLOAT_EQ(s.objects[2].texture[0].finish->diffuse, 0.5f);
    EXPECT_FLOAT_EQ(s.objects[2].texture[0].finish->phong, 1.0f);
}

TEST(Camera, LookAtKeepsLengthsAndHandedness) {
    // angle 60 with right 4/3: |direction| = (4/3) / tan(30 deg) / 2.
    Scene s =
        parse("camera { location <0, 0, -5> right x*4/3 angle 60 look_at <0, 0, 0> }");
    double d = (4.0 / 3.0) / std::tan(kPi / 6) / 2;
    expect_vec_near(s.camera.direction, 0, 0, d);
    expect_vec_near(s.camera.right, 4.0 / 3.0, 0, 0);
    expect_vec_near(s.camera.up, 0, 1, 0);
    // A left-handed frame (right -x) flips right only; up stays direction x right.
    Scene l = parse("camera { location <0, 0, -5> right -x up y look_at <5, 0, -5> }");
    expect_vec_near(l.camera.direction, 1, 0, 0);
    expect_vec_near(l.camera.right, 0, 0, 1);
    expect_vec_near(l.camera.up, 0, 1, 0);
    // Items apply in POV-Ray's fixed order: look_at before angle in the file changes
    // nothing.
    Scene o = parse("camera { look_at <0, 0, 0> angle 90 location <0, 0, -5> }");
    expect_vec_near(o.camera.direction, 0, 0, 1.33 / 2);
    // Sky tilts right and up.
    Scene k = parse("camera { location <0, 0, -1> sky x look_at 0 }");
    expect_vec_near(k.camera.right, 0, -1.33, 0);
    expect_vec_near(k.camera.up, 1, 0, 0);
}

TEST(Includes, SearchOrderAndLocationsInsideIncludes) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "povwall_parser_include_test";
    fs::create_directories(dir / "lib");
    std::ofstream(dir / "lib" / "a.inc") << "#declare FromLib = 1;\n";
    std::ofstream(dir / "b.inc") << "#declare FromScene = 2;\n\n  sphere { 0, }\n";
    std::ofstream(dir / "scene.pov") << "#include \"a.inc\"\n#include \"b.inc\"\n";
    ParseOptions o;
    o.library_paths.push_back((dir / "lib").string());
    try {
        parse_scene_file((dir / "scene.pov").string(), o);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        std::string first =
            std::string(e.what()).substr(0, std::string(e.what()).find('\n'));
        EXPECT_EQ(first, (dir / "b.inc").string() +
                             ":3:15: error: expected the sphere's radius but found '}'");
    }
    std::ofstream(dir / "scene.pov") << "#include \"missing.inc\"\n";
    try {
        parse_scene_file((dir / "scene.pov").string(), o);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(std::string(e.what()).substr(0, std::string(e.what()).find('\n')),
                  (dir / "scene.pov").string() +
                      ":1:10: error: cannot find include file \"missing.inc\"");
    }
    fs::remove_all(dir);
}

// POV-Ray looks for an include by its name as given, from the working folder, first: a
// scene rendered from its project's root finds `includes/col.inc` there; the working
// folder's file wins over one of that name beside the scene.
TEST(Includes, TheWorkingFolderComesFirst) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "povwall_parser_include_cwd_test";
    fs::remove_all(dir);
    fs::create_directories(dir / "includes");
    fs::create_directories(dir / "sub" / "includes");
    std::ofstream(dir / "includes" / "col.inc") << "#declare R = 2;\n";
    std::ofstream(dir / "sub" / "includes" / "col.inc") << "#declare R = 3;\n";
    std::ofstream(dir / "sub" / "scene.pov")
        << "#include \"includes/col.inc\"\nsphere { 0, R }\n";
    const fs::path before = fs::current_path();
    fs::current_path(dir);
    const Scene from_root = parse_scene_file("sub/scene.pov", ParseOptions{});
    fs::current_path(dir / "sub");
    const Scene from_sub = parse_scene_file("scene.pov", ParseOptions{});
    fs::current_path(before);
    ASSERT_EQ(from_root.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(from_root.objects[0].shape).radius, 2);
    EXPECT_EQ(std::get<Sphere>(from_sub.objects[0].shape).radius, 3);
    fs::remove_all(dir);
}

// #fopen stays inside the output folder and the scene's folder; data-file errors point
// into the data file; a worker's parse (write_user_files off) writes nothing.
TEST(FileIo, FoldersErrorsAndWorkerParses) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "povwall_parser_fileio_test";
    fs::remove_all(dir);
    fs::create_directories(dir / "out");
    fs::create_directories(dir / "scene");
    ParseOptions o;
    o.output_dir = (dir / "out").string();
    auto first_line_of_error = [&](const std::string& text) -> std::string {
        std::ofstream(dir / "scene" / "s.pov") << text;
        try {
            parse_scene_file((dir / "scene" / "s.pov").string(), o);
        } catch (const ParseError& e) {
            const std::string w = e.what();
            return w.substr(0, w.find('\n'));
        }
        return "(no error)";
    };
    const std::string s = (dir / "scene" / "s.pov").string();
    EXPECT_EQ(first_line_of_error("#fopen F \"../escape.txt\" write"),
              s + ":1:10: error: #fopen: '../escape.txt' is outside the folders a scene "
                  "may write (the output folder and the scene's folder)");
    EXPECT_FALSE(fs::exists(dir / "escape.txt"));
    EXPECT_EQ(
        first_line_of_error("#fopen F \"/etc/passwd\" read"),
        s + ":1:10: error: #fopen: '/etc/passwd' is outside the folders a scene may "
            "read (the output folder, the scene's folder and the library paths)");
    EXPECT_EQ(first_line_of_error("#fopen F \"nope.txt\" read"),
              s + ":1:10: error: cannot open user file \"nope.txt\" for reading");
    EXPECT_EQ(first_line_of_error("#fopen F \"x.txt\" reed"),
              s + ":1:18: error: expected read, write or append but found 'reed'");
    EXPECT_EQ(first_line_of_error("#read (F, A)"),
              s + ":1:8: error: 'F' is not an open file");
    EXPECT_EQ(
        first_line_of_error("#fopen F \"w.txt\" write #read (F, A)"),
        s + ":1:24: error: cannot read from file \"w.txt\": it is open for writing");
    // A relative name is written to the output folder and read back from there first.
    std::ofstream(dir / "scene" / "w.txt") << "\"from the scene folder\"";
    EXPECT_EQ(first_line_of_error("#fopen F \"w.txt\" write #write (F, \"1, \", <2, 3>) "
                                  "#fclose F #fopen F \"w.txt\" read #read (F, A, B) "
                                  "#if (A != 1 | B.y != 3) #error \"wrong\" #end"),
              "(no error)");
    std::ifstream written(dir / "out" / "w.txt");
    std::string line;
    std::getline(written, line);
    EXPECT_EQ(line, "1, <2,3> ");
    // Bad data is located in the data file.
    std::ofstream(dir / "out" / "bad.txt") << "1,\n  2, foo";
    EXPECT_EQ(first_line_of_error("#fopen F \"bad.txt\" read #read (F, A, B, C)"),
              (dir / "out" / "bad.txt").string() +
                  ":2:6: error: expected a float, vector or string literal");
    EXPECT_EQ(first_line_of_error("#declare V = <1, 2>; #fopen F \"bad.txt\" read "
                                  "#read (F, V)"),
              s + ":1:56: error: cannot #read into 'V': it holds a 2-component vector");
    // A worker's parse: the writes go nowhere, the parse goes on.
    o.write_user_files = false;
    EXPECT_EQ(first_line_of_error("#fopen F \"worker.txt\" write #write (F, \"x\") "
                                  "#fclose F"),
              "(no error)");
    EXPECT_FALSE(fs::exists(dir / "out" / "worker.txt"));
    fs::remove_all(dir);
}

// A file of 16 MB or more is mapped instead of copied: it parses like any other, errors
// in it are located, and a scene cannot #fopen it for writing while it is being read.
TEST(SourceText, LargeFilesAreMappedAndProtected) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "povwall_parser_mapped_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string big = (dir / "big.pov").string();
    std::string padding;
    for (int i = 0; i < 280000; ++i)
        padding += "// 64 bytes a line, 17 MB in all ..........................\n";
    auto write_big = [&](const std::string& tail) {
        std::ofstream(big, std::ios::binary) << "sphere { <1, 2, 3>, 0.5 }\n"
                                             << padding << tail;
    };
    write_big("box { 0, 1 }\n");
    SourceText text;
    ASSERT_TRUE(text.read_file(big));
    EXPECT_TRUE(text.mapped());
    EXPECT_EQ(text.size(), 26 + padding.size() + 13);
    EXPECT_EQ(text.view().substr(0, 8), "sphere {");
    SourceText small("sphere { 0, 1 }");
    EXPECT_FALSE(small.mapped());

    ParseOptions o;
    o.output_dir = dir.string();
    Scene s = parse_scene_file(big, o);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).centre, (Point3{1, 2, 3}));
    auto first_line_of_error = [&] {
        try {
            parse_scene_file(big, o);
        } catch (const ParseError& e) {
            const std::string w = e.what();
            return w.substr(0, w.find('\n'));
        }
        return std::string("(no error)");
    };
    write_big("box { 0, 1 ");
    EXPECT_EQ(first_line_of_error(), big +
                                         ":280002:12: error: expected an object modifier "
                                         "or '}' but found end of file");
    write_big("#fopen F \"big.pov\" write");
    EXPECT_EQ(first_line_of_error(),
              big +
                  ":280002:10: error: #fopen: \"big.pov\" is a source "
                  "file being parsed; it cannot be written");
    EXPECT_EQ(fs::file_size(big), 26 + padding.size() + 24);
    fs::remove_all(dir);
}

// A declaration directive allows one more ';' after its value's own (POV-Ray's
// Parse_Declare after `#`): `#local A = 1;;` inside an object is not a stray ';'; a third
// is an error there as in POV-Ray.
TEST(Directives, DeclarationTakesASecondSemicolon) {
    Scene s = parse(R"(
object {
  #local A = 2;;
  #declare B = sphere { 0, 1 };;
  object { B scale A }
}
)");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].transform.point({1, 0, 0}), (Vector3{2, 0, 0}));
    EXPECT_THROW(parse("object {\n  #local A = 2;;;\n  sphere { 0, A }\n}\n"),
                 parser::ParseError);
}

// `#local S = Macro()` whose body ends with '}': the macro's frame is still open when the
// value is bound, yet S belongs to the scope of the macro that holds the #local
// (transforms.inc's Spline_Trans does `#local Matrix = Matrix_Trans(...)`).
TEST(Directives, LocalFromAMacroCallBelongsToTheCallersScope) {
    Scene s = parse(R"(
#macro MakeS() sphere { 0, 1 } #end
#macro Use() #local S = MakeS() object { S translate 2*x } #end
Use()
#ifdef (S) #error "S leaked" #end
)");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}), (Vector3{2, 0, 0}));
}

// A macro whose body ends in the name of its own #local, called as another macro's
// argument (LDCad's LDraw exports: `Pig(getIdx(1))`): the argument is the local's value
// when it was read, though reading on past it ends the inner macro.
TEST(Directives, MacroArgumentThatIsAnotherMacrosLocal) {
    std::string out;
    parse(R"(
#macro Get(C) #local R = C + 1; R #end
#macro Show(A, B) #debug concat(str(A, 0, 0), " ", str(B, 0, 0), ";") #end
Show(Get(1), 7)
Show(7, Get(1))
Show(Get(1) * 10, Get(2) + 1)
#macro Vec(C) #local V = <C, 2, 3>; V #end
Show(Vec(5).x, vlength(Vec(0)))
)",
          &out);
    EXPECT_EQ(out, "2 7;7 2;20 4;5 4;");
}

// `#undef A[i]` unassigns one element (Complex_Functions.inc re-declares elements so);
// #ifdef sees every dimension's subscript; undef of an unassigned element and a
// subscript out of range are POV-Ray's errors.
TEST(Directives, UndefOfAnArrayElement) {
    std::string out;
    parse(R"(
#declare A = array[2][3];
#declare A[1][2] = 5;
#macro Say(B) #debug concat(str(B, 0, 0), ";") #end
Say(defined(A[1][2])) Say(defined(A[0][2]))
#undef A[1][2]
Say(defined(A[1][2]))
#declare A[1][2] = 7;
Say(A[1][2])
)",
          &out);
    EXPECT_EQ(out, "1;0;0;7;");
    auto first_line = [](const std::string& text) {
        const std::string e = error_of(text);
        return e.substr(0, e.find('\n'));
    };
    EXPECT_EQ(first_line("#declare A = array[2];\n#undef A[1]"),
              "test.pov:2:8: error: Attempt to access uninitialized array element.");
    EXPECT_EQ(first_line("#declare A = array[2] {1, 2}\n#undef A[2]"),
              "test.pov:2:10: error: array subscript 2 out of range 0..1");
    EXPECT_EQ(first_line("#declare A = 1;\n#undef A[0]"),
              "test.pov:2:9: error: 'A' is not an array");
}

// A #for variable belongs to the current scope (POV-Ray's Parse_For_Param adds it to the
// innermost table): a macro looping over `i` leaves its caller's `i` alone (a scene's
// nested macros looped forever). The loop runs while within 1e-10 past its end.
// POV-Ray 3.7 (its output: "0 1 1 | -1 2 | 1"): a number's identifier followed by
// another identifier with no comma between is passed as that next identifier, by
// reference (writes go to it); one followed by a literal or a comma is itself. Each
// such argument is named in a warning.
TEST(Directives, IdentifierArgumentsWithoutCommasPassTheNextIdentifier) {
    std::string out;
    parse(
        "#declare P = -1; #declare Q = 0; #declare R = 1;\n"
        "#macro Three(A B C) #debug concat(str(A, 0, 0), \" \", str(B, 0, 0), \" \", "
        "str(C, 0, 0), \" | \") #end\n"
        "#macro Two(A B) #debug concat(str(A, 0, 0), \" \", str(B, 0, 0), \" | \") "
        "#declare A = 5; #end\n"
        "Three(P Q R)\nTwo(P 2)\nTwo(R Q)\n#debug str(Q, 0, 0)\n",
        &out);
    EXPECT_EQ(
        out,
        "test.pov:4:9: warning: macro argument 'P' is followed by 'Q' with no comma: "
        "POV-Ray 3.7 passes 'Q' in its place\nThree(P Q R)\n        ^\n"
        "test.pov:4:11: warning: macro argument 'Q' is followed by 'R' with no comma: "
        "POV-Ray 3.7 passes 'R' in its place\nThree(P Q R)\n          ^\n"
        "0 1 1 | -1 2 | "
        "test.pov:6:7: warning: macro argument 'R' is followed by 'Q' with no comma: "
        "POV-Ray 3.7 passes 'Q' in its place\nTwo(R Q)\n      ^\n"
        "0 0 | 5");
}

TEST(Directives, ForVariableIsLocalToItsMacro) {
    std::string out;
    parse(R"(
#macro Row() #for (i, 1, 2) #debug "r" #end #end
#for (i, 1, 3) Row() #debug concat(str(i, 0, 0), ";") #end
#declare N = 0;
#for (X, 0, 1, 0.1) #declare N = N + 1; #end
#debug concat(str(N, 0, 0), ";")
#for (J, 3, 1, -1) #debug str(J, 0, 0) #end
)",
          &out);
    EXPECT_EQ(out, "rr1;rr2;rr3;11;321");
    const std::string e = error_of("#for (i, 1, 2, 1e-11) #end");
    EXPECT_EQ(e.substr(0, e.find('\n')),
              "test.pov:1:1: error: #for loop increment must be non-zero.");
}

// `declare` and `include` written without '#' between scene items: POV-Ray runs them as
// the directives, with its warning.
TEST(Directives, DeclareAndIncludeWithoutHash) {
    std::string out;
    Scene s = parse(R"(
declare R = 2;
sphere { 0, R }
#debug concat(str(R, 0, 0), ";")
)",
                    &out);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NE(out.find("test.pov:2:1: warning: Should have '#' before 'declare'."),
              std::string::npos);
    EXPECT_NE(out.find("2;"), std::string::npos);
}

// Function-language errors are located; an internal function povwall lacks stops only a
// scene that uses it (functions.inc declares all of them).
TEST(Functions, LocatedErrorsAndTolerance) {
    EXPECT_EQ(error_of("#declare F = function(a) { a }\n#declare B = F(1, 2);"),
              "test.pov:2:17: error: expected ')' after the 1 argument of 'F' but found "
              "','");
    EXPECT_EQ(error_of("#declare F = function(a, b) { a }\n#declare B = F(1);"),
              "test.pov:2:14: error: 'F' takes 2 arguments, not 1");
    EXPECT_EQ(error_of("#declare P = function { pigment { rgb 1 } }\n"
                       "#declare G = function { P(x, y, z) + 1 }"),
              "test.pov:2:25: error: 'P' returns a vector: follow the call with a "
              "component, such as .x");
    EXPECT_EQ(error_of("#declare G = function { foo + 1 }"),
              "test.pov:1:25: error: 'foo' is not a parameter, float or function here");
    EXPECT_EQ(error_of("#declare V = <1, 2, 3>;\n#declare G = function { V * x }"),
              "test.pov:2:25: error: a function works on floats: 'V' is a vector");
    EXPECT_EQ(error_of("#declare G = function { min(x) }"),
              "test.pov:1:25: error: 'min' takes two or more arguments");
    std::string deep = "#declare G = function { ";
    for (int i = 0; i < 150; ++i) deep += "1 + (";
    deep += "x" + std::string(150, ')') + " }";
    EXPECT_EQ(error_of(deep).substr(0, 45),
              "test.pov:1:667: error: function too deeply ne");
    // Runaway loops and call chains are located errors, not hangs or stack overflows.
    EXPECT_EQ(error_of("#declare F = function { sum(i, 0, 1e18, i) }\n"
                       "#declare A = F(0, 0, 0);"),
              "test.pov:2:14: error: sum/prod in 'F' ran more than 10000000 iterations "
              "(--max-loop-iterations)");
    // select runs only the branch it picks, as POV-Ray's compiled jumps: the runaway
    // loop in the other branch is never entered.
    std::string picked;
    parse(
        "#declare F = function(a) { select(a, sum(i, 0, 1e18, i), 5) }\n"
        "#declare G = function(a) { select(a, 1, select(a - 1, 2, 3, sum(i, 0, 1e18, i)),"
        " prod(i, 1, 4, i)) + select(a, 10, 20) }\n"
        "#debug concat(str(F(1), 0, 0), \" \", str(G(-1), 0, 0), \" \", str(G(0), 0, 0), "
        "\" \", str(G(1), 0, 0))",
        &picked);
    EXPECT_EQ(picked, "5 11 22 44");
    EXPECT_EQ(error_of("#declare F = function(a) { select(a, sum(i, 0, 1e18, i), 5) }\n"
                       "#declare A = F(-1);"),
              "test.pov:2:14: error: sum/prod in 'F' ran more than 10000000 iterations "
              "(--max-loop-iterations)");
    EXPECT_EQ(error_of("#declare F = function { select(x, 1) }"),
              "test.pov:1:25: error: 'select' takes 3 or 4 arguments, not 2");
    EXPECT_EQ(error_of("#declare F = function { select(x, 1, 2, 3, 4) }"),
              "test.pov:1:25: error: 'select' takes 3 or 4 arguments, not 5");
    std::string chain = "#declare F0 = function { x }\n";
    for (int i = 1; i < 1100; ++i)
        chain += "#declare F" + std::to_string(i) + " = function { F" +
                 std::to_string(i - 1) + "(x, y, z) + 1 }\n";
    EXPECT_EQ(
        error_of(chain),
        "test.pov:1001:43: error: functions call each other too deeply (limit 1000)");
    // POV-Ray 3.7 has internal(0) ... internal(78); another number is an error where it
    // is declared, with POV-Ray's message.
    EXPECT_EQ(error_of("#declare F = function { internal(78) }\nsphere { 0, 1 }"),
              "(no error)");
    EXPECT_EQ(error_of("#declare F = function { internal(79) }\nsphere { 0, 1 }"),
              "test.pov:1:34: error: Function 'internal(79)' does not exist.");
    // A scene including functions.inc and math.inc parses, and their functions work.
    std::string out;
    parse("#include \"math.inc\"\n#debug str(f_r(1, 2, 2) + sind(30) + f_sqr(3), 0, 6)",
          &out);
    EXPECT_EQ(out, "12.500000");
}

// `now` and datetime(): days since 2000-01-01 UTC (the strings are what povray 3.7.0.10
// printed for the same calls).
TEST(Expressions, NowAndDatetime) {
    std::string out;
    parse(
        "#debug concat(datetime(0), \"|\", datetime(1.5, \"%Y/%m/%d %H:%M\"), \"|\", "
        "datetime(9832.25))",
        &out);
    EXPECT_EQ(out, "2000-01-01 00:00:00Z|2000/01/02 12:00|2026-12-02 06:00:00Z");
    parse("#debug str(now, 0, 6)", &out);
    const double days = (double(std::time(nullptr)) - 946684800.0) / 86400.0;
    EXPECT_NEAR(std::stod(out), days, 0.01);
}

TEST(Lexer, NestedCommentsAndStrayHash) {
    std::string out;
    parse("/* a /* nested */ still comment */ #debug \"x\" // line\n#\n#debug \"y\"\n",
          &out);
    EXPECT_EQ(out, "xy");
}

TEST(Lexer, StringsSpanLinesAsInPovRay) {
    // A line break inside quotes is part of the string (shapes3.inc writes one), and the
    // tokens after it keep their own lines.
    std::string out;
    parse("#declare S = concat(\"one\n two\");\n#debug S\n#debug str(strlen(S), 0, 0)",
          &out);
    EXPECT_EQ(out, "one\n two8");
    EXPECT_EQ(full_error_of("#declare S = \"one\n two\";\n#declare T = Q;").substr(0, 35),
              "test.pov:3:14: error: undeclared id");
    // A backslash right before the break, or no closing quote, is an error.
    EXPECT_EQ(full_error_of("#declare S = \"one\\\n two\";").substr(0, 76),
              "test.pov:1:18: error: unterminated string literal (a backslash before a "
              "line");
    EXPECT_EQ(full_error_of("#declare S = \"one\n two;").substr(0, 42),
              "test.pov:1:14: error: unterminated string\n");
}

// A second point ends a number with an error, as in POV-Ray (a 3.7 scene wrote
// `<1,0,0,0.0.95>`); a point after an integer or a whole number is still a decimal point.
TEST(Lexer, ASecondPointInANumberIsAnError) {
    EXPECT_EQ(
        full_error_of("#declare C = <1, 0, 0, 0.0.95>;").substr(0, 73),
        "test.pov:1:27: error: unexpected additional '.' in floating-point number\n");
    EXPECT_EQ(full_error_of("#declare X = 1e5.2;").substr(0, 32),
              "test.pov:1:17: error: unexpected");
    EXPECT_EQ(full_error_of("#declare X = 12..5;").substr(0, 32),
              "test.pov:1:17: error: unexpected");
    std::string out;
    parse("#declare X = 12.; #declare Y = .5; #debug str(X + Y, 0, 1)", &out);
    EXPECT_EQ(out, "12.5");
}

// Short decimals take an integer-and-division fast path; every literal must read as the
// correctly rounded double that from_chars gives (exact equality, 20,000 random literals
// of 1 to 18 digits with and without fraction, exponent or leading zeros).
TEST(Lexer, NumbersReadExactlyAsFromChars) {
    std::mt19937_64 rng(11);
    std::string text;
    std::vector<std::string> literals = {"0",
                                         "0.1",
                                         "0.3",
                                         ".5",
                                         "5.",
                                         "123456789012345",
                                         "1234567890123456",
                                         "0.000000000000001",
                                         "9007199254740993",
                                         "1e3",
                                         "2.5E-3",
                                         "0007.250"};
    for (int k = 0; k < 20000; ++k) {
        std::string lit;
        const int whole = int(rng() % 10), frac = int(rng() % 10);
        for (int d = 0; d < whole; ++d) lit += char('0' + rng() % 10);
        if (frac > 0 || whole == 0) {
            lit += '.';
            for (int d = 0; d < std::max(frac, 1); ++d) lit += char('0' + rng() % 10);
        }
        if (rng() % 8 == 0) lit += "e" + std::to_string(int(rng() % 40) - 20);
        literals.push_back(lit);
    }
    for (const std::string& l : literals) text += l + " ";
    SourceManager sm;
    const SourceFile& f = sm.file(sm.add("numbers.pov", text));
    ASSERT_EQ(f.tokens.size(), literals.size() + 1);
    for (size_t k = 0; k < literals.size(); ++k) {
        double expected = 0;
        std::from_chars(literals[k].data(), literals[k].data() + literals[k].size(),
                        expected);
        ASSERT_EQ(f.tokens[k].kind, TokenKind::Number) << literals[k];
        EXPECT_EQ(f.tokens[k].number, expected) << literals[k];
    }
}

TEST(Textures, WarpsAndClassicTurbulence) {
    Scene s = parse(
        "sphere { 0, 1 pigment { marble turbulence 0.5 octaves 3\n"
        "  warp { turbulence <1, 2, 3> octaves 4 }\n"
        "  warp { black_hole <1, 0, 0>, 0.5 strength 2 falloff 3 inverse }\n"
        "  warp { planar z, 0.25 } warp { toroidal orientation y dist_exp 1 major_radius "
        "2 } } }\n");
    const auto& w = s.objects[0].texture[0].pigment.pattern->warps;
    ASSERT_EQ(w.size(), 5u);
    EXPECT_TRUE(w[0].classic);
    EXPECT_EQ(w[0].octaves, 3);
    EXPECT_FALSE(w[1].classic);
    expect_vec_near(w[1].turbulence, 1, 2, 3);
    EXPECT_EQ(w[2].kind, Warp::Kind::BlackHole);
    expect_vec_near(w[2].centre, 1, 0, 0);
    EXPECT_EQ(w[2].radius, 0.5);
    EXPECT_EQ(w[2].strength, 2);
    EXPECT_TRUE(w[2].inverse);
    EXPECT_EQ(w[3].kind, Warp::Kind::Planar);
    expect_vec_near(w[3].orientation, 0, 0, 1);
    EXPECT_EQ(w[3].plane_offset, 0.25);
    EXPECT_EQ(w[4].kind, Warp::Kind::Toroidal);
    EXPECT_EQ(w[4].major_radius, 2);
}

TEST(Mesh2, PlainAndComputedVectorsAgree) {
    // The first vertices are plain numbers (fast path), the others expressions.
    Scene s = parse(
        "#declare H = 0.5;\n"
        "mesh2 { vertex_vectors { 4, <0, 0, 0>, <1, -2.5, 0>, <0, 1 + 1, 0> <H, H, -H> "
        "}\n"
        "  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } "
        "}\n"
        "  face_indices { 2, <0, 1, 2>, 1, <1, 2, 3> 0, } }\n");
    const MeshData& m = *std::get<Mesh>(s.objects.at(0).shape).data;
    ASSERT_EQ(m.vertices.size(), 4u);
    expect_vec_near(m.vertices[1], 1, -2.5, 0);
    expect_vec_near(m.vertices[2], 0, 2, 0);
    expect_vec_near(m.vertices[3], 0.5, 0.5, -0.5);
    ASSERT_EQ(m.faces.size(), 2u);
    EXPECT_EQ(m.faces[0].v[2], 2u);
    EXPECT_EQ(m.faces[0].texture, 1);
    EXPECT_EQ(m.faces[1].v[0], 1u);
    EXPECT_EQ(m.faces[1].texture, 0);
    EXPECT_EQ(
        error_of(
            "mesh2 { vertex_vectors { 1, <0, 0, 0> } face_indices { 1, <0, 0, 5> } }"),
        "test.pov:1:59: error: mesh2 face index out of range");
}

TEST(BadInput, LocatedErrorsInsteadOfCrashesOrHangs) {
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { rgb <1, 0"),
              "test.pov:1:34: error: expected '>' to close the vector but found end of "
              "file");
    EXPECT_EQ(
        error_of("union { sphere { 0, 1 }\n"),
        "test.pov:2:1: error: expected an object modifier or '}' but found end of file");
    EXPECT_EQ(error_of("#macro M() M() #end\nM()\n"),
              "test.pov:1:12: error: macro 'M' nested too deeply (limit 1000): runaway "
              "recursion?");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 1e12, <0, 0, 0> } }"),
              "test.pov:1:26: error: list length 1000000000000.000000 out of range");
    // Counts within range that the file cannot hold: the lists reserve only what the
    // tokens left could fill (900,000,000 vertices would be 21.6 GB).
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 900000000, <0, 0, 0> } }"),
              "test.pov:1:47: error: expected an expression but found '}'");
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } "
                       "face_indices { 900000000, <0, 1, 2> } }"),
              "test.pov:1:93: error: expected an expression but found '}'");
    EXPECT_EQ(error_of("#declare A = array[100000][100000][1000];"),
              "test.pov:1:28: error: array too large");
    EXPECT_EQ(error_of("#for (I, 0, 1, 1e-9) #end"),
              "test.pov:1:1: error: #for loop ran 10000000 times: runaway loop? "
              "(--max-loop-iterations)");
}

std::string first_line_with(const std::string& text, const ParseOptions& options) {
    try {
        parse_scene_text(text, "test.pov", options);
    } catch (const ParseError& e) {
        const std::string what = e.what();
        return what.substr(0, what.find('\n'));
    }
    return "(no error)";
}

TEST(BadInput, LoopAndParseTimeLimitsAreSettable) {
    ParseOptions few;
    few.max_loop_iterations = 100;
    EXPECT_EQ(
        first_line_with("#declare I = 0; #while (I < 100) #declare I = I + 1; #end", few),
        "(no error)");
    EXPECT_EQ(first_line_with(
                  "#declare I = 0;\n#while (I < 101) #declare I = I + 1; #end", few),
              "test.pov:2:1: error: #while loop ran 100 times: runaway loop? "
              "(--max-loop-iterations)");
    // A loop inside its iteration limit that runs longer than the time limit.
    ParseOptions quick;
    quick.max_parse_seconds = 0.2;
    const std::string err = first_line_with(
        "#declare I = 0;\n#while (I < 9000000) #declare I = I + 1; #end", quick);
    EXPECT_EQ(err.rfind("test.pov:2:", 0), 0u) << err;
    EXPECT_NE(
        err.find(": error: parse time limit of 0.2 s exceeded (--max-parse-seconds)"),
        std::string::npos)
        << err;
}

}  // namespace
}  // namespace povwall::parser

namespace povwall::parser {
namespace {

// POV-Ray 3.7's input gamma rules, with a stand-in reader giving one pixel of 0.5:
// #version 3.7 decodes PNG as sRGB and leaves PPM linear; bump_map reads raw; an explicit
// gamma wins; a 3.6 scene without assumed_gamma reads raw; assumed_gamma 2.2 re-encodes.
TEST(ImageMap, InputGammaRules) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "povwall_parser_image_test";
    fs::create_directories(dir);
    for (const char* f : {"a.png", "a.ppm"}) std::ofstream(dir / f) << "x";
    ParseOptions o;
    o.image_reader = [](const std::string& path) {
        StoredImage s;
        s.pixels = Image(1, 1);
        for (int c = 0; c < 4; ++c) s.pixels.rgba[size_t(c)] = 0.5f;
        s.format = path.substr(path.size() - 3) == "png" ? "png" : "pnm";
        return s;
    };
    auto red = [&](const std::string& head, const std::string& item) {
        std::ofstream(dir / "s.pov") << head << "\nplane { z, 0 " << item << " }\n";
        Scene s = parse_scene_file((dir / "s.pov").string(), o);
        const Texture& t = s.objects.at(0).texture.at(0);
        const PatternSpec& p =
            t.normal ? t.normal->pattern.get() : t.pigment.pattern.get();
        EXPECT_EQ(p.kind, PatternKind::ImageMap);
        return p.image->pixels->rgbft[0];
    };
    const std::string v37 = "#version 3.7;";
    EXPECT_FLOAT_EQ(red(v37, "pigment { image_map { png \"a.png\" } }"), 0.21404114f);
    EXPECT_FLOAT_EQ(red(v37, "pigment { image_map { ppm \"a.ppm\" } }"), 0.5f);
    EXPECT_FLOAT_EQ(red(v37, "normal { bump_map { png \"a.png\" } }"), 0.5f);
    EXPECT_FLOAT_EQ(red(v37, "pigment { image_map { png \"a\" gamma 2 } }"), 0.25f);
    EXPECT_FLOAT_EQ(red("#version 3.6;", "pigment { image_map { png \"a.png\" } }"),
                    0.5f);
    EXPECT_FLOAT_EQ(red(v37 + " global_settings { assumed_gamma 2.2 }",
                        "pigment { image_map { png \"a.png\" } }"),
                    std::pow(0.21404114f, 1 / 2.2f));
    fs::remove_all(dir);
}

// Only image_map refuses a map_type POV-Ray 3.7 does not know (Parse_Image_Map); a
// bump_map, image_pattern or material_map keeps the number (mapped as planar).
TEST(ImageMap, OnlyImageMapRefusesAnUnknownMapType) {
    namespace fs = std::filesystem;
    const fs::path dir = povwall_test::process_scratch("povwall_parser_map_type");
    std::ofstream(dir / "a.png") << "x";
    ParseOptions o;
    o.image_reader = [](const std::string&) {
        StoredImage s;
        s.pixels = Image(1, 1);
        s.format = "png";
        return s;
    };
    auto parse = [&](const std::string& item) {
        std::ofstream(dir / "s.pov") << "plane { z, 0 " << item << " }\n";
        return parse_scene_file((dir / "s.pov").string(), o);
    };
    try {
        parse("pigment { image_map { png \"a.png\" map_type 3 } }");
        ADD_FAILURE() << "image_map took map_type 3";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.message(), "invalid map_type value");
        EXPECT_EQ(e.loc().column, 57);  // the value
    }
    const Scene bump = parse("normal { bump_map { png \"a.png\" map_type 3 } }");
    EXPECT_EQ(bump.objects.at(0).texture.at(0).normal->pattern->image->map_type, 3);
    const Scene pattern = parse("pigment { image_pattern { png \"a.png\" map_type 4 } }");
    EXPECT_EQ(pattern.objects.at(0).texture.at(0).pigment.pattern->image->map_type, 4);
}

// `function W, H { }` for an image file (Make_Pattern_Image): sample (i, j) is the
// function at (j / (W - 1), i / (H - 1), 0), stored as float(v) * 65535 through a 32-bit
// int into 16 bits (wrapping) and read back as k / 65535; a pigment function's transmit
// becomes alpha and back; no image file, no gamma (a 3.6 scene's assumed_gamma 2.2 too).
TEST(ImageMap, FunctionImagesAreSixteenBitSamplesOfTheFunction) {
    auto pixels_of = [](const std::string& pigment) {
        const Scene s = parse(
            "#version 3.6; global_settings { assumed_gamma 2.2 }\n"
            "plane { z, 0 pigment { " +
            pigment + " } }");
        return s.objects.at(0).texture.at(0).pigment.pattern->image;
    };
    const auto grey = pixels_of("image_map { function 3, 2 { x * 0.5 + y * 1.25 } }");
    ASSERT_TRUE(grey && grey->pixels);
    EXPECT_TRUE(grey->path.empty());
    EXPECT_EQ(grey->width, 3);
    EXPECT_EQ(grey->height, 2);
    auto stored = [](double v) {
        return float(uint16_t(int32_t(float(v) * 65535.0f))) / 65535.0f;
    };
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 3; ++j) {
            float c[5];
            grey->pixels->fetch(j, i, c);
            const float want = stored(j / 2.0 * 0.5 + i * 1.25);
            EXPECT_EQ(c[0], want) << i << "," << j;
            EXPECT_EQ(c[1], want);
            EXPECT_EQ(c[2], want);
            EXPECT_EQ(c[4], 0.0f);
        }
    }
    // 1.25 wraps: 81918 in the int, 16382 in the channel.
    float top[5];
    grey->pixels->fetch(0, 1, top);
    EXPECT_EQ(top[0], 16382.0f / 65535.0f);
    // The pigment function's RGBA form is in the golden scene function_images.
    EXPECT_EQ(error_of("plane { z, 0 pigment { image_map { function 1, 5 { x } } } }"),
              "test.pov:1:45: error: unsupported: image_map function smaller than 2 x 2");
    EXPECT_EQ(
        error_of("plane { z, 0 normal { bump_map { function 4, 4 { x * 1e6 } } } }"),
        "test.pov:1:48: error: unsupported: bump_map function value out of range");
}

// An 8-bit file's pixels are kept as codes with a decoding table (4 bytes a pixel, not 5
// floats): every pixel fetches exactly what the float form gives for the same samples,
// for each gamma rule; a sample that is no 8-bit code keeps the float form.
TEST(ImageMap, EightBitFilesKeepCodesThatFetchAsTheFloats) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "povwall_parser_image_codes_test";
    fs::create_directories(dir);
    std::ofstream(dir / "a.png") << "x";
    int bits = 8;
    float odd = 0;  // when set, the first sample (not a code's value)
    ParseOptions o;
    o.image_reader = [&](const std::string&) {
        StoredImage s;
        s.pixels = Image(3, 2);
        for (size_t i = 0; i < s.pixels.rgba.size(); ++i)
            s.pixels.rgba[i] = float((i * 37 + 11) % 256) * (1.0f / 255.0f);
        if (odd != 0) s.pixels.rgba[0] = odd;
        s.format = "png";
        s.bits = bits;
        s.has_alpha = true;
        return s;
    };
    auto pixels = [&](const std::string& head, const std::string& item) {
        std::ofstream(dir / "s.pov") << head << "\nplane { z, 0 " << item << " }\n";
        Scene s = parse_scene_file((dir / "s.pov").string(), o);
        return s.objects.at(0).texture.at(0).pigment.pattern->image->pixels;
    };
    for (const std::string& head :
         {std::string("#version 3.7;"), std::string("#version 3.6;"),
          std::string("#version 3.7; global_settings { assumed_gamma 2.2 }")}) {
        for (const std::string& item :
             {std::string("pigment { image_map { png \"a.png\" } }"),
              std::string("pigment { image_map { png \"a.png\" "
                          "gamma 1.8 } }")}) {
            SCOPED_TRACE(head + " " + item);
            bits = 8;
            const auto codes = pixels(head, item);
            bits = 16;  // the same samples, not taken as codes
            const auto floats = pixels(head, item);
            ASSERT_EQ(codes->codes.size(), 24u);
            EXPECT_TRUE(codes->rgbft.empty());
            EXPECT_TRUE(floats->codes.empty());
            EXPECT_TRUE(codes->see_through);
            for (int y = 0; y < 2; ++y) {
                for (int x = 0; x < 3; ++x) {
                    float a[5], b[5];
                    codes->fetch(x, y, a);
                    floats->fetch(x, y, b);
                    for (int c = 0; c < 5; ++c) EXPECT_EQ(a[c], b[c]) << x << "," << y;
                }
            }
        }
    }
    bits = 8;
    odd = 0.5f;
    EXPECT_TRUE(pixels("#version 3.7;", "pigment { image_map { png \"a.png\" } }")
                    ->codes.empty());
    fs::remove_all(dir);
}

// ---- Expressions in loops and macros run as compiled programs (expression_program.h);
// they must give bit for bit what reading the tokens gives.

struct CompiledParse {
    Scene scene;
    std::string debug;
    std::string error;  // first line, or empty
    ParseOptions::ExpressionCounts counts;
};

CompiledParse parse_compiled(const std::string& text, bool compile) {
    CompiledParse r;
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.clock = 0.375;
    o.compile_expressions = compile;
    o.expression_counts = &r.counts;
    try {
        r.scene = parse_scene_text(text, "test.pov", o);
    } catch (const ParseError& e) {
        r.error = std::string(e.what()).substr(0, std::string(e.what()).find('\n'));
    }
    r.debug = messages.str();
    return r;
}

void expect_same_transforms(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const auto& m = a.objects[i].transform.forward().m;
        const auto& n = b.objects[i].transform.forward().m;
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 4; ++c) {
                // Bit for bit: EXPECT_EQ on doubles is exact.
                EXPECT_EQ(m[r][c], n[r][c])
                    << "object " << i << " m[" << r << "][" << c << "]";
            }
        }
    }
}

TEST(CompiledExpressions, GiveBitForBitWhatReadingTheTokensGives) {
    const char* expressions[] = {
        "(2 * rand(R) - 1) * H",
        "<0.2 + rand(R) * (Top - 0.2), -H, 2 * -I>",
        "<1, 2, 3> * 2 + 1 - x / 4",
        "<1 2 3,>",
        "<1, -2>",
        "<1, 2, 3, 4, 5> * I",
        "-1 - -2 * +3 / 7",
        "1 + 2 * 3 - 4 / 5 * 6",
        ("(I < 1) + (I <= 1) * 2 + (I > 1) * 4 + (I >= 1) * 8 + (I = 1) * 16 + "
         "(I != 1) * 32"),
        "(1 < 2 & 2 < 1 | !0) * 3 + !I",
        "(0.1 + 0.2 = 0.3) + (0.1 + 0.2 != 0.3) * 2",
        "<sin(I), cos(I * pi / 3), sqrt(2 + I)>",
        "<pow(2 I), mod(7, I + 2), atan2(1, I + 1)>",
        "<abs(-H), int(-2.5), floor(-2.5)> + ceil(2.5) + degrees(tau) + radians(90)",
        "<clock, image_width, image_height> + y * z.y",
        "rand(R) + rand(R) * <1, 2, 3>",
        "(((((I + 1) * 2) - 3) / 4) + ((H)))",
    };
    std::string text =
        "#declare R = seed(42);\n#declare H = 14;\n#declare Top = 9;\n"
        "#for (I, 0, 3)\n";
    for (const char* e : expressions) {
        text += "  sphere { 0, 1 translate " + std::string(e) + " }\n";
        text += "  #declare V = " + std::string(e) + ";\n";
        text += "  sphere { 0, 1 translate V }\n";
    }
    text += "#end\n";
    // A macro whose argument is a float on one call and a vector on the next.
    text +=
        "#macro M(A) sphere { 0, 1 translate A * 2 - A } #end\n"
        "#for (J, 0, 1) M(1.5) M(<1, 2, 3>) M(J) #end\n";
    // The while condition and counter as in generated scenes.
    text +=
        "#declare K = 0;\n#while (K < 3)\n  sphere { <K, K * K, -K>, 1 }\n"
        "  #declare K = K + 1;\n#end\n";

    CompiledParse compiled = parse_compiled(text, true);
    CompiledParse plain = parse_compiled(text, false);
    ASSERT_EQ(compiled.error, "");
    ASSERT_EQ(plain.error, "");
    EXPECT_EQ(plain.counts.runs, 0u);
    // Every expression above compiles; `z.y` leaves its line to the token reader.
    EXPECT_GE(compiled.counts.compiled, 2 * std::size(expressions) - 2);
    EXPECT_GE(compiled.counts.runs, 4 * (2 * std::size(expressions) - 2));
    expect_same_transforms(compiled.scene, plain.scene);
    // A spot check against a hand-computed value: line 7 of the list at I = 0.
    const auto& m = compiled.scene.objects.at(2 * 6).transform.forward().m;
    EXPECT_EQ(m[0][3], -1 - -2 * +3 / 7.0);
}

TEST(CompiledExpressions, AnIdentifierThatStopsBeingANumberFallsBackToTheTokenReader) {
    const std::string text =
        "#declare Q = 1;\n#for (I, 0, 2)\n  #declare V = 1 + Q;\n"
        "  #if (I = 1) #declare Q = \"s\"; #end\n#end\n";
    const std::string expected =
        "test.pov:3:16: error: expected a numeric expression but found string";
    EXPECT_EQ(parse_compiled(text, true).error, expected);
    EXPECT_EQ(parse_compiled(text, false).error, expected);
    // The first turn compiled `1 + Q` and ran it; the third read the tokens.
    EXPECT_EQ(parse_compiled(text, true).counts.compiled >= 1, true);
}

TEST(CompiledExpressions, ErrorsInsideAProgramNameTheSameToken) {
    const std::string text =
        "#declare R = seed(1);\n#for (I, 0, 1)\n  #declare V = 2 * rand(R + I * 5);\n"
        "#end\n";
    const std::string expected = "test.pov:3:25: error: illegal random number generator";
    CompiledParse compiled = parse_compiled(text, true);
    EXPECT_EQ(compiled.error, expected);
    EXPECT_EQ(compiled.counts.runs, 1u);  // the turn with I = 0 ran the program
    EXPECT_EQ(parse_compiled(text, false).error, expected);
}

// POV-Ray's front end declares input_file_name, a string: the scene file's name without
// its folder (vfe.cpp); the scene may test it, redeclare it or #undef it.
TEST(Declares, InputFileNameIsTheSceneFilesName) {
    std::string messages;
    parse(
        "#debug concat(\"[\", input_file_name, \"]\\n\")\n"
        "#declare input_file_name = \"other\";\n#debug input_file_name\n",
        &messages);
    EXPECT_EQ(messages, "[test.pov]\nother");
    namespace fs = std::filesystem;
    const fs::path dir = povwall_test::process_scratch("povwall_parser_input_file_name");
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "sub" / "My Scene.pov")
        << "#if (strcmp(input_file_name, \"My Scene.pov\") = 0) sphere { 0, 1 } #end\n";
    ParseOptions o;
    EXPECT_EQ(parse_scene_file((dir / "sub" / "My Scene.pov").string(), o).objects.size(),
              1u);
}

}  // namespace
}  // namespace povwall::parser

namespace povwall::parser {
namespace {

// Parse_Colour_Map reads a whole expression after an entry's value when a float could
// start one: one term is the old [v1, v2 color A color B] form, a colour the entry's
// colour (`0.6 * White`), anything else an error.
TEST(ColourMaps, AnEntrysExpressionDecidesItsForm) {
    const Scene s = parse(
        "#declare W = color rgb <1, 0.5, 0.25>;\n"
        "plane { y, 0 pigment { gradient x color_map { [0 0.6 * W] [0.5, 0.8 color rgb 1 "
        "color rgb 0] } } }\n");
    const ColourMap& m = s.objects.at(0).texture.at(0).pigment.maps->colour_map;
    ASSERT_EQ(m.size(), 3u);
    EXPECT_FLOAT_EQ(m[0].colour.rgb.g, 0.3f);
    EXPECT_FLOAT_EQ(m[2].value, 0.8f);
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { gradient x color_map { [0 0.5 * <1, 1, 1>] } "
                 "} }"),
        "test.pov:1:50: error: Illegal expression syntax in color_map.");
}

// POV-Ray's Parse_Directive hands back a word after '#' that names no directive: a
// macro is called (`#M()`), anything else is read as the word, with povwall's warning.
TEST(Directives, HashBeforeAWordThatIsNoDirectiveIsDropped) {
    std::string messages;
    const Scene s = parse(
        "#macro M() sphere { 0, 1 } #end\n#M()\n"
        "difference { sphere { 0, 1 } box { 0, 1 } #cutaway_textures }\n",
        &messages);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(std::get<Csg>(s.objects[1].shape).cutaway_textures);
    EXPECT_EQ(messages,
              "test.pov:3:44: warning: '#' before 'cutaway_textures', which names no "
              "directive, is dropped (as POV-Ray does)\n"
              "difference { sphere { 0, 1 } box { 0, 1 } #cutaway_textures }\n"
              "                                           ^~~~~~~~~~~~~~~~\n");
    EXPECT_EQ(error_of("#delcare X = 1;"),
              "test.pov:1:2: error: undeclared identifier 'delcare'");
}

}  // namespace
}  // namespace povwall::parser
