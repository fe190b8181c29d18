// pavement: its six values read as POV-Ray 3.7's Parse_Pattern reads them (each an
// unsigned char, the last one given wins), reduced and checked when the block ends, with
// POV-Ray's messages located at the token that ends it; its keywords on other patterns
// are POV-Ray's "can only be used" errors.
#include <gtest/gtest.h>

#include <array>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::parse;

PatternSpec::Pavement pavement_of(const std::string& pigment) {
    const Scene s = parse("plane { y, 0 pigment { " + pigment + " } }");
    const PatternSpec& spec = *s.objects.at(0).texture.at(0).pigment.pattern;
    EXPECT_EQ(spec.kind, PatternKind::Pavement) << pigment;
    return spec.pavement;
}

// sides, tiles, pattern, exterior, interior, form.
std::array<int, 6> values(const PatternSpec::Pavement& p) {
    return {p.sides, p.tiles, p.pattern, p.exterior, p.interior, p.form};
}

TEST(Pavement, BarePavementIsTriangles) {
    EXPECT_EQ(values(pavement_of("pavement")), (std::array<int, 6>{3, 1, 1, 0, 0, 0}));
    EXPECT_EQ(
        values(pavement_of("pavement number_of_sides 6 number_of_tiles 5 pattern 22 "
                           "exterior 1 interior 2 form 1")),
        (std::array<int, 6>{6, 5, 22, 1, 2, 1}));
}

TEST(Pavement, ValuesAreTruncatedBytesReducedAtTheEnd) {
    // Truncated toward zero: pattern 2.9 is 2, number_of_tiles 5.99 is 5.
    EXPECT_EQ(values(pavement_of("pavement number_of_sides 4.7 number_of_tiles 5.99 "
                                 "pattern 2.9")),
              (std::array<int, 6>{4, 5, 2, 0, 0, 0}));
    // interior and exterior modulo 3; form modulo 4 on squares (3: no form rounding)
    // and modulo 3 on triangles and hexagons.
    EXPECT_EQ(
        values(pavement_of("pavement number_of_sides 4 interior 4 exterior 5 form 5")),
        (std::array<int, 6>{4, 1, 1, 2, 1, 1}));
    EXPECT_EQ(values(pavement_of("pavement number_of_sides 4 form 3")),
              (std::array<int, 6>{4, 1, 1, 0, 0, 3}));
    EXPECT_EQ(values(pavement_of("pavement form 3")),
              (std::array<int, 6>{3, 1, 1, 0, 0, 0}));
    EXPECT_EQ(values(pavement_of("pavement number_of_sides 6 form 3 interior 3")),
              (std::array<int, 6>{6, 1, 1, 0, 0, 0}));
    // The low 8 bits of the truncated value: -252 is 4, 259 is 3, -1 is 255 (mod 3: 0).
    EXPECT_EQ(values(pavement_of("pavement number_of_sides -252 number_of_tiles 259 "
                                 "exterior -1")),
              (std::array<int, 6>{4, 3, 1, 0, 0, 0}));
}

TEST(Pavement, AnyOrderLastOneWins) {
    EXPECT_EQ(values(pavement_of("pavement form 2 pattern 3 number_of_tiles 4 pattern 5 "
                                 "number_of_sides 3 number_of_sides 4 form 1")),
              (std::array<int, 6>{4, 4, 5, 0, 0, 1}));
    // Between the other modifiers, a map and transforms.
    EXPECT_EQ(values(pavement_of("pavement scale 2 number_of_sides 6 colour_map { [0 rgb "
                                 "0] [1 rgb 1] } number_of_tiles 3 rotate y*30 pattern 3 "
                                 "turbulence 0.1 interior 1")),
              (std::array<int, 6>{6, 3, 3, 0, 1, 0}));
}

