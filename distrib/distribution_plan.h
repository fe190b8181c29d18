// How a render is spread over workers, decided once per scene from its size and the
// memory a worker may use (issue: "leave out what a given scene does not need"):
//
//   single: one process; its threads take image rows as they finish (screen subdivision
//           inside one process: every thread shares the one copy of the scene);
//   screen: worker processes each hold the whole scene and take image tiles as they
//   finish
//           (distrib/screen_render.h);
//   space:  virtual walls cut the scene into black boxes, each holding only its objects.
//
// auto picks screen subdivision when the whole prepared scene fits the worker memory
// budget (in this process's threads, or over --procs worker processes), else the fewest
// balanced boxes whose largest local scene fits it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/scene.h"
#include "distrib/space_render.h"

namespace povwall::distrib {

enum class RenderMode { Auto, Single, Screen, Space };

struct DistributionRequest {
    RenderMode mode = RenderMode::Auto;
    std::string boxes;         // --boxes as given (empty: not given)
    size_t worker_memory = 0;  // bytes; 0: half of this machine's memory
    int threads = 0;           // 0: all cores
    int procs = 0;             // screen worker processes (0: not asked for)
};

struct DistributionPlan {
    RenderMode mode = RenderMode::Single;
    SpaceOptions space;            // mode == Space
    size_t scene_bytes = 0;        // estimated prepared size of the whole scene
    size_t largest_box_bytes = 0;  // estimated, mode == Space
    size_t worker_memory = 0;
    int threads = 1;
    int procs = 0;                     // mode == Screen: worker processes
    std::vector<std::string> reasons;  // plain words, for --explain
};

struct DistributionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses "4x4x4" (equal slabs), "N" (balanced N x N x N) or "auto". Throws
// DistributionError on a bad value.
SpaceOptions parse_boxes(const std::string& spec);

// Parses a memory size: "512M", "2G", "300000K", "1.5G", plain bytes.
size_t parse_memory_size(const std::string& text);

DistributionPlan plan_distribution(const Scene& scene,
                                   const DistributionRequest& request);

// "12.3 MB"
std::string format_bytes(size_t bytes);

}  // namespace povwall::distrib
