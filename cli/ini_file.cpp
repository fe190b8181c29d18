// POV-Ray .ini option files, read as POV-Ray 3.7 reads them (processoptions.cpp and
// processrenderoptions.cpp; notes/parser-rules.md §4): every key of its table is
// accepted. The keys povwall implements act, most through the equivalent +X switch; the
// others that could change the image print one warning line when their value is not
// POV-Ray's default; display, console, log and shell-command keys are accepted
// silently. An unknown key is an error, as in POV-Ray.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/options.h"

namespace povwall::cli {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return s;
}

// What povwall does with a key.
enum class Use : uint8_t {
    Act,         // implemented
    Silent,      // cannot change the image: display, console, logs, shell commands
    Warn,        // could change the image, not implemented: a warning unless default
    Deprecated,  // POV-Ray 3.7 warns that it is no longer used
};
// How POV-Ray reads the value.
enum class Type : uint8_t { Bool, Int, Float, String, Special };

struct Key {
    const char* name;
    Use use;
    Type type;
    // Warn keys: POV-Ray's default, which changes nothing (nullptr: any value warns).
    const char* standard = nullptr;
};

// RenderOptions_INI_Table of POV-Ray 3.7, in its order.
constexpr Key kKeys[] = {
    {"All_Console", Use::Silent, Type::Bool},
    {"All_File", Use::Silent, Type::String},
    {"Antialias_Depth", Use::Act, Type::Int},
    {"Antialias", Use::Act, Type::Bool},
    {"Antialias_Threshold", Use::Act, Type::Float},
    {"Antialias_Gamma", Use::Act, Type::Float},
    {"Append_File", Use::Silent, Type::Bool},
    {"Bits_Per_Color", Use::Act, Type::Int},
    {"Bits_Per_Colour", Use::Act, Type::Int},
    {"Bounding", Use::Silent, Type::Bool},
    {"Bounding_Method", Use::Silent, Type::Int},
    {"Bounding_Threshold", Use::Silent, Type::Int},
    {"BSP_BaseAccessCost", Use::Silent, Type::Float},
    {"BSP_ChildAccessCost", Use::Silent, Type::Float},
    {"BSP_ISectCost", Use::Silent, Type::Float},
    {"BSP_MaxDepth", Use::Silent, Type::Int},
    {"BSP_MissChance", Use::Silent, Type::Float},
    {"Buffer_Output", Use::Deprecated, Type::String},
    {"Buffer_Size", Use::Deprecated, Type::String},
    {"Clock", Use::Act, Type::Float},
    {"Clockless_Animation", Use::Warn, Type::Bool, "off"},
    {"Compression", Use::Silent, Type::Int},  // JPEG only; povwall writes no JPEG
    {"Continue_Trace", Use::Act, Type::Bool},
    {"Create_Histogram", Use::Deprecated, Type::String},
    {"Create_Ini", Use::Silent, Type::String},
    {"Cyclic_Animation", Use::Act, Type::Bool},
    {"Debug_Console", Use::Silent, Type::Bool},
    {"Debug_File", Use::Silent, Type::String},
    {"Declare", Use::Act, Type::Special},
    {"Display", Use::Silent, Type::Bool},
    {"Display_Gamma", Use::Act, Type::Special},
    {"Dither", Use::Warn, Type::Bool, "off"},
    {"Dither_Method", Use::Warn, Type::Special},
    {"Draw_Vistas", Use::Silent, Type::Bool},
    {"End_Column", Use::Act, Type::Float},
    {"End_Row", Use::Act, Type::Float},
    {"Fatal_Console", Use::Silent, Type::Bool},
    {"Fatal_Error_Command", Use::Silent, Type::Special},
    {"Fatal_Error_Return", Use::Silent, Type::Special},
    {"Fatal_File", Use::Silent, Type::String},
    {"Field_Render", Use::Warn, Type::Bool, "off"},
    {"File_Gamma", Use::Act, Type::Special},
    {"Final_Clock", Use::Act, Type::Float},
    {"Final_Frame", Use::Act, Type::Int},
    {"Frame_Step", Use::Warn, Type::Int, "1"},
    {"Grayscale_Output", Use::Warn, Type::Bool, "off"},
    {"Height", Use::Act, Type::Int},
    {"High_Reproducibility", Use::Warn, Type::Bool, "off"},
    {"Histogram_Name", Use::Deprecated, Type::String},
    {"Histogram_Grid_Size", Use::Deprecated, Type::String},
    {"Histogram_Type", Use::Deprecated, Type::String},
    {"Initial_Clock", Use::Act, Type::Float},
    {"Initial_Frame", Use::Act, Type::Int},
    {"Input_File_Name", Use::Act, Type::String},
    {"Include_Header", Use::Warn, Type::String, ""},
    {"Include_Ini", Use::Act, Type::Special},
    {"Jitter_Amount", Use::Act, Type::Float},
    {"Jitter", Use::Act, Type::Bool},
    {"Library_Path", Use::Act, Type::Special},
    {"Light_Buffer", Use::Silent, Type::Bool},
    {"Max_Image_Buffer_Memory", Use::Silent, Type::Int},
    {"Odd_Field", Use::Warn, Type::Bool, "off"},
    {"Output_Alpha", Use::Act, Type::Bool},
    {"Output_File_Name", Use::Act, Type::String},
    {"Output_File_Type", Use::Act, Type::Special},
    {"Output_To_File", Use::Warn, Type::Bool, "on"},
    {"Palette", Use::Silent, Type::Special},
    {"Pause_When_Done", Use::Silent, Type::Bool},
    {"Post_Frame_Command", Use::Silent, Type::Special},
    {"Post_Frame_Return", Use::Silent, Type::Special},
    {"Post_Scene_Command", Use::Silent, Type::Special},
    {"Post_Scene_Return", Use::Silent, Type::Special},
    {"Preview_End_Size", Use::Silent, Type::Int},
    {"Preview_Start_Size", Use::Silent, Type::Int},
    {"Pre_Frame_Command", Use::Silent, Type::Special},
    {"Pre_Frame_Return", Use::Silent, Type::Special},
    {"Pre_Scene_Command", Use::Silent, Type::Special},
    {"Pre_Scene_Return", Use::Silent, Type::Special},
    {"Quality", Use::Act, Type::Int},
    {"Radiosity_File_Name", Use::Warn, Type::String, ""},
    {"Radiosity_From_File", Use::Warn, Type::Bool, "off"},
    {"Radiosity_To_File", Use::Warn, Type::Bool, "off"},
    {"Radiosity_Vain_Pretrace", Use::Warn, Type::Bool, "on"},
    {"Real_Time_Raytracing", Use::Silent, Type::Bool},
    {"Remove_Bounds", Use::Warn, Type::Bool, "on"},
    {"Render_Block_Size", Use::Act, Type::Int},
    {"Render_Block_Step", Use::Silent, Type::Int},
    {"Render_Console", Use::Silent, Type::Bool},
    {"Render_File", Use::Silent, Type::String},
    {"Render_Pattern", Use::Silent, Type::Int},
    {"Sampling_Method", Use::Act, Type::Int},
    {"Split_Unions", Use::Warn, Type::Bool, "off"},
    {"Start_Column", Use::Act, Type::Float},
    {"Start_Row", Use::Act, Type::Float},
    {"Statistic_Console", Use::Silent, Type::Bool},
    {"Statistic_File", Use::Silent, Type::String},
    {"Subset_End_Frame", Use::Act, Type::Float},
    {"Subset_Start_Frame", Use::Act, Type::Float},
    {"Test_Abort_Count", Use::Silent, Type::Int},
    {"Test_Abort", Use::Silent, Type::Bool},
    {"User_Abort_Command", Use::Silent, Type::Special},
    {"User_Abort_Return", Use::Silent, Type::Special},
    {"Verbose", Use::Silent, Type::Bool},
    {"Version", Use::Act, Type::Float},
    {"Video_Mode", Use::Silent, Type::Special},
    {"Vista_Buffer", Use::Silent, Type::Bool},
    {"Warning_Console", Use::Silent, Type::Bool},
    {"Warning_File", Use::Silent, Type::String},
    {"Warning_Level", Use::Silent, Type::Int},
    {"Width", Use::Act, Type::Int},
    {"Work_Threads", Use::Act, Type::Int},
};

