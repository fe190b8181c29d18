// `povwall sweep`: error against run time. The scene is rendered at a ladder of settings
// that trade accuracy for time and each image is measured against one accurate POV-Ray
// reference (anti-aliased, made once and cached); POV-Ray's own renders at its usual
// settings are measured the same way, so its points sit on the same plot.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
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
#include "cli/scratch_folder.h"
#include "output/diff.h"
#include "output/error_time_plot.h"
#include "output/image_io.h"

namespace povwall::cli {
namespace {

namespace fs = std::filesystem;

struct Rung {
    Rung(std::string l, std::vector<std::string> a, bool pov = false)
        : label(std::move(l)), args(std::move(a)), povray(pov) {}
    std::string label;
    std::vector<std::string> args;  // povwall render arguments, or POV-Ray switches
    bool povray = false;
    std::vector<double> seconds;
    output::DiffResult diff;
    bool failed = false;
};

// The reference and the anti-aliased rungs share these switches: POV-Ray's adaptive
// supersampling (method 1), jitter off so every run gives the same image.
std::vector<std::string> aa_switches(const std::string& threshold, int depth) {
    return {"+A" + threshold, "+AM1", "+R" + std::to_string(depth), "-J"};
}

std::vector<Rung> ladder() {
    std::vector<Rung> r;
    r.push_back({"max_trace_level 1", {"-A", "--max-trace-level", "1"}});
    r.push_back({"max_trace_level 2", {"-A", "--max-trace-level", "2"}});
    r.push_back({"adc_bailout 0.1", {"-A", "--adc-bailout", "0.1"}});
    r.push_back({"no AA", {"-A", "--mode", "single"}});
    r.push_back({"no AA, 8 boxes", {"-A", "--boxes", "2x2x2"}});
    r.push_back({"no AA, screen tiles", {"-A", "--mode", "screen"}});
    r.push_back({"AA 0.5 depth 2", aa_switches("0.5", 2)});
    r.push_back({"AA 0.3 depth 3", aa_switches("0.3", 3)});
    r.push_back({"AA 0.1 depth 3", aa_switches("0.1", 3)});
    r.push_back({"AA 0.0 depth 3", aa_switches("0.0", 3)});
    r.push_back({"POV-Ray no AA", {"-A"}, true});
    r.push_back({"POV-Ray AA 0.3", aa_switches("0.3", 3), true});
    return r;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Applies POV-Ray switches of a rung to options used for the POV-Ray command line.
RenderOptions with_switches(RenderOptions o, const std::vector<std::string>& switches) {
    for (const auto& s : switches) apply_pov_switch(s, o);
    return o;
}

}  // namespace

int run_sweep(int argc, char** argv) {
    CLI::App app{
        "Error against run time: render a scene at a ladder of settings and measure "
        "each against an accurate POV-Ray reference",
        "povwall sweep"};
    RenderOptions o;
    int repeat = 3, threads = 0;
    std::string csv, plot, cache, keep;
    app.add_option("SCENE", o.scene, "scene file")->required();
    app.add_option("-W", o.width, "image width")->capture_default_str();
    app.add_option("-H", o.height, "image height")->capture_default_str();
    app.add_option("-L", o.library_paths, "include folder (repeatable)");
    app.add_option("--repeat", repeat, "timed runs per setting (median)")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    app.add_option("--threads", threads, "threads for both renderers (0: all cores)");
    app.add_option("--csv", csv, "write the table as CSV");
    app.add_option("--plot", plot, "write error against time as SVG");
    app.add_option("--cache", cache,
                   "folder for the POV-Ray reference (default: a scratch folder)");
    app.add_option("--keep", keep, "folder to keep every image in");
    if (auto done = parse_args(app, argc, argv)) return *done;
    if (!fs::exists(o.scene)) throw UsageError("cannot open scene '" + o.scene + "'");
    const ScratchFolder scratch("povwall-sweep", keep);
    const fs::path& dir = scratch.path();

    // The reference: POV-Ray, every pixel supersampled 3x3 (threshold 0).
    RenderOptions ref_opts = with_switches(o, aa_switches("0.0", 3));
    const std::string ref_png = (dir / "reference-povray.png").string();
    const PovrayRun ref_run =
        run_povray(ref_opts, povray_command(ref_opts, ref_png, threads), cache,
                   (dir / "reference-povray.log").string());
    if (ref_run.status == PovrayRun::Status::NotInstalled) {
        std::cerr << "povwall: povray is not installed or not on PATH: no reference\n";
        return exit_code(ExitCode::NoPovRay);
    }
    if (ref_run.status != PovrayRun::Status::Ok) {
        if (ref_run.status == PovrayRun::Status::Failed)
            std::cerr << "povwall: error: povray failed on the reference (exit "
                      << ref_run.exit_code << ")\n"
                      << ref_run.log;
        return exit_code(ExitCode::Error);
    }
    const Image reference = output::read_image(ref_png);

    std::vector<Rung> rungs = ladder();
    // Alternating runs (every setting once per round), as the machine's load drifts.
    for (int round = 0; round < repeat; ++round) {
        for (size_t i = 0; i < rungs.size(); ++i) {
            Rung& r = rungs[i];
            if (r.failed) continue;
            const std::string png =
                (dir / ("setting-" + std::to_string(i + 1) + ".png")).string();
            const std::string log =
                (dir / ("setting-" + std::to_string(i + 1) + ".log")).string();
            std::vector<std::string> cmd;
            if (r.povray) {
                cmd = povray_command(with_switches(o, r.args), png, threads);
            } else {
                cmd = povwall_command(o, png, threads, r.args);
            }
            const auto t0 = std::chrono::steady_clock::now();
            const int rc = run_process(cmd, log);
            const double s =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                    .count();
            if (rc != 0 || !fs::exists(png)) {
                std::ifstream in(log);
                std::string first;
                std::getline(in, first);
                std::cerr << "povwall: sweep: \"" << r.label << "\" failed (exit " << rc
                          << "): " << first << "\n";
                r.failed = true;
                continue;
            }
            r.seconds.push_back(s);
            if (round == 0)
                r.diff = output::diff_images(output::read_image(png), reference);
        }
    }

    // Table, CSV, plot.
    std::vector<output::PlotPoint> points;
    std::vector<size_t> point_rung;
    for (size_t i = 0; i < rungs.size(); ++i) {
        if (rungs[i].failed) continue;
        points.push_back({rungs[i].label, median(rungs[i].seconds), rungs[i].diff.rmse,
                          rungs[i].povray});
        point_rung.push_back(i);
    }
    std::vector<bool> on_front(rungs.size(), false);
    for (size_t p : output::pareto_front(points)) on_front[point_rung[p]] = true;
    std::printf(
        "sweep of %s at %dx%d against POV-Ray +A0.0 +AM1 +R3 -J%s; seconds are the "
        "median of %d run%s\n",
        o.scene.c_str(), o.width, o.height, ref_run.cached ? " (cached)" : "", repeat,
        repeat == 1 ? "" : "s");
    std::printf("%-3s %-22s %-8s %9s %9s %8s %9s %8s %s\n", "#", "setting", "renderer",
                "seconds", "rmse", "psnr", "bad", "max", "pareto");
    std::ostringstream c;
    c << "setting,renderer,arguments,runs,median_seconds,rmse,psnr,bad_pixel_fraction,"
         "max_abs,pareto\n";
    for (size_t i = 0; i < rungs.size(); ++i) {
        const Rung& r = rungs[i];
        std::string args;
        for (const auto& a : r.args) args += (args.empty() ? "" : " ") + a;
        const char* who = r.povray ? "povray" : "povwall";
        if (r.failed) {
            std::printf("%-3zu %-22s %-8s %9s\n", i + 1, r.label.c_str(), who, "failed");
            c << '"' << r.label << "\"," << who << ",\"" << args << "\",0,,,,,,\n";
            continue;
        }
        const double s = median(r.seconds);
        std::printf("%-3zu %-22s %-8s %9.3f %9.6f %8.2f %9.6f %8.4f %s\n", i + 1,
                    r.label.c_str(), who, s, r.diff.rmse, r.diff.psnr,
                    r.diff.bad_pixel_fraction, r.diff.max_abs, on_front[i] ? "*" : "");
        char line[512];
        std::snprintf(
            line, sizeof line, "\"%s\",%s,\"%s\",%zu,%.6f,%.8f,%.4f,%.8f,%.6f,%d\n",
            r.label.c_str(), who, args.c_str(), r.seconds.size(), s, r.diff.rmse,
            r.diff.psnr, r.diff.bad_pixel_fraction, r.diff.max_abs, on_front[i] ? 1 : 0);
        c << line;
    }
    auto write_file = [](const std::string& path, const std::string& text) {
        const std::string tmp = path + ".tmp";
        {
            std::ofstream out(tmp);
            out << text;
            if (!out) throw std::runtime_error("cannot write '" + path + "'");
        }
        fs::rename(tmp, path);
    };
    if (!csv.empty()) write_file(csv, c.str());
    if (!plot.empty()) {
        write_file(
            plot, output::error_time_svg(points, fs::path(o.scene).filename().string() +
                                                     " " + std::to_string(o.width) + "x" +
                                                     std::to_string(o.height) +
                                                     ": error against time"));
    }
    const bool any_failed =
        std::any_of(rungs.begin(), rungs.end(), [](const Rung& r) { return r.failed; });
    return exit_code(any_failed ? ExitCode::Differs : ExitCode::Ok);
}

}  // namespace povwall::cli
