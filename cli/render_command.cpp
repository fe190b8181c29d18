#include <chrono>
#include <cmath>
#include <thread>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/options.h"
#include "distrib/space_render.h"
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

// "4x4x4": equal slabs; "8": walls balanced on object positions, 8x8x8 (no: N per axis);
// "auto": balanced, about 4 boxes per core. Returns false for one box (no subdivision).
bool parse_boxes(const std::string& spec, distrib::SpaceOptions& space) {
    if (spec == "auto") {
        int n = int(std::max(1u, std::thread::hardware_concurrency()));
        int per_axis = n >= 4 ? 3 : 2;
        space.boxes = {per_axis, per_axis, per_axis};
        space.balanced = true;
        return true;
    }
    int a = 0, b = 0, c = 0;
    if (std::sscanf(spec.c_str(), "%dx%dx%d", &a, &b, &c) == 3 && a > 0 && b > 0 && c > 0) {
        space.boxes = {a, b, c};
        return a * b * c > 1;
    }
    char extra;
    if (std::sscanf(spec.c_str(), "%d%c", &a, &extra) == 1 && a > 0) {
        space.boxes = {a, a, a};
        space.balanced = true;
        return a > 1;
    }
    throw UsageError("bad --boxes value '" + spec + "' (expected NxNxN, N or auto)");
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
    distrib::SpaceOptions space;
    bool use_boxes = parse_boxes(o.boxes, space);
    distrib::SpaceStats space_stats;
    Image image;
    if (use_boxes) {
        if (o.render.antialias) throw UsageError("anti-aliasing is not available with --boxes yet");
        space.results = o.results == "forward"   ? distrib::SpaceOptions::Results::Forward
                        : o.results == "parents" ? distrib::SpaceOptions::Results::Parents
                                                 : distrib::SpaceOptions::Results::Auto;
        space.queue = o.queue == "fifo" ? distrib::QueuePolicy::Fifo : distrib::QueuePolicy::Priority;
        image = distrib::render_space(scene, o.render, space, &space_stats);
        stats.trace_seconds = space_stats.seconds;
        for (const auto& b : space_stats.boxes) {
            stats.camera_rays += b.camera;
            stats.reflected_rays += b.reflected;
            stats.refracted_rays += b.refracted;
            stats.shadow_rays += b.shadow;
        }
    } else {
        image = trace::render_scene(scene, o.render, &stats);
    }
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
        if (use_boxes) {
            j["results"] = space_stats.parent_tracking ? "parents" : "forward";
            nlohmann::json boxes = nlohmann::json::array();
            for (const auto& b : space_stats.boxes) {
                auto lim = [](double v) { return std::isinf(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
                boxes.push_back({{"region", {{"lo", {lim(b.region.lo.x), lim(b.region.lo.y), lim(b.region.lo.z)}},
                                             {"hi", {lim(b.region.hi.x), lim(b.region.hi.y), lim(b.region.hi.z)}}}},
                                 {"objects", b.objects},
                                 {"resident_bytes", b.resident_bytes},
                                 {"rays", {{"camera", b.camera}, {"reflected", b.reflected},
                                           {"refracted", b.refracted}, {"shadow", b.shadow}}},
                                 {"rays_received", b.rays_received},
                                 {"results_received", b.results_received},
                                 {"messages_sent", b.messages_sent},
                                 {"peak_queue", b.peak_queue},
                                 {"peak_waiting_parents", b.peak_parents},
                                 {"busy_seconds", b.busy_seconds}});
            }
            j["boxes"] = boxes;
        } else {
            j["boxes"] = 1;
        }
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
