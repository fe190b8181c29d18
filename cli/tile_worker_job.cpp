#include "cli/tile_worker_job.h"

#include <cstdlib>

namespace povwall::cli {
namespace {

// Each field of the job with the render option it comes from and goes to (`o` is only
// read by of() and only written by apply_to()). The scene's text stays empty: a screen
// worker reads the file.
template <class Job, class Options, class Pair>
void bind(Job& job, Options& o, Pair&& p) {
    p(job.name, o.scene);
    p(job.width, o.width);
    p(job.height, o.height);
    p(job.plan, o.plan);
    p(job.library_paths, o.library_paths);
    p(job.declares, o.declares);
    p(job.language_version, o.language_version);
    p(job.output_file_type, o.format);
    p(job.alpha, o.render.alpha);
    p(job.quality, o.render.quality);
    p(job.antialias, o.render.antialias);
    p(job.aa_threshold, o.render.aa_threshold);
    p(job.aa_method, o.render.aa_method);
    p(job.aa_depth, o.render.aa_depth);
    p(job.aa_jitter, o.render.aa_jitter);
    p(job.aa_jitter_amount, o.render.aa_jitter_amount);
    p(job.aa_gamma, o.render.aa_gamma);
    p(job.max_trace_level, o.max_trace_level);
    p(job.adc_bailout, o.adc_bailout);
    p(job.max_loop_iterations, o.max_loop_iterations);
    p(job.frame, o.frame);
    p(job.initial_frame, o.animation.initial_frame);
    p(job.final_frame, o.animation.final_frame);
    p(job.initial_clock, o.animation.initial_clock);
    p(job.final_clock, o.animation.final_clock);
    p(job.clock, o.animation.clock);
}

}  // namespace

std::string text(const RenderOptions::FrameValues& f) {
    using distrib::job_fields_detail::text;
    return text(f.number) + "," + text(f.clock) + "," + text(f.clock_delta);
}

void read_text(std::string_view name, std::string_view s,
               RenderOptions::FrameValues& out) {
    using distrib::job_fields_detail::read_text;
    const size_t a = s.find(','), b = s.find(',', a == s.npos ? a : a + 1);
    if (a == s.npos || b == s.npos) distrib::job_fields_detail::malformed(name, s);
    read_text(name, s.substr(0, a), out.number);
    read_text(name, s.substr(a + 1, b - a - 1), out.clock);
    read_text(name, s.substr(b + 1), out.clock_delta);
}

TileWorkerJob TileWorkerJob::of(const RenderOptions& o) {
    TileWorkerJob job;
    bind(job, o, [](auto& mine, const auto& theirs) { mine = theirs; });
    return job;
}

void TileWorkerJob::apply_to(RenderOptions& o) const {
    bind(*this, o, [](const auto& mine, auto& theirs) { theirs = mine; });
    o.tile_worker = true;
    o.render.threads = 1;
    o.quiet = true;
}

std::vector<std::string> TileWorkerJob::to_argv() const {
    std::vector<std::string> args = {kFlag};
    distrib::job_to_argv(*this, args);
    return args;
}

TileWorkerJob TileWorkerJob::from_argv(const std::vector<std::string>& args) {
    if (args.empty() || args[0] != kFlag)
        throw UsageError(std::string("tile worker: arguments must start with ") + kFlag);
    TileWorkerJob job;
    try {
        distrib::job_from_argv(args, 1, job);
    } catch (const distrib::JobArgumentError& e) {
        throw UsageError(std::string("tile worker: ") + e.what());
    }
    return job;
}

}  // namespace povwall::cli
