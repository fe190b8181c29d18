// trace(), inside() and the extents while parsing (trace/object_queries.h): the errors a
// scene gets, and what changes without the renderer's answers. Values against POV-Ray
// are in tests/lang/object_queries.pov.
#include "trace/object_queries.h"

#include <gtest/gtest.h>

#include "parser/parser.h"

namespace povwall::trace {
namespace {

// The first line of the error the scene stops with, or "(no error)".
std::string error_of(const std::string& text, bool queries = true) {
    parser::ParseOptions o;
    if (queries) o.object_queries = parse_time_object_queries();
    try {
        parser::parse_scene_text(text, "q.pov", o);
    } catch (const parser::ParseError& e) {
        const std::string what = e.what();
        return what.substr(0, what.find('\n'));
    }
    return "(no error)";
}

TEST(ObjectQueries, ErrorsAreLocated) {
    EXPECT_EQ(
        error_of("#declare P = bicubic_patch { type 0 flatness 0 u_steps 1 v_steps 1\n"
                 "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,\n"
                 "<0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>, <0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> }\n"
                 "#declare A = inside(P, <0, 0, 0>);\n"),
        "q.pov:4:21: error: solid object identifier expected");
    EXPECT_EQ(
        error_of("#declare S = sphere { 0, 1 }\n#declare F = 1;\n"
                 "#declare A = trace(S, -5 * z, z, F);\n"),
        "q.pov:3:34: error: expected a vector identifier for trace's normal, or ')' "
        "but found 'F'");
    EXPECT_EQ(error_of("#declare S = 1;\n#declare A = trace(S, -5 * z, z);\n"),
              "q.pov:2:20: error: expected an object identifier but found 'S'");
    EXPECT_EQ(error_of("#declare M = mesh { triangle { 0, x, y } }\n"
                       "#declare A = inside(M, 0);\n"),
              "q.pov:2:21: error: solid object identifier expected");
}

TEST(ObjectQueries, WithoutTheRendererTraceAndInsideStop) {
    EXPECT_EQ(
        error_of("#declare S = sphere { 0, 1 }\n#declare A = trace(S, -5 * z, z);\n",
                 false),
        "q.pov:2:14: error: unsupported: trace");
    EXPECT_EQ(error_of("#declare S = sphere { 0, 1 }\n#if (inside(S, 0)) #end\n", false),
              "q.pov:2:6: error: unsupported: inside");
    EXPECT_EQ(
        error_of(
            "#declare S = sphere { 0, 1 }\n#debug vstr(3, min_extent(S), \",\", 0, 1)\n",
            false),
        "q.pov:2:16: error: unsupported: min_extent");
}

// A CSG keeps the box it was closed with, moved as a box: a union of two spheres turned
// by 45 degrees about z is the turned box's box (POV-Ray), not the spheres' own boxes.
TEST(ObjectQueries, ClosedCsgBoxMovesAsABox) {
    parser::ParseOptions o;
    o.object_queries = parse_time_object_queries();
    const Scene s = parser::parse_scene_text(
        "union { sphere { -x, 1 } sphere { x, 1 } rotate 45 * z }\n", "q.pov", o);
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& box = std::get<Csg>(s.objects[0].shape).pov_box;
    ASSERT_TRUE(box);
    // The closed box is <-2,-1,-1> .. <2,1,1>; turned, its corners reach 3/sqrt(2) in x
    // and y (the spheres alone reach 1/sqrt(2) + 1).
    EXPECT_FLOAT_EQ(box->lo[0], float(-3 / std::sqrt(2.0)));
    EXPECT_FLOAT_EQ(box->lo[1], float(-3 / std::sqrt(2.0)));
    EXPECT_FLOAT_EQ(box->lo[2], -1.0f);
}

}  // namespace
}  // namespace povwall::trace
