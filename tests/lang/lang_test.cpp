// Scene-language fixtures: each tests/lang/NAME.pov prints values with #debug between
// BEGIN and END lines; NAME.out holds what POV-Ray 3.7 printed for the same file
// (regenerate with `povray +INAME.pov -D +W8 +H8 2>&1 | sed -n '/^BEGIN/,/^END/p' >
// NAME.out`).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "parser/parser.h"
#include "trace/object_queries.h"
#include "trace/pattern.h"

namespace povwall::parser {
namespace {

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string debug_output(const std::string& name) {
    std::ostringstream messages;
    ParseOptions o;
    o.messages = &messages;
    o.function_hooks =
        trace::parse_time_function_hooks();  // pattern and pigment functions
    o.object_queries = trace::parse_time_object_queries();  // trace(), inside(), extents
    // Files the fixtures write (#fopen) go to a scratch folder.
    const auto scratch =
        std::filesystem::temp_directory_path() / ("povwall_lang_" + name);
    std::filesystem::create_directories(scratch);
    o.output_dir = scratch.string();
    parse_scene_file(std::string(POVWALL_LANG_DIR) + "/" + name + ".pov", o);
    std::filesystem::remove_all(scratch);
    std::string all = messages.str();
    size_t b = all.find("BEGIN\n"), e = all.find("END\n");
    if (b == std::string::npos || e == std::string::npos) return all;
    return all.substr(b, e + 4 - b);
}

class LangFixture : public ::testing::TestWithParam<const char*> {};

TEST_P(LangFixture, DebugOutputMatchesPovRay) {
    std::string name = GetParam();
    std::string expected = read(std::string(POVWALL_LANG_DIR) + "/" + name + ".out");
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_EQ(debug_output(name), expected);
}

INSTANTIATE_TEST_SUITE_P(
    Pov37, LangFixture,
    ::testing::Values("expressions", "directives", "colours", "splines", "functions",
                      "functions_internal", "fileio", "keywords", "text_extents",
                      "object_queries", "string_relations", "legacy_semicolons",
                      "torus_pov_solver", "inside_rules", "cylinder_trace_bits",
                      "colour_terms", "cone_trace_bits", "macro_rvalue_semicolons",
                      "sor_lathe_trace_bits", "degree_constants", "sphere_extents"));

}  // namespace
}  // namespace povwall::parser
