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
#include <optional>
#include <sstream>
#include <thread>

#include "cli/diff_report.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "cli/povray_reference.h"
#include "cli/scratch_folder.h"
#include "output/diff.h"
#include "output/image_io.h"
#include "parser/parser.h"
#include "trace/ties.h"

namespace povwall::cli {

// The bad pixels (row-major indices) of the scene `o` renders classified by the tie
// probe (trace/ties.h): a mask over the image holding each one's TieProbe::Kind. Throws
// parser::ParseError.
std::vector<uint8_t> tie_pixels(const RenderOptions& o, const std::vector<size_t>& bad,
                                int levels) {
    RenderOptions first = o;
    if (const std::vector<Frame> frames = animation_frames(o); !frames.empty())
        first.frame = RenderOptions::FrameValues{
            frames.front().number, frames.front().clock, frames.front().clock_delta};
    const Scene scene = parse_render_scene(first);
    trace::RenderSettings settings = o.render;
    settings.width = o.width;
    settings.height = o.height;
    trace::TieProbeOptions probe;
    probe.levels = levels;
    trace::TieProbe ties(scene, settings, probe);
    std::vector<uint8_t> mask(size_t(o.width) * size_t(o.height), 0);
    for (size_t i : bad)
        mask[i] = uint8_t(ties.pixel(int(i % size_t(o.width)), int(i / size_t(o.width))));
    return mask;
}

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

}  // namespace

