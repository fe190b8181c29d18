// `povwall bench`: povwall against POV-Ray 3.7 on one scene, wall time of whole
// processes, alternating (POV-Ray, then povwall, RUNS times) so that a machine's slow
// minutes hit both, medians compared; then the two images diffed. This is how speed bars
// are measured (docs/performance.md): timed tests would only measure the machine.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/diff_report.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/povray_reference.h"
#include "cli/process.h"
#include "cli/scratch_folder.h"
#include "output/diff.h"
#include "output/image_io.h"

namespace povwall::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The middle value; for an even count the lower of the two middle ones (a time that was
// measured, not an average of two).
double measured_median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[(v.size() - 1) / 2];
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

int run_bench(int argc, char** argv) {
    CLI::App app{
        "Time povwall against POV-Ray 3.7 on a scene: whole processes, alternating, "
        "medians; then diff the images",
        "povwall bench"};
    RenderOptions o;
    o.width = 600;  // the size of the speed bars
    o.height = 600;
    int threads = 0, runs = 5;
    bool json = false;
    std::string boxes;
    app.add_option("SCENE", o.scene, "scene file")->required();
    app.add_option("-W", o.width, "image width")->capture_default_str();
    app.add_option("-H", o.height, "image height")->capture_default_str();
    app.add_option("-L", o.library_paths, "include folder (repeatable)");
    app.add_option("--threads", threads, "threads for both renderers (0: all cores)");
    app.add_option("--runs", runs, "renders by each, alternating")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    app.add_option("--boxes", boxes, "povwall's black boxes (see render --boxes)");
    app.add_flag("--json", json, "print one JSON object");
    output::DiffThresholds t;
    add_diff_threshold_options(app, t);
    std::vector<std::string> pov_switches;
    if (int code = parse_with_pov_switches(app, argc, argv, o, pov_switches); code >= 0)
        return code;
    o.render.threads = threads;
    const ScratchFolder scratch("povwall-bench");
    const fs::path& dir = scratch.path();
    const std::string stem = fs::path(o.scene).stem().string();
    const std::string pov_png = (dir / (stem + "-povray.png")).string();
    const std::string our_png = (dir / (stem + "-povwall.png")).string();
    const std::string pov_log = (dir / "povray.log").string();
    const std::string our_log = (dir / "povwall.log").string();
    const std::vector<std::string> pov_cmd = povray_command(o, pov_png, threads);
    std::vector<std::string> our_extra;
    if (!boxes.empty()) our_extra = {"--boxes", boxes};
    our_extra.insert(our_extra.end(), pov_switches.begin(), pov_switches.end());
    const std::vector<std::string> our_cmd =
        povwall_command(o, our_png, threads, our_extra);

    std::vector<double> pov_s, our_s;
    for (int i = 0; i < runs; ++i) {
        const PovrayRun pov = run_povray(o, pov_cmd, "", pov_log);
        switch (pov.status) {
            case PovrayRun::Status::Ok:
                break;
            case PovrayRun::Status::NotInstalled:
                std::cerr
                    << "povwall: povray is not installed or not on PATH: nothing to "
                       "measure against\n";
                return exit_code(ExitCode::NoPovRay);
            case PovrayRun::Status::SceneError:
                return exit_code(ExitCode::Error);
            case PovrayRun::Status::Failed:
                std::cerr << "povwall: error: povray failed (exit " << pov.exit_code
                          << ")\n"
                          << pov.log;
                return exit_code(ExitCode::Error);
        }
        pov_s.push_back(pov.seconds);
        const auto start = Clock::now();
        const int rc = run_process(our_cmd, our_log);
        our_s.push_back(std::chrono::duration<double>(Clock::now() - start).count());
        if (rc != 0) {
            std::cerr << slurp(our_log);
            return rc > 0 && rc < 128 ? rc : 1;
        }
        if (!json) {
            std::fprintf(stderr, "run %d/%d: povray %.3f s, povwall %.3f s\n", i + 1,
                         runs, pov_s.back(), our_s.back());
        }
    }
    output::DiffResult r;
    try {
        r = output::diff_images(output::read_image(our_png), output::read_image(pov_png),
                                t);
    } catch (const output::ImageIoError& e) {
        r.status = output::DiffResult::Status::Unreadable;
        r.error = e.what();
    }
    const double pov_median = measured_median(pov_s), our_median = measured_median(our_s);
    const double speed_up = pov_median / our_median;
    if (json) {
        nlohmann::json j = diff_json(r);
        j["scene"] = o.scene;
        j["threads"] = threads;
        j["runs"] = runs;
        j["povray_seconds"] = pov_s;
        j["povwall_seconds"] = our_s;
        j["povray_median_seconds"] = pov_median;
        j["povwall_median_seconds"] = our_median;
        j["speed_up"] = speed_up;
        std::printf("%s\n", j.dump().c_str());
    } else {
        const std::string cores = threads == 1  ? std::string("1 thread")
                                  : threads > 0 ? std::to_string(threads) + " threads"
                                                : std::string("all cores");
        std::printf("scene: %s (%dx%d, %s, %d runs each, alternating)\n", o.scene.c_str(),
                    o.width, o.height, cores.c_str(), runs);
        std::printf("povray:  %.3f s (median)\npovwall: %.3f s (median)\n", pov_median,
                    our_median);
        std::printf("speed-up: %.2fx\n", speed_up);
        print_diff(r);
    }
    return exit_code(r.status);
}

}  // namespace povwall::cli
