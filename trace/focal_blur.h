// Focal blur as POV-Ray 3.7 takes it: every camera sample averages several rays, each
// through a sub-pixel position near the sample and from a point of the lens aperture,
// aimed so that all meet on the focal plane. The rays go in batches (of POV-Ray's
// hexagonal grids: 7, 6, 6, ...; else 4); after each batch a sample with at least
// blur_samples_min rays stops once the variance of its mean is below a threshold made
// from confidence and variance (chi-square). Everything is deterministic: aperture points
// from fixed grids and Halton sequences (a bokeh pigment: also POV-Ray's Mersenne Twister
// rejection sampling), sub-pixel positions from its hash and jitter tables. So a sample's
// rays are a function of its position and ray index alone, and renderers that trace rays
// in waves (sample_waves.h) ask for them by (position, index).
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "core/scene.h"
#include "trace/camera.h"
#include "trace/pattern.h"
#include "trace/pixel_sampler.h"

namespace povwall::trace {

// A mesh camera with several rays per pixel goes the same way (POV-Ray's TracePixel):
// each sample averages its rays_per_pixel rays, all in one batch, over the rays that
// found a face (none: transparent black).
class FocalBlur {
  public:
    // Focal blur is on when the camera has an aperture and blur samples; a mesh camera
    // with more than one ray per pixel averages them here too.
    static bool enabled(const Camera& camera) {
        return (camera.aperture != 0 && camera.blur_samples > 0) ||
               (camera.kind == Camera::Kind::Mesh && camera.mesh->rays_per_pixel > 1);
    }
    // The mesh camera's rays rather than focal blur's.
    bool mesh_rays() const { return mesh_rays_; }
    // `env`: for the bokeh pigment.
    FocalBlur(const Camera& camera, const PatternEnv& env);
    const Camera& camera() const { return camera_; }

    int max_rays() const { return max_rays_; }
    // Rays in batch `level` (0, 1, ...).
    int batch(int level) const {
        return size_t(level) < batches_.size() && batches_[size_t(level)] > 0
                   ? batches_[size_t(level)]
                   : 4;
    }
    // After `n` rays with channel sums `s1` and sums of squares `s2` (rgbt): may the
    // sample stop?
    bool good_enough(int n, const float* s1, const float* s2) const;

    // Ray `ray` of the sample at POV-Ray pixel position (x, y): its image position and
    // how its aperture point moves it.
    void ray_position(Real x, Real y, int ray, Real& rx, Real& ry) const;
    ApertureShift aperture_shift(Real shifted_x, Real shifted_y, int ray) const;

  private:
    const Camera& camera_;
    bool mesh_rays_ = false;
    int max_rays_ = 0, min_rays_ = 0;
    std::vector<int> batches_;           // rays per batch (0 ends the list: 4 from there)
    std::vector<double> thresholds_;     // of the mean's variance after n rays, at n - 1
    std::vector<Real> grid_x_, grid_y_;  // aperture points in [-0.5, 0.5]^2
    Real max_jitter_ = 0, radius_ = 0, focal_scale_ = 1;
    Vector3 x_perp_, y_perp_;
};

// Ray `ray` of the focal-blurred sample at POV-Ray pixel position (x, y) (none where the
// camera sees nothing).
inline std::optional<Ray> focal_blur_ray(const FocalBlur& blur, Real x, Real y, int ray,
                                         int width, int height) {
    if (blur.mesh_rays())
        return camera_ray_shifted(blur.camera(), x + 0.5, y - 0.5, width, height, nullptr,
                                  ray);
    Real rx, ry;
    blur.ray_position(x, y, ray, rx, ry);
    const Real sx = rx + 0.5, sy = ry - 0.5;  // POV-Ray's shift to the pixel centre
    const ApertureShift shift = blur.aperture_shift(sx, sy, ray);
    return camera_ray_shifted(blur.camera(), sx, sy, width, height, &shift);
}

// What a source of ray colours answers for one of a sample's rays.
enum class RayAnswer { Traced, NoRay, Missing };

// How far a sample's rays are averaged: renderers that trace rays in waves resume it
// batch by batch.
struct FocalProgress {
    float sum[4] = {0, 0, 0, 0}, s1[4] = {0, 0, 0, 0}, s2[4] = {0, 0, 0, 0};
    int rays = 0, level = 0;
    int traced = 0;  // rays the camera had
    bool finished = false;
};

// The sample's colour (rgbt) from its finished rays: focal blur divides by all its rays,
// a mesh camera by those it traced.
inline void focal_mean(const FocalBlur& blur, const FocalProgress& p, float* rgbt) {
    if (blur.mesh_rays() && p.traced == 0) {
        rgbt[0] = rgbt[1] = rgbt[2] = 0;
        rgbt[3] = 1;
        return;
    }
    const int n = blur.mesh_rays() ? p.traced : p.rays;
    for (int ch = 0; ch < 4; ++ch) rgbt[ch] = float(double(p.sum[ch]) / double(n));
}

// The sample's colour (rgbt) from its rays as POV-Ray averages them, going on from
// `progress`: `ray(k, rgbt)` gives ray k. Every ray of a batch is asked for before giving
// up: false when one is missing (rgbt then unspecified; `progress` keeps the batches
// before it). POV-Ray counts a ray the camera does not have as fully transparent black
// in the variance but not in the colour.
template <class RayColour>
bool continue_focal_rays(const FocalBlur& blur, RayColour&& ray, FocalProgress& progress,
                         float* rgbt) {
    FocalProgress& p = progress;
    std::vector<float> colours;
    std::vector<RayAnswer> answers;
    while (!p.finished) {
        const int end = std::min(p.rays + blur.batch(p.level), blur.max_rays());
        colours.resize(size_t(end - p.rays) * 4);
        answers.resize(size_t(end - p.rays));
        bool complete = true;
        for (int k = p.rays; k < end; ++k) {
            answers[size_t(k - p.rays)] = ray(k, &colours[size_t(k - p.rays) * 4]);
            complete &= answers[size_t(k - p.rays)] != RayAnswer::Missing;
        }
        if (!complete) return false;
        for (int k = p.rays; k < end; ++k) {
            const float* col = &colours[size_t(k - p.rays) * 4];
            float v[4] = {0, 0, 0, 1};
            if (answers[size_t(k - p.rays)] == RayAnswer::Traced) {
                ++p.traced;
                for (int ch = 0; ch < 4; ++ch) {
                    v[ch] = col[ch];
                    p.sum[ch] += col[ch];
                }
            }
            for (int ch = 0; ch < 4; ++ch) {
                p.s1[ch] += v[ch];
                p.s2[ch] += v[ch] * v[ch];
            }
        }
        p.rays = end;
        ++p.level;
        p.finished = blur.good_enough(p.rays, p.s1, p.s2) || p.rays >= blur.max_rays();
    }
    focal_mean(blur, p, rgbt);
    return true;
}

template <class RayColour>
bool average_focal_rays(const FocalBlur& blur, RayColour&& ray, float* rgbt) {
    FocalProgress progress;
    return continue_focal_rays(blur, ray, progress, rgbt);
}

// The camera ray of `p` (POV-Ray pixel coordinates): ray p.ray of a focal-blurred sample
// (with `blur`), else the sample's one ray.
inline std::optional<Ray> sample_camera_ray(const Camera& camera, const FocalBlur* blur,
                                            const SamplePosition& p, int width,
                                            int height) {
    if (p.ray >= 0 && blur) return focal_blur_ray(*blur, p.x, p.y, p.ray, width, height);
    return camera_ray_pov(camera, p.x, p.y, width, height);
}

}  // namespace povwall::trace
