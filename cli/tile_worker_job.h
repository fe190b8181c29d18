// The settings a screen (tile) worker renders with: the job every worker gets
// (distrib::SceneJob, the scene by its path) and what screen workers add. The
// coordinator makes it from its render options (of), writes it as the worker's command
// line (to_argv), and the worker reads it back (from_argv) into its own options
// (apply_to). The command line is the job's field list (distrib/wire/job_fields.h);
// of() and apply_to() pair each field with its render option in bind() in
// tile_worker_job.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/options.h"
#include "distrib/wire/job.h"

namespace povwall::cli {

struct TileWorkerJob : distrib::SceneJob {
    PlanChoice plan = PlanChoice::Auto;
    int quality = 9;
    double aa_threshold = 0.3;
    int aa_method = 1, aa_depth = 3;
    bool aa_jitter = true;
    double aa_jitter_amount = 1.0;
    double aa_gamma = 2.5;
    // The clock as this process has it: the frame of an animation, or a still's clock.
    std::optional<RenderOptions::FrameValues> frame;
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0.0, final_clock = 1.0, clock = 0.0;

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("scene_job", static_cast<distrib::copy_const_t<Self, distrib::SceneJob>&>(s));
        v("plan", s.plan);
        v("quality", s.quality);
        v("aa_threshold", s.aa_threshold);
        v("aa_method", s.aa_method);
        v("aa_depth", s.aa_depth);
        v("aa_jitter", s.aa_jitter);
        v("aa_jitter_amount", s.aa_jitter_amount);
        v("aa_gamma", s.aa_gamma);
        v("frame", s.frame);
        v("initial_frame", s.initial_frame);
        v("final_frame", s.final_frame);
        v("initial_clock", s.initial_clock);
        v("final_clock", s.final_clock);
        v("clock", s.clock);
    }

    static TileWorkerJob of(const RenderOptions& o);
    // The worker's own options: `o`'s defaults with these settings, one thread, quiet.
    void apply_to(RenderOptions& o) const;
    // The worker's arguments after `render` (the first is kFlag), and back; from_argv
    // throws UsageError on an argument it does not know or a malformed value.
    std::vector<std::string> to_argv() const;
    static TileWorkerJob from_argv(const std::vector<std::string>& args);
    bool operator==(const TileWorkerJob&) const = default;

    static constexpr const char* kFlag = "--tile-worker";
};

// A frame's values on the command line: "number,clock,clock_delta".
std::string text(const RenderOptions::FrameValues& f);
void read_text(std::string_view name, std::string_view s,
               RenderOptions::FrameValues& out);

}  // namespace povwall::cli
