// The single-process renderer: a scene and output settings in, a working-space image out.
#pragma once

#include <atomic>
#include <cstdint>

#include "core/image.h"
#include "core/scene.h"

namespace povwall::trace {

struct RenderSettings {
    int width = 320, height = 240;
    int threads = 0;  // 0: all cores
    // POV-Ray +A: adaptive supersampling when a pixel differs from its neighbours.
    bool antialias = false;
    double aa_threshold = 0.3;
    int aa_method = 1, aa_depth = 3;
    bool aa_jitter = false;
    double aa_jitter_amount = 1.0;
    bool alpha = false;  // +UA: background contributes transparency
    // Partial render (+SR/+ER/+SC/+EC), 0-based inclusive rows/columns; -1: to the end.
    int first_row = 0, last_row = -1, first_col = 0, last_col = -1;
};

struct RenderStats {
    uint64_t camera_rays = 0, reflected_rays = 0, refracted_rays = 0, shadow_rays = 0;
    uint64_t intersection_tests = 0;
    double prepare_seconds = 0, trace_seconds = 0;
};

Image render_scene(const Scene& scene, const RenderSettings& settings,
                   RenderStats* stats = nullptr);

}  // namespace povwall::trace
