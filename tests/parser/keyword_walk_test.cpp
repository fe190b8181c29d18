// The keyword walk: every one of POV-Ray 3.7's reserved words (pov37_keywords.txt, the
// word entries of its reswords.cpp) is either implemented or classified, never silently
// ignored.
//
// Implemented means: named by a scene that is rendered or run by POV-Ray and compared
// with povwall. A keyword counts when it occurs as a whole word
//   - in scenes/golden/*.pov and *.inc (the golden suite renders each with both and
//     compares the images) or tests/lang/*.pov (each prints values that must equal
//     POV-Ray's printout), outside comments and string literals;
//   - in a string literal of tests/trace/pattern_test.cpp, normal_test.cpp,
//     pov_compare_test.cpp or pattern_parsed_test.cpp: those literals are the .pov text
//     those tests hand to POV-Ray and compare with povwall's result.
// Every other keyword has exactly one line in keyword_classes.txt, which says why it is
// not implemented, and this test checks what the line claims:
//   refused KEYWORD | FEATURE | SNIPPET
//       The snippet (one line of scene text naming the keyword) fails with a located
//       ParseError of kind Unsupported whose message names FEATURE ("-": the keyword).
//   error KEYWORD | SNIPPET | WHY
//       POV-Ray 3.7 rejects the keyword there too (reserved but unused, disabled, or not
//       valid in that place): the snippet fails with a located error that is not
//       "unsupported". WHY says what POV-Ray does.
//   harmless KEYWORD | REASON [| SNIPPET]
//       The keyword changes nothing in POV-Ray's image either (REASON says why, in a few
//       words at least); the snippet, when given, must parse.
// A classified keyword that a compared scene names is a stale line and fails the test, as
// do a keyword classified twice and a classified word that is not a POV-Ray 3.7 keyword.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "output/image_io.h"
#include "parser/parser.h"

namespace povwall::parser {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool word_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '_';
}

void add_words(std::string_view text, std::set<std::string>& out) {
    size_t i = 0;
    while (i < text.size()) {
        if (!word_char(text[i])) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j < text.size() && word_char(text[j])) ++j;
        if (!(text[i] >= '0' && text[i] <= '9'))
            out.insert(std::string(text.substr(i, j - i)));
        i = j;
    }
}

bool names_word(std::string_view text, std::string_view word) {
    std::set<std::string> words;
    add_words(text, words);
    return words.count(std::string(word)) > 0;
}

// The words of scene text outside comments (nested /* */ as POV-Ray reads them) and
// string literals.
void add_pov_words(const std::string& text, std::set<std::string>& out) {
    std::string code;
    size_t i = 0;
    const size_t n = text.size();
    while (i < n) {
        if (text.compare(i, 2, "//") == 0) {
            while (i < n && text[i] != '\n') ++i;
        } else if (text.compare(i, 2, "/*") == 0) {
            int depth = 0;
            do {
                if (text.compare(i, 2, "/*") == 0) {
                    ++depth;
                    i += 2;
                } else if (text.compare(i, 2, "*/") == 0) {
                    --depth;
                    i += 2;
                } else {
                    ++i;
                }
            } while (i < n && depth > 0);
        } else if (text[i] == '"') {
            for (++i; i < n && text[i] != '"'; ++i) {
                if (text[i] == '\\') ++i;
            }
            ++i;
            code += ' ';
        } else {
            code += text[i++];
        }
    }
    add_words(code, out);
}

