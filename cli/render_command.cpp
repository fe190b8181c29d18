#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "cli/exit_codes.h"
#include "cli/interrupt.h"
#include "cli/option_names.h"
#include "cli/options.h"
#include "cli/progress_bar.h"
#include "cli/tile_worker_job.h"
#include "core/self_exe.h"
#include "distrib/distribution_plan.h"
#include "distrib/screen_render.h"
#include "distrib/space_render.h"
#include "distrib/stats_json.h"
#include "distrib/tcp.h"
#include "output/image_io.h"
#include "parser/parser.h"
#include "trace/object_queries.h"
#include "trace/pattern.h"
#include "trace/render_plan.h"
#include "trace/shapes/isosurface.h"

namespace povwall::cli {

using Clock = std::chrono::steady_clock;

OutputEncoding encoding_for(const Scene& scene, const RenderOptions& o) {
    OutputEncoding enc;
    enc.gamma_handling = scene.gamma_handling();
    enc.working_gamma = scene.settings.assumed_gamma.value_or(GammaCurve{});
    enc.file_srgb = !o.file_gamma;
    enc.file_gamma = o.file_gamma.value_or(2.2f);
    enc.bits = o.bits;
    enc.alpha = o.render.alpha;
    return enc;
}

// A screen-subdivision worker: this binary, the same scene and settings, one thread,
// serving tiles on stdin/stdout.
std::vector<std::string> tile_worker_command(const RenderOptions& o) {
    const std::string exe = self_exe();
    if (exe.empty())
        throw UsageError("cannot find the povwall binary for worker processes");
    std::vector<std::string> cmd = {exe, "render"};
    for (std::string& a : TileWorkerJob::of(o).to_argv()) cmd.push_back(std::move(a));
    return cmd;
}

// +C keeps an image that exists (images are only ever renamed into place once complete,
// so an existing one is whole) and is not older than the scene file; an older one was
// made from another version of the scene and is rendered again.
enum class Kept { No, Yes, Stale };
Kept keep_existing(const std::string& image, const std::string& scene) {
    std::error_code ec;
    if (!std::filesystem::exists(image, ec)) return Kept::No;
    const auto made = std::filesystem::last_write_time(image, ec);
    if (ec) return Kept::No;
    const auto edited = std::filesystem::last_write_time(scene, ec);
    return !ec && edited > made ? Kept::Stale : Kept::Yes;
}

// An animation: each frame is a still with its own clock, written to a numbered file.
// With +C (Continue_Trace) frames are kept as above, so an interrupted batch resumes.
int run_animation(const RenderOptions& options, const std::vector<Frame>& frames) {
    RenderOptions base = options;
    base.frame_workers = std::make_shared<std::unique_ptr<distrib::TcpSession>>();
    int rendered = 0, kept = 0;
    for (const Frame& f : frames) {
        const Kept k =
            base.continue_trace ? keep_existing(f.output, base.scene) : Kept::No;
        if (k == Kept::Yes) {
            ++kept;
            if (!base.quiet)
                std::fprintf(stderr, "povwall: frame %d: %s exists, kept (+C)\n",
                             f.number, f.output.c_str());
            continue;
        }
        if (k == Kept::Stale && !base.quiet)
            std::fprintf(stderr,
                         "povwall: frame %d: %s is older than %s, rendered again (+C)\n",
                         f.number, f.output.c_str(), base.scene.c_str());
        RenderOptions o = base;
        o.output = f.output;
        o.frame = RenderOptions::FrameValues{f.number, f.clock, f.clock_delta};
        if (int rc = run_render(o); rc != 0)
            return rc;  // POV-Ray stops at a failing frame
        ++rendered;
    }
    if (!base.quiet) {
        std::fprintf(stderr, "povwall: frames %d..%d: %d rendered, %d kept\n",
                     frames.front().number, frames.back().number, rendered, kept);
    }
    return 0;
}

// The parse options `render` uses for `o` (#write files go to `output_dir`).
parser::ParseOptions render_parse_options(const RenderOptions& o,
                                          const std::string& output_dir) {
    parser::ParseOptions popts;
    popts.library_paths = o.library_paths;
    popts.image_width = o.width;
    popts.image_height = o.height;
    popts.declares = o.declares;
    popts.language_version = o.language_version;
    popts.output_file_type = o.format;
    popts.image_reader = output::read_stored_image;
    popts.function_hooks = trace::parse_time_function_hooks();
    popts.object_queries = trace::parse_time_object_queries();
    popts.initial_frame = o.animation.initial_frame;
    popts.final_frame = o.frame ? o.animation.final_frame : o.animation.initial_frame;
    popts.initial_clock = o.animation.initial_clock;
    popts.final_clock = o.animation.final_clock;
    popts.clock = o.frame ? o.frame->clock : o.animation.clock;
    popts.clock_delta = o.frame ? o.frame->clock_delta : 0.0;
    popts.frame_number = o.frame ? o.frame->number : 0;
    popts.messages = o.quiet ? nullptr : &std::cerr;
    popts.max_loop_iterations = o.max_loop_iterations;
    popts.max_parse_seconds = o.max_parse_seconds;
    popts.output_dir = output_dir;
    return popts;
}

Scene parse_render_scene(const RenderOptions& o) {
    parser::ParseOptions popts = render_parse_options(o, "");
    popts.messages = nullptr;
    popts.write_user_files = false;
    Scene scene = parser::parse_scene_file(o.scene, popts);
    if (o.max_trace_level) scene.settings.max_trace_level = *o.max_trace_level;
    if (o.adc_bailout) scene.settings.adc_bailout = float(*o.adc_bailout);
    return scene;
}

int run_render(RenderOptions o) {
    if (o.scene.empty())
        throw UsageError("no scene file given (+ISCENE.pov or render SCENE.pov)");
    if (o.width <= 0 || o.height <= 0) throw UsageError("image size must be positive");
    if (!o.frame && !o.tile_worker) {  // a tile worker renders the still it was given
        const std::vector<Frame> frames = animation_frames(o);
        if (!frames.empty()) return run_animation(o, frames);
    }
    if (o.continue_trace && !o.frame) {
        std::string out = o.output.empty() ? default_output_name(o) : o.output;
        if (std::filesystem::path(out).extension().empty())
            out += format_extension(o.format);
        const Kept k = keep_existing(out, o.scene);
        if (k == Kept::Yes) {
            if (!o.quiet)
                std::fprintf(stderr, "povwall: %s exists, kept (+C)\n", out.c_str());
            return 0;
        }
        if (k == Kept::Stale && !o.quiet)
            std::fprintf(stderr, "povwall: %s is older than %s, rendered again (+C)\n",
                         out.c_str(), o.scene.c_str());
    }
    if (o.output.empty()) o.output = default_output_name(o);
    // As POV-Ray does: an output name without an extension gets the format's.
    if (std::filesystem::path(o.output).extension().empty()) {
        o.output += format_extension(o.format);
    }
    // #fopen ... write puts relative names beside the image.
    parser::ParseOptions popts =
        render_parse_options(o, std::filesystem::path(o.output).parent_path().string());
    // What this render is doing, for the message of an interrupt (cli/interrupt.h).
    RenderRecord& record = g_render_record;
    record.frame = o.frame ? o.frame->number : -1;
    record.parse.set(o.scene, 0);  // the parser gives the line once it has read the file
    record.output.set(o.output, 0);
    record.progress.reset();
    record.phase = RenderPhase::Parsing;
    struct Finished {
        ~Finished() {
            g_render_record.phase = RenderPhase::None;
            g_render_record.frame = -1;
        }
    } finished;
    popts.place = &record.parse;
    auto load_scene = [&] {
        Scene scene = parser::parse_scene_file(o.scene, popts);
        if (o.max_trace_level) scene.settings.max_trace_level = *o.max_trace_level;
        if (o.adc_bailout) scene.settings.adc_bailout = float(*o.adc_bailout);
        return scene;
    };
    resolve_partial_render(o);
    o.render.width = o.width;
    o.render.height = o.height;
    o.render.plan_everything_on = o.plan == PlanChoice::All;
    auto t0 = Clock::now();
    Scene scene;
    // A single frame's worker processes, released after the frame: they exit while the
    // image is written, and are reaped on return.
    std::unique_ptr<distrib::TcpSession> released_workers;
    try {
        if (o.tile_worker) {
            // POVWALL_FAULT_WORKER_EXIT_AFTER=N: the worker dies after N tiles (for the
            // tests).
            const char* fault = std::getenv("POVWALL_FAULT_WORKER_EXIT_AFTER");
            return distrib::serve_tiles(load_scene, o.render, 0, 1,
                                        fault ? std::atoi(fault) : -1);
        }
        scene = load_scene();
    } catch (const parser::ParseError& e) {
        std::cerr << e.what() << "\n";
        return exit_code(ExitCode::Error);
    }
    auto t1 = Clock::now();
    record.progress.objects = scene.objects.size();
    record.phase = RenderPhase::Rendering;
    // What the scene needs traced, made once for every driver, --explain and --stats.
    const trace::RenderPlan plan =
        trace::make_render_plan(scene, o.render.plan_everything_on, o.render.quality);
    distrib::DistributionRequest request;
    request.mode = o.mode;
    request.boxes = o.boxes;
    request.threads = o.render.threads;
    request.procs = o.procs;
    request.keep_on_cores = o.worker_cores == WorkerCores::Auto;
    request.teams = o.teams == "auto" ? 0 : std::atoi(o.teams.c_str());
    request.workers = int(o.workers.size());
    request.pixels = size_t(o.render.width) * size_t(o.render.height);
    request.width = o.render.width;
    request.height = o.render.height;
    // Running workers host black boxes: --workers means space subdivision.
    if (!o.workers.empty() && request.mode == distrib::RenderMode::Auto)
        request.mode = distrib::RenderMode::Space;
    if (!o.workers.empty() && request.mode != distrib::RenderMode::Space)
        throw UsageError("--workers hosts black boxes: it needs --mode space (or auto)");
    if (!o.workers.empty() && o.procs > 0)
        throw UsageError("--procs and --workers exclude each other");
    distrib::DistributionPlan dplan;
    try {
        if (!o.worker_memory.empty())
            request.worker_memory = distrib::parse_memory_size(o.worker_memory);
        dplan = distrib::plan_distribution(scene, request);
    } catch (const distrib::UnsupportedInMode& e) {
        std::cerr << e.what() << "\n";
        return exit_code(ExitCode::Error);
    } catch (const distrib::DistributionError& e) {
        throw UsageError(e.what());
    }
    if (o.explain) {
        std::printf("render plan for %s:\n", o.scene.c_str());
        for (const auto& line : trace::explain_plan(plan, scene))
            std::printf("  %s\n", line.c_str());
        for (const auto& line : dplan.reasons) std::printf("  %s\n", line.c_str());
        std::fflush(stdout);
    }
    trace::RenderStats stats;
    o.render.progress = &record.progress;
    std::optional<ProgressBar> bar;
    bar.emplace(record.progress, !o.quiet);
    distrib::SpaceOptions space = dplan.space;
    const bool use_boxes = dplan.mode == distrib::RenderMode::Space;
    distrib::SpaceStats space_stats;
    int worker_frames = 0, worker_processes = 0;  // TCP workers (--stats)
    bool workers_forked = false;
    bool traced_here = false;  // the rays were traced in this process
    Image image;
    if (use_boxes) {
        space.results = o.results;
        space.queue = o.queue;
        // Worker processes: --procs, --workers, or as many as auto mode needs for the
        // memory budget.
        if (dplan.procs > 0 || !o.workers.empty()) {
            distrib::SceneSource source;
            std::ifstream in(o.scene, std::ios::binary);
            source.parse.scene.assign(std::istreambuf_iterator<char>(in), {});
            source.parse.name = o.scene;
            source.parse.library_paths = popts.library_paths;
            source.parse.declares = popts.declares;
            source.parse.language_version = popts.language_version;
            source.parse.output_file_type = popts.output_file_type;
            source.parse.max_loop_iterations = popts.max_loop_iterations;
            source.parse.max_trace_level = o.max_trace_level;
            source.parse.adc_bailout = o.adc_bailout;
            source.animation = distrib::AnimationValues::of(popts);
            distrib::TcpOptions tcp;
            tcp.procs = o.workers.empty() ? dplan.procs : 0;
            tcp.workers = o.workers;
            tcp.token = o.token;
            tcp.recover = o.recover;
            tcp.worker_binary = self_exe();
            // Forked workers share the coordinator's whole scene, which a memory budget
            // (--worker-memory, or auto mode spreading a scene too big for one worker)
            // is there to avoid: each of those parses only its part.
            tcp.fork_workers = o.worker_start == WorkerStart::Fork && o.procs > 0 &&
                               o.worker_memory.empty();
            tcp.image_reader = output::read_stored_image;
            // One frame, or a frame of an animation on the previous frame's workers.
            std::unique_ptr<distrib::TcpSession> one_frame;
            std::unique_ptr<distrib::TcpSession>& session =
                o.frame_workers ? *o.frame_workers : one_frame;
            if (!session) session = std::make_unique<distrib::TcpSession>(tcp);
            try {
                image =
                    session->render(scene, source, o.render, space, &space_stats, &plan);
                worker_frames = session->frames_on_these_workers();
                worker_processes = session->processes_started();
                workers_forked = session->workers_forked();
                if (one_frame) {
                    one_frame->release_workers();
                    released_workers = std::move(one_frame);
                }
                // The budget shapes the walls; a worker keeps the objects of all its
                // boxes plus the process itself (binary, parser), so it can outgrow
                // the budget: said, not hidden.
                const auto& peaks = space_stats.worker_peak_resident;
                for (size_t w = 0;
                     w < peaks.size() && !o.worker_memory.empty() && !o.quiet; ++w) {
                    if (peaks[w] > dplan.worker_memory) {
                        std::fprintf(
                            stderr,
                            "povwall: warning: worker %zu peaked at %.1f MB, over "
                            "the %.1f MB --worker-memory (it held %zu of the scene's "
                            "objects, those of its boxes; more workers hold fewer "
                            "each)\n",
                            w, peaks[w] / 1048576.0, dplan.worker_memory / 1048576.0,
                            w < space_stats.worker_objects_kept.size()
                                ? space_stats.worker_objects_kept[w]
                                : size_t(0));
                    }
                }
            } catch (const distrib::DistribError& e) {
                std::cerr << "povwall: error: " << e.what() << " (no image written)\n";
                return exit_code(ExitCode::WorkerLost);
            }
        } else {
            image = distrib::render_space(scene, o.render, space, &space_stats, &plan);
            traced_here = true;
        }
        stats.trace_seconds = space_stats.seconds;
        for (const auto& b : space_stats.boxes) stats.rays += b.rays;
    } else if (dplan.mode == distrib::RenderMode::Screen) {
        distrib::ScreenOptions screen;
        screen.workers = dplan.procs;
        // Tiles are POV-Ray's render blocks, which decide the anti-aliasing.
        screen.tile =
            trace::clamped_block_size(o.render.block_size, trace::render_area(o.render));
        screen.worker_command = tile_worker_command(o);
        screen.recover = o.recover;
        distrib::ScreenStats screen_stats;
        try {
            image = distrib::render_screen(o.render, screen, &screen_stats);
        } catch (const distrib::ScreenError& e) {
            // A lost worker, as over TCP (README: exit codes).
            std::cerr << "povwall: error: " << e.what() << " (no image written)\n";
            return exit_code(ExitCode::WorkerLost);
        }
        stats.trace_seconds = screen_stats.seconds;
        stats.rays = screen_stats.rays;
    } else {
        image = trace::render_scene(scene, o.render, &stats, &plan);
        traced_here = true;
    }
    bar.reset();
    // POV-Ray's isosurface messages, from the rays this process traced (worker
    // processes keep theirs).
    if (traced_here)
        for (const std::string& m : trace::isosurface_messages(scene))
            std::cerr << m << "\n";
    auto t2 = Clock::now();
    try {
        std::string format;
        if (o.format_given) format = format_extension(o.format).substr(1);
        record.phase = RenderPhase::Writing;
        output::write_image(image, o.output, encoding_for(scene, o), format);
        record.phase = RenderPhase::Written;
    } catch (const output::ImageIoError& e) {
        std::cerr << "povwall: error: " << e.what() << "\n";
        return exit_code(ExitCode::Error);
    }
    double parse_s = std::chrono::duration<double>(t1 - t0).count();
    double total_s = std::chrono::duration<double>(t2 - t0).count();
    if (!o.quiet) {
        std::fprintf(
            stderr,
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
        j["rays"] = distrib::rays_json(stats.rays);
        j["intersection_tests"] = stats.intersection_tests;
        // What the plan left out, with the counters that show it cost nothing.
        nlohmann::json lights = nlohmann::json::array();
        for (const auto& l : plan.lights)
            lights.push_back({{"shadow_rays", l.shadow_rays}, {"why", l.reason}});
        using distrib::RenderMode;
        const RenderMode ran = use_boxes                          ? RenderMode::Space
                               : dplan.mode == RenderMode::Screen ? RenderMode::Screen
                                                                  : RenderMode::Single;
        j["plan"] = {{"mode", choice_name(ran)},
                     {"forced_on", plan.everything_on},
                     {"reflection_rays", plan.reflection_rays},
                     {"transmission_rays", plan.transmission_rays},
                     {"refraction_rays", plan.refraction_rays},
                     {"lights", lights},
                     {"parent_tracking", use_boxes && space_stats.parent_tracking},
                     {"scene_bytes_estimate", dplan.scene_bytes},
                     {"prepared_bytes_estimate", dplan.prepared_bytes},
                     {"worker_processes", dplan.procs},
                     {"largest_worker_bytes_estimate", dplan.largest_worker_bytes},
                     {"worker_memory", dplan.worker_memory}};
        if (!use_boxes) {
            j["plan"]["octree"] = stats.octree_flat ? "flat list" : "octree";
            j["plan"]["octree_nodes"] = stats.octree_nodes;
            j["plan"]["octree_dense_top_levels"] = stats.octree_dense_top;
            j["plan"]["resident_bytes"] = stats.resident_bytes;
        }
        if (use_boxes) {
            j["results"] = space_stats.parent_tracking ? "parents" : "forward";
            // Anti-aliasing: the camera samples each wave traced.
            if (!space_stats.wave_samples.empty())
                j["antialias_wave_samples"] = space_stats.wave_samples;
            nlohmann::json boxes = nlohmann::json::array();
            for (const auto& b : space_stats.boxes) {
                auto lim = [](double v) {
                    return std::isinf(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
                };
                nlohmann::json box = distrib::box_stats_json(b);
                box["region"] = {
                    {"lo", {lim(b.region.lo.x), lim(b.region.lo.y), lim(b.region.lo.z)}},
                    {"hi", {lim(b.region.hi.x), lim(b.region.hi.y), lim(b.region.hi.z)}}};
                boxes.push_back(std::move(box));
            }
            j["boxes"] = boxes;
            if (worker_frames > 0) {
                j["workers"] = {
                    {"frames_on_these_workers", worker_frames},
                    {"processes_started", worker_processes},
                    {"processes_forked", workers_forked},
                    {"peak_resident_bytes", space_stats.worker_peak_resident},
                    {"objects_kept", space_stats.worker_objects_kept},
                    {"objects_left_out", space_stats.worker_objects_left_out}};
                j["workers"]["teams"] = space_stats.teams;
                if (!space_stats.worker_cores.empty())
                    j["workers"]["cores"] = space_stats.worker_cores;
            }
        } else {
            j["boxes"] = 1;
        }
        if (o.stats_file == "-") {  // as usual for a file name: standard output
            std::cout << j.dump(2) << "\n" << std::flush;
        } else {
            std::string tmp = o.stats_file + ".tmp";
            {
                std::ofstream out(tmp);
                out << j.dump(2) << "\n";
            }
            std::filesystem::rename(tmp, o.stats_file);
        }
    }
    return 0;
}

}  // namespace povwall::cli
