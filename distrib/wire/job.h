// The job a coordinator gives its workers, as types: what to parse, how to render, which
// boxes are whose. Each struct lists its fields once (fields(), see job_fields.h), and
// that one list writes and reads it as JSON (TCP workers' "job" and "frame" messages) and
// as a command line (screen workers, cli/tile_worker_job.h): a field added there travels
// to every kind of worker with no other change.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/scene.h"
#include "distrib/object_boxes.h"
#include "distrib/space_render.h"
#include "distrib/wire/job_fields.h"
#include "parser/parser.h"
#include "trace/render.h"
#include "trace/render_plan.h"

namespace povwall::distrib {

std::array<std::pair<SpaceOptions::Results, const char*>, 3> enum_names(
    SpaceOptions::Results);
std::array<std::pair<QueuePolicy, const char*>, 2> enum_names(QueuePolicy);

// What a worker parses, and what the parse depends on: every worker parses the scene
// as the coordinator did.
struct ParseJob {
    std::string scene;  // the main file's text (empty: workers read the file `name`)
    std::string name;   // its path: diagnostics and relative includes
    std::vector<std::string> library_paths;
    std::map<std::string, double> declares;
    std::optional<int> language_version;        // +MV
    char output_file_type = 'N';                // the scene reads it (+F's letter)
    uint64_t max_loop_iterations = 10'000'000;  // the coordinator's parse limit
    // The coordinator's overrides of the scene's global_settings.
    std::optional<int> max_trace_level;
    std::optional<double> adc_bailout;

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("scene", s.scene);
        v("name", s.name);
        v("library_path", s.library_paths);
        v("declare", s.declares);
        v("language_version", s.language_version);
        v("output_file_type", s.output_file_type);
        v("max_loop_iterations", s.max_loop_iterations);
        v("max_trace_level", s.max_trace_level);
        v("adc_bailout", s.adc_bailout);
    }
    // The parse's settings (library paths, declares, version, +F, loop limit).
    void apply_to(parser::ParseOptions& options) const;
    // The overrides of the parsed scene's global_settings.
    void override_settings(Scene& parsed) const;
    bool operator==(const ParseJob&) const = default;
};

// What every worker needs, whatever the mode: the scene and the settings its parse and
// its pixels depend on.
struct SceneJob : ParseJob {
    int width = 0, height = 0;
    bool alpha = false;
    bool antialias = false;

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("parse_job", static_cast<copy_const_t<Self, ParseJob>&>(s));
        v("width", s.width);
        v("height", s.height);
        v("alpha", s.alpha);
        v("antialias", s.antialias);
    }
    bool operator==(const SceneJob&) const = default;
};

// What every frame a TCP coordinator renders on the same workers shares: the scene and
// how the boxes render. A frame whose FixedJob differs gets new workers. (With
// `antialias`, samples go out in waves and their sums come back as records.)
struct FixedJob : SceneJob {
    bool plan_everything_on = false;
    SpaceOptions::Results results = SpaceOptions::Results::Auto;
    QueuePolicy queue = QueuePolicy::Priority;
    int threads = 0;
    std::array<int, 3> boxes{1, 1, 1};
    bool balanced = false;

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("scene_job", static_cast<copy_const_t<Self, SceneJob>&>(s));
        v("plan_everything_on", s.plan_everything_on);
        v("results", s.results);
        v("queue", s.queue);
        v("threads", s.threads);
        v("boxes", s.boxes);
        v("balanced", s.balanced);
    }
    static FixedJob of(const ParseJob& parse, const trace::RenderSettings& settings,
                       const SpaceOptions& options);
    bool operator==(const FixedJob&) const = default;
};

// The language's animation values of one frame (clock, frame_number, ...).
struct AnimationValues {
    double clock = 0, clock_delta = 0, initial_clock = 0, final_clock = 0;
    int frame_number = 0, initial_frame = 1, final_frame = 1;

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("clock", s.clock);
        v("clock_delta", s.clock_delta);
        v("initial_clock", s.initial_clock);
        v("final_clock", s.final_clock);
        v("frame_number", s.frame_number);
        v("initial_frame", s.initial_frame);
        v("final_frame", s.final_frame);
    }
    static AnimationValues of(const parser::ParseOptions& options);
    void apply_to(parser::ParseOptions& options) const;
    bool operator==(const AnimationValues&) const = default;
};

// What a TCP session's workers parse: the scene as the coordinator parsed it, at one
// frame's animation values.
struct SceneSource {
    ParseJob parse;
    AnimationValues animation;
};

// What changes from frame to frame: the "frame" message, and part of the first job.
struct FrameJob {
    AnimationValues animation;
    trace::RenderPlan plan;
    std::vector<size_t> expected_objects;  // objects each worker keeps (a parse check)
    // Boxes that also hold the objects around one whose surface can lie outside its
    // POV-Ray box (distrib/object_boxes.h).
    std::vector<WalkReach> walk_reaches;

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("animation", s.animation);
        v("plan", s.plan);
        v("expected_objects", s.expected_objects);
        v("walk_reaches", s.walk_reaches);
    }
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

    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("fixed", s.fixed);
        v("frame", s.frame);
        v("walls", s.walls);
        v("workers", s.workers);
        v("inherited", s.inherited);
        v("index", s.index);
        v("owner", s.owner);
    }
};

// A walk reach in a job: {"box", "lo", "hi"}; JSON has no infinity, so an unbounded
// side travels as the largest finite number.
void to_json(nlohmann::json& j, const WalkReach& reach);
void from_json(const nlohmann::json& j, WalkReach& reach);

nlohmann::json to_json(const FixedJob& job);
FixedJob fixed_job_from_json(const nlohmann::json& j);
nlohmann::json to_json(const FrameJob& frame);
FrameJob frame_job_from_json(const nlohmann::json& j);
// With "type": "job".
nlohmann::json to_json(const WorkerJob& job);
WorkerJob worker_job_from_json(const nlohmann::json& j);

}  // namespace povwall::distrib

namespace povwall::trace {
// A plan inside a job's JSON (job_fields.h reads and writes fields through nlohmann).
void to_json(nlohmann::json& j, const RenderPlan& plan);
void from_json(const nlohmann::json& j, RenderPlan& plan);
}  // namespace povwall::trace