TEST(Pavement, AKeywordStartsFromTheDefaults) {
    const Scene s = parse(
        "#declare P = pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 35 "
        "form 2 }\n"
        "plane { y, 0 pigment { P } }\n"
        "plane { y, 0 pigment { P pavement } }\n"
        "plane { y, 0 pigment { P number_of_tiles 5 pattern 12 } }\n");
    auto of = [&](size_t i) {
        return values(s.objects.at(i).texture.at(0).pigment.pattern->pavement);
    };
    EXPECT_EQ(of(0), (std::array<int, 6>{4, 6, 35, 0, 0, 2}));
    EXPECT_EQ(of(1), (std::array<int, 6>{3, 1, 1, 0, 0, 0}));
    EXPECT_EQ(of(2), (std::array<int, 6>{4, 5, 12, 0, 0, 2}));
    // The edited copy is checked again when its block ends.
    EXPECT_EQ(
        error_of("#declare P = pigment { pavement number_of_sides 4 number_of_tiles "
                 "6 pattern 35 }\n"
                 "plane { y, 0 pigment { P number_of_tiles 5 } }"),
        "test.pov:2:44: error: pattern value for pavement is out of range. "
        "max per tile:(1,1,2,5,12,35)");
}

TEST(Pavement, InNormalsTexturesAndMaps) {
    const Scene s = parse(
        "plane { y, 0 normal { pavement 0.4 number_of_sides 4 number_of_tiles 3 "
        "pattern 2 } }\n"
        "plane { y, 0 texture { pavement number_of_sides 6 interior 2 texture_map { [0 "
        "pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }\n"
        "plane { y, 0 pigment { gradient x pigment_map { [0 pavement number_of_tiles 6 "
        "pattern 12] [1 rgb 1] } } }\n");
    const Normal& n = *s.objects.at(0).texture.at(0).normal;
    EXPECT_EQ(n.pattern->kind, PatternKind::Pavement);
    EXPECT_FLOAT_EQ(float(n.amount), 0.4f);
    EXPECT_EQ(values(n.pattern->pavement), (std::array<int, 6>{4, 3, 2, 0, 0, 0}));
    const Texture& t = s.objects.at(1).texture.at(0);
    ASSERT_TRUE(bool(t.map_pattern));
    EXPECT_EQ(values(t.map_pattern->pavement), (std::array<int, 6>{6, 1, 1, 0, 2, 0}));
    const Pigment& entry = s.objects.at(2).texture.at(0).pigment.maps->list.at(0);
    EXPECT_EQ(values(entry.pattern->pavement), (std::array<int, 6>{3, 6, 12, 0, 0, 0}));
}

