// Render statistics as JSON: what `--stats` writes and what a TCP worker reports to the
// coordinator for each of its boxes, by name (one field added here reaches both).
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>
#include <type_traits>

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

// One box's statistics as `--stats` lists them (BoxStats::visit_pairs).
inline nlohmann::json box_stats_json(const BoxStats& b) {
    nlohmann::json j = {{"rays", rays_json(b.rays)}};
    BoxStats::visit_pairs(
        b, b, [&](const char* name, const auto& field, const auto&, BoxStats::Combine) {
            j[name] = field;
        });
    return j;
}

// The inverse of box_stats_json (the region is not in it); throws
// nlohmann::json::exception naming a missing or mistyped field.
inline BoxStats box_stats_from_json(const nlohmann::json& j) {
    BoxStats b;
    b.rays = rays_from_json(j.at("rays"));
    BoxStats::visit_pairs(b, b,
                          [&](const char* name, auto& field, auto&, BoxStats::Combine) {
                              field = j.at(name).get<std::decay_t<decltype(field)>>();
                          });
    return b;
}

// Adds a copy's report to `out`: the counts and times of a box's copies (one per team)
// add up, the peaks are the largest copy's.
inline void add_box_stats(BoxStats& out, const BoxStats& copy) {
    out.rays += copy.rays;
    BoxStats::visit_pairs(
        out, copy, [](const char*, auto& into, const auto& x, BoxStats::Combine how) {
            switch (how) {
                case BoxStats::Combine::Count:
                case BoxStats::Combine::Time:
                    into += x;
                    break;
                case BoxStats::Combine::Peak:
                    into = std::max(into, x);
                    break;
                case BoxStats::Combine::Size:
                    into = x;
                    break;
            }
        });
}

// What a box's lane counted, added to `into` (its counts only: the box's times, peaks and
// sizes are its own).
inline void add_lane_counts(BoxStats& into, const BoxStats& lane) {
    into.rays += lane.rays;
    BoxStats::visit_pairs(
        into, lane, [](const char*, auto& sum, const auto& x, BoxStats::Combine how) {
            if (how == BoxStats::Combine::Count) sum += x;
        });
}

}  // namespace povwall::distrib
