// The child index of large CSGs (trace/csg_children.h): which children can never be
// inside (POV-Ray's Inside rules), which boxes a ray's line and a point select, and that
// a copy of a CSG starts without the index built for the original.
#include "trace/csg_children.h"

#include <gtest/gtest.h>

#include <string>

#include "parser/parser.h"

namespace povwall::trace {
namespace {

Object first_object(const std::string& sdl) {
    const Scene s = parser::parse_scene_text("#version 3.7;\n" + sdl, "c.pov", {});
    EXPECT_EQ(s.objects.size(), 1u);
    return s.objects.at(0);
}

TEST(CsgChildren, NeverInsideFollowsPovRaysInsideRules) {
    const char* tri = "triangle { <0,0,0>, <1,0,0>, <0,1,0> }";
    const char* sph = "sphere { 0, 1 }";
    auto never = [](const std::string& sdl, bool inverted = false) {
        return never_inside(first_object(sdl), inverted);
    };
    EXPECT_TRUE(never(tri));
    // POV-Ray's Invert leaves a triangle as it is.
    EXPECT_TRUE(never("triangle { <0,0,0>, <1,0,0>, <0,1,0> inverse }"));
    EXPECT_TRUE(never(tri, true));
    EXPECT_FALSE(never(sph));
    EXPECT_FALSE(never(sph, true));
    EXPECT_TRUE(never("mesh { " + std::string(tri) + " }", true));
    EXPECT_FALSE(never("mesh { " + std::string(tri) + " inside_vector z }"));
    EXPECT_TRUE(never("polygon { 4, <0,0>, <1,0>, <1,1>, <0,0> }"));
    // A merge needs one child inside, an intersection every child.
    EXPECT_TRUE(never("merge { " + std::string(tri) + tri + " }"));
    EXPECT_FALSE(never("merge { " + std::string(tri) + sph + " }"));
    EXPECT_TRUE(never("intersection { " + std::string(sph) + tri + " }"));
    // Inverted, a merge turns into an intersection of inverted children and the other
    // way round; a difference's later children are inverted once more.
    EXPECT_TRUE(never("merge { " + std::string(tri) + sph + " inverse }"));
    EXPECT_FALSE(never("intersection { " + std::string(sph) + tri + " inverse }"));
    EXPECT_TRUE(never("difference { " + std::string(tri) + sph + " }"));
    EXPECT_FALSE(never("difference { " + std::string(sph) + sph + " }"));
    // A triangle keeps no inverted flag: cut from a sphere, it leaves nothing inside.
    EXPECT_TRUE(never("difference { " + std::string(sph) + tri + " }"));
    EXPECT_TRUE(never("union { }"));
}

std::string spheres_in_a_row(int n) {
    std::string sdl = "merge {";
    for (int i = 0; i < n; ++i)
        sdl += " sphere { <" + std::to_string(i) + ", 0, 0>, 0.4 }";
    return sdl + " triangle { <0,5,0>, <1,5,0>, <0,6,0> } plane { y, -3 } }";
}

TEST(CsgChildren, TheIndexSelectsTheChildrenABoxHolds) {
    const Object merge = first_object(spheres_in_a_row(20));
    const Csg& csg = std::get<Csg>(merge.shape);
    EXPECT_EQ(csg_child_index(csg), nullptr);  // not prepared yet
    index_csg_children(merge);
    const CsgChildIndex* index = csg_child_index(csg);
    ASSERT_NE(index, nullptr);
    // The plane (child 21) is met by every ray and can be inside anywhere; the triangle
    // (20) is never inside.
    EXPECT_EQ(index->surface_always, std::vector<uint32_t>{21});
    const CsgChildIndex::Insides& written = index->insides[0];
    EXPECT_EQ(written.anywhere, std::vector<uint32_t>{21});
    EXPECT_EQ(written.never, std::vector<uint32_t>{20});
    EXPECT_EQ(written.within.children.size(), 20u);
    EXPECT_TRUE(written.outside.children.empty());
    // Held inverted, each sphere holds every point outside its box.
    const CsgChildIndex::Insides& inverted = index->insides[1];
    EXPECT_EQ(inverted.outside.children.size(), 20u);
    EXPECT_TRUE(inverted.within.children.empty());
    EXPECT_EQ(inverted.anywhere, std::vector<uint32_t>{21});
    // A vertical line through x = 7 meets sphere 7's box: its leaf's spheres (four at
    // most) are the candidates.
    std::vector<uint32_t> met;
    index->surfaces.line_candidates({7, -10, 0}, {0, 1, 0}, met);
    EXPECT_LE(met.size(), 4u);
    bool seven = false;
    for (uint32_t e : met) seven = seven || index->surface_children[e] == 7;
    EXPECT_TRUE(seven);
    // A point in sphere 12: the plane, then sphere 12, the only box holding it.
    std::vector<size_t> asked;
    auto never_skipped = [](size_t) { return false; };
    auto inside_12 = [&](size_t j) {
        asked.push_back(j);
        return j == 12;
    };
    EXPECT_TRUE(inside_any_child(*index, false, {12.1, 0, 0}, kNoChild, never_skipped,
                                 inside_12));
    EXPECT_EQ(asked, (std::vector<size_t>{21, 12}));
    // Left out, sphere 12 is not asked.
    asked.clear();
    EXPECT_FALSE(
        inside_any_child(*index, false, {12.1, 0, 0}, 12, never_skipped, inside_12));
    EXPECT_EQ(asked, std::vector<size_t>{21});
    // Inverted, the spheres whose boxes do not hold the point hold it: no question.
    asked.clear();
    EXPECT_TRUE(
        inside_any_child(*index, true, {12.1, 0, 0}, 21, never_skipped, inside_12));
    EXPECT_TRUE(asked.empty());
    // An intersection-like rule: the triangle is never inside, so nothing is asked.
    EXPECT_FALSE(inside_every_child(*index, false, {12.1, 0, 0}, kNoChild, inside_12));
    EXPECT_TRUE(asked.empty());
    // Fewer than sixteen children: no index.
    const Object small = first_object(spheres_in_a_row(10));
    index_csg_children(small);
    EXPECT_EQ(csg_child_index(std::get<Csg>(small.shape)), nullptr);
}

TEST(CsgChildren, ACopyStartsWithoutTheIndex) {
    const Object merge = first_object(spheres_in_a_row(20));
    index_csg_children(merge);
    ASSERT_NE(csg_child_index(std::get<Csg>(merge.shape)), nullptr);
    Object copy = merge;
    EXPECT_EQ(csg_child_index(std::get<Csg>(copy.shape)), nullptr);
    copy = merge;
    EXPECT_EQ(csg_child_index(std::get<Csg>(copy.shape)), nullptr);
}

}  // namespace
}  // namespace povwall::trace
