// `povwall compare`: the same scene through POV-Ray and povwall, both timed, then diffed.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli/options.h"
#include "cli/process.h"
#include "output/diff.h"
#include "output/image_io.h"
#include "parser/parser.h"


namespace povwall::cli {

nlohmann::json diff_json(const output::DiffResult& r);
void print_diff(const output::DiffResult& r);

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

uint64_t fnv1a(uint64_t h, std::string_view bytes) {
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// Hash of every file the scene reads and of the POV-Ray command line: a cached reference
// render is reused only when none of them changed.
std::string cache_key(const RenderOptions& o, const std::vector<std::string>& cmd) {
    parser::ParseOptions popts;
    popts.library_paths = o.library_paths;
    popts.image_width = o.width;
    popts.image_height = o.height;
    popts.declares = o.declares;
    Scene scene;
    try {
        scene = parser::parse_scene_file(o.scene, popts);
    } catch (const parser::ParseError& e) {
        std::cerr << e.what() << "\n";
        return {};
    }
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

}  // namespace

int run_compare(int argc, char** argv) {
    CLI::App app{
        "Render a scene with POV-Ray and with povwall, time both, diff the images",
        "povwall compare"};
    RenderOptions o;
    bool json = false;
    std::string keep;
    int threads = 0;
    app.add_option("SCENE", o.scene, "scene file")->required();
    app.add_option("-W", o.width, "image width")->capture_default_str();
    app.add_option("-H", o.height, "image height")->capture_default_str();
    app.add_option("-L", o.library_paths, "include folder (repeatable)");
    app.add_option("--threads", threads, "threads for both renderers (0: all cores)");
    app.add_flag("--json", json, "print one JSON object");
    app.add_option("--boxes", o.boxes, "povwall's black boxes (see render --boxes)")
        ->capture_default_str();
    app.add_option(
        "--keep", keep,
        "folder to keep both images (SCENE-povray.png, SCENE-povwall.png) and their "
        "difference (SCENE-diff.png) in");
    std::string cache;
    bool warn_ok = false;
    app.add_option(
        "--cache", cache,
        "reuse POV-Ray renders from this folder, keyed by a hash of the scene, its "
        "includes and the render settings");
    app.add_flag("--warn-ok", warn_ok, "exit 0 on a warning (tests)");
    output::DiffThresholds t;
    app.add_option("--max-rmse", t.max_rmse, "largest RMSE that passes")
        ->capture_default_str();
    app.add_option("--max-bad-fraction", t.max_bad_fraction,
                   "largest fraction of bad pixels that passes")
        ->capture_default_str();
    app.add_option("--fail", t.fail, "per-channel difference making a pixel bad")
        ->capture_default_str();
    std::vector<std::string> pov_switches, rest;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (looks_like_pov_switch(a))
            pov_switches.push_back(a);
        else
            rest.push_back(a);
    }
    std::vector<char*> args{argv[0]};
    for (auto& r : rest) args.push_back(r.data());
    try {
        app.parse(int(args.size()), args.data());
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    for (const auto& s : pov_switches) {
        if (!apply_pov_switch(s, o)) throw UsageError("unknown switch '" + s + "'");
    }
    o.render.threads = threads;
    fs::path dir = keep.empty() ? fs::temp_directory_path() /
                                      ("povwall-compare-" + std::to_string(getpid()))
                                : fs::path(keep);
    fs::create_directories(dir);
    std::string stem = fs::path(o.scene).stem().string();
    std::string pov_png = (dir / (stem + "-povray.png")).string();
    std::string our_png = (dir / (stem + "-povwall.png")).string();
    std::string log = (dir / (stem + "-povray.log")).string();

    std::vector<std::string> cmd{"povray",
                                 "+I" + o.scene,
                                 "+O" + pov_png,
                                 "+W" + std::to_string(o.width),
                                 "+H" + std::to_string(o.height),
                                 "-D",
                                 "+FN"};
    unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    cmd.push_back("+WT" + std::to_string(threads > 0 ? unsigned(threads) : cores));
    if (o.render.antialias) {
        std::ostringstream a;
        a << "+A" << o.render.aa_threshold;
        cmd.push_back(a.str());
        cmd.push_back("+AM" + std::to_string(o.render.aa_method));
        cmd.push_back("+R" + std::to_string(o.render.aa_depth));
        cmd.push_back(o.render.aa_jitter ? "+J" : "-J");
    } else {
        cmd.push_back("-A");
    }
    if (o.render.alpha) cmd.push_back("+UA");
    // Partial renders: POV-Ray writes the full-size image with the rest black, as
    // povwall.
    for (const auto& sw : pov_switches) {
        std::string head = sw.substr(1, 2);
        for (char& c : head) c = char(std::toupper((unsigned char)c));
        if (head == "SR" || head == "ER" || head == "SC" || head == "EC")
            cmd.push_back(sw);
    }
    std::string scene_dir = fs::path(o.scene).parent_path().string();
    cmd.push_back("+L" + (scene_dir.empty() ? std::string(".") : scene_dir));
    for (const auto& l : o.library_paths) cmd.push_back("+L" + l);
    cmd.push_back("+L/usr/share/povray-3.7/include");
    for (const auto& [k, v] : o.declares) {
        std::ostringstream d;
        d << "Declare=" << k << "=" << v;
        cmd.push_back(d.str());
    }

    std::string cached;
    if (!cache.empty()) {
        std::string key = cache_key(o, cmd);
        if (key.empty())
            return 2;  // the scene does not parse: run_render reports it below
        fs::create_directories(cache);
        cached = (fs::path(cache) / (stem + "-" + key + ".png")).string();
    }
    auto t0 = Clock::now();
    int rc = 0;
    const bool from_cache = !cached.empty() && fs::exists(cached);
    if (from_cache) {
        fs::copy_file(cached, pov_png, fs::copy_options::overwrite_existing);
    } else {
        rc = run_process(cmd, log);
        if (rc == 0 && !cached.empty() && fs::exists(pov_png)) {
            std::string tmp = cached + ".tmp";
            fs::copy_file(pov_png, tmp, fs::copy_options::overwrite_existing);
            fs::rename(tmp, cached);
        }
    }
    auto t1 = Clock::now();
    if (rc == -1) {
        std::cerr
            << "povwall: povray is not installed or not on PATH: nothing to compare "
               "with\n";
        return 77;  // CTest's skip code
    }
    if (rc != 0 || !fs::exists(pov_png)) {
        std::ifstream in(log);
        std::stringstream ss;
        ss << in.rdbuf();
        std::cerr << "povwall: error: povray failed (exit " << rc << ")"
                  << (rc == -1 ? ": is povray installed and on PATH?" : "") << "\n"
                  << ss.str();
        return 2;
    }
    o.output = our_png;
    o.format_given = false;  // both renders are 8-bit PNG, compared as stored
    o.bits = 8;
    o.quiet = true;
    auto t2 = Clock::now();
    int our_rc = run_render(o);
    auto t3 = Clock::now();
    if (our_rc != 0) return our_rc;
    double pov_s = std::chrono::duration<double>(t1 - t0).count();
    double our_s = std::chrono::duration<double>(t3 - t2).count();
    output::DiffResult r;
    try {
        Image ours = output::read_image(our_png), theirs = output::read_image(pov_png);
        r = output::diff_images(ours, theirs, t);
        if (!keep.empty() && r.status != output::DiffResult::Status::SizeMismatch) {
            OutputEncoding raw;  // |povwall - povray| as values, for looking at
            raw.gamma_handling = false;
            output::write_image(output::difference_image(ours, theirs),
                                (dir / (stem + "-diff.png")).string(), raw);
        }
    } catch (const output::ImageIoError& e) {
        r.status = output::DiffResult::Status::Unreadable;
        r.error = e.what();
    }
    if (json) {
        nlohmann::json j = diff_json(r);
        j["povwall_seconds"] = our_s;
        // A cached reference has no render time of its own.
        j["povray_seconds"] =
            from_cache ? nlohmann::json(nullptr) : nlohmann::json(pov_s);
        j["povray_cached"] = from_cache;
        j["scene"] = o.scene;
        std::printf("%s\n", j.dump().c_str());
    } else {
        std::printf("scene: %s (%dx%d)\n", o.scene.c_str(), o.width, o.height);
        if (from_cache) {
            std::printf("povray: cached reference %s\npovwall: %.3f s\n", cached.c_str(),
                        our_s);
        } else {
            std::printf("povray: %.3f s\npovwall: %.3f s (%.2fx faster)\n", pov_s, our_s,
                        our_s > 0 ? pov_s / our_s : 0.0);
        }
        print_diff(r);
    }
    if (keep.empty()) fs::remove_all(dir);
    if (warn_ok && r.status == output::DiffResult::Status::Warn) return 0;
    return int(r.status);
}

}  // namespace povwall::cli