// POV-Ray matches keys case-insensitively and exactly.
const Key* find_key(const std::string& name) {
    const std::string l = lower(name);
    for (const Key& k : kKeys) {
        if (lower(k.name) == l) return &k;
    }
    return nullptr;
}

// POV-Ray's IsTrue: the value and one of on/true/yes/1 agree over the shorter of the two
// (so "y", "TRUE", "10" and "" are true); anything else is false.
bool is_true(const std::string& value) {
    for (const char* word : {"on", "true", "yes", "1"}) {
        bool match = true;
        for (size_t i = 0; word[i] && i < value.size(); ++i)
            match = match && word[i] == std::tolower((unsigned char)value[i]);
        if (match) return true;
    }
    return false;
}

// sscanf("%d") and sscanf("%lf"), as POV-Ray reads numbers: the longest number at the
// start (after spaces), the rest ignored; nothing when there is none.
std::optional<int> int_prefix(const std::string& v) {
    int i = 0;
    if (std::sscanf(v.c_str(), "%d", &i) != 1) return std::nullopt;
    return i;
}
std::optional<double> float_prefix(const std::string& v) {
    double d = 0;
    if (std::sscanf(v.c_str(), "%lf", &d) != 1) return std::nullopt;
    return d;
}

std::string number_text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// One line of the file and a read position in it.
struct Cursor {
    const std::string& line;
    size_t pos = 0;
    bool at_end() const { return pos >= line.size(); }
    char peek() const { return at_end() ? '\0' : line[pos]; }
    void skip_space() {
        // Any white space, not only blanks and tabs: a stray \r or \f mid-line would
        // otherwise end every word before it starts and the line would never advance.
        while (!at_end() && std::isspace((unsigned char)line[pos])) ++pos;
    }
};

