// light_group { objects lights [transforms] [global_lights B] }: which lights light which
// leaves, as POV-Ray 3.7's Promote_Local_Lights and Set_CSG_Children_Flag settle it
// (nesting, copies, groups without lights or objects), and the refusals.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::parse;

struct Leaf {
    uint32_t group;
    bool global;
    bool operator==(const Leaf&) const = default;
};

// The leaves of the scene's objects in order: their light group and global_lights.
std::vector<Leaf> leaves(const Scene& s) {
    std::vector<Leaf> out;
    auto visit = [&](auto& self, const Object& o) -> void {
        if (const Csg* c = std::get_if<Csg>(&o.shape)) {
            for (const Object& ch : c->children) self(self, ch);
        } else {
            out.push_back({o.light_group, o.global_lights});
        }
    };
    for (const Object& o : s.objects) visit(visit, o);
    return out;
}

std::vector<uint32_t> light_groups(const Scene& s) {
    std::vector<uint32_t> out;
    for (const Light& l : s.lights) out.push_back(l.light_group);
    return out;
}

TEST(LightGroup, LightsLightTheirGroupOnly) {
    Scene s = parse(
        "light_source { <0, 9, 0> rgb 1 }\n"
        "light_group { light_source { <1, 2, 3> rgb 1 } sphere { 0, 1 } box { 0, 1 }\n"
        "  translate x }\n"
        "sphere { x, 1 }\n"
        "light_group { sphere { 0, 1 } light_source { 0 rgb 1 } global_lights }\n"
        "light_group { cone { 0, 1, y, 0 } global_lights off }\n"
        "light_group { light_source { 0 rgb 1 } }\n");
    EXPECT_EQ(light_groups(s), (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(leaves(s), (std::vector<Leaf>{
                             {1, false}, {1, false}, {0, true}, {2, true}, {0, false}}));
    // The group's light moves with it.
    EXPECT_DOUBLE_EQ(s.lights.at(1).location.x, 2);
}

TEST(LightGroup, NestingAndCopies) {
    Scene s = parse(
        "light_group {\n"
        "  light_source { 0 rgb 1 }\n"
        "  sphere { 0, 1 }\n"
        "  light_group { light_source { 0 rgb 1 } sphere { 0, 1 } global_lights off }\n"
        "  light_group { sphere { 0, 1 } }\n"  // no lights: the outer group's
        "  union { sphere { 0, 1 } light_source { 0 rgb 1 } }\n"  // a global light
        "  global_lights on\n"
        "}\n"
        "#declare L = light_source { 0 rgb 1 }\n"
        "#declare G = light_group { object { L } sphere { 0, 1 } }\n"
        "object { G translate x }\n"
        "G\n");
    // Outer group 1, inner 2 (the union's light is global), copies 3 and 4.
    EXPECT_EQ(light_groups(s), (std::vector<uint32_t>{1, 2, 0, 3, 4}));
    EXPECT_EQ(leaves(s), (std::vector<Leaf>{{1, true},
                                            {2, true},  // the outermost group decides
                                            {1, true},
                                            {1, true},
                                            {3, false},
                                            {4, false}}));
}

// Members written as bare identifiers (vtkPOVExporter scenes): a declared light is the
// group's light, a declared object its member, as `light_source { L }` and `object { S
// }`.
TEST(LightGroup, BareIdentifiersAreMembers) {
    Scene bare = parse(
        "#declare L = light_source { <1, 2, 3> rgb 1 }\n"
        "#declare S = sphere { 0, 1 }\n"
        "light_group { L S translate x }\n");
    Scene written = parse(
        "#declare L = light_source { <1, 2, 3> rgb 1 }\n"
        "#declare S = sphere { 0, 1 }\n"
        "light_group { light_source { L } object { S } translate x }\n");
    EXPECT_EQ(light_groups(bare), (std::vector<uint32_t>{1}));
    EXPECT_EQ(leaves(bare), (std::vector<Leaf>{{1, false}}));
    EXPECT_EQ(light_groups(bare), light_groups(written));
    EXPECT_EQ(leaves(bare), leaves(written));
    EXPECT_DOUBLE_EQ(bare.lights.at(0).location.x, 2);
}

TEST(LightGroup, RefusalsAndErrors) {
    // Media are lit by the lights of the object a ray ends on (golden
    // light_group_media): no refusal.
    EXPECT_EQ(error_of("light_group { light_source { 0 rgb 1 } sphere { 0, 1 } }\n"
                       "sphere { 0, 1 hollow interior { media { emission 1 } } }"),
              "(no error)");
    EXPECT_EQ(
        error_of("light_group { light_source { 0 rgb 1 looks_like { sphere { 0, 1 } "
                 "} } }"),
        "test.pov:1:1: error: unsupported: looks_like in a light_group");
    EXPECT_EQ(error_of("light_group { sphere { 0, 1 } photons { target } }"),
              "test.pov:1:31: error: unsupported: photons");
    EXPECT_EQ(error_of("light_group { sphere { 0, 1 } pigment { rgb 1 } }"),
              "test.pov:1:31: error: expected an object, light_source, transformation, "
              "global_lights or '}' but found 'pigment'");
}

}  // namespace
}  // namespace povwall::parser
