#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/options.h"
#include "output/image_io.h"
#include "parser/parser.h"

namespace povwall::cli {

using Clock = std::chrono::steady_clock;

OutputEncoding encoding_for(const Scene& scene, const RenderOptions& o) {
    OutputEncoding enc;
    enc.gamma_handling = scene.gamma_handling();
    enc.working_gamma = scene.settings.assumed_gamma.value_or(1.0f);
    enc.bits = o.bits > 8 ? 16 : 8;
    enc.alpha = o.render.alpha;
    return enc;
}

int run_render(RenderOptions o) {
    if (o.scene.empty()) throw UsageError("no scene file given (+ISCENE.pov or render SCENE.pov)");
    if (o.width <= 0 || o.height <= 0) throw UsageError("image size must be positive");
    if (o.output.empty()) o.output = default_output_name(o);
    parser::ParseOptions popts;
    popts.library_paths = o.library_paths;
    popts.image_width = o.width;
    popts.image_height = o.height;
    popts.declares = o.declares;
    popts.messages = o.quiet ? nullptr : &std::cerr;
    auto t0 = Clock::now();
    Scene scene;
    try {
        scene = parser::parse_scene_file(o.scene, popts);
    } catch (const parser::ParseError& e) {
        std::cerr << e.what() << "\n";
        return 2;
    }
    auto t1 = Clock::now();
    o.render.width = o.width;
    o.render.height = o.height;
    trace::RenderStats stats;
    Image image = trace::render_scene(scene, o.render, &stats);
    auto t2 = Clock::now();
    try {
        output::write_image(image, o.output, encoding_for(scene, o));
    } catch (const output::ImageIoError& e) {
        std::cerr << "povwall: error: " << e.what() << "\n";
        return 2;
    }
    double parse_s = std::chrono::duration<double>(t1 - t0).count();
    double total_s = std::chrono::duration<double>(t2 - t0).count();
    if (!o.quiet) {
        std::fprintf(stderr,
                     "povwall: %s %dx%d: parse %.3f s, prepare %.3f s, trace %.3f s, total %.3f s"
                     "\n",
                     o.output.c_str(), o.width, o.height, parse_s, stats.prepare_seconds,
                     stats.trace_seconds, total_s);
    }
    if (!o.stats_file.empty()) {
        nlohmann::json j;
        j["scene"] = o.scene;
        j["width"] = o.width;
        j["height"] = o.height;
        j["seconds"] = {{"parse", parse_s},
                        {"prepare", stats.prepare_seconds},
                        {"trace", stats.trace_seconds},
                        {"total", total_s}};
        j["rays"] = {{"camera", stats.camera_rays},
                     {"reflected", stats.reflected_rays},
                     {"refracted", stats.refracted_rays},
                     {"shadow", stats.shadow_rays}};
        j["intersection_tests"] = stats.intersection_tests;
        j["boxes"] = 1;
        std::string tmp = o.stats_file + ".tmp";
        {
            std::ofstream out(tmp);
            out << j.dump(2) << "\n";
        }
        std::filesystem::rename(tmp, o.stats_file);
    }
    return 0;
}

}  // namespace povwall::cli