bool ends_word(char c, bool key) {
    return std::isspace((unsigned char)c) || c == ',' || c == ';' || c == '#' ||
           c == '"' || c == '\'' || (key && (c == '[' || c == ']' || c == '='));
}

// A key or switch (Parse_INI_String with its default end: space , ; # quotes [ ] =).
std::string read_word(Cursor& c, bool key) {
    size_t start = c.pos;
    while (!c.at_end() && !ends_word(c.line[c.pos], key)) ++c.pos;
    return c.line.substr(start, c.pos - start);
}

// An unquoted value: up to a space, comma, comment or quote; at a space POV-Ray's "smart
// mode" looks ahead, and when what follows is neither a comment, a comma, a switch nor a
// known key, the value is a path with spaces and runs to the comment or the line's end.
std::string read_unquoted(Cursor& c, bool smart) {
    size_t start = c.pos;
    while (!c.at_end()) {
        const char ch = c.line[c.pos];
        if (smart && (ch == ' ' || ch == '\t')) {
            Cursor ahead{c.line, c.pos};
            ahead.skip_space();
            const char n = ahead.peek();
            bool ends = ahead.at_end() || n == ';' || n == '#' || n == ',';
            if (!ends && (n == '+' || n == '-') && ahead.pos + 1 < c.line.size() &&
                std::isalpha((unsigned char)c.line[ahead.pos + 1]))
                ends = true;
            if (!ends) ends = find_key(read_word(ahead, true)) != nullptr;
            if (ends) break;
            while (!c.at_end() && c.line[c.pos] != ';' && c.line[c.pos] != '#') ++c.pos;
            std::string v = c.line.substr(start, c.pos - start);
            v.erase(v.find_last_not_of(" \t\r") + 1);
            return v;
        }
        if (ends_word(ch, false)) break;
        ++c.pos;
    }
    return c.line.substr(start, c.pos - start);
}

// A value: quoted with " or ' (to the matching quote), or unquoted.
std::string read_value(Cursor& c, bool smart) {
    const char q = c.peek();
    if (q == '"' || q == '\'') {
        size_t end = c.line.find(q, c.pos + 1);
        if (end == std::string::npos) end = c.line.size();
        std::string v = c.line.substr(c.pos + 1, end - c.pos - 1);
        c.pos = std::min(end + 1, c.line.size());
        return v;
    }
    return read_unquoted(c, smart);
}

class IniReader {
  public:
    IniReader(RenderOptions& o, std::ostream* warnings, int depth)
        : o_(o), warnings_(warnings), depth_(depth) {}

