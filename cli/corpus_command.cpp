// `povwall corpus`: every scene of a folder or list rendered by POV-Ray and by povwall,
// diffed, and reported as a table on stdout and an HTML page with the images. povwall's
// renders run as child processes of this binary with a time limit, so a scene that
// crashes or hangs povwall becomes one failed row instead of ending the report.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "cli/povray_reference.h"
#include "cli/process.h"
#include "core/self_exe.h"
#include "output/diff.h"
#include "output/html_report.h"
#include "output/image_io.h"

namespace povwall::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct CorpusScene {
    std::string name;  // as listed (list files) or relative to the folder
    fs::path path;     // absolute
};

struct CorpusSettings {
    int width = 160, height = 120;
    int threads = 1;  // per renderer: one each makes the per-scene times comparable
    double timeout_seconds = 300;
    std::vector<std::string> library_paths;
    output::DiffThresholds thresholds;
    fs::path out_dir;   // absolute
    fs::path work_dir;  // the renderers' working folder, inside out_dir
    std::string cache_dir;
    std::string exe;      // this binary, for povwall's renders
    bool use_ini = true;  // a scene's .ini of the same name applies (scene_ini_file)
};

enum class Outcome { Matched, Mismatched, Unsupported, Failed };

const char* outcome_name(Outcome o) {
    switch (o) {
        case Outcome::Matched:
            return "matched";
        case Outcome::Mismatched:
            return "mismatched";
        case Outcome::Unsupported:
            return "unsupported";
        case Outcome::Failed:
            return "failed";
    }
    return "";
}

struct SceneResult {
    Outcome outcome = Outcome::Failed;
    bool warning = false;   // matched, but some pixels are over the warning threshold
    bool rendered = false;  // both renderers made an image: times and diff are valid
    double povray_seconds = 0, povwall_seconds = 0;
    bool povray_cached = false;
    output::DiffResult diff;
    int block_mean = 0;  // > 0: the images were compared as means of blocks this wide
    std::string note;    // the unsupported feature, or the first line of the failure
    // Relative to the report folder; "" when there is no such file.
    std::string povray_image, povwall_image, heatmap_image, log;
};

bool is_pov_file(const fs::path& p) {
    std::string ext = p.extension().string();
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext == ".pov";
}

std::vector<CorpusScene> corpus_scenes(const std::string& source,
                                       const std::string& root) {
    std::vector<CorpusScene> scenes;
    const fs::path src(source);
    std::error_code ec;
    if (fs::is_directory(src, ec)) {
        if (!root.empty()) throw UsageError("--root applies to list files, not folders");
        for (const auto& e : fs::recursive_directory_iterator(src, ec)) {
            if (e.is_regular_file() && is_pov_file(e.path()))
                scenes.push_back({fs::relative(e.path(), src).string(),
                                  fs::absolute(e.path()).lexically_normal()});
        }
        if (ec) throw UsageError("cannot read folder '" + source + "': " + ec.message());
        std::sort(scenes.begin(), scenes.end(),
                  [](const auto& a, const auto& b) { return a.name < b.name; });
        return scenes;
    }
    if (!fs::is_regular_file(src, ec))
        throw UsageError("no such scene folder or list file '" + source + "'");
    if (is_pov_file(src)) return {{source, fs::absolute(src).lexically_normal()}};
    std::ifstream in(src);
    if (!in) throw UsageError("cannot open list file '" + source + "'");
    const fs::path base =
        root.empty() ? fs::absolute(src).parent_path() : fs::absolute(root);
    for (std::string line; std::getline(in, line);) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        const size_t last = line.find_last_not_of(" \t\r");
        const std::string name = line.substr(first, last - first + 1);
        const fs::path p(name);
        scenes.push_back({name, (p.is_absolute() ? p : base / p).lexically_normal()});
    }
    return scenes;
}

// A file-name-safe stem for a scene's images and logs, unique through its row number.
std::string file_stem(size_t index, const std::string& name) {
    char number[16];
    std::snprintf(number, sizeof number, "%03zu-", index + 1);
    std::string stem = fs::path(name).replace_extension().string();
    for (char& c : stem)
        if (!std::isalnum((unsigned char)c) && c != '-' && c != '_' && c != '.') c = '_';
    return number + stem;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The first line of `text` containing `needle`, else "".
std::string first_line_with(const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.find(needle) != std::string::npos) return line;
    return {};
}