// The words of the string literals of C++ source (ordinary and raw).
void add_cpp_string_words(const std::string& text, std::set<std::string>& out) {
    size_t i = 0;
    const size_t n = text.size();
    while (i < n) {
        if (text.compare(i, 2, "//") == 0) {
            while (i < n && text[i] != '\n') ++i;
        } else if (text.compare(i, 2, "/*") == 0) {
            const size_t e = text.find("*/", i + 2);
            i = e == std::string::npos ? n : e + 2;
        } else if (text[i] == '\'') {  // a character literal ('"' among them)
            for (++i; i < n && text[i] != '\''; ++i) {
                if (text[i] == '\\') ++i;
            }
            ++i;
        } else if (text.compare(i, 2, "R\"") == 0 &&
                   (i == 0 || !word_char(text[i - 1]))) {
            const size_t open = text.find('(', i + 2);
            const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
            const size_t end = text.find(close, open);
            add_words(std::string_view(text).substr(open + 1, end - open - 1), out);
            i = end + close.size();
        } else if (text[i] == '"') {
            std::string s;
            for (++i; i < n && text[i] != '"'; ++i) {
                if (text[i] == '\\') {
                    ++i;
                    s += ' ';  // an escape (\n) ends a word
                    continue;
                }
                s += text[i];
            }
            ++i;
            add_words(s, out);
        } else {
            ++i;
        }
    }
}

std::vector<std::string> keyword_list() {
    std::vector<std::string> out;
    std::istringstream in(read_file(POVWALL_KEYWORD_LIST));
    for (std::string line; std::getline(in, line);) {
        if (!line.empty()) out.push_back(line);
    }
    return out;
}

// What the compared scenes name.
std::set<std::string> compared_words() {
    std::set<std::string> words;
    const fs::path root = POVWALL_SOURCE_DIR;
    for (const char* dir : {"scenes/golden", "tests/lang"}) {
        for (const auto& e : fs::directory_iterator(root / dir)) {
            const std::string ext = e.path().extension().string();
            if (ext == ".pov" || (ext == ".inc" && std::string(dir) == "scenes/golden"))
                add_pov_words(read_file(e.path()), words);
        }
    }
    for (const char* f :
         {"tests/trace/pattern_test.cpp", "tests/trace/normal_test.cpp",
          "tests/trace/pov_compare_test.cpp", "tests/trace/pattern_parsed_test.cpp"})
        add_cpp_string_words(read_file(root / f), words);
    return words;
}

struct Classified {
    std::string cls, keyword;
    std::vector<std::string> fields;  // after the keyword, split at " | "
    int line = 0;
};

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.pop_back();
    size_t b = 0;
    while (b < s.size() && (s[b] == ' ' || s[b] == '\t')) ++b;
    return s.substr(b);
}

std::vector<Classified> classes() {
    std::vector<Classified> out;
    std::istringstream in(read_file(POVWALL_KEYWORD_CLASSES));
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (trim(line).empty() || line[0] == '#') continue;
        Classified c;
        c.line = number;
        std::istringstream words(line);
        words >> c.cls >> c.keyword;
        std::string rest;
        std::getline(words, rest);
        rest = trim(rest);
        if (rest.rfind("| ", 0) == 0) rest = rest.substr(2);
        // At most two fields: the last one takes the rest of the line.
        for (int k = 0; k < 1; ++k) {
            const size_t bar = rest.find(" | ");
            if (bar == std::string::npos) break;
            c.fields.push_back(trim(rest.substr(0, bar)));
            rest = rest.substr(bar + 3);
        }
        c.fields.push_back(trim(rest));
        out.push_back(c);
    }
    return out;
}

// Parses a snippet as a scene file in scenes/golden (so "images/card.png" is found), with
// the image reader the commands use; returns the error, if any.
std::optional<ParseError> parse_snippet(const std::string& snippet) {
    static const fs::path scratch = [] {
        fs::path p = fs::temp_directory_path() / "povwall_keyword_walk";
        fs::create_directories(p);
        return p;
    }();
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.image_reader = output::read_stored_image;
    o.output_dir = scratch.string();
    try {
        parse_scene_text(snippet,
                         std::string(POVWALL_SOURCE_DIR) + "/scenes/golden/kw.pov", o);
    } catch (const ParseError& e) {
        return e;
    }
    return std::nullopt;
}

