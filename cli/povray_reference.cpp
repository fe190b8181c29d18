#include "cli/povray_reference.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "cli/process.h"
#include "cli/scratch_folder.h"
#include "core/self_exe.h"
#include "parser/parser.h"
#include "trace/object_queries.h"
#include "trace/pattern.h"

namespace povwall::cli {
namespace {

namespace fs = std::filesystem;

uint64_t fnv1a(uint64_t h, std::string_view bytes) {
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// Hash of every file the scene reads and of the POV-Ray command line: a cached reference
// render is reused only when none of them changed. Empty when the scene does not parse.
std::string cache_key(const RenderOptions& o, const std::vector<std::string>& cmd,
                      bool& random) {
    // Files the scene writes go to a folder of their own, removed after: a scene that
    // reads back what it wrote (fileio.pov) parses as it does in a render.
    std::error_code dir_error;
    const fs::path written = fs::temp_directory_path(dir_error) /
                             ("povwall-cache-key-" + std::to_string(::getpid()) + "-" +
                              std::to_string(reinterpret_cast<uintptr_t>(&o)));
    fs::create_directories(written, dir_error);
    struct RemoveAfter {
        fs::path dir;
        ~RemoveAfter() {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        }
    } remove_after{written};
    // The values of the frame rendered: an animation's first (of the subset), as
    // run_render has them; a scene may read a different set of files in another frame.
    RenderOptions first = o;
    if (const std::vector<Frame> frames = animation_frames(o); !frames.empty())
        first.frame = RenderOptions::FrameValues{
            frames.front().number, frames.front().clock, frames.front().clock_delta};
    parser::ParseOptions popts = render_parse_options(first, written.string());
    popts.messages = nullptr;
    Scene scene;
    try {
        scene = parser::parse_scene_file(o.scene, popts);
    } catch (const parser::ParseError& e) {
        std::cerr << e.what() << "\n";
        return {};
    }
    random = std::any_of(scene.lights.begin(), scene.lights.end(),
                         [](const Light& l) { return l.area && l.area->jitter; }) ||
             scene.settings.photons.has_value() || scene.settings.radiosity.has_value() ||
             std::any_of(scene.rainbows.begin(), scene.rainbows.end(),
                         [](const Rainbow& r) { return r.jitter > 0; });
    uint64_t h = 1469598103934665603ull;
    for (const std::string& f : scene.files) {
        std::ifstream in(f, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        h = fnv1a(h, ss.str());
    }
    for (size_t i = 0; i < cmd.size(); ++i) {
        if (i == 1 || i == 2) continue;  // input and output paths
        h = fnv1a(h, cmd[i]);
    }
    // The povray binary found on PATH (a new POV-Ray build invalidates the cache).
    const char* path_env = std::getenv("PATH");
    std::stringstream dirs(path_env ? path_env : "");
    for (std::string d; std::getline(dirs, d, ':');) {
        std::error_code ec;
        fs::path exe = fs::path(d.empty() ? "." : d) / "povray";
        auto stamp = fs::last_write_time(exe, ec);
        if (ec) continue;
        h = fnv1a(h, fs::canonical(exe, ec).string());
        h = fnv1a(h, std::to_string(stamp.time_since_epoch().count()));
        h = fnv1a(h, std::to_string(fs::file_size(exe, ec)));
        break;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
    return buf;
}

// The shortest text that reads back as `v` exactly.
std::string shortest(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

// A path as a POV-Ray switch's value: POV-Ray splits an option at a space unless the
// value is in double quotes (`+I"my scene.pov"`).
std::string path_switch(const std::string& prefix, const std::string& path) {
    if (path.find_first_of(" \t") == std::string::npos) return prefix + path;
    return prefix + "\"" + path + "\"";
}
std::string path_of_switch(const std::string& value) {
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        return value.substr(1, value.size() - 2);
    return value;
}

// POV-Ray 3.7 turns paths into ASCII (UCS2toASCIIString): an image name with other
// bytes is written under another name.
bool plain_ascii(const std::string& path) {
    for (unsigned char c : path)
        if (c >= 0x80) return false;
    return true;
}

}  // namespace

std::vector<std::string> povwall_command(const RenderOptions& o,
                                         const std::string& out_png, int threads,
                                         const std::vector<std::string>& extra) {
    const std::string exe = self_exe();
    if (exe.empty()) throw UsageError("cannot find the povwall binary");
    std::vector<std::string> cmd{exe,
                                 "render",
                                 o.scene,
                                 "-o",
                                 out_png,
                                 "-W",
                                 std::to_string(o.width),
                                 "-H",
                                 std::to_string(o.height),
                                 "-q"};
    if (threads > 0) cmd.insert(cmd.end(), {"--threads", std::to_string(threads)});
    for (const auto& l : o.library_paths) cmd.insert(cmd.end(), {"-L", l});
    cmd.insert(cmd.end(), extra.begin(), extra.end());
    return cmd;
}

std::vector<std::string> povray_command(const RenderOptions& o,
                                        const std::string& out_png, int threads,
                                        const std::vector<std::string>& extra) {
    // Input and output stay at [1] and [2]: the cache key leaves them out.
    std::vector<std::string> cmd{"povray",
                                 path_switch("+I", o.scene),
                                 path_switch("+O", out_png),
                                 "+W" + std::to_string(o.width),
                                 "+H" + std::to_string(o.height),
                                 "-D",
                                 "+FN"};
    unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    cmd.push_back("+WT" + std::to_string(threads > 0 ? unsigned(threads) : cores));
    if (o.render.antialias) {
        std::ostringstream a;
        a << o.render.aa_threshold;
        // POV-Ray refuses "+A0" and "+A1": the threshold must be written as a decimal.
        std::string threshold = a.str();
        if (threshold.find_first_of(".e") == std::string::npos) threshold += ".0";
        cmd.push_back("+A" + threshold);
        cmd.push_back("+AM" + std::to_string(o.render.aa_method));
        cmd.push_back("+R" + std::to_string(o.render.aa_depth));
        cmd.push_back(o.render.aa_jitter ? "+J" + shortest(o.render.aa_jitter_amount)
                                         : std::string("-J"));
        cmd.push_back("+AG" + shortest(o.render.aa_gamma));
        cmd.push_back("+BS" + std::to_string(o.render.block_size));
    } else {
        cmd.push_back("-A");
    }
    if (o.render.alpha) cmd.push_back("+UA");
    if (o.file_gamma) cmd.push_back("File_Gamma=" + shortest(*o.file_gamma));
    if (o.render.quality != 9) cmd.push_back("+Q" + std::to_string(o.render.quality));
    // Every other setting that changes the image, as povwall has it from its switches
    // and .ini files.
    if (o.language_version) cmd.push_back("+MV" + shortest(*o.language_version / 100.0));
    auto partial = [&](const char* sw, const RenderOptions::Partial& p) {
        if (p.value < 0) return;
        std::string v = shortest(p.value);
        if (p.fraction && v.find('.') == std::string::npos) v += ".0";
        cmd.push_back(std::string("+") + sw + v);
    };
    partial("SR", o.start_row);
    partial("ER", o.end_row);
    partial("SC", o.start_col);
    partial("EC", o.end_col);
    const RenderOptions::Animation& a = o.animation;
    if (a.final_frame > a.initial_frame) {
        cmd.push_back("+KFI" + std::to_string(a.initial_frame));
        cmd.push_back("+KFF" + std::to_string(a.final_frame));
        cmd.push_back("+KI" + shortest(a.initial_clock));
        cmd.push_back("+KF" + shortest(a.final_clock));
        if (a.cyclic) cmd.push_back("+KC");
        if (a.subset_start) cmd.push_back("+SF" + shortest(*a.subset_start));
        if (a.subset_end) cmd.push_back("+EF" + shortest(*a.subset_end));
    } else if (a.clock != 0) {
        cmd.push_back("+K" + shortest(a.clock));
    }
    for (const auto& sw : extra) cmd.push_back(sw);
    std::string scene_dir = fs::path(o.scene).parent_path().string();
    cmd.push_back(path_switch("+L", scene_dir.empty() ? std::string(".") : scene_dir));
    for (const auto& l : o.library_paths) cmd.push_back(path_switch("+L", l));
    cmd.push_back("+L/usr/share/povray-3.7/include");
    for (const auto& [k, v] : o.declares)
        cmd.push_back("Declare=" + k + "=" + shortest(v));
    return cmd;
}

std::string scene_ini_file(const std::string& scene) {
    fs::path ini(scene);
    ini.replace_extension(".ini");
    std::error_code ec;
    return fs::is_regular_file(ini, ec) ? ini.string() : std::string();
}

PovrayRun run_povray(const RenderOptions& o, const std::vector<std::string>& cmd,
                     const std::string& cache_dir, const std::string& log_path,
                     double timeout_seconds, const std::string& working_dir) {
    PovrayRun run;
    const std::string requested = path_of_switch(cmd.at(2).substr(2));
    // An animation's one frame is written under its frame-numbered name.
    auto written_name = [&](const std::string& output) {
        RenderOptions named = o;
        named.output = output;
        const std::vector<Frame> frames = animation_frames(named);
        return frames.empty() ? output : frames.front().output;
    };
    std::string out_png = written_name(requested);
    // A name POV-Ray cannot write as given (not ASCII): it renders into a scratch folder
    // and the image is moved to its name.
    std::optional<ScratchFolder> ascii_folder;
    std::vector<std::string> command = cmd;
    std::string pov_png = out_png;
    if (!plain_ascii(requested)) {
        ascii_folder.emplace("povwall-povray-out");
        const std::string ascii =
            (ascii_folder->path() / ("image" + fs::path(requested).extension().string()))
                .string();
        command[2] = path_switch("+O", ascii);
        pov_png = written_name(ascii);
    }
    std::string cached;
    if (!cache_dir.empty()) {
        const std::string key = cache_key(o, cmd, run.random);
        if (key.empty()) {
            run.status = PovrayRun::Status::SceneError;
            return run;
        }
        fs::create_directories(cache_dir);
        cached = (fs::path(cache_dir) /
                  (fs::path(o.scene).stem().string() + "-" + key + ".png"))
                     .string();
    }
    // The render time is kept next to the cached image, so reports made from the cache
    // still show how long POV-Ray took.
    const std::string seconds_file = cached + ".seconds";
    if (!cached.empty() && fs::exists(cached)) {
        fs::copy_file(cached, out_png, fs::copy_options::overwrite_existing);
        run.cached = true;
        std::ifstream(seconds_file) >> run.seconds;
        return run;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = run_process(command, log_path, timeout_seconds, working_dir);
    if (pov_png != out_png && fs::exists(pov_png)) {
        std::error_code ignored;
        fs::rename(pov_png, out_png, ignored);
        if (ignored)
            fs::copy_file(pov_png, out_png, fs::copy_options::overwrite_existing);
    }
    run.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (rc == -1) {
        run.status = PovrayRun::Status::NotInstalled;
        return run;
    }
    if (rc != 0 || !fs::exists(out_png)) {
        std::error_code ignored;  // a killed or failed POV-Ray may leave a partial image
        fs::remove(out_png, ignored);
        run.timed_out = rc == kProcessTimedOut;
        std::ifstream in(log_path);
        std::stringstream ss;
        ss << in.rdbuf();
        run.status = PovrayRun::Status::Failed;
        run.exit_code = rc;
        run.log = ss.str();
        return run;
    }
    if (!cached.empty()) {
        // A temporary name of this process's, then rename: a cache entry is always whole,
        // also when several processes (the sanitizer and release suites) share the cache.
        std::string tmp = cached + "." + std::to_string(::getpid()) + ".tmp";
        std::ofstream(tmp) << run.seconds << "\n";
        fs::rename(tmp, seconds_file);
        fs::copy_file(out_png, tmp, fs::copy_options::overwrite_existing);
        fs::rename(tmp, cached);
    }
    return run;
}

std::string povray_error_lines(const std::string& log) {
    // POV-Ray wraps a message over lines that start with a space; the message ends
    // where its "Fatal error ..." or "Render failed" summary begins.
    std::istringstream in(log);
    std::string line, message;
    bool in_message = false;
    while (std::getline(in, line)) {
        const bool summary =
            line.rfind("Fatal error", 0) == 0 || line.rfind("Render failed", 0) == 0;
        if (in_message) {
            if (summary || line.empty() || line[0] != ' ') break;
            message += line;
        } else if (!summary && (line.find("Error") != std::string::npos ||
                                line.find("error:") != std::string::npos)) {
            message = line;
            in_message = true;
        }
    }
    return message;
}

}  // namespace povwall::cli
