// Renders rectangles of the image with one prepared scene: what a screen-subdivision
// worker does with each tile it is handed (the scene is prepared once, tiles come one by
// one).
#pragma once

#include <vector>

#include "core/scene.h"
#include "trace/camera_interiors.h"
#include "trace/prepared_scene.h"
#include "trace/render.h"
#include "trace/render_plan.h"
#include "trace/tracer.h"

namespace povwall::trace {

class TileRenderer {
  public:
    TileRenderer(const Scene& scene, const RenderSettings& settings);
    // Pixels [x0, x1) x [y0, y1) into `out` (RGBA floats, row-major, (x1-x0)*(y1-y0)*4),
    // exactly as render_scene() computes them when the rectangle is one of its render
    // blocks (anti-aliasing is decided per block).
    void render(int x0, int y0, int x1, int y1, float* out);
    const TraceCounters& counters() const { return tracer_.counters(); }

  private:
    RenderSettings settings_;
    RenderPlan plan_;
    PreparedScene prepared_;
    CameraInteriors camera_interiors_;
    Tracer tracer_;
    CameraSamples samples_;
    PixelSampler sampler_;
    std::vector<float> rgbt_;
};

}  // namespace povwall::trace
