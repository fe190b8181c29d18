#include "distrib/wire/job.h"

#include "distrib/wire/control.h"

namespace povwall::distrib {

using json = nlohmann::json;

std::array<std::pair<SpaceOptions::Results, const char*>, 3> enum_names(
    SpaceOptions::Results) {
    return {{{SpaceOptions::Results::Auto, "auto"},
             {SpaceOptions::Results::Forward, "forward"},
             {SpaceOptions::Results::Parents, "parents"}}};
}

std::array<std::pair<QueuePolicy, const char*>, 2> enum_names(QueuePolicy) {
    return {{{QueuePolicy::Priority, "priority"}, {QueuePolicy::Fifo, "fifo"}}};
}

namespace {

[[noreturn]] void bad_value(const std::string& field, const json& value) {
    job_fields_detail::bad_json_value(field, value);
}

void check(const FixedJob& f) {
    if (f.width <= 0 || f.height <= 0 || int64_t(f.width) * f.height > (int64_t(1) << 31))
        bad_value("image size", {f.width, f.height});
}

}  // namespace

void ParseJob::apply_to(parser::ParseOptions& o) const {
    o.library_paths = library_paths;
    o.declares = declares;
    o.language_version = language_version;
    o.output_file_type = output_file_type;
    o.max_loop_iterations = max_loop_iterations;
}

void ParseJob::override_settings(Scene& parsed) const {
    if (max_trace_level) parsed.settings.max_trace_level = *max_trace_level;
    if (adc_bailout) parsed.settings.adc_bailout = float(*adc_bailout);
}

FixedJob FixedJob::of(const ParseJob& parse, const trace::RenderSettings& settings,
                      const SpaceOptions& options) {
    FixedJob f;
    static_cast<ParseJob&>(f) = parse;
    f.width = settings.width;
    f.height = settings.height;
    f.alpha = settings.alpha;
    f.antialias = settings.antialias;
    f.plan_everything_on = settings.plan_everything_on;
    f.results = options.results;
    f.queue = options.queue;
    f.threads = settings.threads;
    f.boxes = options.boxes;
    f.balanced = options.balanced;
    return f;
}

AnimationValues AnimationValues::of(const parser::ParseOptions& o) {
    return {o.clock,        o.clock_delta,   o.initial_clock, o.final_clock,
            o.frame_number, o.initial_frame, o.final_frame};
}

void AnimationValues::apply_to(parser::ParseOptions& o) const {
    o.clock = clock, o.clock_delta = clock_delta;
    o.initial_clock = initial_clock, o.final_clock = final_clock;
    o.frame_number = frame_number, o.initial_frame = initial_frame;
    o.final_frame = final_frame;
}

void to_json(json& j, const WalkReach& r) {
    auto finite = [](const Point3& v) {
        constexpr Real kMax = std::numeric_limits<Real>::max();
        return std::array<Real, 3>{std::clamp(v.x, -kMax, kMax),
                                   std::clamp(v.y, -kMax, kMax),
                                   std::clamp(v.z, -kMax, kMax)};
    };
    j = {{"box", r.box}, {"lo", finite(r.hull.lo)}, {"hi", finite(r.hull.hi)}};
}

void from_json(const json& j, WalkReach& r) {
    job_fields_detail::read_json("walk_reaches", j.at("box"), r.box);
    std::array<Real, 3> lo, hi;
    job_fields_detail::read_json("walk_reaches", j.at("lo"), lo);
    job_fields_detail::read_json("walk_reaches", j.at("hi"), hi);
    r.hull = Bounds3{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

json to_json(const FixedJob& f) { return job_to_json(f); }

FixedJob fixed_job_from_json(const json& j) {
    FixedJob f;
    job_from_json(j, f);
    check(f);
    return f;
}

json to_json(const FrameJob& frame) { return job_to_json(frame); }

FrameJob frame_job_from_json(const json& j) {
    FrameJob frame;
    job_from_json(j, frame);
    return frame;
}

json to_json(const WorkerJob& job) {
    json j = job_to_json(job);
    j["type"] = "job";
    return j;
}

WorkerJob worker_job_from_json(const json& j) {
    WorkerJob job;
    job_from_json(j, job);
    check(job.fixed);
    if (job.index < 0 || size_t(job.index) >= job.workers.size() ||
        size_t(job.index) >= job.frame.expected_objects.size())
        bad_value("index", j.at("index"));
    for (int o : job.owner)
        if (o < -1 || size_t(o + 1) > job.workers.size())
            bad_value("owner", j.at("owner"));
    return job;
}

}  // namespace povwall::distrib

namespace povwall::trace {
void to_json(nlohmann::json& j, const RenderPlan& plan) {
    j = distrib::plan_to_json(plan);
}
void from_json(const nlohmann::json& j, RenderPlan& plan) {
    plan = distrib::plan_from_json(j);
}
}  // namespace povwall::trace