void add_diff_threshold_options(CLI::App& app, output::DiffThresholds& t) {
    // Given twice, the last wins: a golden scene's `// golden-args:` line overrides the
    // suite's thresholds (stochastic scenes compared by block means).
    app.add_option("--max-rmse", t.max_rmse, "largest RMSE that passes")
        ->capture_default_str()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    app.add_option("--max-bad-fraction", t.max_bad_fraction,
                   "largest fraction of bad pixels that passes")
        ->capture_default_str()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    app.add_option("--fail", t.fail, "per-channel difference making a pixel bad")
        ->capture_default_str()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

int parse_with_pov_switches(CLI::App& app, int argc, char** argv, RenderOptions& o,
                            std::vector<std::string>& switches,
                            const std::function<void(RenderOptions&)>& before_switches) {
    std::vector<std::string> rest;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (looks_like_pov_switch(a))
            switches.push_back(a);
        else
            rest.push_back(a);
    }
    std::vector<char*> args{argv[0]};
    for (auto& r : rest) args.push_back(r.data());
    if (auto done = parse_args(app, int(args.size()), args.data())) return *done;
    if (before_switches) before_switches(o);
    for (const auto& s : switches) {
        if (!apply_pov_switch(s, o)) throw UsageError("unknown switch '" + s + "'");
    }
    return -1;
}

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
    app.add_flag("--warn-ok", warn_ok,
                 "exit 0 on a warning (the default now: a warning is within the "
                 "thresholds; kept for older scripts)");
    bool ours_only = false;
    app.add_flag(
        "--ours-only", ours_only,
        "render with povwall alone, as the comparison would, and compare nothing "
        "(the sanitizer suite: its golden scenes look for memory errors, the "
        "release suite compares)");
    int block = 1;
    app.add_option("--block-mean", block,
                   "compare the means of NxN pixel squares (stochastic features: crand, "
                   "jitter)")
        ->check(CLI::Range(1, 4096));
    bool exclude_ties = false;
    int tie_levels = 2;
    app.add_flag(
        "--exclude-ties", exclude_ties,
        "leave the bad pixels that are exact ties (a ray meeting two surfaces at "
        "the same depth) out of the pass/fail decision");
    app.add_option("--tie-levels", tie_levels,
                   "trace levels searched for ties at a bad pixel (1: the camera ray, 2: "
                   "also the rays its first hit spawns)")
        ->capture_default_str()
        ->check(CLI::Range(1, 256));
    output::DiffThresholds t;
    add_diff_threshold_options(app, t);
    bool no_ini = false;
    app.add_flag(
        "--no-ini", no_ini,
        "ignore the .ini file of the scene's name in its folder (by default its "
        "options apply, as `povray SCENE.ini` would, before the command line's)");
    // The scene's own .ini first, as a user renders it; the command line's size,
    // folders and switches then win.
    // POV-Ray's default INI ($POVINI, ./povray.ini, ...) comes before both: POV-Ray reads
    // it too, from the same working folder.
    auto with_scene_ini = [&](RenderOptions& r) {
        const RenderOptions given = r;
        apply_default_ini(r);
        const std::string ini = no_ini ? "" : scene_ini_file(r.scene);
        if (!ini.empty()) {
            apply_ini_file(ini, r);
            std::fprintf(stderr, "povwall: options from %s\n", ini.c_str());
        }
        r.scene = given.scene;  // whatever an Input_File_Name says
        if (app.count("-W")) r.width = given.width;
        if (app.count("-H")) r.height = given.height;
    };
    std::vector<std::string> pov_switches;
    if (int code =
            parse_with_pov_switches(app, argc, argv, o, pov_switches, with_scene_ini);
        code >= 0)
        return code;
    o.render.threads = threads;
    const ScratchFolder scratch("povwall-compare", keep);
    const fs::path& dir = scratch.path();
    std::string stem = fs::path(o.scene).stem().string();
    std::string pov_png = (dir / (stem + "-povray.png")).string();
    std::string our_png = (dir / (stem + "-povwall.png")).string();
    std::string log = (dir / (stem + "-povray.log")).string();

    // An animation is compared on its first frame (of the subset): both renderers
    // render that one frame with the animation's clock and frame values, and write it
    // under POV-Ray's numbered name.
    std::string pov_image = pov_png, our_image = our_png;
    if (const std::vector<Frame> frames = animation_frames(o); !frames.empty()) {
        o.animation.subset_start = o.animation.subset_end = frames.front().number;
        RenderOptions named = o;
        named.output = pov_png;
        pov_image = animation_frames(named).front().output;
        named.output = our_png;
        our_image = animation_frames(named).front().output;
    }
    if (ours_only) {
        o.output = our_png;
        o.format_given = false;
        o.bits = 8;
        o.quiet = true;
        return run_render(o);
    }
    const std::vector<std::string> cmd = povray_command(o, pov_png, threads);
    const PovrayRun pov = run_povray(o, cmd, cache, log);
    switch (pov.status) {
        case PovrayRun::Status::Ok:
            break;
        case PovrayRun::Status::NotInstalled:
            std::cerr << "povwall: povray is not installed or not on PATH: nothing to "
                         "compare with\n";
            return exit_code(ExitCode::NoPovRay);
        case PovrayRun::Status::SceneError:
            return exit_code(ExitCode::Error);
        case PovrayRun::Status::Failed: {
            // Its error line first; the whole log only when it names none.
            const std::string message = povray_error_lines(pov.log);
            std::cerr << "povwall: error: povray failed (exit " << pov.exit_code << ")"
                      << (message.empty() ? "\n" + pov.log : ": " + message + "\n");
            if (!keep.empty()) std::cerr << "povwall: povray's log: " << log << "\n";
            return exit_code(ExitCode::Error);
        }
    }
    const bool from_cache = pov.cached;
    const std::string cached = cache;
    o.output = our_png;
    o.format_given = false;  // both renders are 8-bit PNG, compared as stored
    o.bits = 8;
    o.quiet = true;
    auto t2 = Clock::now();
    int our_rc = run_render(o);
    auto t3 = Clock::now();
    if (our_rc != 0) return our_rc;
    double pov_s = pov.seconds;
    double our_s = std::chrono::duration<double>(t3 - t2).count();
    output::DiffResult r;
    // Bad pixels that are exact ties (only pixel by pixel, one frame: the probe traces
    // the first frame's scene).
    std::optional<long long> ties;
    long long pattern_ties = 0;
    try {
        Image ours = output::block_means(output::read_image(our_image), block),
              theirs = output::block_means(output::read_image(pov_image), block);
        r = output::diff_images(ours, theirs, t);
        const std::vector<size_t> bad = output::bad_pixel_indices(ours, theirs, t.fail);
        if (block == 1 && !bad.empty() &&
            r.status != output::DiffResult::Status::SizeMismatch) {
            try {
                const std::vector<uint8_t> mask = tie_pixels(o, bad, tie_levels);
                ties = 0;
                for (uint8_t m : mask) {
                    *ties += m == uint8_t(trace::TieProbe::Kind::Surface);
                    pattern_ties += m == uint8_t(trace::TieProbe::Kind::Pattern);
                }
                if (exclude_ties) r = output::diff_images(ours, theirs, t, &mask);
            } catch (const parser::ParseError& e) {
                std::cerr << "povwall: warning: no tie search: " << e.what() << "\n";
            }
        } else if (block == 1 && r.status != output::DiffResult::Status::SizeMismatch) {
            ties = 0;
        }
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
        j["tie_pixels"] = ties ? nlohmann::json(*ties) : nlohmann::json(nullptr);
        j["pattern_boundary_pixels"] =
            ties ? nlohmann::json(pattern_ties) : nlohmann::json(nullptr);
        j["ties_excluded"] = exclude_ties && ties;
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
            std::printf("povray: cached reference in %s\npovwall: %.3f s\n",
                        cached.c_str(), our_s);
        } else {
            std::printf("povray: %.3f s\npovwall: %.3f s (%.2fx faster)\n", pov_s, our_s,
                        our_s > 0 ? pov_s / our_s : 0.0);
        }
        char note[160] = "";
        if (ties && exclude_ties) {
            std::snprintf(note, sizeof note,
                          "left out of the decision: %lld exact ties, %lld on a pattern "
                          "boundary",
                          *ties, pattern_ties);
        } else if (ties && pattern_ties > 0) {
            std::snprintf(
                note, sizeof note,
                "bad pixels: %lld (%lld exact ties, %lld on a pattern boundary, "
                "%lld other)",
                r.bad_pixels, *ties, pattern_ties, r.bad_pixels - *ties - pattern_ties);
        } else if (ties) {
            std::snprintf(note, sizeof note,
                          "bad pixels: %lld (%lld exact ties, %lld other)", r.bad_pixels,
                          *ties, r.bad_pixels - *ties);
        }
        print_diff(r, note);
    }
    return exit_code(r.status);
}

}  // namespace povwall::cli