std::string first_nonblank_line(const std::string& text) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.find_first_not_of(" \t\r") != std::string::npos) return line;
    return {};
}

// povwall's diagnostic: its first error line (warnings may come before it), with the
// scene's absolute path shortened to its name in the report.
std::string povwall_message(const std::string& log, const CorpusScene& scene) {
    std::string line = first_line_with(log, "error: ");
    if (line.empty()) line = first_nonblank_line(log);
    const std::string abs = scene.path.string();
    if (line.rfind(abs, 0) == 0) line = scene.name + line.substr(abs.size());
    return line;
}

// Where a render stopped at the time limit was, from the line its SIGTERM handler wrote
// ("povwall: interrupted while tracing: 10 of 20 pixels (50.0 %); no image written"): "
// while tracing: 10 of 20 pixels (50.0 %)", the scene named as listed; "" when none.
std::string interrupted_phase(const std::string& log, const CorpusScene& scene) {
    const std::string line = first_line_with(log, "interrupted while ");
    const size_t at = line.find("interrupted while ");
    if (at == std::string::npos) return {};
    std::string phase = line.substr(at + std::string("interrupted").size());
    for (const char* tail : {"; no image written", ": the partly written image"})
        if (const size_t end = phase.find(tail); end != std::string::npos)
            phase.resize(end);
    const std::string abs = scene.path.string();
    if (const size_t p = phase.find(abs); p != std::string::npos)
        phase.replace(p, abs.size(), scene.name);
    return phase;
}

// POV-Ray's console output starts with a banner; the line saying what failed has "Error"
// in it ("File 'x.pov' line 1: Parse Error: ...").
std::string povray_message(const PovrayRun& run) {
    std::string line = first_line_with(run.log, "Error");
    if (line.empty()) line = first_line_with(run.log, "error");
    return "povray failed (exit " + std::to_string(run.exit_code) + ")" +
           (line.empty() ? "" : ": " + line);
}

std::string format_seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", s);
    return buf;
}

