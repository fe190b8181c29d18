// The job a coordinator sends its workers, as types: what to parse, how to render, which
// boxes are whose. Serialised by name (to_json / *_from_json), so a field added to one of
// these structs travels with no other change; a missing or mistyped field throws
// nlohmann::json::exception, which the worker reports as a malformed job.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "distrib/space_render.h"
#include "distrib/tcp.h"
#include "parser/parser.h"
#include "trace/render.h"
#include "trace/render_plan.h"

namespace povwall::distrib {

// What every frame a coordinator renders on the same workers shares: the scene source and
// the render's settings. A frame whose FixedJob differs gets new workers.
struct FixedJob {
    std::string scene;  // the main file's text
    std::string name;   // its path: diagnostics and relative includes
    std::vector<std::string> library_paths;
    std::map<std::string, double> declares;
    std::optional<int> language_version;
    char output_file_type = 'N';
    uint64_t max_loop_iterations = 0;
    std::optional<int> max_trace_level;
    std::optional<double> adc_bailout;
    int width = 0, height = 0;
    bool alpha = false;
    bool antialias = false;  // samples go out in waves (their sums come back as records)
    bool plan_everything_on = false;
    SpaceOptions::Results results = SpaceOptions::Results::Auto;
    QueuePolicy queue = QueuePolicy::Priority;
    int threads = 0;
    std::array<int, 3> boxes{1, 1, 1};
    bool balanced = false;

    static FixedJob of(const SceneSource& source, const trace::RenderSettings& settings,
                       const SpaceOptions& options);
    bool operator==(const FixedJob&) const = default;
};

// The language's animation values of one frame (clock, frame_number, ...).
struct AnimationValues {
    double clock = 0, clock_delta = 0, initial_clock = 0, final_clock = 0;
    int frame_number = 0, initial_frame = 1, final_frame = 1;

    static AnimationValues of(const SceneSource& source);
    void apply_to(parser::ParseOptions& options) const;
    bool operator==(const AnimationValues&) const = default;
};

// What changes from frame to frame: the "frame" message, and part of the first job.
struct FrameJob {
    AnimationValues animation;
    trace::RenderPlan plan;
    std::vector<size_t> expected_objects;  // objects each worker keeps (a parse check)
};

// The "job" message: a worker's first frame.
struct WorkerJob {
    FixedJob fixed;
    FrameJob frame;
    std::array<std::vector<Real>, 3> walls;
    std::vector<std::string> workers;  // every worker's address, by index
    bool inherited = false;            // forked with this frame's scene parsed already
    int index = 0;                     // this worker's
    std::vector<int> owner;            // the worker of each box (of this worker's team)
};

nlohmann::json to_json(const FixedJob& job);
FixedJob fixed_job_from_json(const nlohmann::json& j);
nlohmann::json to_json(const FrameJob& frame);
FrameJob frame_job_from_json(const nlohmann::json& j);
// With "type": "job".
nlohmann::json to_json(const WorkerJob& job);
WorkerJob worker_job_from_json(const nlohmann::json& j);

}  // namespace povwall::distrib
