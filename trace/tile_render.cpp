#include "trace/tile_render.h"

#include <algorithm>
#include <optional>

#include "trace/camera.h"

namespace povwall::trace {

TileRenderer::TileRenderer(const Scene& scene, const RenderSettings& settings)
    : scene_(scene),
      settings_(settings),
      plan_(make_render_plan(scene, settings.plan_everything_on, settings.quality)),
      prepared_(scene, &plan_, PrepareOptions{settings.threads, true}),
      camera_interiors_(scene),
      tracer_(prepared_) {
    prepared_.set_alpha_background(settings.alpha);
}

void TileRenderer::render(int x0, int y0, int x1, int y1, float* out) {
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x, out += 4)
            trace_camera_sample(tracer_, scene_.camera, camera_interiors_, x + 0.5,
                                y + 0.5, settings_, out);
    }
}

}  // namespace povwall::trace
