// POV-Ray's command-line switches: `+` turns an option on (or sets a value), `-` off.
#include <cctype>
#include <filesystem>

#include "cli/options.h"

namespace povwall::cli {
namespace {

bool starts_with_ci(const std::string& s, size_t at, const char* prefix) {
    for (size_t i = 0; prefix[i]; ++i) {
        if (at + i >= s.size() || std::toupper((unsigned char)s[at + i]) != prefix[i]) return false;
    }
    return true;
}

double number(const std::string& arg, const std::string& value) {
    try {
        size_t used = 0;
        double v = std::stod(value, &used);
        if (used != value.size()) throw std::invalid_argument(value);
        return v;
    } catch (const std::exception&) {
        throw UsageError("bad value in switch '" + arg + "'");
    }
}

}  // namespace

bool looks_like_pov_switch(const std::string& arg) {
    if (arg.size() >= 2 && arg[0] == '+') return true;
    if (arg.rfind("Declare=", 0) == 0 || arg.rfind("declare=", 0) == 0) return true;
    if (arg.size() >= 2 && arg[0] == '-' && arg[1] != '-') {
        // povwall's own short options: -o -W -H -L -h (with a separate or attached value).
        char c = arg[1];
        if (c == 'o' || c == 'h' || c == 'q') return false;
        if ((c == 'W' || c == 'H' || c == 'L') && arg.size() == 2) return false;
        return true;
    }
    return false;
}

bool apply_pov_switch(const std::string& arg, RenderOptions& o) {
    if (arg.rfind("Declare=", 0) == 0 || arg.rfind("declare=", 0) == 0) {
        std::string rest = arg.substr(8);
        size_t eq = rest.find('=');
        if (eq == std::string::npos) throw UsageError("expected Declare=NAME=VALUE: '" + arg + "'");
        o.declares[rest.substr(0, eq)] = number(arg, rest.substr(eq + 1));
        return true;
    }
    if (arg.size() < 2 || (arg[0] != '+' && arg[0] != '-')) return false;
    const bool on = arg[0] == '+';
    const std::string v2 = arg.size() > 2 ? arg.substr(2) : "";
    if (starts_with_ci(arg, 1, "WT")) {
        o.render.threads = int(number(arg, arg.substr(3)));
    } else if (starts_with_ci(arg, 1, "UA")) {
        o.render.alpha = on;
    } else if (starts_with_ci(arg, 1, "AM")) {
        o.render.aa_method = int(number(arg, arg.substr(3)));
    } else if (starts_with_ci(arg, 1, "SR")) {
        o.render.first_row = int(number(arg, arg.substr(3))) - 1;
    } else if (starts_with_ci(arg, 1, "ER")) {
        o.render.last_row = int(number(arg, arg.substr(3))) - 1;
    } else if (starts_with_ci(arg, 1, "SC")) {
        o.render.first_col = int(number(arg, arg.substr(3))) - 1;
    } else if (starts_with_ci(arg, 1, "EC")) {
        o.render.last_col = int(number(arg, arg.substr(3))) - 1;
    } else if (starts_with_ci(arg, 1, "GA") || starts_with_ci(arg, 1, "GD") ||
               starts_with_ci(arg, 1, "GF") || starts_with_ci(arg, 1, "GR") ||
               starts_with_ci(arg, 1, "GS") || starts_with_ci(arg, 1, "GW")) {
        o.quiet = !on;
    } else {
        switch (std::toupper((unsigned char)arg[1])) {
            case 'I': o.scene = v2; break;
            case 'O': o.output = v2; break;
            case 'W': o.width = int(number(arg, v2)); break;
            case 'H': o.height = int(number(arg, v2)); break;
            case 'L': o.library_paths.push_back(v2); break;
            case 'A':
                o.render.antialias = on;
                if (on && !v2.empty()) o.render.aa_threshold = number(arg, v2);
                break;
            case 'R': o.render.aa_depth = int(number(arg, v2)); break;
            case 'J':
                o.render.aa_jitter = on;
                if (on && !v2.empty()) o.render.aa_jitter_amount = number(arg, v2);
                break;
            case 'F':
                if (!v2.empty()) {
                    o.format = char(std::toupper((unsigned char)v2[0]));
                    if (v2.size() > 1) o.bits = int(number(arg, v2.substr(1)));
                }
                break;
            case 'D': case 'V': case 'P': case 'X': case 'Q': case 'B': case 'C': case 'K':
            case 'M':
                break;  // display, verbosity, pause, quality, buffers: no effect on the image
            default: return false;
        }
    }
    return true;
}

std::string default_output_name(const RenderOptions& o) {
    std::filesystem::path p(o.scene);
    const char* ext = o.format == 'T' || o.format == 'C' ? ".tga"
                      : o.format == 'P'                  ? ".ppm"
                      : o.format == 'E'                  ? ".exr"
                                                         : ".png";
    return p.filename().replace_extension(ext).string();
}

}  // namespace povwall::cli
