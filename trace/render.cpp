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
#include "trace/tracer.h"

namespace povwall::trace {
namespace {

using Clock = std::chrono::steady_clock;

// POV-Ray compares neighbours for anti-aliasing after encoding with gamma 2.5.
float aa_encode(float v) { return std::pow(std::max(0.0f, v), 1.0f / 2.5f); }

// Colour distance for the anti-aliasing tests: summed channel differences after the AA
// gamma, plus the alpha difference (constant 1 without +UA, so it then adds nothing), as
// POV-Ray's RGBT distance.
float aa_distance(const float* a, const float* b) {
    float d = std::fabs(a[3] - b[3]);
    for (int c = 0; c < 3; ++c) d += std::fabs(aa_encode(a[c]) - aa_encode(b[c]));
    return d;
}

}  // namespace

// A hash of the sample's image position, so a render is repeatable and a position shared
// by two pixels gets the same offset (POV-Ray's jitter is likewise a fixed function of
// the position, from its own table).
void aa_jitter_offset(Real px, Real py, Real& jx, Real& jy) {
    auto mix = [](uint64_t z) {
        z += 0x9e3779b97f4a7c15ull;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    // Sample positions are at least 2^-9 pixel apart (+AM2 +R9); quantise finer.
    const auto qx = uint64_t(int64_t(std::llround(px * 4096.0)));
    const auto qy = uint64_t(int64_t(std::llround(py * 4096.0)));
    const uint64_t h = mix(qx * 0x632be59bd9b4e019ull ^ mix(qy));
    jx = Real(h >> 40) / Real(1ull << 24) - 0.5;
    jy = Real((h >> 16) & 0xffffffull) / Real(1ull << 24) - 0.5;
}

void trace_camera_sample(Tracer& tracer, const Camera& camera,
                         const CameraInteriors& interiors, Real px, Real py,
                         const RenderSettings& settings, float* out) {
    std::optional<Ray> ray = camera_ray(camera, px, py, settings.width, settings.height);
    if (!ray) {
        out[0] = out[1] = out[2] = 0;
        out[3] = settings.alpha ? 0.0f : 1.0f;
        return;
    }
    TraceRay r;
    r.ray = *ray;
    interiors.seed(r.ray.origin, r.interiors);
    TraceResult res = tracer.trace(r);
    out[0] = res.colour.r;
    out[1] = res.colour.g;
    out[2] = res.colour.b;
    // Background transmit shows only when writing alpha (POV-Ray drops it otherwise).
    out[3] = settings.alpha ? 1.0f - std::clamp(res.transmit, 0.0f, 1.0f) : 1.0f;
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

Image render_scene(const Scene& scene, const RenderSettings& settings,
                   RenderStats* stats) {
    auto t0 = Clock::now();
    if (settings.progress) {
        settings.progress->objects = scene.objects.size();
        settings.progress->stage = RenderProgress::Stage::Preparing;
    }
    const RenderPlan plan =
        make_render_plan(scene, settings.plan_everything_on, settings.quality);
    PrepareOptions prepare;
    prepare.threads = settings.threads;
    prepare.progress = settings.progress;
    PreparedScene prepared(scene, &plan, prepare);
    prepared.set_alpha_background(settings.alpha);
    const CameraInteriors camera_interiors(scene);
    auto t1 = Clock::now();
    const int W = settings.width, H = settings.height;
    Image image(W, H);
    const int first_row = std::clamp(settings.first_row, 0, H);
    const int last_row =
        settings.last_row < 0 ? H - 1 : std::min(settings.last_row, H - 1);
    const int first_col = std::clamp(settings.first_col, 0, W);
    const int last_col =
        settings.last_col < 0 ? W - 1 : std::min(settings.last_col, W - 1);
    int threads = settings.threads > 0
                      ? settings.threads
                      : int(std::max(1u, std::thread::hardware_concurrency()));

    auto sample = [&](Tracer& tracer, Real px, Real py, float* out) {
        trace_camera_sample(tracer, scene.camera, camera_interiors, px, py, settings,
                            out);
    };

    auto run_pool = [&](auto&& fn) {
        std::vector<std::thread> pool;
        for (int i = 1; i < threads; ++i) pool.emplace_back(fn, i);
        fn(0);
        for (auto& t : pool) t.join();
    };
    // Rows [first, last] handed out one at a time to the threads; counters summed per
    // thread.
    std::vector<TraceCounters> counters(threads);
    std::vector<uint64_t> tests(threads, 0);
    RenderProgress* const progress = settings.progress;
    auto rays_of = [](const TraceCounters& c) {
        return c.camera + c.reflected + c.refracted + c.shadow;
    };
    auto over_rows = [&](int first, int last, auto&& per_row) {
        std::atomic<int> next_row{first};
        const uint64_t row_pixels = uint64_t(std::max(0, last_col - first_col + 1));
        if (progress) progress->start_pass(row_pixels * std::max(0, last - first + 1));
        run_pool([&](int ti) {
            Tracer tracer(prepared);
            uint64_t reported = 0;
            for (int y; (y = next_row.fetch_add(1)) <= last;) {
                per_row(tracer, y);
                if (progress) {
                    const uint64_t rays = rays_of(tracer.counters());
                    progress->rays += rays - reported;
                    progress->pixels_done += row_pixels;
                    reported = rays;
                }
            }
            counters[ti] += tracer.counters();
            tests[ti] += tracer.intersection_tests();
        });
    };
    const bool recursive_aa = settings.antialias && settings.aa_method == 2;
    const double jitter_amount =
        settings.aa_jitter ? std::clamp(settings.aa_jitter_amount, 0.0, 1.0) : 0.0;

    if (!recursive_aa) {
        over_rows(first_row, last_row, [&](Tracer& tracer, int y) {
            for (int x = first_col; x <= last_col; ++x) {
                sample(tracer, x + 0.5, y + 0.5, image.pixel(x, y));
            }
        });
    }

    if (settings.antialias && !recursive_aa) {
        // Method 1: a pixel differing from its left or upper neighbour by the threshold
        // is supersampled on a depth x depth grid plus its first sample (as is that
        // neighbour).
        std::vector<uint8_t> need(size_t(W) * H, 0);
        for (int y = first_row; y <= last_row; ++y) {
            for (int x = first_col; x <= last_col; ++x) {
                const float* p = image.pixel(x, y);
                if (x > first_col &&
                    aa_distance(p, image.pixel(x - 1, y)) >= settings.aa_threshold) {
                    need[size_t(y) * W + x] = need[size_t(y) * W + x - 1] = 1;
                }
                if (y > first_row &&
                    aa_distance(p, image.pixel(x, y - 1)) >= settings.aa_threshold) {
                    need[size_t(y) * W + x] = need[size_t(y - 1) * W + x] = 1;
                }
            }
        }
        const int d = std::clamp(settings.aa_depth, 1, 9);
        const Real jitter_scale = jitter_amount / d;
        over_rows(first_row, last_row, [&](Tracer& tracer, int y) {
            for (int x = first_col; x <= last_col; ++x) {
                if (!need[size_t(y) * W + x]) continue;
                float* p = image.pixel(x, y);
                float acc[4] = {p[0], p[1], p[2], p[3]};
                for (int j = 0; j < d; ++j) {
                    for (int i = 0; i < d; ++i) {
                        Real sx = x + (i + 0.5) / d, sy = y + (j + 0.5) / d;
                        if (jitter_scale > 0) {
                            Real jx, jy;
                            aa_jitter_offset(sx, sy, jx, jy);
                            sx += jx * jitter_scale;
                            sy += jy * jitter_scale;
                        }
                        float s[4];
                        sample(tracer, sx, sy, s);
                        for (int c = 0; c < 4; ++c) acc[c] += s[c];
                    }
                }
                for (int c = 0; c < 4; ++c) p[c] = acc[c] / float(d * d + 1);
            }
        });
    }

    if (recursive_aa) {
        // Method 2, POV-Ray 3.7's recursive subdivision: sample every pixel corner, then
        // per pixel, while depth remains and any two of a square's four corners differ by
        // the threshold, sample the edge midpoints and centre and recurse into the four
        // quarters; a square's colour is the mean of its corners (or of its quarters).
        // Midpoint samples are jittered by amount / (2^depth + 1); corners never are.
        const int depth = std::clamp(settings.aa_depth, 1, 9);
        const int cols = last_col - first_col + 2, rows = last_row - first_row + 2;
        std::vector<float> corners(size_t(cols) * rows * 4);
        auto corner = [&](int x, int y) {
            return &corners[(size_t(y - first_row) * cols + (x - first_col)) * 4];
        };
        over_rows(first_row, last_row + 1, [&](Tracer& tracer, int y) {
            for (int x = first_col; x <= last_col + 1; ++x)
                sample(tracer, x, y, corner(x, y));
        });
        const size_t full = size_t(1) << depth, side = full + 1;
        const Real jitter_scale = jitter_amount / Real(full + 1);
        over_rows(first_row, last_row, [&](Tracer& tracer, int y) {
            // Samples of the current pixel on a (2^depth + 1)^2 grid, reused by the
            // quarters.
            std::vector<float> grid(side * side * 4);
            std::vector<uint8_t> have(side * side);
            auto at = [&](size_t bx, size_t by) { return &grid[(by * side + bx) * 4]; };
            auto ensure = [&](size_t bx, size_t by, Real sx, Real sy) {
                if (have[by * side + bx]) return;
                if (jitter_scale > 0) {
                    Real jx, jy;
                    aa_jitter_offset(sx, sy, jx, jy);
                    sx += jx * jitter_scale;
                    sy += jy * jitter_scale;
                }
                sample(tracer, sx, sy, at(bx, by));
                have[by * side + bx] = 1;
            };
            // (cx, cy): centre of the square, half: its half width, (bx, by) its top-left
            // grid index and step its grid width; out receives the square's colour.
            auto subdivide = [&](auto&& self, Real cx, Real cy, Real half, size_t bx,
                                 size_t by, size_t step, int level, float* out) -> void {
                const float* c[4] = {at(bx, by), at(bx, by + step), at(bx + step, by),
                                     at(bx + step, by + step)};
                bool split = false;
                for (int i = 0; i < 4 && level > 0 && !split; ++i) {
                    for (int j = i + 1; j < 4; ++j) {
                        if (aa_distance(c[i], c[j]) >= settings.aa_threshold)
                            split = true;
                    }
                }
                if (!split) {
                    for (int k = 0; k < 4; ++k)
                        out[k] = (c[0][k] + c[1][k] + c[2][k] + c[3][k]) / 4;
                    return;
                }
                const size_t h = step / 2;
                ensure(bx, by + h, cx - half, cy);
                ensure(bx + h, by, cx, cy - half);
                ensure(bx + step, by + h, cx + half, cy);
                ensure(bx + h, by + step, cx, cy + half);
                ensure(bx + h, by + h, cx, cy);
                const Real q = half / 2;
                float quarter[4][4];
                self(self, cx - q, cy - q, q, bx, by, h, level - 1, quarter[0]);
                self(self, cx - q, cy + q, q, bx, by + h, h, level - 1, quarter[1]);
                self(self, cx + q, cy - q, q, bx + h, by, h, level - 1, quarter[2]);
                self(self, cx + q, cy + q, q, bx + h, by + h, h, level - 1, quarter[3]);
                for (int k = 0; k < 4; ++k) {
                    out[k] =
                        (quarter[0][k] + quarter[1][k] + quarter[2][k] + quarter[3][k]) /
                        4;
                }
            };
            for (int x = first_col; x <= last_col; ++x) {
                std::fill(have.begin(), have.end(), 0);
                std::copy_n(corner(x, y), 4, at(0, 0));
                std::copy_n(corner(x, y + 1), 4, at(0, full));
                std::copy_n(corner(x + 1, y), 4, at(full, 0));
                std::copy_n(corner(x + 1, y + 1), 4, at(full, full));
                have[0] = have[full * side] = have[full] = have[full * side + full] = 1;
                subdivide(subdivide, x + 0.5, y + 0.5, 0.5, 0, 0, full, depth - 1,
                          image.pixel(x, y));
            }
        });
    }
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