    void read(std::istream& in, const std::string& path, const std::string& section) {
        std::string line;
        int number = 0;
        // Options before any [Section] apply; a named section only when it was asked
        // for (file.ini[Section]), and then only that one.
        bool active = true;
        while (std::getline(in, line)) {
            ++number;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            where_ = path + ":" + std::to_string(number);
            Cursor c{line};
            for (;;) {
                c.skip_space();
                if (c.at_end() || c.peek() == ';' || c.peek() == '#') break;
                if (c.peek() == '[') {
                    size_t end = line.find(']', c.pos);
                    const std::string name = line.substr(
                        c.pos + 1,
                        (end == std::string::npos ? line.size() : end) - c.pos - 1);
                    active = !section.empty() && lower(name) == lower(section);
                    break;
                }
                if (!active) break;
                const size_t before = c.pos;
                if (!item(c)) break;  // an option takes the rest of its line
                // Every item consumes text; one that did not would loop on this line.
                if (c.pos == before)
                    error(std::string("cannot read an item starting with '") + c.peek() +
                          "'");
            }
        }
    }

  private:
    // One item at the cursor: false when the rest of the line is done with.
    bool item(Cursor& c) {
        const char first = c.peek();
        if (std::iscntrl((unsigned char)first)) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02x", (unsigned char)first);
            error(std::string("unexpected control character ") + code);
        }
        if (first == '+' || first == '-') {
            std::string sw = read_word(c, true);
            if (c.peek() == '"' || c.peek() == '\'') sw += read_value(c, false);
            if (!apply_switch(sw)) error("unknown switch '" + sw + "'");
            return true;
        }
        if (std::isalnum((unsigned char)first) || first == '_') {
            Cursor k = c;
            const std::string name = read_word(k, true);
            const Key* key = find_key(name);
            k.skip_space();
            if (key && k.peek() == '=') {
                ++k.pos;
                option(*key, name, k);
                return false;
            }
            Cursor plain = c;
            const std::string word = read_unquoted(plain, true);
            if (word.find('=') != std::string::npos)
                error("unknown key '" + name + "' in INI file");
            c.pos = plain.pos;
            unknown_string(word);
            return true;
        }
        if (first == ',') {  // a separator between items, as between a key's values
            ++c.pos;
            return true;
        }
        const std::string word = read_value(c, first != '"' && first != '\'');
        unknown_string(word);
        return true;
    }

    // `Key = value[, value...]`: the option once per value.
    void option(const Key& key, const std::string& name, Cursor& c) {
        c.skip_space();
        // Shell commands are read raw, to the comment or the end of the line.
        const std::string lname = lower(name);
        if (key.type == Type::Special && lname.size() > 8 &&
            lname.compare(lname.size() - 8, 8, "_command") == 0) {
            return;
        }
        std::string value = read_value(c, true);
        for (;;) {
            apply(key, name, value);
            c.skip_space();
            if (c.peek() != ',') break;
            ++c.pos;
            c.skip_space();
            value = read_value(c, false);
        }
    }

    void apply(const Key& key, const std::string& name, const std::string& value) {
        // Numbers are checked whatever povwall does with them, as POV-Ray does.
        std::optional<int> i;
        std::optional<double> f;
        if (key.type == Type::Int && !(i = int_prefix(value)))
            error("integer parameter expected for option '" + name + "', found '" +
                  value + "'");
        if (key.type == Type::Float && !(f = float_prefix(value)))
            error("floating-point parameter expected for option '" + name + "', found '" +
                  value + "'");
        switch (key.use) {
            case Use::Silent:
                return;
            case Use::Deprecated:
                warn("INI option '" + name +
                     "' is no longer used and will result in an error in future "
                     "versions of POV-Ray");
                return;
            case Use::Warn:
                warn_unless_standard(key, name, value, i);
                return;
            case Use::Act:
                act(key, value, i, f);
                return;
        }
    }

    void warn_unless_standard(const Key& key, const std::string& name,
                              const std::string& value, std::optional<int> i) {
        const std::string k = lower(key.name);
        bool standard = false;
        if (k == "dither_method") {
            standard = !dither_;  // no effect without Dither=on
        } else if (key.standard == nullptr) {
            standard = false;
        } else if (key.type == Type::Bool) {
            standard = is_true(value) == is_true(key.standard);
        } else if (key.type == Type::Int) {
            standard = *i == std::atoi(key.standard);
        } else if (key.type == Type::String) {
            standard = value.empty();
        } else if (std::string(key.standard) == "srgb") {
            standard = lower(value) == "srgb";
        } else {
            standard = std::atof(value.c_str()) == std::atof(key.standard);
        }
        if (k == "dither") dither_ = is_true(value);
        if (!standard)
            warn(name + "=" + value + " is accepted but has no effect in povwall");
    }

    void act(const Key& key, const std::string& value, std::optional<int> i,
             std::optional<double> f) {
        const std::string k = lower(key.name);
        const std::string sign = is_true(value) ? "+" : "-";
        if (k == "input_file_name") {
            o_.scene = value;
        } else if (k == "output_file_name") {
            o_.output = value;
        } else if (k == "library_path") {
            o_.library_paths.push_back(value);
        } else if (k == "include_ini") {
            include(value);
        } else if (k == "declare") {
            apply_switch("Declare=" + value);
        } else if (k == "output_file_type") {
            // The first character names the type (POV-Ray's ParseFileType).
            const size_t at = value.find_first_not_of(" \t");
            apply_switch("+F" + (at == std::string::npos ? std::string("?")
                                                         : value.substr(at, 1)));
        } else if (k == "file_gamma" || k == "display_gamma") {
            // A number (1: neutral, above 0: a power law) or sRGB, as POV-Ray reads
            // both. Display_Gamma is the preview window's: POV-Ray's files never depend
            // on it (a legacy scene's values are written raw whatever it is).
            const double g = std::atof(value.c_str());
            const bool srgb = !(g > 0) && lower(value) == "srgb";
            if (!(g > 0) && !srgb) error("Unrecognized gamma setting '" + value + "'.");
            if (k == "file_gamma") {
                if (srgb)
                    o_.file_gamma.reset();
                else
                    o_.file_gamma = float(g);
            }
        } else if (k == "bits_per_color" || k == "bits_per_colour") {
            o_.bits = *i;
        } else if (k == "antialias") {
            o_.render.antialias = is_true(value);
        } else if (k == "antialias_threshold") {
            o_.render.aa_threshold = *f;  // the threshold alone does not turn AA on
        } else if (k == "jitter") {
            o_.render.aa_jitter = is_true(value);
        } else if (k == "jitter_amount") {
            o_.render.aa_jitter_amount = *f;
        } else if (k == "antialias_gamma") {
            o_.render.aa_gamma = *f;
        } else if (k == "render_block_size") {
            apply_switch("+BS" + std::to_string(*i));
        } else if (k == "antialias_depth") {
            apply_switch("+R" + std::to_string(*i));
        } else if (k == "sampling_method") {
            apply_switch("+AM" + std::to_string(*i));
        } else if (k == "quality") {
            apply_switch("+Q" + std::to_string(*i));
        } else if (k == "width") {
            apply_switch("+W" + std::to_string(*i));
        } else if (k == "height") {
            apply_switch("+H" + std::to_string(*i));
        } else if (k == "work_threads") {
            apply_switch("+WT" + std::to_string(*i));
        } else if (k == "initial_frame") {
            apply_switch("+KFI" + std::to_string(*i));
        } else if (k == "final_frame") {
            apply_switch("+KFF" + std::to_string(*i));
        } else if (k == "output_alpha") {
            apply_switch(sign + "UA");
        } else if (k == "cyclic_animation") {
            apply_switch(sign + "KC");
        } else if (k == "continue_trace") {
            apply_switch(sign + "C");
        } else {
            // Floats: the switch of the same meaning.
            static const std::pair<const char*, const char*> kFloatSwitch[] = {
                {"start_row", "SR"},
                {"end_row", "ER"},
                {"start_column", "SC"},
                {"end_column", "EC"},
                {"initial_clock", "KI"},
                {"final_clock", "KF"},
                {"clock", "K"},
                {"subset_start_frame", "SF"},
                {"subset_end_frame", "EF"},
                {"version", "MV"}};
            for (const auto& [name, letters] : kFloatSwitch) {
                if (k == name) {
                    apply_switch(std::string("+") + letters + number_text(*f));
                    return;
                }
            }
            error("internal: no action for '" + std::string(key.name) + "'");
        }
    }

    // A word that is neither a switch nor an option (POV-Ray's ProcessUnknownString):
    // a .pov file is the scene, a name ending in '/' a library path, anything else an
    // INI file to read.
    void unknown_string(const std::string& word) {
        if (word.empty()) return;
        const size_t dot = word.rfind('.');
        if (dot != std::string::npos && lower(word.substr(dot)) == ".pov") {
            o_.scene = word;
        } else if (word.back() == '/') {
            o_.library_paths.push_back(word);
        } else {
            include(word);
        }
    }

    void include(const std::string& spec) {
        if (depth_ >= 16) error("INI files included too deeply (limit 16)");
        try {
            apply_ini_file(spec, o_, warnings_, depth_ + 1);
        } catch (const UsageError& e) {
            const std::string what = e.what();
            // Located where the file was named, unless the error is inside it.
            if (what.rfind("cannot open", 0) == 0) error(what);
            throw;
        }
    }

    bool apply_switch(const std::string& sw) {
        try {
            return apply_pov_switch(sw, o_);
        } catch (const UsageError& e) {
            error(e.what());
        }
    }

    [[noreturn]] void error(const std::string& message) {
        throw IniFileError(where_ + ": " + message);
    }
    void warn(const std::string& message) {
        if (warnings_ && !o_.quiet)
            *warnings_ << ("povwall: warning: " + where_ + ": " + message + "\n");
    }

    RenderOptions& o_;
    std::ostream* warnings_;
    int depth_;
    std::string where_;
    bool dither_ = false;
};

}  // namespace