// POV-Ray stops with these once the block's last modifier is read: at the token that
// ends the block.
TEST(Pavement, RangeErrorsAsPovRay) {
    EXPECT_EQ(error_of("plane { y, 0 pigment { pavement\n  number_of_sides 5\n} }"),
              "test.pov:3:1: error: number_of_sides of pavement must be 3, 4 or 6.");
    EXPECT_EQ(error_of("plane { y, 0 pigment { pavement number_of_sides 0 } }"),
              "test.pov:1:51: error: number_of_sides of pavement must be 3, 4 or 6.");
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { pavement number_of_sides 4 number_of_tiles "
                 "7 } }"),
        "test.pov:1:69: error: number_of_tiles of pavement must be between 1 and "
        "6.");
    EXPECT_EQ(error_of("plane { y, 0 pigment { pavement number_of_tiles 0 } }"),
              "test.pov:1:51: error: number_of_tiles of pavement must be between 1 and "
              "6.");
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { pavement number_of_sides 6 number_of_tiles "
                 "6 } }"),
        "test.pov:1:69: error: number_of_tiles of pavement must be between 1 and "
        "5.");
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { pavement number_of_sides 4 number_of_tiles "
                 "6 pattern 36 } }"),
        "test.pov:1:80: error: pattern value for pavement is out of range. max "
        "per tile:(1,1,2,5,12,35)");
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { pavement number_of_sides 3 number_of_tiles "
                 "4 pattern 0 } }"),
        "test.pov:1:79: error: pattern value for pavement is out of range. max "
        "per tile:(1,1,1,3,4,12)");
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { pavement number_of_sides 6 number_of_tiles "
                 "3 pattern 4 } }"),
        "test.pov:1:79: error: pattern value for pavement is out of range. max "
        "per tile:(1,1,3,7,22)");
    // 2 tiles have one pattern (257 is 1, its low byte).
    EXPECT_EQ(error_of("plane { y, 0 pigment { pavement number_of_tiles 2 pattern 2 } }"),
              "test.pov:1:61: error: pattern value for pavement is out of range. max "
              "per tile:(1,1,1,3,4,12)");
    EXPECT_EQ(values(pavement_of("pavement number_of_tiles 2 pattern 257")),
              (std::array<int, 6>{3, 2, 1, 0, 0, 0}));
    // Past a 32-bit int the byte is 0 (as POV-Ray 3.7 on x86-64 reads 2^32 + 4).
    EXPECT_EQ(error_of("plane { y, 0 pigment { pavement number_of_sides 4294967300 } }"),
              "test.pov:1:60: error: number_of_sides of pavement must be 3, 4 or 6.");
    // The same in a normal, a texture and a map entry.
    EXPECT_EQ(error_of("plane { y, 0 normal { pavement number_of_sides 2 } }"),
              "test.pov:1:50: error: number_of_sides of pavement must be 3, 4 or 6.");
    EXPECT_EQ(error_of("plane { y, 0 texture { pavement number_of_sides 2\n"
                       "texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] }\n"
                       "} }"),
              "test.pov:3:1: error: number_of_sides of pavement must be 3, 4 or 6.");
    EXPECT_EQ(
        error_of("plane { y, 0 pigment { bozo pigment_map { [0 pavement pattern 2]\n"
                 "[1 rgb 1] } } }"),
        "test.pov:1:64: error: pattern value for pavement is out of range. max "
        "per tile:(1,1,1,3,4,12)");
}

// POV-Ray's pattern functions have no pavement ("No matching } in 'pattern', pavement
// found instead").
TEST(Pavement, NotInPatternFunctions) {
    EXPECT_EQ(error_of("#declare F = function { pattern { pavement } }"),
              "test.pov:1:35: error: expected a pattern but found 'pavement'");
}

TEST(Pavement, ItsKeywordsOnOtherPatterns) {
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo number_of_sides 4 } }"),
              "test.pov:1:29: error: Keyword 'number_of_sides' can only be used in a "
              "pavement statement.");
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo number_of_tiles 4 } }"),
              "test.pov:1:29: error: Keyword 'number_of_tiles' can only be used in a "
              "pavement statement.");
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo pattern 4 } }"),
              "test.pov:1:29: error: Keyword 'pattern' can only be used in a pavement "
              "statement.");
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo form 1 } }"),
              "test.pov:1:29: error: Keyword 'form' can only be used in a crackle or "
              "pavement statement.");
    // POV-Ray names exterior for either keyword.
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo exterior 1 } }"),
              "test.pov:1:29: error: Keyword 'exterior' can only be used in a mandel, "
              "julia, magnet or pavement statement.");
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo interior 1 } }"),
              "test.pov:1:29: error: Keyword 'exterior' can only be used in a mandel, "
              "julia, magnet or pavement statement.");
    // On pavement they take one value, not the fractals' type and factor.
    EXPECT_EQ(error_of("plane { y, 0 pigment { pavement interior 1, 0.5 } }"),
              "test.pov:1:43: error: expected a pigment item or '}' but found ','");
    // crackle keeps its vector form.
    const Scene s = parse("plane { y, 0 pigment { crackle form <0.5, -0.3, 0.4> } }");
    EXPECT_EQ(s.objects.at(0).texture.at(0).pigment.pattern->vector,
              (Vector3{0.5, -0.3, 0.4}));
}

}  // namespace
}  // namespace povwall::parser
