// POV-Ray's command-line switches: `+` turns an option on (or sets a value), `-` off.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "cli/options.h"

namespace povwall::cli {
namespace {

bool starts_with_ci(const std::string& s, size_t at, const char* prefix) {
    for (size_t i = 0; prefix[i]; ++i) {
        if (at + i >= s.size() || std::toupper((unsigned char)s[at + i]) != prefix[i])
            return false;
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

// As POV-Ray 3.7 (scene/view.cpp): a start in [0, 1) or an end in [0, 1] is a fraction
// of the image, any other value a 1-based row or column number.
RenderOptions::Partial partial(const std::string& arg, bool end) {
    std::string v = arg.substr(3);
    RenderOptions::Partial p;
    p.value = number(arg, v);
    if (p.value < 0) throw UsageError("bad value in switch '" + arg + "'");
    p.fraction = end ? p.value <= 1.0 : p.value < 1.0;
    return p;
}

}  // namespace

void resolve_partial_render(RenderOptions& o) {
    auto first = [](const RenderOptions::Partial& p, int size) {
        if (p.value < 0) return 0;
        return p.fraction ? int(p.value * size) : int(p.value) - 1;
    };
    auto last = [](const RenderOptions::Partial& p, int size) {
        if (p.value < 0) return -1;
        return p.fraction ? int(p.value * size) - 1 : int(p.value) - 1;
    };
    o.render.first_row = first(o.start_row, o.height);
    o.render.last_row = last(o.end_row, o.height);
    o.render.first_col = first(o.start_col, o.width);
    o.render.last_col = last(o.end_col, o.width);
}

bool looks_like_pov_switch(const std::string& arg) {
    if (arg.size() >= 2 && arg[0] == '+') return true;
    if (arg.rfind("Declare=", 0) == 0 || arg.rfind("declare=", 0) == 0) return true;
    if (looks_like_ini_option(arg)) return true;
    if (arg.size() >= 2 && arg[0] == '-' && arg[1] != '-') {
        // povwall's own short options: -o -W -H -L -h (with a separate or attached
        // value).
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
        if (eq == std::string::npos)
            throw UsageError("expected Declare=NAME=VALUE: '" + arg + "'");
        // POV-Ray keeps the first value a name is given (its default INI's before the
        // command line's).
        o.declares.emplace(rest.substr(0, eq), number(arg, rest.substr(eq + 1)));
        return true;
    }
    if (looks_like_ini_option(arg)) {
        apply_ini_option(arg, o);
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
    } else if (starts_with_ci(arg, 1, "AG")) {
        o.render.aa_gamma = number(arg, arg.substr(3));
    } else if (starts_with_ci(arg, 1, "BS")) {
        // POV-Ray's front end refuses blocks smaller than 4 pixels.
        const int size = int(number(arg, arg.substr(3)));
        if (size < 4)
            throw UsageError("render block size in '" + arg + "' must be at least 4");
        o.render.block_size = size;
    } else if (starts_with_ci(arg, 1, "KFI")) {
        o.animation.initial_frame = int(number(arg, arg.substr(4)));
    } else if (starts_with_ci(arg, 1, "KFF")) {
        o.animation.final_frame = int(number(arg, arg.substr(4)));
    } else if (starts_with_ci(arg, 1, "KI")) {
        o.animation.initial_clock = number(arg, arg.substr(3));
    } else if (starts_with_ci(arg, 1, "KF")) {
        o.animation.final_clock = number(arg, arg.substr(3));
    } else if (starts_with_ci(arg, 1, "KC")) {
        o.animation.cyclic = on;
    } else if (starts_with_ci(arg, 1, "SF")) {
        o.animation.subset_start = number(arg, arg.substr(3));
    } else if (starts_with_ci(arg, 1, "EF")) {
        o.animation.subset_end = number(arg, arg.substr(3));
    } else if (starts_with_ci(arg, 1, "SR")) {
        o.start_row = partial(arg, false);
    } else if (starts_with_ci(arg, 1, "ER")) {
        o.end_row = partial(arg, true);
    } else if (starts_with_ci(arg, 1, "SC")) {
        o.start_col = partial(arg, false);
    } else if (starts_with_ci(arg, 1, "EC")) {
        o.end_col = partial(arg, true);
    } else if (starts_with_ci(arg, 1, "MV")) {
        // As POV-Ray: the version times 100, rounded, kept within 1.0 .. 100.
        const double v = number(arg, arg.substr(3));
        o.language_version = std::clamp(int(v * 100.0 + 0.5), 100, 10000);
    } else if (starts_with_ci(arg, 1, "GA") || starts_with_ci(arg, 1, "GD") ||
               starts_with_ci(arg, 1, "GF") || starts_with_ci(arg, 1, "GR") ||
               starts_with_ci(arg, 1, "GS") || starts_with_ci(arg, 1, "GW")) {
        o.quiet = !on;
    } else {
        switch (std::toupper((unsigned char)arg[1])) {
            case 'I':
                o.scene = v2;
                break;
            case 'O':
                o.output = v2;
                break;
            case 'W':
                o.width = int(number(arg, v2));
                break;
            case 'H':
                o.height = int(number(arg, v2));
                break;
            case 'L':
                o.library_paths.push_back(v2);
                break;
            case 'A':
                o.render.antialias = on;
                if (on && !v2.empty()) o.render.aa_threshold = number(arg, v2);
                break;
            case 'R':
                o.render.aa_depth = int(number(arg, v2));
                break;
            case 'J':
                o.render.aa_jitter = on;
                if (on && !v2.empty()) o.render.aa_jitter_amount = number(arg, v2);
                break;
            case 'F':
                if (!v2.empty()) {
                    o.format = char(std::toupper((unsigned char)v2[0]));
                    if (std::string("NTCPEHJ").find(o.format) == std::string::npos) {
                        throw UsageError(
                            "unsupported output format in '" + arg +
                            "' (povwall writes +FN, +FT, +FC, +FP, +FE, +FH, +FJ)");
                    }
                    o.format_given = true;
                    if (v2.size() > 1) o.bits = int(number(arg, v2.substr(1)));
                }
                break;
            case 'C':
                o.continue_trace = on;
                break;
            case 'Q':
                // POV-Ray's quality level; it treats anything above 9 as 9.
                o.render.quality = std::clamp(int(number(arg, v2)), 0, 9);
                break;
            case 'K':
                if (!v2.empty()) o.animation.clock = number(arg, v2);
                break;
            case 'D':
            case 'V':
            case 'P':
            case 'X':
            case 'B':
            case 'M':
                break;  // display, verbosity, pause, abort, buffers, bounding: no
                        // effect on the image
            default:
                return false;
        }
    }
    return true;
}

std::string format_extension(char format) {
    return format == 'T' || format == 'C' ? ".tga"
           : format == 'P'                ? ".ppm"
           : format == 'E'                ? ".exr"
           : format == 'H'                ? ".hdr"
           : format == 'J'                ? ".jpg"
                                          : ".png";
}

std::string default_output_name(const RenderOptions& o) {
    std::filesystem::path p(o.scene);
    return p.filename().replace_extension(format_extension(o.format)).string();
}

std::vector<Frame> animation_frames(const RenderOptions& o) {
    const RenderOptions::Animation& a = o.animation;
    if (a.final_frame <= a.initial_frame) return {};
    // POV-Ray: frames initial..final share the clock range evenly; a cyclic animation
    // leaves the last step for the wrap to the first frame.
    const int steps = a.final_frame - a.initial_frame + (a.cyclic ? 1 : 0);
    const double delta = (a.final_clock - a.initial_clock) / steps;
    const int digits = int(std::to_string(a.final_frame).size());
    std::filesystem::path out(o.output.empty() ? default_output_name(o) : o.output);
    const std::string ext =
        out.extension().empty() ? format_extension(o.format) : out.extension().string();
    const std::filesystem::path stem = out.parent_path() / out.stem();
    // POV-Ray's subset (animationprocessing.cpp): a value that is 0 or at least 1 is a
    // frame number, one between them that fraction of the frames (a cyclic animation's
    // wrap frame counted); the start no earlier than the first frame, the end no earlier
    // than the start.
    auto subset_frame = [&](double v) {
        v = std::max(v, 0.0);
        if (v == 0 || v >= 1) return int(v);
        return int((a.final_frame + (a.cyclic ? 1 : 0) - a.initial_frame + 1) * v);
    };
    const int first = a.subset_start
                          ? std::max(subset_frame(*a.subset_start), a.initial_frame)
                          : a.initial_frame;
    const int last = a.subset_end ? std::min(std::max(subset_frame(*a.subset_end), first),
                                             a.final_frame)
                                  : a.final_frame;
    std::vector<Frame> frames;
    for (int n = first; n <= last; ++n) {
        Frame f;
        f.number = n;
        f.clock = a.initial_clock + delta * (n - a.initial_frame);
        f.clock_delta = delta;
        std::string num = std::to_string(n);
        if (int(num.size()) < digits) num.insert(0, size_t(digits) - num.size(), '0');
        f.output = stem.string() + num + ext;
        frames.push_back(f);
    }
    return frames;
}

}  // namespace povwall::cli
