#include "trace/render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "trace/camera.h"
#include "trace/tracer.h"

namespace povwall::trace {
namespace {

using Clock = std::chrono::steady_clock;

// POV-Ray compares neighbours for anti-aliasing after encoding with gamma 2.5.
float aa_encode(float v) { return std::pow(std::max(0.0f, v), 1.0f / 2.5f); }

}  // namespace

Image render_scene(const Scene& scene, const RenderSettings& settings, RenderStats* stats) {
    auto t0 = Clock::now();
    PreparedScene prepared(scene);
    auto t1 = Clock::now();
    const int W = settings.width, H = settings.height;
    Image image(W, H);
    const int first_row = std::clamp(settings.first_row, 0, H);
    const int last_row = settings.last_row < 0 ? H - 1 : std::min(settings.last_row, H - 1);
    const int first_col = std::clamp(settings.first_col, 0, W);
    const int last_col = settings.last_col < 0 ? W - 1 : std::min(settings.last_col, W - 1);
    int threads = settings.threads > 0 ? settings.threads
                                       : int(std::max(1u, std::thread::hardware_concurrency()));

    // Background transmit shows only when writing alpha (POV-Ray drops it otherwise).
    auto sample = [&](Tracer& tracer, Real px, Real py, float* out) {
        TraceRay r;
        r.ray = camera_ray(scene.camera, px, py, W, H);
        TraceResult res = tracer.trace(r);
        out[0] = res.colour.r;
        out[1] = res.colour.g;
        out[2] = res.colour.b;
        out[3] = settings.alpha ? 1.0f - std::clamp(res.transmit, 0.0f, 1.0f) : 1.0f;
    };

    std::atomic<int> next_row{first_row};
    std::vector<TraceCounters> counters(threads);
    std::vector<uint64_t> tests(threads, 0);
    auto work = [&](int ti) {
        Tracer tracer(prepared);
        for (;;) {
            int y = next_row.fetch_add(1);
            if (y > last_row) break;
            for (int x = first_col; x <= last_col; ++x) {
                sample(tracer, x + 0.5, y + 0.5, image.pixel(x, y));
            }
        }
        counters[ti] = tracer.counters();
        tests[ti] = tracer.intersection_tests();
    };
    auto run_pool = [&](auto&& fn) {
        std::vector<std::thread> pool;
        for (int i = 1; i < threads; ++i) pool.emplace_back(fn, i);
        fn(0);
        for (auto& t : pool) t.join();
    };
    run_pool(work);

    if (settings.antialias) {
        // Method 1: a pixel differing from its left or upper neighbour by the threshold is
        // supersampled on a depth x depth grid plus its first sample (as is that neighbour).
        std::vector<uint8_t> need(size_t(W) * H, 0);
        auto dist = [&](const float* a, const float* b) {
            float d = 0;
            for (int c = 0; c < 3; ++c) d += std::fabs(aa_encode(a[c]) - aa_encode(b[c]));
            return d;
        };
        for (int y = first_row; y <= last_row; ++y) {
            for (int x = first_col; x <= last_col; ++x) {
                const float* p = image.pixel(x, y);
                if (x > first_col && dist(p, image.pixel(x - 1, y)) >= settings.aa_threshold) {
                    need[size_t(y) * W + x] = need[size_t(y) * W + x - 1] = 1;
                }
                if (y > first_row && dist(p, image.pixel(x, y - 1)) >= settings.aa_threshold) {
                    need[size_t(y) * W + x] = need[size_t(y - 1) * W + x] = 1;
                }
            }
        }
        const int d = std::max(1, settings.aa_depth);
        std::atomic<int> aa_row{first_row};
        auto aa_work = [&](int) {
            Tracer tracer(prepared);
            for (;;) {
                int y = aa_row.fetch_add(1);
                if (y > last_row) break;
                for (int x = first_col; x <= last_col; ++x) {
                    if (!need[size_t(y) * W + x]) continue;
                    float* p = image.pixel(x, y);
                    float acc[4] = {p[0], p[1], p[2], p[3]};
                    for (int j = 0; j < d; ++j) {
                        for (int i = 0; i < d; ++i) {
                            float s[4];
                            sample(tracer, x + (i + 0.5) / d, y + (j + 0.5) / d, s);
                            for (int c = 0; c < 4; ++c) acc[c] += s[c];
                        }
                    }
                    for (int c = 0; c < 4; ++c) p[c] = acc[c] / float(d * d + 1);
                }
            }
        };
        run_pool(aa_work);
    }
    auto t2 = Clock::now();
    if (stats) {
        for (int i = 0; i < threads; ++i) {
            stats->camera_rays += counters[i].camera;
            stats->reflected_rays += counters[i].reflected;
            stats->refracted_rays += counters[i].refracted;
            stats->shadow_rays += counters[i].shadow;
            stats->intersection_tests += tests[i];
        }
        stats->prepare_seconds = std::chrono::duration<double>(t1 - t0).count();
        stats->trace_seconds = std::chrono::duration<double>(t2 - t1).count();
    }
    return image;
}

}  // namespace povwall::trace
