#include "trace/ties.h"

#include "trace/camera_interiors.h"
#include "trace/prepared_scene.h"
#include "trace/render_plan.h"
#include "trace/tracer.h"

namespace povwall::trace {

TieProbe::TieProbe(const Scene& scene, const RenderSettings& settings,
                   const TieProbeOptions& options)
    : scene_(scene), settings_(settings) {
    settings_.threads = 1;
    // Every ray the render would trace (nothing left out), so that a tie on a
    // reflection or refraction the plan would drop is still found.
    const RenderPlan plan = make_render_plan(scene, true, settings.quality);
    PrepareOptions prepare;
    prepare.threads = 1;
    prepared_ = std::make_unique<PreparedScene>(scene, &plan, prepare);
    prepared_->set_alpha_background(settings.alpha);
    interiors_ = std::make_unique<CameraInteriors>(scene);
    tracer_ = std::make_unique<Tracer>(*prepared_);
    tracer_->set_tie_probe(options.tolerance, options.levels);
}

TieProbe::~TieProbe() = default;

TieProbe::Kind TieProbe::pixel(int x, int y) {
    const uint64_t ties = tracer_->ties(), patterns = tracer_->pattern_ties();
    float rgba[4];
    trace_camera_sample(*tracer_, scene_.camera, *interiors_, x + 0.5, y + 0.5, settings_,
                        rgba);
    if (tracer_->ties() > ties) return Kind::Surface;
    if (tracer_->pattern_ties() > patterns) return Kind::Pattern;
    return Kind::None;
}

}  // namespace povwall::trace
