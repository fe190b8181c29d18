#include "trace/focal_blur.h"

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <random>

#include "trace/pixel_sampler.h"

namespace povwall::trace {
namespace {

struct GridPoint {
    Real x, y;
};

// POV-Ray's standard aperture grids: a 2x2 square, and hexagonal grids of 7, 19 and 37
// points in the order it takes them (ring by ring), with the maximum jitter of each and
// the rays per batch (0 ends the list).
constexpr GridPoint kSquare[4] = {
    {-0.25, 0.25}, {0.25, 0.25}, {-0.25, -0.25}, {0.25, -0.25}};
constexpr GridPoint kHex7[7] = {{-0.288675, 0.0},  {0.0, 0.0},         {0.288675, 0.0},
                                {-0.144338, 0.25}, {-0.144338, -0.25}, {0.144338, 0.25},
                                {0.144338, -0.25}};
constexpr GridPoint kHex19[19] = {{-0.192450, 0.333333},
                                  {-0.192450, -0.333333},
                                  {0.192450, 0.333333},
                                  {0.192450, -0.333333},
                                  {0.384900, 0.0},
                                  {-0.384900, 0.0},
                                  {0.0, 0.0},
                                  {0.0, 0.333333},
                                  {0.0, -0.333333},
                                  {-0.288675, 0.166667},
                                  {-0.288675, -0.166667},
                                  {0.288675, 0.166667},
                                  {0.288675, -0.166667},
                                  {-0.096225, 0.166667},
                                  {-0.096225, -0.166667},
                                  {0.096225, 0.166667},
                                  {0.096225, -0.166667},
                                  {-0.192450, 0.0},
                                  {0.192450, 0.0}};
constexpr GridPoint kHex37[37] = {
    {0.0, 0.0},          {-0.216506, 0.375}, {0.216506, -0.375}, {-0.216506, -0.375},
    {0.216506, 0.375},   {-0.433013, 0.0},   {0.433013, 0.0},    {-0.144338, 0.25},
    {0.144338, -0.25},   {-0.144338, -0.25}, {0.144338, 0.25},   {-0.288675, 0.0},
    {0.288675, 0.0},     {-0.072169, 0.125}, {0.072169, -0.125}, {-0.072169, -0.125},
    {0.072169, 0.125},   {-0.144338, 0.0},   {0.144338, 0.0},    {-0.360844, 0.125},
    {-0.360844, -0.125}, {0.360844, 0.125},  {0.360844, -0.125}, {-0.288675, 0.25},
    {-0.288675, -0.25},  {0.288675, 0.25},   {0.288675, -0.25},  {-0.072169, 0.375},
    {-0.072169, -0.375}, {0.072169, 0.375},  {0.072169, -0.375}, {-0.216506, 0.125},
    {-0.216506, -0.125}, {0.216506, 0.125},  {0.216506, -0.125}, {0.0, 0.25},
    {0.0, -0.25}};

// Entry i (from 0) of the Halton sequence of `base`, as POV-Ray's generators count (from
// 1).
double halton(size_t i, unsigned base) {
    double h = 0, q = 1.0 / base;
    for (size_t k = i + 1; k > 0; k /= base, q /= base) h += double(k % base) * q;
    return h;
}

// cephes' chdtri: the chi-square value with `df` degrees of freedom that is exceeded with
// probability `y`.
double chi_square_exceeded(double df, double y) {
    return 2.0 * boost::math::gamma_q_inv(0.5 * df, y);
}

}  // namespace

FocalBlur::FocalBlur(const Camera& camera, const PatternEnv& env) : camera_(camera) {
    if (camera.kind == Camera::Kind::Mesh) {
        mesh_rays_ = true;
        max_rays_ = min_rays_ = camera.mesh->rays_per_pixel;
        batches_ = {max_rays_, 0};
        return;
    }
    const int n = camera.blur_samples;
    max_rays_ = n;
    min_rays_ = camera.blur_samples_min;
    radius_ = camera.aperture * 0.5;
    thresholds_.assign(size_t(n), 0.0);
    if (n > 1) {
        const double t1 = camera.variance / chi_square_exceeded(n - 1, camera.confidence);
        for (int i = 0; i < n; ++i)
            thresholds_[size_t(i)] = t1 * chi_square_exceeded(i + 1, camera.confidence);
    }
    grid_x_.resize(size_t(n));
    grid_y_.resize(size_t(n));
    if (camera.bokeh) {
        // Points of the unit square (Halton, bases 2 and 3) kept with a probability of
        // the pigment's grey there, raised with every try so that it ends.
        max_jitter_ = 0.5 / std::sqrt(double(n));
        const double max_tries = double(n) * double(n);
        std::mt19937 random;  // POV-Ray's generator: default seed, first value dropped
        auto uniform = [&] { return double(random()) / 4294967296.0; };
        uniform();
        size_t tries = 0, index = 0;
        for (int i = 0; i < n; ++i) {
            Real x, y;
            double weight;
            do {
                x = -0.5 + halton(index, 2);
                y = -0.5 + halton(index, 3);
                ++index;
                const Colour c =
                    evaluate_pigment(*camera.bokeh, Point3{x + 0.5, y + 0.5, 0}, env);
                weight = float(0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b);
                weight += double(tries) / max_tries;
                ++tries;
            } while (uniform() > weight);
            grid_x_[size_t(i)] = x, grid_y_[size_t(i)] = y;
        }
    } else {
        const GridPoint* standard = kSquare;
        int standard_size = 4;
        if (n >= 37) {
            standard = kHex37, standard_size = 37, batches_ = {7, 6, 6, 4, 4, 4, 4, 2, 0};
        } else if (n >= 19) {
            standard = kHex19, standard_size = 19, batches_ = {7, 6, 6, 0};
        } else if (n >= 7) {
            standard = kHex7, standard_size = 7, batches_ = {7, 0};
        }
        switch (n) {
            case 7:
                max_jitter_ = 0.144338;
                break;
            case 19:
                max_jitter_ = 0.096225;
                break;
            case 37:
                max_jitter_ = 0.0721688;
                break;
            default:
                max_jitter_ = 0.5 / std::sqrt(double(n));
                break;
        }
        for (int i = 0; i < std::min(standard_size, n); ++i)
            grid_x_[size_t(i)] = standard[i].x, grid_y_[size_t(i)] = standard[i].y;
        if (n > standard_size) {
            // The rest: points of the disc (Halton) in cells of a grid not yet taken.
            const int size = 2 * int(std::ceil(std::sqrt(n / kPi))) + 1;
            std::vector<int> taken(size_t(size) * size_t(size), 0);
            auto cell = [&](Real v) { return std::min(int((v + 0.5) * size), size - 1); };
            for (int i = 0; i < standard_size; ++i)
                ++taken[size_t(int((standard[i].y + 0.5) * size)) * size_t(size) +
                        size_t(int((standard[i].x + 0.5) * size))];
            size_t remain = size_t(n) * 10, index = 0;
            auto next = [&](Real& x, Real& y) {
                const double r = std::sqrt(0.25 * halton(index, 2));
                const double theta = halton(index, 3) * (2 * kPi);
                ++index;
                x = r * std::cos(theta), y = r * std::sin(theta);
                --remain;
            };
            for (int i = standard_size; i < n; ++i) {
                Real x, y;
                next(x, y);
                while ((taken[size_t(cell(y)) * size_t(size) + size_t(cell(x))] ||
                        x * x + y * y > 0.25) &&
                       remain > size_t(n - i))
                    next(x, y);
                grid_x_[size_t(i)] = x, grid_y_[size_t(i)] = y;
                ++taken[size_t(cell(y)) * size_t(size) + size_t(cell(x))];
            }
        }
    }
    // The aperture's axes: across and up, perpendicular to the view.
    x_perp_ = normalize(cross(camera.up, camera.direction));
    y_perp_ = normalize(cross(camera.direction, x_perp_));
    focal_scale_ = camera.focal_distance / length(camera.direction);
}

bool FocalBlur::good_enough(int n, const float* s1, const float* s2) const {
    if (n < min_rays_ || mesh_rays_) return false;
    const double count = n, threshold = thresholds_[size_t(n - 1)];
    for (int ch = 0; ch < 4; ++ch) {
        const double mean = s1[ch] / count;
        const float variance = float((s2[ch] / count - mean * mean) / count);
        if (!(variance < threshold)) return false;
    }
    return true;
}

void FocalBlur::ray_position(Real x, Real y, int ray, Real& rx, Real& ry) const {
    // A cell of a 16 x 16 sub-pixel grid picked by POV-Ray's hash, then jittered in it.
    constexpr int kCells = 16;
    const int seed = int(x * 313.0 + 11.0) + int(y * 311.0 + 17.0);
    const int cx = pov_hash(seed + ray) % kCells, cy = pov_hash(seed + ray + 1) % kCells;
    Real dx = Real(2 * cx + 1) / (2 * kCells) - 0.5;
    Real dy = Real(2 * cy + 1) / (2 * kCells) - 0.5;
    Real jx, jy;
    pov_jitter(dx, dy, jx, jy);
    // POV-Ray takes its jitter (already centred on 0) minus one half again.
    dx += (jx - 0.5) / kCells;
    dy += (jy - 0.5) / kCells;
    rx = x + dx;
    ry = y + dy;
}

ApertureShift FocalBlur::aperture_shift(Real shifted_x, Real shifted_y, int ray) const {
    Real jx, jy;
    pov_jitter(shifted_x, shifted_y, jx, jy);
    const Real across = radius_ * (grid_x_[size_t(ray)] + jx * max_jitter_ * 2.0);
    const Real up = radius_ * (grid_y_[size_t(ray)] + jy * max_jitter_ * 2.0);
    return ApertureShift{x_perp_ * across - y_perp_ * up, focal_scale_};
}

}  // namespace povwall::trace
