#include "cli/tile_worker_job.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <utility>

namespace povwall::cli {
namespace {

// Every setting: its name on the command line, the job's field, and the render option
// it comes from and goes to (`o` is only read or written by of() and apply_to()).
template <class Job, class Options, class Visit>
void fields(Job& job, Options& o, Visit&& v) {
    v("scene", job.scene, o.scene);
    v("width", job.width, o.width);
    v("height", job.height, o.height);
    v("plan", job.plan, o.plan);
    v("library-path", job.library_paths, o.library_paths);
    v("declare", job.declares, o.declares);
    v("language-version", job.language_version, o.language_version);
    v("format", job.format, o.format);
    v("alpha", job.alpha, o.render.alpha);
    v("quality", job.quality, o.render.quality);
    v("antialias", job.antialias, o.render.antialias);
    v("aa-threshold", job.aa_threshold, o.render.aa_threshold);
    v("aa-method", job.aa_method, o.render.aa_method);
    v("aa-depth", job.aa_depth, o.render.aa_depth);
    v("aa-jitter", job.aa_jitter, o.render.aa_jitter);
    v("aa-jitter-amount", job.aa_jitter_amount, o.render.aa_jitter_amount);
    v("aa-gamma", job.aa_gamma, o.render.aa_gamma);
    v("max-trace-level", job.max_trace_level, o.max_trace_level);
    v("adc-bailout", job.adc_bailout, o.adc_bailout);
    v("max-loop-iterations", job.max_loop_iterations, o.max_loop_iterations);
    v("frame", job.frame, o.frame);
    v("initial-frame", job.initial_frame, o.animation.initial_frame);
    v("final-frame", job.final_frame, o.animation.final_frame);
    v("initial-clock", job.initial_clock, o.animation.initial_clock);
    v("final-clock", job.final_clock, o.animation.final_clock);
    v("clock", job.clock, o.animation.clock);
}

// Values as text, exactly: doubles with 17 significant digits read back bit for bit.
std::string text(const std::string& s) { return s; }
std::string text(char c) { return std::string(1, c); }
std::string text(bool b) { return b ? "1" : "0"; }
std::string text(int i) { return std::to_string(i); }
std::string text(uint64_t i) { return std::to_string(i); }
std::string text(double d) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", d);
    return buf;
}
std::string text(const RenderOptions::FrameValues& f) {
    return text(f.number) + "," + text(f.clock) + "," + text(f.clock_delta);
}

[[noreturn]] void malformed(std::string_view name, std::string_view value) {
    throw UsageError("tile worker: malformed --" + std::string(name) + "=" +
                     std::string(value));
}

template <class Int>
Int whole(std::string_view name, std::string_view s) {
    Int v{};
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size()) malformed(name, s);
    return v;
}
double real(std::string_view name, std::string_view s) {
    const std::string copy(s);
    char* end = nullptr;
    const double v = std::strtod(copy.c_str(), &end);
    if (copy.empty() || end != copy.c_str() + copy.size()) malformed(name, s);
    return v;
}

void read(std::string_view, std::string_view s, std::string& out) { out = s; }
void read(std::string_view name, std::string_view s, char& out) {
    if (s.size() != 1) malformed(name, s);
    out = s[0];
}
void read(std::string_view name, std::string_view s, bool& out) {
    if (s != "0" && s != "1") malformed(name, s);
    out = s == "1";
}
void read(std::string_view name, std::string_view s, int& out) {
    out = whole<int>(name, s);
}
void read(std::string_view name, std::string_view s, uint64_t& out) {
    out = whole<uint64_t>(name, s);
}
void read(std::string_view name, std::string_view s, double& out) { out = real(name, s); }
void read(std::string_view name, std::string_view s, RenderOptions::FrameValues& out) {
    const size_t a = s.find(','), b = s.find(',', a == s.npos ? a : a + 1);
    if (a == s.npos || b == s.npos) malformed(name, s);
    out.number = whole<int>(name, s.substr(0, a));
    out.clock = real(name, s.substr(a + 1, b - a - 1));
    out.clock_delta = real(name, s.substr(b + 1));
}
template <class T>
void read(std::string_view name, std::string_view s, std::optional<T>& out) {
    T value{};  // (not out.emplace(): clang reads a nested struct with member
                // initialisers as not default-constructible there)
    read(name, s, value);
    out = value;
}
// Lists and maps: one argument per entry.
void read(std::string_view, std::string_view s, std::vector<std::string>& out) {
    out.emplace_back(s);
}
void read(std::string_view name, std::string_view s, std::map<std::string, double>& out) {
    const size_t eq = s.find('=');
    if (eq == s.npos || eq == 0) malformed(name, s);
    out[std::string(s.substr(0, eq))] = real(name, s.substr(eq + 1));
}

template <class T>
void write(std::vector<std::string>& args, const char* name, const T& v) {
    args.push_back("--" + std::string(name) + "=" + text(v));
}
template <class T>
void write(std::vector<std::string>& args, const char* name, const std::optional<T>& v) {
    if (v) write(args, name, *v);
}
void write(std::vector<std::string>& args, const char* name,
           const std::vector<std::string>& v) {
    for (const std::string& s : v) write(args, name, s);
}
void write(std::vector<std::string>& args, const char* name,
           const std::map<std::string, double>& v) {
    for (const auto& [key, value] : v) write(args, name, key + "=" + text(value));
}

}  // namespace

TileWorkerJob TileWorkerJob::of(const RenderOptions& o) {
    TileWorkerJob job;
    fields(job, o, [](const char*, auto& mine, const auto& theirs) { mine = theirs; });
    return job;
}

void TileWorkerJob::apply_to(RenderOptions& o) const {
    fields(*this, o, [](const char*, const auto& mine, auto& theirs) { theirs = mine; });
    o.tile_worker = true;
    o.render.threads = 1;
    o.quiet = true;
}

std::vector<std::string> TileWorkerJob::to_argv() const {
    std::vector<std::string> args = {kFlag};
    RenderOptions unused;
    fields(*this, unused, [&](const char* name, const auto& mine, const auto&) {
        write(args, name, mine);
    });
    return args;
}

TileWorkerJob TileWorkerJob::from_argv(const std::vector<std::string>& args) {
    if (args.empty() || args[0] != kFlag)
        throw UsageError(std::string("tile worker: arguments must start with ") + kFlag);
    TileWorkerJob job;
    RenderOptions unused;
    for (size_t i = 1; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const size_t eq = a.find('=');
        if (a.substr(0, 2) != "--" || eq == a.npos)
            throw UsageError("tile worker: unexpected argument '" + args[i] + "'");
        const std::string_view name = a.substr(2, eq - 2), value = a.substr(eq + 1);
        bool known = false;
        fields(job, unused, [&](const char* n, auto& mine, const auto&) {
            if (known || name != n) return;
            known = true;
            read(name, value, mine);
        });
        if (!known) throw UsageError("tile worker: unknown setting '" + args[i] + "'");
    }
    return job;
}

}  // namespace povwall::cli