TEST(KeywordWalk, ListIsPovRay37sReservedWords) {
    const std::vector<std::string> list = keyword_list();
    EXPECT_EQ(list.size(), 503u);
    EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
    EXPECT_EQ(std::set<std::string>(list.begin(), list.end()).size(), list.size());
}

TEST(KeywordWalk, EveryKeywordIsImplementedOrClassifiedOnce) {
    const std::vector<std::string> list = keyword_list();
    const std::set<std::string> known(list.begin(), list.end());
    const std::set<std::string> named = compared_words();
    std::map<std::string, int> seen;  // keyword -> line
    std::map<std::string, int> per_class;
    int implemented = 0;
    for (const Classified& c : classes()) {
        SCOPED_TRACE("keyword_classes.txt:" + std::to_string(c.line));
        EXPECT_TRUE(c.cls == "refused" || c.cls == "error" || c.cls == "harmless")
            << "unknown class '" << c.cls << "'";
        EXPECT_TRUE(known.count(c.keyword))
            << c.keyword << " is not a POV-Ray 3.7 keyword";
        auto [it, fresh] = seen.emplace(c.keyword, c.line);
        EXPECT_TRUE(fresh) << c.keyword << " is classified twice (also on line "
                           << it->second << ")";
        EXPECT_FALSE(named.count(c.keyword))
            << c.keyword
            << " is named by a compared scene: it is implemented, remove its " << c.cls
            << " line";
        ++per_class[c.cls];
    }
    std::vector<std::string> missing;
    for (const std::string& k : list) {
        if (named.count(k))
            ++implemented;
        else if (!seen.count(k))
            missing.push_back(k);
    }
    std::string text;
    for (const std::string& k : missing) text += " " + k;
    EXPECT_TRUE(missing.empty())
        << missing.size()
        << " keywords are neither named by a compared scene nor classified:" << text;
    RecordProperty("implemented", implemented);
    for (const auto& [cls, n] : per_class) RecordProperty(cls, n);
    std::printf("implemented %d, refused %d, error %d, harmless %d\n", implemented,
                per_class["refused"], per_class["error"], per_class["harmless"]);
}

TEST(KeywordWalk, RefusedKeywordsAreUnsupportedErrors) {
    for (const Classified& c : classes()) {
        if (c.cls != "refused") continue;
        SCOPED_TRACE("keyword_classes.txt:" + std::to_string(c.line) + " " + c.keyword);
        ASSERT_EQ(c.fields.size(), 2u) << "expected: refused KEYWORD | FEATURE | SNIPPET";
        const std::string feature = c.fields[0] == "-" ? c.keyword : c.fields[0];
        const std::string& snippet = c.fields[1];
        EXPECT_TRUE(names_word(snippet, c.keyword))
            << "the snippet must name the keyword";
        std::optional<ParseError> e = parse_snippet(snippet);
        ASSERT_TRUE(e) << "parsed without error: " << snippet;
        EXPECT_EQ(e->kind(), ParseError::Kind::Unsupported) << e->what();
        EXPECT_NE(e->message().find("unsupported: "), std::string::npos) << e->what();
        EXPECT_NE(e->message().find(feature), std::string::npos)
            << "the refusal should name '" << feature << "': " << e->what();
        EXPECT_GT(e->loc().line, 0) << e->what();
    }
}

TEST(KeywordWalk, ErrorKeywordsAreLocatedErrors) {
    for (const Classified& c : classes()) {
        if (c.cls != "error") continue;
        SCOPED_TRACE("keyword_classes.txt:" + std::to_string(c.line) + " " + c.keyword);
        ASSERT_EQ(c.fields.size(), 2u) << "expected: error KEYWORD | SNIPPET | WHY";
        const std::string& snippet = c.fields[0];
        EXPECT_TRUE(names_word(snippet, c.keyword))
            << "the snippet must name the keyword";
        EXPECT_GE(std::count(c.fields[1].begin(), c.fields[1].end(), ' '), 2)
            << "say what POV-Ray 3.7 does";
        std::optional<ParseError> e = parse_snippet(snippet);
        ASSERT_TRUE(e) << "parsed without error: " << snippet;
        EXPECT_EQ(e->kind(), ParseError::Kind::Syntax) << e->what();
        EXPECT_GT(e->loc().line, 0) << e->what();
    }
}

