// POV-Ray .ini option files: `Key=Value` lines mapped onto the equivalent +X switches.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>

#include "cli/options.h"

namespace povwall::cli {
namespace {

std::string trim(const std::string& s) {
    size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    size_t b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return s;
}

// POV-Ray's boolean spellings.
bool truth(const std::string& key, const std::string& v, const std::string& where) {
    std::string l = lower(v);
    if (l == "on" || l == "true" || l == "yes" || l == "1") return true;
    if (l == "off" || l == "false" || l == "no" || l == "0") return false;
    throw UsageError(where + ": expected on/off for " + key + ", found '" + v + "'");
}

}  // namespace

bool looks_like_ini_file(const std::string& arg) {
    return arg.size() > 4 && arg[0] != '+' && arg[0] != '-' &&
           lower(arg.substr(arg.size() - 4)) == ".ini";
}

void apply_ini_file(const std::string& path, RenderOptions& o) {
    std::ifstream in(path);
    if (!in) throw UsageError("cannot open option file '" + path + "'");
    apply_ini_stream(in, path, o);
}

void apply_ini_stream(std::istream& in, const std::string& path, RenderOptions& o) {
    // Keys taking a value and the switch letter(s) they stand for.
    static const std::map<std::string, std::string> kValue = {
        {"input_file_name", "I"},
        {"output_file_name", "O"},
        {"width", "W"},
        {"height", "H"},
        {"library_path", "L"},
        {"antialias_threshold", "A"},
        {"antialias_depth", "R"},
        {"sampling_method", "AM"},
        {"jitter_amount", "J"},
        {"work_threads", "WT"},
        {"start_row", "SR"},
        {"end_row", "ER"},
        {"start_column", "SC"},
        {"end_column", "EC"},
        {"initial_frame", "KFI"},
        {"final_frame", "KFF"},
        {"initial_clock", "KI"},
        {"final_clock", "KF"},
        {"clock", "K"},
        {"subset_start_frame", "SF"},
        {"subset_end_frame", "EF"},
    };
    static const std::map<std::string, std::string> kFlag = {
        {"antialias", "A"},         {"jitter", "J"},         {"output_alpha", "UA"},
        {"display", "D"},           {"verbose", "V"},        {"pause_when_done", "P"},
        {"cyclic_animation", "KC"}, {"continue_trace", "C"},
    };
    std::string line;
    int number = 0;
    std::string bits;
    while (std::getline(in, line)) {
        ++number;
        const std::string where = path + ":" + std::to_string(number);
        size_t semi = line.find(';');
        if (semi != std::string::npos) line.resize(semi);
        line = trim(line);
        if (line.empty() || line[0] == '[') continue;  // sections select nothing here
        if (line[0] == '+' || line[0] == '-') {
            if (!apply_pov_switch(line, o))
                throw UsageError(where + ": unknown switch '" + line + "'");
            continue;
        }
        size_t eq = line.find('=');
        if (eq == std::string::npos) throw UsageError(where + ": expected Key=Value");
        std::string key = lower(trim(line.substr(0, eq)));
        std::string value = trim(line.substr(eq + 1));
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
            value = value.substr(1, value.size() - 2);
        }
        if (key == "declare") {
            apply_pov_switch("Declare=" + value, o);
        } else if (key == "output_file_type") {
            apply_pov_switch("+F" + value + bits, o);
        } else if (key == "bits_per_color") {
            bits = value;
            apply_pov_switch(std::string("+F") + o.format + bits, o);
        } else if (auto v = kValue.find(key); v != kValue.end()) {
            apply_pov_switch("+" + v->second + value, o);
        } else if (auto f = kFlag.find(key); f != kFlag.end()) {
            apply_pov_switch((truth(key, value, where) ? "+" : "-") + f->second, o);
        } else {
            throw UsageError(where + ": option '" + trim(line.substr(0, eq)) +
                             "' is not supported by povwall");
        }
    }
}

}  // namespace povwall::cli