bool looks_like_ini_file(const std::string& arg) {
    if (arg.empty() || arg[0] == '+' || arg[0] == '-') return false;
    std::string name = arg;
    // file.ini[Section]
    if (name.back() == ']' && name.find('[') != std::string::npos)
        name.resize(name.find('['));
    return name.size() > 4 && lower(name.substr(name.size() - 4)) == ".ini";
}

void apply_ini_file(const std::string& spec, RenderOptions& o, std::ostream* warnings,
                    int depth) {
    std::string path = spec, section;
    if (size_t open = spec.find('['); open != std::string::npos) {
        const size_t close = spec.find(']', open);
        if (close == std::string::npos)
            throw UsageError("bad INI file specification '" + spec + "'");
        path = spec.substr(0, open);
        section = spec.substr(open + 1, close - open - 1);
    }
    // As POV-Ray: the name, then with .ini added, in the current folder and then in the
    // library paths.
    namespace fs = std::filesystem;
    std::vector<fs::path> tries;
    const bool has_extension = fs::path(path).has_extension();
    for (const fs::path& dir : [&] {
             std::vector<fs::path> dirs{fs::path()};
             if (fs::path(path).is_relative())
                 for (const auto& l : o.library_paths) dirs.emplace_back(l);
             return dirs;
         }()) {
        if (has_extension) tries.push_back(dir / path);
        tries.push_back(dir / (path + ".ini"));
    }
    std::ifstream in;
    std::string found;
    for (const fs::path& p : tries) {
        std::error_code ec;
        if (!fs::is_regular_file(p, ec)) continue;
        in.open(p);
        if (in) {
            found = p.string();
            break;
        }
    }
    if (found.empty()) throw UsageError("cannot open option file '" + path + "'");
    IniReader(o, warnings, depth).read(in, found, section);
}

