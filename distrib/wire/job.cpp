#include "distrib/wire/job.h"

#include "distrib/wire/control.h"

namespace povwall::distrib {

using json = nlohmann::json;

namespace {

[[noreturn]] void bad_value(const std::string& field, const json& value) {
    throw json::other_error::create(501, "bad " + field + ": " + value.dump(), nullptr);
}

std::string results_name(SpaceOptions::Results r) {
    switch (r) {
        case SpaceOptions::Results::Auto:
            return "auto";
        case SpaceOptions::Results::Forward:
            return "forward";
        case SpaceOptions::Results::Parents:
            return "parents";
    }
    return "";
}

SpaceOptions::Results results_of(const json& j) {
    for (auto r : {SpaceOptions::Results::Auto, SpaceOptions::Results::Forward,
                   SpaceOptions::Results::Parents})
        if (j.get<std::string>() == results_name(r)) return r;
    bad_value("results", j);
}

std::string queue_name(QueuePolicy q) {
    switch (q) {
        case QueuePolicy::Priority:
            return "priority";
        case QueuePolicy::Fifo:
            return "fifo";
    }
    return "";
}

QueuePolicy queue_of(const json& j) {
    for (auto q : {QueuePolicy::Priority, QueuePolicy::Fifo})
        if (j.get<std::string>() == queue_name(q)) return q;
    bad_value("queue", j);
}

template <class T>
json optional_json(const std::optional<T>& v) {
    return v ? json(*v) : json();
}

template <class T>
std::optional<T> optional_of(const json& j) {
    if (j.is_null()) return std::nullopt;
    return j.get<T>();
}

}  // namespace

FixedJob FixedJob::of(const SceneSource& source, const trace::RenderSettings& settings,
                      const SpaceOptions& options) {
    FixedJob f;
    f.scene = source.text;
    f.name = source.display_name;
    f.library_paths = source.library_paths;
    f.declares = source.declares;
    f.language_version = source.language_version;
    f.output_file_type = source.output_file_type;
    f.max_loop_iterations = source.max_loop_iterations;
    f.max_trace_level = source.max_trace_level;
    f.adc_bailout = source.adc_bailout;
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

AnimationValues AnimationValues::of(const SceneSource& s) {
    return {s.clock,        s.clock_delta,   s.initial_clock, s.final_clock,
            s.frame_number, s.initial_frame, s.final_frame};
}

void AnimationValues::apply_to(parser::ParseOptions& o) const {
    o.clock = clock, o.clock_delta = clock_delta;
    o.initial_clock = initial_clock, o.final_clock = final_clock;
    o.frame_number = frame_number, o.initial_frame = initial_frame;
    o.final_frame = final_frame;
}

json to_json(const FixedJob& f) {
    return {{"scene", f.scene},
            {"name", f.name},
            {"library_paths", f.library_paths},
            {"declares", f.declares},
            {"language_version", optional_json(f.language_version)},
            {"output_file_type", std::string(1, f.output_file_type)},
            {"max_loop_iterations", f.max_loop_iterations},
            {"max_trace_level", optional_json(f.max_trace_level)},
            {"adc_bailout", optional_json(f.adc_bailout)},
            {"width", f.width},
            {"height", f.height},
            {"alpha", f.alpha},
            {"antialias", f.antialias},
            {"plan_everything_on", f.plan_everything_on},
            {"results", results_name(f.results)},
            {"queue", queue_name(f.queue)},
            {"threads", f.threads},
            {"boxes", f.boxes},
            {"balanced", f.balanced}};
}

FixedJob fixed_job_from_json(const json& j) {
    FixedJob f;
    f.scene = j.at("scene").get<std::string>();
    f.name = j.at("name").get<std::string>();
    f.library_paths = j.at("library_paths").get<std::vector<std::string>>();
    f.declares = j.at("declares").get<std::map<std::string, double>>();
    f.language_version = optional_of<int>(j.at("language_version"));
    const std::string type = j.at("output_file_type").get<std::string>();
    if (type.size() != 1) bad_value("output_file_type", j.at("output_file_type"));
    f.output_file_type = type[0];
    f.max_loop_iterations = j.at("max_loop_iterations").get<uint64_t>();
    f.max_trace_level = optional_of<int>(j.at("max_trace_level"));
    f.adc_bailout = optional_of<double>(j.at("adc_bailout"));
    f.width = j.at("width").get<int>();
    f.height = j.at("height").get<int>();
    if (f.width <= 0 || f.height <= 0 || int64_t(f.width) * f.height > (int64_t(1) << 31))
        bad_value("image size", {f.width, f.height});
    f.alpha = j.at("alpha").get<bool>();
    f.antialias = j.at("antialias").get<bool>();
    f.plan_everything_on = j.at("plan_everything_on").get<bool>();
    f.results = results_of(j.at("results"));
    f.queue = queue_of(j.at("queue"));
    f.threads = j.at("threads").get<int>();
    f.boxes = j.at("boxes").get<std::array<int, 3>>();
    f.balanced = j.at("balanced").get<bool>();
    return f;
}

json to_json(const FrameJob& frame) {
    const AnimationValues& a = frame.animation;
    return {{"animation",
             {{"clock", a.clock},
              {"clock_delta", a.clock_delta},
              {"initial_clock", a.initial_clock},
              {"final_clock", a.final_clock},
              {"frame_number", a.frame_number},
              {"initial_frame", a.initial_frame},
              {"final_frame", a.final_frame}}},
            {"plan", plan_to_json(frame.plan)},
            {"expected_objects", frame.expected_objects}};
}

FrameJob frame_job_from_json(const json& j) {
    FrameJob frame;
    const json& a = j.at("animation");
    AnimationValues& v = frame.animation;
    v.clock = a.at("clock").get<double>();
    v.clock_delta = a.at("clock_delta").get<double>();
    v.initial_clock = a.at("initial_clock").get<double>();
    v.final_clock = a.at("final_clock").get<double>();
    v.frame_number = a.at("frame_number").get<int>();
    v.initial_frame = a.at("initial_frame").get<int>();
    v.final_frame = a.at("final_frame").get<int>();
    frame.plan = plan_from_json(j.at("plan"));
    frame.expected_objects = j.at("expected_objects").get<std::vector<size_t>>();
    return frame;
}

json to_json(const WorkerJob& job) {
    json j = to_json(job.fixed);
    j.update(to_json(job.frame));
    j["type"] = "job";
    j["walls"] = job.walls;
    j["workers"] = job.workers;
    j["inherited"] = job.inherited;
    j["index"] = job.index;
    j["owner"] = job.owner;
    return j;
}

WorkerJob worker_job_from_json(const json& j) {
    WorkerJob job;
    job.fixed = fixed_job_from_json(j);
    job.frame = frame_job_from_json(j);
    job.walls = j.at("walls").get<std::array<std::vector<Real>, 3>>();
    job.workers = j.at("workers").get<std::vector<std::string>>();
    job.inherited = j.at("inherited").get<bool>();
    job.index = j.at("index").get<int>();
    job.owner = j.at("owner").get<std::vector<int>>();
    if (job.index < 0 || size_t(job.index) >= job.workers.size() ||
        size_t(job.index) >= job.frame.expected_objects.size())
        bad_value("index", j.at("index"));
    for (int o : job.owner)
        if (o < -1 || size_t(o + 1) > job.workers.size())
            bad_value("owner", j.at("owner"));
    return job;
}

}  // namespace povwall::distrib
