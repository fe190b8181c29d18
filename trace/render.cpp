#include "trace/render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <thread>
#include <vector>

#include "trace/camera.h"
#include "trace/camera_interiors.h"
#include "trace/focal_blur.h"
#include "trace/photon_map.h"
#include "trace/prepared_scene.h"
#include "trace/radiosity/pretrace.h"
#include "trace/tracer.h"

namespace povwall::trace {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

CameraSamples::CameraSamples(Tracer& tracer, const Camera& camera,
                             const CameraInteriors& interiors,
                             const RenderSettings& settings)
    : tracer_(tracer), camera_(camera), interiors_(interiors), settings_(settings) {
    if (FocalBlur::enabled(camera))
        blur_ = std::make_unique<FocalBlur>(camera, tracer.scene().pattern_env());
}

CameraSamples::~CameraSamples() = default;

bool CameraSamples::sample(Real x, Real y, float* rgbt) {
    if (blur_) {
        return average_focal_rays(
            *blur_,
            [&](int k, float* c) {
                return trace(focal_blur_ray(*blur_, x, y, k, settings_.width,
                                            settings_.height),
                             c)
                           ? RayAnswer::Traced
                           : RayAnswer::NoRay;
            },
            rgbt);
    }
    if (!trace(camera_ray_pov(camera_, x, y, settings_.width, settings_.height), rgbt)) {
        rgbt[0] = rgbt[1] = rgbt[2] = 0;
        rgbt[3] = 1;
    }
    return true;
}

bool CameraSamples::trace(const std::optional<Ray>& ray, float* rgbt) {
    if (!ray) return false;
    TraceRay r;
    r.ray = *ray;
    interiors_.seed(r.ray.origin, r.interiors);
    const TraceResult res = tracer_.trace(r);
    rgbt[0] = res.colour.r;
    rgbt[1] = res.colour.g;
    rgbt[2] = res.colour.b;
    // Background transmit counts only when writing alpha (POV-Ray drops it otherwise).
    rgbt[3] = settings_.alpha ? std::clamp(res.transmit, 0.0f, 1.0f) : 0.0f;
    return true;
}

void trace_camera_sample(Tracer& tracer, const Camera& camera,
                         const CameraInteriors& interiors, Real px, Real py,
                         const RenderSettings& settings, float* out) {
    float rgbt[4];
    CameraSamples(tracer, camera, interiors, settings).sample(px - 0.5, py - 0.5, rgbt);
    finish_pixel(rgbt, settings.alpha, out);
}

void finish_pixels_without_camera_ray(Image& image, const Camera& camera,
                                      const RenderSettings& settings) {
    if (!settings.alpha) return;  // black and opaque already: nothing added up there
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (camera_ray(camera, x + 0.5, y + 0.5, settings.width, settings.height))
                continue;
            float* p = image.pixel(x, y);
            p[0] = p[1] = p[2] = p[3] = 0;
        }
    }
}

Image render_scene(const Scene& scene, const RenderSettings& settings, RenderStats* stats,
                   const RenderPlan* given_plan) {
    auto t0 = Clock::now();
    if (settings.progress) {
        settings.progress->objects = scene.objects.size();
        settings.progress->stage = RenderProgress::Stage::Preparing;
    }
    std::optional<RenderPlan> own_plan;
    const RenderPlan& plan =
        given_plan ? *given_plan
                   : own_plan.emplace(make_render_plan(scene, settings.plan_everything_on,
                                                       settings.quality));
    PrepareOptions prepare;
    prepare.threads = settings.threads;
    prepare.progress = settings.progress;
    PreparedScene prepared(scene, &plan, prepare);
    prepared.set_alpha_background(settings.alpha);
    if (settings.progress && scene.settings.photons)
        settings.progress->stage = RenderProgress::Stage::ShootingPhotons;
    prepared.set_photons(build_photon_map(prepared));
    const CameraInteriors camera_interiors(scene);
    if (settings.progress && scene.settings.radiosity)
        settings.progress->stage = RenderProgress::Stage::Pretracing;
    prepared.set_radiosity(
        radiosity::run_pretrace(prepared, camera_interiors, settings, settings.threads));
    auto t1 = Clock::now();
    const int W = settings.width, H = settings.height;
    Image image(W, H);
    int threads = settings.threads > 0
                      ? settings.threads
                      : int(std::max(1u, std::thread::hardware_concurrency()));
    // POV-Ray's render blocks, handed out in its order to the threads; a block's pixels
    // depend only on the block.
    const std::vector<PixelBlock> blocks =
        render_blocks(render_area(settings), settings.block_size);
    const SamplerSettings sampling = sampler_settings(settings, scene);
    std::vector<TraceCounters> counters(static_cast<size_t>(threads));
    std::vector<uint64_t> tests(static_cast<size_t>(threads), 0);
    RenderProgress* const progress = settings.progress;
    if (progress) {
        uint64_t pixels = 0;
        for (const PixelBlock& b : blocks) pixels += uint64_t(b.pixels());
        progress->start_pass(pixels);
    }
    std::atomic<size_t> next_block{0};
    auto work = [&](int ti) {
        Tracer tracer(prepared);
        CameraSamples samples(tracer, scene.camera, camera_interiors, settings);
        PixelSampler sampler(sampling);
        std::vector<float> rgbt;
        uint64_t reported = 0;
        for (size_t k; (k = next_block.fetch_add(1)) < blocks.size();) {
            const PixelBlock& b = blocks[k];
            tracer.begin_block();
            rgbt.resize(size_t(b.pixels()) * 4);
            sampler.render_block(b, samples, rgbt.data());
            const float* in = rgbt.data();
            for (int y = b.y0; y < b.y1; ++y)
                for (int x = b.x0; x < b.x1; ++x, in += 4)
                    finish_pixel(in, settings.alpha, image.pixel(x, y));
            if (progress) {
                const TraceCounters& c = tracer.counters();
                const uint64_t rays = c.camera + c.reflected + c.refracted + c.shadow;
                progress->rays += rays - reported;
                progress->pixels_done += uint64_t(b.pixels());
                reported = rays;
            }
        }
        counters[size_t(ti)] += tracer.counters();
        tests[size_t(ti)] += tracer.intersection_tests();
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work, i);
    work(0);
    for (auto& t : pool) t.join();
    auto t2 = Clock::now();
    if (stats) {
        for (int i = 0; i < threads; ++i) {
            stats->rays += counters[i];
            stats->intersection_tests += tests[i];
        }
        stats->prepare_seconds = std::chrono::duration<double>(t1 - t0).count();
        stats->octree_flat = prepared.tree().stats().flat;
        stats->octree_nodes = prepared.tree().stats().nodes;
        stats->octree_dense_top = prepared.tree().stats().dense_top;
        stats->resident_bytes = prepared.resident_bytes();
        stats->trace_seconds = std::chrono::duration<double>(t2 - t1).count();
    }
    return image;
}

}  // namespace povwall::trace
