// Render statistics as JSON: what `--stats` writes and what a TCP worker reports to the
// coordinator for each of its boxes, by name (one field added here reaches both).
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>

#include "distrib/space_render.h"
#include "trace/tracer.h"

namespace povwall::distrib {

inline nlohmann::json rays_json(const trace::TraceCounters& c) {
    return {{"camera", c.camera},
            {"reflected", c.reflected},
            {"refracted", c.refracted},
            {"shadow", c.shadow},
            {"radiosity", c.radiosity},
            {"saved_by_adc_bailout", c.adc_saved},
            {"max_trace_level_reached", c.max_level}};
}

inline trace::TraceCounters rays_from_json(const nlohmann::json& j) {
    trace::TraceCounters c;
    c.camera = j.at("camera").get<uint64_t>();
    c.reflected = j.at("reflected").get<uint64_t>();
    c.refracted = j.at("refracted").get<uint64_t>();
    c.shadow = j.at("shadow").get<uint64_t>();
    c.radiosity = j.at("radiosity").get<uint64_t>();
    c.adc_saved = j.at("saved_by_adc_bailout").get<uint64_t>();
    c.max_level = j.at("max_trace_level_reached").get<int>();
    return c;
}

// One box's statistics as `--stats` lists them.
inline nlohmann::json box_stats_json(const BoxStats& b) {
    return {{"objects", b.objects},
            {"resident_bytes", b.resident_bytes},
            {"rays", rays_json(b.rays)},
            {"rays_received", b.rays_received},
            {"results_received", b.results_received},
            {"messages_sent", b.messages_sent},
            {"messages_received", b.messages_received},
            {"bytes_sent", b.bytes_sent},
            {"bytes_received", b.bytes_received},
            {"peak_queue", b.peak_queue},
            {"peak_waiting_parents", b.peak_parents},
            {"busy_seconds", b.busy_seconds},
            {"idle_seconds", b.idle_seconds}};
}

// The inverse of box_stats_json (the region is not in it); throws
// nlohmann::json::exception naming a missing or mistyped field.
inline BoxStats box_stats_from_json(const nlohmann::json& j) {
    BoxStats b;
    b.objects = j.at("objects").get<size_t>();
    b.resident_bytes = j.at("resident_bytes").get<size_t>();
    b.rays = rays_from_json(j.at("rays"));
    b.rays_received = j.at("rays_received").get<uint64_t>();
    b.results_received = j.at("results_received").get<uint64_t>();
    b.messages_sent = j.at("messages_sent").get<uint64_t>();
    b.messages_received = j.at("messages_received").get<uint64_t>();
    b.bytes_sent = j.at("bytes_sent").get<uint64_t>();
    b.bytes_received = j.at("bytes_received").get<uint64_t>();
    b.peak_queue = j.at("peak_queue").get<size_t>();
    b.peak_parents = j.at("peak_waiting_parents").get<size_t>();
    b.busy_seconds = j.at("busy_seconds").get<double>();
    b.idle_seconds = j.at("idle_seconds").get<double>();
    return b;
}

// Adds a copy's report to `out`: the counts and times of a box's copies (one per team)
// add up, the peaks are the largest copy's.
inline void add_box_stats(BoxStats& out, const BoxStats& copy) {
    out.objects = copy.objects;
    out.resident_bytes = copy.resident_bytes;
    out.rays += copy.rays;
    out.rays_received += copy.rays_received;
    out.results_received += copy.results_received;
    out.messages_sent += copy.messages_sent;
    out.messages_received += copy.messages_received;
    out.bytes_sent += copy.bytes_sent;
    out.bytes_received += copy.bytes_received;
    out.peak_queue = std::max(out.peak_queue, copy.peak_queue);
    out.peak_parents = std::max(out.peak_parents, copy.peak_parents);
    out.busy_seconds += copy.busy_seconds;
    out.idle_seconds += copy.idle_seconds;
}

}  // namespace povwall::distrib