std::string default_ini_file() {
    namespace fs = std::filesystem;
    std::vector<fs::path> tries;
    if (const char* env = std::getenv("POVINI"); env && *env) tries.emplace_back(env);
    tries.emplace_back("povray.ini");
    if (const char* home = std::getenv("HOME"); home && *home)
        tries.push_back(fs::path(home) / ".povray" / "3.7" / "povray.ini");
    for (const fs::path& p : tries) {
        std::error_code ec;
        if (fs::is_regular_file(p, ec)) return p.string();
    }
    return {};
}

void apply_default_ini(RenderOptions& o, std::ostream* warnings) {
    const std::string path = default_ini_file();
    if (!path.empty()) apply_ini_file(path, o, warnings);
}

bool looks_like_ini_option(const std::string& arg) {
    const size_t eq = arg.find('=');
    if (arg.empty() || arg[0] == '+' || arg[0] == '-' || eq == std::string::npos)
        return false;
    std::string key = arg.substr(0, eq);
    key.erase(key.find_last_not_of(" \t") + 1);
    return find_key(key) != nullptr;
}

void apply_ini_option(const std::string& arg, RenderOptions& o) {
    std::istringstream line(arg);
    IniReader(o, &std::cerr, 0).read(line, "command line", "");
}

void apply_ini_stream(std::istream& in, const std::string& path, RenderOptions& o,
                      std::ostream* warnings) {
    IniReader(o, warnings, 0).read(in, path, "");
}

}  // namespace povwall::cli
