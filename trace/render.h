// The single-process renderer: a scene and output settings in, a working-space image out.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/image.h"
#include "core/scene.h"
#include "trace/pixel_sampler.h"
#include "trace/render_plan.h"
#include "trace/tracer.h"

namespace povwall::trace {

// Live counters a progress display (or the message of an interrupted render) reads while
// a render runs (renderers add to them from any thread). Work is counted in pixel passes:
// every pass over the image (the first samples, an anti-aliasing pass) adds its pixels to
// the total when it starts.
struct RenderProgress {
    std::atomic<uint64_t> pixels_done{0};
    std::atomic<uint64_t> pixels_total{0};
    std::atomic<uint64_t> rays{0};
    // What comes before the first pass, which can take long on a large scene.
    enum class Stage : uint8_t {
        Preparing,
        BuildingOctree,
        ShootingPhotons,  // the photon map, before the first pass
        Pretracing,       // radiosity's pretrace passes
        Tracing
    };
    std::atomic<Stage> stage{Stage::Preparing};
    // Preparing: the scene's top-level objects; BuildingOctree: the bounded primitives
    // being sorted into it.
    std::atomic<uint64_t> objects{0};

    // A pass over `pixels` pixels begins.
    void start_pass(uint64_t pixels) {
        pixels_total += pixels;
        stage = Stage::Tracing;
    }
    void reset() {
        pixels_done = pixels_total = rays = objects = 0;
        stage = Stage::Preparing;
    }
};

struct RenderSettings {
    int width = 320, height = 240;
    int threads = 0;  // 0: all cores
    // POV-Ray +A: adaptive supersampling when a pixel differs from its neighbours.
    bool antialias = false;
    double aa_threshold = 0.3;
    int aa_method = 1, aa_depth = 3;
    bool aa_jitter = true;  // POV-Ray jitters AA samples unless -J
    double aa_jitter_amount = 1.0;
    double aa_gamma = 2.5;  // +AG: colours compared after this gamma (<= 0: none)
    int block_size = 32;    // +BS: anti-aliasing is decided per block of this size
    bool alpha = false;     // +UA: background contributes transparency
    int quality = 9;        // +Q (trace::Quality)
    // Partial render (+SR/+ER/+SC/+EC), 0-based inclusive rows/columns; -1: to the end.
    int first_row = 0, last_row = -1, first_col = 0, last_col = -1;
    // --plan all: leave nothing out (tests that the render plan changes no pixel).
    bool plan_everything_on = false;
    RenderProgress* progress = nullptr;  // optional, not owned
};

struct RenderStats {
    TraceCounters rays;
    uint64_t intersection_tests = 0;
    double prepare_seconds = 0, trace_seconds = 0;
    // What the prepared scene holds: octree or flat list, and its size.
    bool octree_flat = false;
    int octree_nodes = 0;
    int octree_dense_top = 0;  // levels walked as a dense array of cells
    size_t resident_bytes = 0;
};

class Tracer;
class CameraInteriors;
class FocalBlur;

// Camera samples traced with `tracer`: red, green, blue and the background's transmit
// (only with +UA; 1 where the camera sees nothing, as POV-Ray). With focal blur a sample
// is the average of its rays (focal_blur.h).
class CameraSamples final : public SampleSource {
  public:
    CameraSamples(Tracer& tracer, const Camera& camera, const CameraInteriors& interiors,
                  const RenderSettings& settings);
    ~CameraSamples();
    bool sample(Real x, Real y, float* rgbt) override;  // always true

  private:
    // One camera ray's colour as a sample's (false: the camera has no such ray).
    bool trace(const std::optional<Ray>& ray, float* rgbt);
    Tracer& tracer_;
    const Camera& camera_;
    const CameraInteriors& interiors_;
    const RenderSettings& settings_;
    std::unique_ptr<FocalBlur> blur_;  // when the camera blurs
};

// A pixel as written: rgbt to rgba (alpha 1 - transmit with +UA, else opaque).
inline void finish_pixel(const float* rgbt, bool alpha, float* rgba) {
    rgba[0] = rgbt[0];
    rgba[1] = rgbt[1];
    rgba[2] = rgbt[2];
    rgba[3] = alpha ? 1.0f - std::clamp(rgbt[3], 0.0f, 1.0f) : 1.0f;
}
// One camera sample at image position (px, py): RGBA into `out`, as every renderer writes
// it (nothing seen, e.g. a fisheye's corners: black and transparent; background transmit
// only with +UA).
// `interiors`: what the camera ray starts inside of.
void trace_camera_sample(Tracer& tracer, const Camera& camera,
                         const CameraInteriors& interiors, Real px, Real py,
                         const RenderSettings& settings, float* out);

// Pixels whose centre has no camera ray (a fisheye's corners): black, and transparent
// with +UA, as trace_camera_sample gives them. The black-box drivers, which add up what
// the rays they emitted bring back, finish their images with this.
void finish_pixels_without_camera_ray(Image& image, const Camera& camera,
                                      const RenderSettings& settings);

// `plan`: the scene's render plan when the caller made it already (else made here).
Image render_scene(const Scene& scene, const RenderSettings& settings,
                   RenderStats* stats = nullptr, const RenderPlan* plan = nullptr);

}  // namespace povwall::trace
