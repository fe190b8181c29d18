// `povwall check-numerics`: first hits of the camera rays, fast path against the 50-digit
// oracle, per shape kind; non-finite pixels; and, with --povray, which of POV-Ray and
// povwall the oracle supports where their images differ.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "cli/process.h"
#include "cli/scratch_folder.h"
#include "output/image_io.h"
#include "parser/parser.h"
#include "trace/numerics_check.h"
#include "trace/object_queries.h"
#include "trace/pattern.h"
#include "trace/render.h"
#include "trace/ties.h"

namespace povwall::cli {
namespace {

namespace fs = std::filesystem;

}  // namespace

int run_check_numerics(int argc, char** argv) {
    CLI::App app{"Fast-path first hits against a 50-digit oracle",
                 "povwall check-numerics"};
    std::string scene_path;
    int width = 64, height = 48;
    bool with_povray = false, json = false;
    std::vector<std::string> library_paths;
    app.add_option("SCENE", scene_path, "scene file (.pov)")->required();
    app.add_option("-W,--width", width, "camera rays across")->capture_default_str();
    app.add_option("-H,--height", height, "camera rays down")->capture_default_str();
    app.add_option("-L,--library-path", library_paths, "include folder (repeatable)");
    app.add_flag("--povray", with_povray,
                 "render with POV-Ray too; classify the differing pixels by the oracle");
    app.add_flag("--json", json, "machine-readable report");
    if (auto done = parse_args(app, argc, argv)) return *done;
    if (width <= 0 || height <= 0) throw UsageError("image size must be positive");
    parser::ParseOptions popts;
    popts.library_paths = library_paths;
    popts.write_user_files = false;
    popts.function_hooks = trace::parse_time_function_hooks();
    popts.object_queries = trace::parse_time_object_queries();
    popts.image_reader = output::read_stored_image;  // height fields need the pixels
    popts.image_width = width;
    popts.image_height = height;
    Scene scene;
    try {
        scene = parser::parse_scene_file(scene_path, popts);
    } catch (const parser::ParseError& e) {
        std::cerr << e.what() << "\n";
        return exit_code(ExitCode::Error);
    }
    trace::NumericsReport rep = trace::check_numerics(scene, width, height);

    nlohmann::json j;
    j["rays"] = rep.rays;
    j["unsupported_rays"] = rep.unsupported;
    j["nonfinite_pixels"] = rep.nonfinite_pixels;
    for (const auto& [kind, k] : rep.kinds) {
        j["kinds"][kind] = {{"rays", k.rays},
                            {"hit_miss", k.hit_miss},
                            {"other_object", k.other_object},
                            {"compared", k.compared},
                            {"max_rel_error", k.max_rel_error},
                            {"median_rel_error", k.median_rel_error}};
    }
    if (with_povray) {
        const ScratchFolder scratch("povwall-numerics");
        const fs::path& dir = scratch.path();
        std::string pov_png = (dir / "povray.png").string();
        std::vector<std::string> cmd{"povray",
                                     "+I" + scene_path,
                                     "+O" + pov_png,
                                     "+W" + std::to_string(width),
                                     "+H" + std::to_string(height),
                                     "-D",
                                     "-A",
                                     "+WT1",
                                     "-GA"};
        for (const auto& l : library_paths) cmd.push_back("+L" + l);
        if (run_process(cmd) != 0) {
            std::cerr << "povwall: error: povray failed on " << scene_path << "\n";
            return exit_code(ExitCode::Error);
        }
        Image pov = output::read_image(pov_png);
        trace::RenderSettings rs;
        rs.width = width;
        rs.height = height;
        Image ours = trace::render_scene(scene, rs);
        OutputEncoding enc;
        enc.gamma_handling = scene.gamma_handling();
        enc.working_gamma = scene.settings.assumed_gamma.value_or(GammaCurve{});
        uint64_t differ = 0, ours_supported = 0, ours_contradicted = 0, unknown = 0;
        uint64_t ties = 0, pattern_ties = 0;
        trace::TieProbe tie_probe(scene, rs);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                bool d = false;
                for (int c = 0; c < 3; ++c) {
                    float a = output::encode_channel(ours.pixel(x, y)[c], enc);
                    d = d || std::fabs(a - pov.pixel(x, y)[c]) > 0.1f;
                }
                if (!d) continue;
                ++differ;
                const trace::TieProbe::Kind kind = tie_probe.pixel(x, y);
                ties += kind == trace::TieProbe::Kind::Surface;
                pattern_ties += kind == trace::TieProbe::Kind::Pattern;
                switch (rep.verdict[size_t(y) * width + x]) {
                    case trace::PixelVerdict::Agree:
                        ++ours_supported;
                        break;
                    case trace::PixelVerdict::Disagree:
                        ++ours_contradicted;
                        break;
                    case trace::PixelVerdict::Unsupported:
                        ++unknown;
                        break;
                }
            }
        }
        j["povray"] = {{"differing_pixels", differ},
                       {"tie_pixels", ties},
                       {"pattern_boundary_pixels", pattern_ties},
                       {"oracle_agrees_with_povwall_first_hit", ours_supported},
                       {"oracle_contradicts_povwall_first_hit", ours_contradicted},
                       {"oracle_unsupported", unknown}};
    }
    if (json) {
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("%s: %llu camera rays, %llu outside the oracle, %llu non-finite pixels\n",
                scene_path.c_str(), (unsigned long long)rep.rays,
                (unsigned long long)rep.unsupported,
                (unsigned long long)rep.nonfinite_pixels);
    std::printf("%-16s %8s %9s %9s %9s %12s %12s\n", "kind", "rays", "hit/miss",
                "other-obj", "compared", "max-rel-err", "median");
    for (const auto& [kind, k] : rep.kinds) {
        std::printf("%-16s %8llu %9llu %9llu %9llu %12.3g %12.3g\n", kind.c_str(),
                    (unsigned long long)k.rays, (unsigned long long)k.hit_miss,
                    (unsigned long long)k.other_object, (unsigned long long)k.compared,
                    k.max_rel_error, k.median_rel_error);
    }
    if (with_povray) {
        const auto& p = j["povray"];
        const auto differ = (unsigned long long)p["differing_pixels"];
        const auto ties = (unsigned long long)p["tie_pixels"];
        std::printf(
            "POV-Ray: %llu pixels differ (>0.1); oracle agrees with povwall's first hit "
            "on %llu, "
            "contradicts it on %llu, cannot tell on %llu\n",
            differ, (unsigned long long)p["oracle_agrees_with_povwall_first_hit"],
            (unsigned long long)p["oracle_contradicts_povwall_first_hit"],
            (unsigned long long)p["oracle_unsupported"]);
        const auto patterns = (unsigned long long)p["pattern_boundary_pixels"];
        if (patterns > 0) {
            std::printf(
                "bad pixels: %llu (%llu exact ties, %llu on a pattern boundary, "
                "%llu other)\n",
                differ, ties, patterns, differ - ties - patterns);
        } else {
            std::printf("bad pixels: %llu (%llu exact ties, %llu other)\n", differ, ties,
                        differ - ties);
        }
    }
    return 0;
}

}  // namespace povwall::cli
