#include "trace/tile_render.h"

#include <algorithm>

#include "trace/photon_map.h"
#include "trace/radiosity/pretrace.h"

namespace povwall::trace {

TileRenderer::TileRenderer(const Scene& scene, const RenderSettings& settings)
    : settings_(settings),
      plan_(make_render_plan(scene, settings.plan_everything_on, settings.quality)),
      prepared_(scene, &plan_, PrepareOptions{settings.threads, true}),
      camera_interiors_(scene),
      tracer_(prepared_),
      samples_(tracer_, scene.camera, camera_interiors_, settings_),
      sampler_(sampler_settings(settings, scene)) {
    prepared_.set_alpha_background(settings.alpha);
    // Each screen-mode worker builds the map from the whole scene: the same map as in
    // one process (trace/photon_map.h).
    prepared_.set_photons(build_photon_map(prepared_));
    // ... and runs the whole radiosity pretrace: the same cache as in one process
    // (trace/radiosity/pretrace.h). The tracer made before it gets its gatherer now.
    prepared_.set_radiosity(radiosity::run_pretrace(prepared_, camera_interiors_,
                                                    settings_, settings_.threads));
    if (prepared_.radiosity()) tracer_.attach_radiosity();
}

void TileRenderer::render(int x0, int y0, int x1, int y1, float* out) {
    const PixelBlock block{x0, y0, x1, y1};
    tracer_.begin_block();
    rgbt_.resize(size_t(std::max(0, block.pixels())) * 4);
    sampler_.render_block(block, samples_, rgbt_.data());
    for (size_t p = 0; p < rgbt_.size(); p += 4)
        finish_pixel(&rgbt_[p], settings_.alpha, out + p);
}

}  // namespace povwall::trace
