// The settings a screen (tile) worker renders with, as one type: the coordinator makes it
// from its render options (of), writes it as the worker's command line (to_argv), and the
// worker reads it back (from_argv) into its own options (apply_to). Every setting is one
// line of fields() in tile_worker_job.cpp, which all four go through: a setting added
// there travels to the workers with no other change.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/options.h"

namespace povwall::cli {

struct TileWorkerJob {
    std::string scene;
    int width = 0, height = 0;
    std::string plan;
    std::vector<std::string> library_paths;
    std::map<std::string, double> declares;
    std::optional<int> language_version;
    char format = 'N';  // the scene reads it (output_file_type... as +F gave it)
    bool alpha = false;
    int quality = 9;
    bool antialias = false;
    double aa_threshold = 0.3;
    int aa_method = 1, aa_depth = 3;
    bool aa_jitter = true;
    double aa_jitter_amount = 1.0;
    double aa_gamma = 2.5;
    std::optional<int> max_trace_level;
    std::optional<double> adc_bailout;
    uint64_t max_loop_iterations = 0;
    // The clock as this process has it: the frame of an animation, or a still's clock.
    std::optional<RenderOptions::FrameValues> frame;
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0.0, final_clock = 1.0, clock = 0.0;

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

}  // namespace povwall::cli