std::string number_text(double v, const char* format) {
    char buf[32];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

void remove_quietly(const fs::path& p) {
    std::error_code ignored;
    fs::remove(p, ignored);
}

SceneResult run_scene(const CorpusSettings& s, const CorpusScene& scene, size_t index) {
    SceneResult result;
    const std::string stem = file_stem(index, scene.name);
    const fs::path images = s.out_dir / "images", logs = s.out_dir / "logs";
    const std::string pov_png = stem + "-povray.png", our_png = stem + "-povwall.png",
                      heat_png = stem + "-diff.png";
    // Images of an earlier report must not stand in for renders that fail this time.
    for (const auto& f : {pov_png, our_png, heat_png}) remove_quietly(images / f);

    // The settings both renderers get, as a user would give them: the scene's .ini
    // (an animation's first frame), then the report's size, threads and 8-bit PNG
    // without anti-aliasing, which win over it.
    RenderOptions o;
    o.library_paths = s.library_paths;
    const std::string ini = s.use_ini ? scene_ini_file(scene.path.string()) : "";
    std::vector<std::string> switches{"+W" + std::to_string(s.width),
                                      "+H" + std::to_string(s.height), "-A",
                                      "+WT" + std::to_string(s.threads), "+FN8"};
    try {
        if (!ini.empty()) apply_ini_file(ini, o, nullptr);
        for (const auto& sw : switches) apply_pov_switch(sw, o);
        if (const std::vector<Frame> frames = animation_frames(o); !frames.empty()) {
            for (const auto& sw : {"+SF" + std::to_string(frames.front().number),
                                   "+EF" + std::to_string(frames.front().number)}) {
                switches.push_back(sw);
                apply_pov_switch(sw, o);
            }
        }
    } catch (const UsageError& e) {
        result.note = e.what();
        return result;
    }
    o.scene = scene.path.string();

    // Each renderer runs in its own empty folder of REPORT/files/: files the scene writes
    // (#fopen) go there, to POV-Ray's working folder and beside povwall's image (its
    // rule), so neither renderer nor an earlier run sees the other's. Emptied folders
    // are removed again.
    const fs::path scratch = s.work_dir / stem, pov_dir = scratch / "povray",
                   our_dir = scratch / "povwall";
    {
        std::error_code ec;
        fs::remove_all(scratch, ec);
        fs::create_directories(pov_dir, ec);
        fs::create_directories(our_dir, ec);
    }
    struct RemoveEmpty {
        std::vector<fs::path> dirs;
        ~RemoveEmpty() {
            for (const auto& d : dirs) remove_quietly(d);  // only when empty
        }
    } cleanup{{pov_dir, our_dir, scratch}};
    // The image a render made in `made` (an animation's frame under its numbered
    // name), moved to the report's name.
    auto take_image = [&](const fs::path& made, const std::string& png) {
        RenderOptions named = o;
        named.output = made.string();
        const std::vector<Frame> frames = animation_frames(named);
        std::error_code ec;
        fs::rename(frames.empty() ? made : fs::path(frames.front().output), images / png,
                   ec);
    };

    // povwall first: a scene it cannot read needs no reference render.
    std::vector<std::string> cmd{s.exe, "render", scene.path.string()};
    if (!ini.empty()) cmd.push_back(ini);
    for (const auto& sw : switches) cmd.push_back(sw);
    cmd.push_back("+O" + (our_dir / our_png).string());
    cmd.push_back("-q");
    for (const auto& l : s.library_paths) {
        cmd.push_back("-L");
        cmd.push_back(l);
    }
    const std::string our_log = stem + "-povwall.log";
    const auto t0 = Clock::now();
    // Past the limit the render gets SIGTERM first, to say where it was; its handler
    // answers at once, the grace covers a loaded machine.
    constexpr double kGraceSeconds = 2;
    const int rc = run_process(cmd, (logs / our_log).string(), s.timeout_seconds,
                               our_dir.string(), kGraceSeconds);
    result.povwall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (rc == 0) take_image(our_dir / our_png, our_png);
    if (rc != 0 || !fs::exists(images / our_png)) {
        result.log = "logs/" + our_log;
        const std::string message = povwall_message(slurp(logs / our_log), scene);
        const size_t at = message.find("error: unsupported: ");
        if (rc == 2 && at != std::string::npos) {
            result.outcome = Outcome::Unsupported;
            result.note = message.substr(at + std::string("error: unsupported: ").size());
        } else if (rc == kProcessTimedOut) {
            result.note = "povwall timed out after " + format_seconds(s.timeout_seconds) +
                          " s" + interrupted_phase(slurp(logs / our_log), scene);
            // A render killed (it ignored SIGTERM) while writing leaves its temporary
            // file: remove it.
            const std::string partial = "." + stem + "-povwall";  // frame numbers too
            std::error_code ec;
            for (const auto& e : fs::directory_iterator(our_dir, ec))
                if (e.path().filename().string().rfind(partial, 0) == 0)
                    remove_quietly(e.path());
        } else if (rc == -1) {
            result.note = "cannot run " + s.exe;
        } else if (rc > 128) {
            result.note = "povwall died of signal " + std::to_string(rc - 128);
        } else {
            result.note = message.empty()
                              ? "povwall failed (exit " + std::to_string(rc) + ")"
                              : message;
        }
        return result;
    }
    result.povwall_image = "images/" + our_png;

    const std::string pov_log = stem + "-povray.log";
    const PovrayRun pov = run_povray(
        o, povray_command(o, (images / pov_png).string(), s.threads), s.cache_dir,
        (logs / pov_log).string(), s.timeout_seconds, pov_dir.string());
    if (pov.status == PovrayRun::Status::Ok) take_image(images / pov_png, pov_png);
    switch (pov.status) {
        case PovrayRun::Status::Ok:
            break;
        case PovrayRun::Status::NotInstalled:
            result.note = "povray is not installed or not on PATH";
            return result;
        case PovrayRun::Status::SceneError:
            result.note = "the scene does not parse for the reference cache's key";
            return result;
        case PovrayRun::Status::Failed:
            result.log = "logs/" + pov_log;
            result.note = pov.timed_out ? "povray timed out after " +
                                              format_seconds(s.timeout_seconds) + " s"
                                        : povray_message(pov);
            return result;
    }
    result.povray_image = "images/" + pov_png;
    result.povray_seconds = pov.seconds;
    result.povray_cached = pov.cached;

    try {
        const Image ours = output::read_image((images / our_png).string());
        const Image theirs = output::read_image((images / pov_png).string());
        // POV-Ray's own image is random there: compared as 8x8 block means, as the
        // golden tests compare such scenes.
        result.block_mean = pov.random ? 8 : 0;
        result.diff =
            pov.random ? output::diff_images(output::block_means(ours, 8),
                                             output::block_means(theirs, 8), s.thresholds)
                       : output::diff_images(ours, theirs, s.thresholds);
        if (result.diff.status == output::DiffResult::Status::SizeMismatch) {
            result.note = result.diff.error;
            return result;
        }
        OutputEncoding raw;  // the ramp's colours as they are
        raw.gamma_handling = false;
        output::write_image(output::difference_heatmap(ours, theirs, s.thresholds.fail),
                            (images / heat_png).string(), raw);
        result.heatmap_image = "images/" + heat_png;
    } catch (const output::ImageIoError& e) {
        result.note = e.what();
        return result;
    }
    result.rendered = true;
    using Status = output::DiffResult::Status;
    const Status st = result.diff.status;
    result.outcome =
        st == Status::Pass || st == Status::Warn ? Outcome::Matched : Outcome::Mismatched;
    result.warning = st == Status::Warn;
    if (result.warning) {
        const long long n = result.diff.warn_pixels;
        const std::string unit = result.block_mean ? " block" : " pixel";
        result.note = "warning: " + std::to_string(n) + unit +
                      (n == 1 ? " differs" : "s differ") + " by more than " +
                      number_text(s.thresholds.warn, "%g");
    }
    if (result.block_mean) {
        result.note +=
            std::string(result.note.empty() ? "" : "; ") + "compared as " +
            std::to_string(result.block_mean) + "x" + std::to_string(result.block_mean) +
            " block means (POV-Ray's area-light jitter, photons and rainbow jitter are "
            "random)";
    }
    return result;
}

std::string status_text(const SceneResult& r) {
    return std::string(outcome_name(r.outcome)) + (r.warning ? " (warning)" : "");
}

std::string ratio_text(double povray_seconds, double povwall_seconds) {
    if (povwall_seconds <= 0 || povray_seconds <= 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", povray_seconds / povwall_seconds);
    return buf;
}

struct Totals {
    size_t scenes = 0, matched = 0, rendered = 0, unsupported = 0, failed = 0;
    double povray_seconds = 0, povwall_seconds = 0;
    size_t untimed_references = 0;  // cached before render times were recorded
};

std::string counts_line(const Totals& t) {
    return std::to_string(t.scenes) + " scenes: " + std::to_string(t.matched) +
           " matched / " + std::to_string(t.rendered) + " rendered / " +
           std::to_string(t.unsupported) + " unsupported / " + std::to_string(t.failed) +
           " failed";
}

std::string times_line(const Totals& t) {
    std::string line = "POV-Ray " + format_seconds(t.povray_seconds) + " s, povwall " +
                       format_seconds(t.povwall_seconds) +
                       " s over the rendered scenes " + "(ratio " +
                       ratio_text(t.povray_seconds, t.povwall_seconds) + ")";
    if (t.untimed_references)
        line += "; " + std::to_string(t.untimed_references) +
                " POV-Ray references came from the cache without a recorded time";
    return line;
}

void print_row(size_t index, const CorpusScene& scene, const SceneResult& r) {
    const bool timed = r.rendered;
    std::printf("%4zu  %-44s %-20s %8s %8s %6s %8s %8s  %s\n", index + 1,
                scene.name.c_str(), status_text(r).c_str(),
                timed ? format_seconds(r.povray_seconds).c_str() : "-",
                timed ? format_seconds(r.povwall_seconds).c_str() : "-",
                timed ? ratio_text(r.povray_seconds, r.povwall_seconds).c_str() : "-",
                timed ? number_text(r.diff.rmse, "%.4f").c_str() : "-",
                timed ? number_text(r.diff.bad_pixel_fraction, "%.4f").c_str() : "-",
                r.note.c_str());
    std::fflush(stdout);
}

output::HtmlRow html_row(size_t index, const CorpusScene& scene, const SceneResult& r) {
    const bool timed = r.rendered;
    output::HtmlRow row;
    row.css_class = outcome_name(r.outcome);
    auto text = [](std::string t, std::string css = "") {
        output::HtmlCell c;
        c.text = std::move(t);
        c.css_class = std::move(css);
        return c;
    };
    auto image = [](const std::string& path, const std::string& alt) {
        output::HtmlCell c;
        c.image = path;
        c.text = path.empty() ? "" : alt;
        return c;
    };
    row.cells.push_back(text(std::to_string(index + 1), "num"));
    row.cells.push_back(text(scene.name));
    row.cells.push_back(text(status_text(r), "status"));
    row.cells.push_back(image(r.povray_image, "POV-Ray"));
    row.cells.push_back(image(r.povwall_image, "povwall"));
    row.cells.push_back(image(r.heatmap_image, "difference"));
    std::string pov_time = timed ? format_seconds(r.povray_seconds) : "";
    if (timed && r.povray_cached) pov_time += " (cached)";
    row.cells.push_back(text(pov_time, "num"));
    row.cells.push_back(text(timed ? format_seconds(r.povwall_seconds) : "", "num"));
    row.cells.push_back(
        text(timed ? ratio_text(r.povray_seconds, r.povwall_seconds) : "", "num"));
    row.cells.push_back(text(timed ? number_text(r.diff.rmse, "%.4f") : "", "num"));
    row.cells.push_back(
        text(timed ? number_text(r.diff.bad_pixel_fraction, "%.4f") : "", "num"));
    output::HtmlCell note = text(r.note);
    note.link = r.log;
    if (note.text.empty() && !r.log.empty()) note.text = "log";
    row.cells.push_back(note);
    return row;
}

bool povray_on_path() {
    const char* path_env = std::getenv("PATH");
    std::stringstream dirs(path_env ? path_env : "");
    for (std::string d; std::getline(dirs, d, ':');) {
        const fs::path exe = fs::path(d.empty() ? "." : d) / "povray";
        if (access(exe.c_str(), X_OK) == 0) return true;
    }
    return false;
}

}  // namespace

int run_corpus(int argc, char** argv) {
    CLI::App app{
        "Render every scene of a folder or list with POV-Ray and povwall and write an "
        "HTML "
        "report with both images, their difference, times and the diff",
        "povwall corpus"};
    std::string source, root, html = "corpus-report", cache;
    CorpusSettings s;
    app.add_option("SOURCE", source,
                   "folder of .pov files (searched recursively) or a list file with one "
                   "scene path per line")
        ->required();
    app.add_option("-W", s.width, "image width")->capture_default_str();
    app.add_option("-H", s.height, "image height")->capture_default_str();
    app.add_option("--html", html, "report folder: index.html, images/, logs/")
        ->capture_default_str();
    app.add_option("--root", root,
                   "folder the list's relative paths are taken from (default: the list "
                   "file's folder)");
    app.add_option("--threads", s.threads, "threads for each renderer (0: all cores)")
        ->capture_default_str();
    app.add_option("--cache", cache,
                   "POV-Ray reference renders reused from this folder (default: "
                   "REPORT/cache)");
    app.add_option("--timeout", s.timeout_seconds, "seconds each render may take")
        ->capture_default_str();
    app.add_option("-L", s.library_paths,
                   "include folder for both renderers (repeatable)");
    bool no_ini = false;
    app.add_flag("--no-ini", no_ini,
                 "ignore a scene's .ini of the same name (by default its options apply, "
                 "an animation's first frame, under the report's size and settings)");
    app.add_option("--max-rmse", s.thresholds.max_rmse, "largest RMSE that matches")
        ->capture_default_str();
    app.add_option("--max-bad-fraction", s.thresholds.max_bad_fraction,
                   "largest fraction of bad pixels that matches")
        ->capture_default_str();
    if (auto done = parse_args(app, argc, argv)) return *done;
    s.use_ini = !no_ini;
    if (s.width <= 0 || s.height <= 0) throw UsageError("-W and -H must be positive");
    if (s.threads < 0) throw UsageError("--threads must be 0 or more");
    if (!(s.timeout_seconds > 0)) throw UsageError("--timeout must be positive");
    const std::vector<CorpusScene> scenes = corpus_scenes(source, root);
    if (!povray_on_path()) {
        std::cerr
            << "povwall: povray is not installed or not on PATH: nothing to compare "
               "with\n";
        return exit_code(ExitCode::NoPovRay);
    }
    s.exe = self_exe();
    if (s.exe.empty()) throw std::runtime_error("cannot find the povwall binary");
    s.out_dir = fs::absolute(html);
    s.work_dir = s.out_dir / "files";
    s.cache_dir = fs::absolute(cache.empty() ? s.out_dir / "cache" : fs::path(cache));
    for (auto& l : s.library_paths) l = fs::absolute(l).string();
    fs::create_directories(s.out_dir / "images");
    fs::create_directories(s.out_dir / "logs");
    fs::create_directories(s.work_dir);

    std::printf("%4s  %-44s %-20s %8s %8s %6s %8s %8s  %s\n", "#", "scene", "status",
                "povray_s", "ours_s", "ratio", "rmse", "bad", "note");
    output::HtmlReport report;
    report.title = "povwall corpus report: " + source;
    report.columns = {"#",       "scene",      "status",     "POV-Ray",
                      "povwall", "difference", "POV-Ray s",  "povwall s",
                      "ratio",   "rmse",       "bad pixels", "unsupported / failure"};
    report.css =
        "tr.matched td.status { background: #c8f0c8; }\n"
        "tr.mismatched td.status { background: #ffd8a0; }\n"
        "tr.unsupported td.status { background: #ddd; }\n"
        "tr.failed td.status { background: #f6a8a8; }\n";
    Totals t;
    t.scenes = scenes.size();
    for (size_t i = 0; i < scenes.size(); ++i) {
        const SceneResult r = run_scene(s, scenes[i], i);
        print_row(i, scenes[i], r);
        report.rows.push_back(html_row(i, scenes[i], r));
        t.matched += r.outcome == Outcome::Matched;
        t.unsupported += r.outcome == Outcome::Unsupported;
        if (r.rendered) {
            ++t.rendered;
            t.povray_seconds += r.povray_seconds;
            t.povwall_seconds += r.povwall_seconds;
            t.untimed_references += r.povray_cached && r.povray_seconds == 0;
        } else if (r.outcome == Outcome::Failed) {
            ++t.failed;
        }
    }
    std::printf("%s\n%s\n", counts_line(t).c_str(), times_line(t).c_str());

    report.summary = {
        std::to_string(s.width) + "x" + std::to_string(s.height) +
            ", no anti-aliasing, " +
            (s.threads ? std::to_string(s.threads) + " thread(s)" : "all cores") +
            " per renderer, at most " + format_seconds(s.timeout_seconds) +
            " s per render. Times are wall seconds of each renderer's process (start, "
            "parse, render, PNG); ratio = POV-Ray time / povwall time.",
        counts_line(t), times_line(t),
        "A scene matches when rmse <= " + number_text(s.thresholds.max_rmse, "%g") +
            " and at most " + number_text(s.thresholds.max_bad_fraction * 100, "%g") +
            " % of pixels are bad (a channel off by more than " +
            number_text(s.thresholds.fail, "%g") +
            "). Difference: each pixel's largest channel difference, black (none), blue, "
            "yellow, red (" +
            number_text(s.thresholds.fail, "%g") + " or more)."};
    const std::string index = (s.out_dir / "index.html").string();
    try {
        output::write_html_report(report, index);
    } catch (const output::HtmlWriteError& e) {
        std::fprintf(stderr, "povwall: error: %s\n", e.what());
        return exit_code(ExitCode::Error);
    }
    std::printf("report: %s\n", index.c_str());
    return 0;
}

}  // namespace povwall::cli