TEST(KeywordWalk, HarmlessKeywordsSayWhyAndParse) {
    for (const Classified& c : classes()) {
        if (c.cls != "harmless") continue;
        SCOPED_TRACE("keyword_classes.txt:" + std::to_string(c.line) + " " + c.keyword);
        ASSERT_GE(c.fields.size(), 1u);
        ASSERT_LE(c.fields.size(), 2u)
            << "expected: harmless KEYWORD | REASON [| SNIPPET]";
        EXPECT_GE(std::count(c.fields[0].begin(), c.fields[0].end(), ' '), 3)
            << "a concrete reason, please";
        if (c.fields.size() < 2) continue;
        const std::string& snippet = c.fields[1];
        EXPECT_TRUE(names_word(snippet, c.keyword))
            << "the snippet must name the keyword";
        std::optional<ParseError> e = parse_snippet(snippet);
        EXPECT_FALSE(e) << e->what();
    }
}

// Details of keywords the walk counts as implemented, where a golden image cannot show
// them.
TEST(KeywordDetails, BinaryWriteRoundsClampsAndOrdersBytes) {
    const fs::path scratch = fs::temp_directory_path() / "povwall_keyword_walk";
    ASSERT_FALSE(parse_snippet(
        "#fopen F \"raw.bin\" write\n"
        "#write (F, uint8 <300, -5, 2.5, 65.49>, sint16le -2, sint16be 40000,\n"
        "        uint16be 258, sint32be -1, sint32le 16909060, sint8 -128.7, \"!\")\n"
        "#fclose F\n"));
    const std::string bytes = read_file(scratch / "raw.bin");
    const std::string expected(
        "\xff\x00\x03\x41"  // clamped, rounded half up
        "\xfe\xff"          // -2, little-endian
        "\x7f\xff"          // 40000 clamped to 32767
        "\x01\x02"          // big-endian
        "\xff\xff\xff\xff"
        "\x04\x03\x02\x01"
        "\x80"  // -128.7 clamped to -128
        "!",
        20);
    EXPECT_EQ(bytes, expected);
    // A string after a raw format is an error, as in POV-Ray.
    std::optional<ParseError> e =
        parse_snippet("#fopen F \"raw.bin\" write\n#write (F, uint8 \"a\")\n#fclose F\n");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->message(),
              "#write: expected a float or vector after 'uint8' but found string");
}

TEST(KeywordDetails, PaletteIndicesAndTheirLimits) {
    // POV-Ray averages the corners' indices when it interpolates: refused.
    std::optional<ParseError> e = parse_snippet(
        "plane { z, 0 normal { bump_map { png \"images/palette.png\" use_index "
        "interpolate 2 } } }");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->kind(), ParseError::Kind::Unsupported);
    EXPECT_EQ(e->message(), "unsupported: bump_map use_index with interpolate");
    EXPECT_EQ(e->loc().column, 59);  // at use_index
    // Of a true-colour image, use_index reads its grey as use_colour does.
    EXPECT_FALSE(parse_snippet(
        "plane { z, 0 normal { bump_map { png \"images/card.png\" use_index } } }"));
    // A palette entry that does not exist, and a per-entry value on a true-colour image.
    e = parse_snippet(
        "plane { z, 0 pigment { image_map { png \"images/palette.png\" filter 8, 1 } } "
        "}");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->message(),
              "filter colour register 8 out of range (the palette has 8 colours)");
    e = parse_snippet(
        "plane { z, 0 pigment { image_map { png \"images/card.png\" transmit 1, 1 } } }");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->message(),
              "transmit <index> needs a colour-mapped image; use transmit all");
}

}  // namespace
}  // namespace povwall::parser
