// text: the TrueType tables as POV-Ray reads them (exact metrics and kerning of the
// shipped fonts), the layout of a text union, charsets, and the exact errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include "parser/parser.h"
#include "parser/truetype_font.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::full_error_of;
using test::parse;

const std::string kFonts = "/usr/share/povray-3.7/include/";

std::vector<uint8_t> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A minimal sfnt holding the given tables (tag, bytes), as fonts are laid out.
std::vector<uint8_t> sfnt(
    const std::vector<std::pair<std::string, std::vector<uint8_t>>>& t) {
    std::vector<uint8_t> out = {0, 1, 0, 0, 0, uint8_t(t.size()), 0, 0, 0, 0, 0, 0};
    uint32_t offset = uint32_t(12 + 16 * t.size());
    std::vector<uint8_t> data;
    auto put32 = [](std::vector<uint8_t>& v, uint32_t x) {
        for (int s = 24; s >= 0; s -= 8) v.push_back(uint8_t(x >> s));
    };
    for (const auto& [tag, bytes] : t) {
        out.insert(out.end(), tag.begin(), tag.end());
        put32(out, 0);
        put32(out, offset + uint32_t(data.size()));
        put32(out, uint32_t(bytes.size()));
        data.insert(data.end(), bytes.begin(), bytes.end());
        while (data.size() % 4) data.push_back(0);
    }
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

std::vector<uint8_t> head_table() {
    std::vector<uint8_t> h(54, 0);
    h[12] = 0x5F, h[13] = 0x0F, h[14] = 0x3C, h[15] = 0xF5;  // magic
    h[18] = 0x03, h[19] = 0xE8;                              // unitsPerEm 1000
    return h;
}

TEST(TrueTypeFont, TimromMetricsAndKerning) {
    TrueTypeFont f(read_bytes(kFonts + "timrom.ttf"), false);
    EXPECT_EQ(f.units_per_em(), 1000);
    EXPECT_EQ(f.glyph_count(), 144);
    EXPECT_EQ(f.glyph_index('A'), 34);
    EXPECT_EQ(f.glyph_index('V'), 55);
    EXPECT_EQ(f.metrics(34).advance, 750);
    EXPECT_EQ(f.metrics(34).lsb, 6);
    EXPECT_EQ(f.metrics(55).advance, 724);
    EXPECT_EQ(f.metrics(55).lsb, 0);
    int kx = 1, ky = 1;
    f.kerning(34, 55, kx, ky);
    EXPECT_EQ(kx, -187);
    EXPECT_EQ(ky, 0);
    f.kerning(55, 34, kx, ky);  // "VA"
    EXPECT_EQ(kx, -150);
    f.kerning(34, 34, kx, ky);  // no pair: 0
    EXPECT_EQ(kx, 0);
}

TEST(TrueTypeFont, CyrveticAndCrystal) {
    TrueTypeFont cyr(read_bytes(kFonts + "cyrvetic.ttf"), false);
    EXPECT_EQ(cyr.metrics(cyr.glyph_index('A')).advance, 664);
    EXPECT_EQ(cyr.metrics(cyr.glyph_index('A')).lsb, 5);
    int kx, ky;
    cyr.kerning(34, 55, kx, ky);
    EXPECT_EQ(kx, -81);
    TrueTypeFont crystal(read_bytes(kFonts + "crystal.ttf"), false);
    EXPECT_EQ(crystal.units_per_em(), 2048);
    EXPECT_EQ(crystal.glyph_index('A'), 36);
    EXPECT_EQ(crystal.metrics(36).advance, 1065);
    EXPECT_EQ(crystal.metrics(36).lsb, 127);
    crystal.kerning(36, 57, kx, ky);  // no kern table
    EXPECT_EQ(kx, 0);
    EXPECT_EQ(ky, 0);
}

TEST(TrueTypeFont, SpaceHasNoOutlineAndGlyphsAreCached) {
    TrueTypeFont f(read_bytes(kFonts + "timrom.ttf"), false);
    const TrueTypeFont::Glyph space = f.glyph(' ');
    EXPECT_TRUE(space.outline->segments.empty());
    EXPECT_EQ(space.xmin, 0);
    EXPECT_EQ(space.xmax, 0);
    const TrueTypeFont::Glyph a = f.glyph('A');
    EXPECT_FALSE(a.outline->segments.empty());
    EXPECT_EQ(f.glyph('A').outline.get(), a.outline.get());
    // Every outline point lies in the (widened) header box.
    for (const GlyphSegment& s : a.outline->segments)
        for (int i = 0; i < (s.curve ? 3 : 2); ++i) {
            EXPECT_GE(s.x[i], a.outline->xmin);
            EXPECT_LE(s.x[i], a.outline->xmax);
        }
}

TEST(TrueTypeFont, CffFontIsRefused) {
    try {
        TrueTypeFont f(sfnt({{"CFF ", {1, 0, 4, 1}}, {"head", head_table()}}), false);
        FAIL() << "read a CFF font";
    } catch (const FontError& e) {
        EXPECT_STREQ(e.what(),
                     "an OpenType font with CFF outlines: POV-Ray reads only TrueType "
                     "('glyf') outlines");
    }
}

TEST(TrueTypeFont, TruncatedAndNonFontFilesAreErrors) {
    std::vector<uint8_t> bytes = read_bytes(kFonts + "timrom.ttf");
    bytes.resize(200);
    EXPECT_THROW(TrueTypeFont(bytes, false), FontError);
    std::string text = "#version 3.7;\n";
    try {
        TrueTypeFont f(std::vector<uint8_t>(text.begin(), text.end()), false);
        FAIL();
    } catch (const FontError& e) {
        EXPECT_STREQ(e.what(), "the file ends inside a table (corrupt font)");
    }
}

// Corrupt fonts: random bytes changed in each shipped font, then every code laid out.
// Errors are fine; crashes, hangs and runaway memory are not.
TEST(TrueTypeFont, CorruptFontsFailCleanly) {
    std::mt19937 rng(1234);
    for (const char* name :
         {"timrom.ttf", "cyrvetic.ttf", "crystal.ttf", "povlogo.ttf"}) {
        const std::vector<uint8_t> good = read_bytes(kFonts + name);
        for (int trial = 0; trial < 60; ++trial) {
            std::vector<uint8_t> bytes = good;
            const int flips = 1 + int(rng() % 40);
            for (int i = 0; i < flips; ++i) bytes[rng() % bytes.size()] = uint8_t(rng());
            try {
                TrueTypeFont f(bytes, trial % 2 == 1);
                for (uint32_t c = 0; c < 300; ++c) {
                    const TrueTypeFont::Glyph g = f.glyph(c);
                    f.metrics(g.metrics);
                    int kx, ky;
                    f.kerning(g.index, g.metrics, kx, ky);
                }
            } catch (const FontError&) {
            }
        }
    }
}

TEST(Text, LayoutKernsAndRotates) {
    Scene s = parse("text { ttf \"timrom.ttf\" \"AV\" 0.5, 0 }");
    // Alone in the scene the text is one union of two glyphs.
    ASSERT_EQ(s.objects.size(), 1u);
    const Csg& u = std::get<Csg>(s.objects[0].shape);
    ASSERT_EQ(u.children.size(), 2u);
    TrueTypeFont f(read_bytes(kFonts + "timrom.ttf"), false);
    const TrueTypeFont::Glyph a = f.glyph('A'), v = f.glyph('V');
    // A's ink starts at 0; V sits at A's advance less its lsb, plus V's lsb less its
    // xMin, plus the "AV" kerning of -187.
    const Transform rot = Transform::rotate({0.001, 0.001, 0.001});
    const Point3 pa = rot.point({-a.xmin / 1000.0, 0, 0});
    const Point3 pv = rot.point({(750 - 6) / 1000.0 + (0 - v.xmin - 187) / 1000.0, 0, 0});
    const Point3 ga = u.children[0].transform.point({0, 0, 0});
    const Point3 gv = u.children[1].transform.point({0, 0, 0});
    EXPECT_NEAR(ga.x, pa.x, 1e-15);
    EXPECT_NEAR(ga.z, pa.z, 1e-15);
    EXPECT_NEAR(gv.x, pv.x, 1e-15);
    EXPECT_NEAR(gv.y, pv.y, 1e-15);
    EXPECT_EQ(std::get<Glyph>(u.children[1].shape).depth, 0.5);
}

TEST(Text, OffsetMovesThePenButNeverZ) {
    Scene s = parse("text { ttf \"timrom.ttf\" \"II\" 1, <0.5, 0.25, 3> }");
    const Csg& u = std::get<Csg>(s.objects[0].shape);
    const Transform inv = Transform::rotate({0.001, 0.001, 0.001}).inverse();
    const Point3 p0 = inv.point(u.children[0].transform.point({0, 0, 0}));
    const Point3 p1 = inv.point(u.children[1].transform.point({0, 0, 0}));
    EXPECT_NEAR(p1.y - p0.y, 0.25, 1e-12);
    EXPECT_NEAR(p1.z, 0, 1e-12);
    // A float offset is a vector: it moves y too.
    Scene f = parse("text { ttf \"timrom.ttf\" \"II\" 1, 0.1 }");
    const Csg& g = std::get<Csg>(f.objects[0].shape);
    EXPECT_NEAR(inv.point(g.children[1].transform.point({0, 0, 0})).y, 0.1, 1e-12);
}

TEST(Text, InternalFontsAreTheShippedFiles) {
    Scene a = parse("text { internal 1 \"Q\" 1, 0 }");
    Scene b = parse("text { ttf \"timrom\" \"Q\" 1, 0 }");
    const Glyph& ga =
        std::get<Glyph>(std::get<Csg>(a.objects[0].shape).children[0].shape);
    const Glyph& gb =
        std::get<Glyph>(std::get<Csg>(b.objects[0].shape).children[0].shape);
    ASSERT_EQ(ga.outline->segments.size(), gb.outline->segments.size());
    EXPECT_EQ(ga.outline->xmax, gb.outline->xmax);
}

TEST(Text, Charsets) {
    std::string messages;
    // ascii (the default): each byte of a UTF-8 "é" becomes a space, with a warning.
    Scene a = parse("text { ttf \"timrom.ttf\" \"\xC3\xA9x\" 1, 0 }", &messages);
    EXPECT_EQ(std::get<Csg>(a.objects[0].shape).children.size(), 3u);
    EXPECT_NE(messages.find("Non-ASCII character has been replaced by space character."),
              std::string::npos);
    Scene u = parse(
        "global_settings { charset utf8 }\n"
        "text { ttf \"timrom.ttf\" \"\xC3\xA9\\u0041\" 1, 0 }");
    EXPECT_EQ(std::get<Csg>(u.objects[0].shape).children.size(), 2u);
    EXPECT_EQ(
        full_error_of(
            "global_settings { charset sys }\ntext { ttf \"timrom.ttf\" \"a\" 1, 0 }"),
        "test.pov:2:25: error: Cannot convert system specific text format to Unicode.\n"
        "text { ttf \"timrom.ttf\" \"a\" 1, 0 }\n"
        "                        ^~~");
    EXPECT_EQ(full_error_of("text { ttf \"timrom.ttf\" \"\\u00\" 1, 0 }"),
              "test.pov:1:25: error: Unexpected end of escape sequence in text string.\n"
              "text { ttf \"timrom.ttf\" \"\\u00\" 1, 0 }\n"
              "                        ^~~~~~");
}

TEST(Text, Errors) {
    EXPECT_EQ(full_error_of("text { \"timrom.ttf\" \"a\" 1, 0 }"),
              "test.pov:1:8: error: expected 'ttf' or 'internal' but found string "
              "\"timrom.ttf\"\n"
              "text { \"timrom.ttf\" \"a\" 1, 0 }\n"
              "       ^~~~~~~~~~~~");
    const std::string missing = full_error_of("text { ttf \"nosuchfont\" \"a\" 1, 0 }");
    EXPECT_EQ(missing.substr(0, missing.find(" (also")),
              "test.pov:1:12: error: cannot find font file \"nosuchfont\"");
    EXPECT_NE(missing.find("/usr/share/povray-3.7/include"), std::string::npos);
    // The offset has no default.
    EXPECT_EQ(full_error_of("text { ttf \"timrom.ttf\" \"a\" 1 }"),
              "test.pov:1:31: error: expected an expression but found '}'\n"
              "text { ttf \"timrom.ttf\" \"a\" 1 }\n"
              "                              ^");
    const std::filesystem::path bad =
        std::filesystem::temp_directory_path() / "povwall_text_test_bad.ttf";
    {
        std::ofstream(bad)
            << "not a font at all, but long enough to hold a table directory";
    }
    EXPECT_EQ(full_error_of("text { ttf \"" + bad.string() + "\" \"a\" 1, 0 }"),
              "test.pov:1:12: error: cannot read TrueType font \"" + bad.string() +
                  "\": the file ends inside a table (corrupt font)\n"
                  "text { ttf \"" +
                  bad.string() +
                  "\" \"a\" 1, 0 }\n"
                  "           ^" +
                  std::string(bad.string().size() + 1, '~'));
    std::filesystem::remove(bad);
}

// The parser knows POV-Ray's box of text objects only (tests/lang/text_extents.pov
// checks the values).
TEST(Text, ExtentsOfOtherObjectsAreUnsupported) {
    EXPECT_EQ(full_error_of("#declare B = sphere { 0, 1 }\nsphere { min_extent(B), 1 }"),
              "test.pov:2:10: error: unsupported: min_extent\n"
              "sphere { min_extent(B), 1 }\n"
              "         ^~~~~~~~~~");
    EXPECT_EQ(
        full_error_of(
            "#declare T = text { internal 1 \"a\" 1, 0 clipped_by { plane { y, 0 } } }\n"
            "sphere { max_extent(T), 1 }"),
        "test.pov:2:10: error: unsupported: max_extent\n"
        "sphere { max_extent(T), 1 }\n"
        "         ^~~~~~~~~~");
    EXPECT_EQ(full_error_of("sphere { max_extent(3), 1 }"),
              "test.pov:1:21: error: expected an object identifier but found '3'\n"
              "sphere { max_extent(3), 1 }\n"
              "                    ^");
}

}  // namespace
}  // namespace povwall::parser
