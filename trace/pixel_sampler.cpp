#include "trace/pixel_sampler.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "core/scene.h"
#include "trace/render.h"

namespace povwall::trace {
namespace {

// POV-Ray's permutation of 0..4095 (its texture hash table, shared with its noise): the
// identity shuffled from the top by a 32-bit linear congruential sequence from 0.
std::array<uint16_t, 4096> make_hash_table() {
    std::array<uint16_t, 4096> t{};
    for (int i = 0; i < 4096; ++i) t[size_t(i)] = uint16_t(i);
    uint32_t s = 0;
    for (int i = 4095; i >= 0; --i) {
        s = s * 1812433253u + 12345u;
        std::swap(t[size_t(i)], t[(s >> 16) & 0xfff]);
    }
    return t;
}

// POV-Ray's 256 jitter values: 15-bit fractions from a shift-and-parity sequence, minus
// one half, as printed in its source (6 decimals, halves away from zero) and read as
// floats.
std::array<float, 256> make_jitter_table() {
    std::array<float, 256> t{};
    for (unsigned i = 0; i < 256; ++i) {
        const unsigned parity = unsigned(std::popcount(i)) & 1u;
        const unsigned k = ((2 * i) ^ (4 * i) ^ (parity << 9)) & 1023u;
        const double exact = double((k << 5) | parity) / 32768.0 - 0.5;
        t[i] = float(std::round(exact * 1e6) / 1e6);
    }
    return t;
}

const std::array<uint16_t, 4096> kHash = make_hash_table();
const std::array<float, 256> kJitter = make_jitter_table();

float jitter_component(Real a, Real b) {
    const int ia = int(a), ib = int(b);  // truncation toward zero, as POV-Ray's casts
    return kJitter[kHash[size_t((kHash[size_t(ia & 0xfff)] ^ ib) & 0xfff)] & 0xffu];
}

// POV-Ray's colour averages: float sums in a fixed order, divided in double.
void divide(float* c, double n) {
    for (int k = 0; k < 4; ++k) c[k] = float(double(c[k]) / n);
}

}  // namespace

void pov_jitter(Real x, Real y, Real& jx, Real& jy) {
    jx = jitter_component(x * 1021.0, y * 1019.0);
    jy = jitter_component(x * 1019.0, y * 1021.0);
}

int pov_hash(int v) { return kHash[size_t(v & 0xfff)]; }

int clamped_block_size(int block_size, const PixelBlock& area) {
    int bs = std::max(block_size, 4);
    const int longest = std::max(area.width(), area.height());
    if (bs > longest) bs = std::max(longest, 1);
    return bs;
}

std::vector<PixelBlock> render_blocks(const PixelBlock& area, int block_size) {
    std::vector<PixelBlock> blocks;
    if (area.width() <= 0 || area.height() <= 0) return blocks;
    const int bs = clamped_block_size(block_size, area);
    for (int y = area.y0; y < area.y1; y += bs)
        for (int x = area.x0; x < area.x1; x += bs)
            blocks.push_back(
                {x, y, std::min(x + bs, area.x1), std::min(y + bs, area.y1)});
    return blocks;
}

PixelBlock render_area(const RenderSettings& settings) {
    const int W = settings.width, H = settings.height;
    PixelBlock a;
    a.y0 = std::clamp(settings.first_row, 0, H);
    a.y1 = (settings.last_row < 0 ? H - 1 : std::min(settings.last_row, H - 1)) + 1;
    a.x0 = std::clamp(settings.first_col, 0, W);
    a.x1 = (settings.last_col < 0 ? W - 1 : std::min(settings.last_col, W - 1)) + 1;
    a.y1 = std::max(a.y1, a.y0);
    a.x1 = std::max(a.x1, a.x0);
    return a;
}

AaEncoding aa_encoding(float antialias_gamma, const Scene& scene) {
    // POV-Ray: the AA curve decodes with gamma g (encodes with 1/g, in float), combined
    // with the scene's working gamma; a power curve within 1 % of 1 is the identity.
    auto curve = [](float exponent) {
        AaEncoding e;
        e.exponent = exponent;
        e.identity = std::fabs(1.0f - exponent) <= 0.01f;
        return e;
    };
    const bool has_aa_curve = antialias_gamma > 0;
    const float aa_encode = has_aa_curve ? 1.0f / antialias_gamma : 1.0f;
    const bool working_power = scene.gamma_mode == GammaMode::Assumed36 ||
                               scene.gamma_mode == GammaMode::Assumed37;
    const GammaCurve working_curve =
        working_power ? scene.settings.assumed_gamma.value_or(GammaCurve{})
                      : GammaCurve{};
    if (working_curve.kind == GammaCurve::Kind::Srgb) {
        // sRGB to linear, then the AA curve: POV-Ray's transcoding of two unlike curves.
        AaEncoding e = has_aa_curve ? curve(aa_encode) : AaEncoding{true, 1.0f};
        e.srgb_decode = true;
        return e;
    }
    const float working = working_curve.decoding_exponent;
    if (!working_power || std::fabs(1.0f - 1.0f / working) <= 0.01f)
        return has_aa_curve ? curve(aa_encode) : AaEncoding{true, 1.0f};
    // Linearise with the working gamma, then encode with the AA curve.
    const float working_decode = 1.0f / (1.0f / working);
    if (!has_aa_curve) return curve(working_decode);
    const float aa_decode = 1.0f / aa_encode;
    return curve(working_decode / aa_decode);
}

SamplerSettings sampler_settings(const RenderSettings& settings, const Scene& scene) {
    SamplerSettings s;
    s.method = settings.antialias ? std::clamp(settings.aa_method, 0, 2) : 0;
    // POV-Ray reads the threshold and jitter amount as floats within [0, 1], the depth
    // as unsigned within 1..9 (a negative depth wraps to 9).
    s.threshold = double(std::clamp(float(settings.aa_threshold), 0.0f, 1.0f));
    s.depth = settings.aa_depth < 0 ? 9 : std::clamp(settings.aa_depth, 1, 9);
    s.jitter = settings.aa_jitter
                   ? double(std::clamp(float(settings.aa_jitter_amount), 0.0f, 1.0f))
                   : 0.0;
    s.encoding = aa_encoding(float(settings.aa_gamma), scene);
    return s;
}

float PixelSampler::distance(const float* a, const float* b) const {
    auto enc = [&](float v) {
        if (s_.encoding.srgb_decode) v = GammaCurve::srgb().decode(v);
        return s_.encoding.identity ? v
                                    : std::pow(std::max(v, 0.0f), s_.encoding.exponent);
    };
    float d = std::fabs(enc(a[0]) - enc(b[0]));
    d += std::fabs(enc(a[1]) - enc(b[1]));
    d += std::fabs(enc(a[2]) - enc(b[2]));
    return d + std::fabs(a[3] - b[3]);
}

bool PixelSampler::render_block(const PixelBlock& block, SampleSource& source,
                                float* out) {
    switch (s_.method) {
        case 1:
            return method1(block, source, out);
        case 2:
            return method2(block, source, out);
        default:
            return method0(block, source, out);
    }
}

void PixelSampler::first_samples(const PixelBlock& area,
                                 std::vector<SamplePosition>& out) const {
    if (s_.method == 2) {
        for (int j = area.y0; j <= area.y1; ++j)
            for (int i = area.x0; i <= area.x1; ++i) out.push_back({i - 0.5, j - 0.5});
        return;
    }
    for (int j = area.y0; j < area.y1; ++j)
        for (int i = area.x0; i < area.x1; ++i) out.push_back({Real(i), Real(j)});
    if (s_.method != 1) return;
    for (int i = area.x0; i < area.x1; ++i) out.push_back({Real(i), Real(area.y0 - 1)});
    for (int j = area.y0; j < area.y1; ++j) out.push_back({Real(area.x0 - 1), Real(j)});
}

void PixelSampler::ask_likely_samples(const PixelBlock& b, SampleSource& src) {
    if (s_.method != 1) return;
    // Raw centres, the block's and its border's, as the block's first comparisons see
    // them: a pixel is supersampled when it differs from its left or upper neighbour,
    // or from its right or lower one inside the block (it is their left or upper
    // neighbour).
    const int w = b.width(), h = b.height(), stride = w + 1;
    cells_.resize(size_t(stride) * size_t(h + 1) * 4);
    done_.assign(size_t(stride) * size_t(h + 1), 0);  // here: centre at hand
    auto cell = [&](int i, int j) {
        return size_t(j - b.y0 + 1) * size_t(stride) + size_t(i - b.x0 + 1);
    };
    for (int j = b.y0 - 1; j < b.y1; ++j)
        for (int i = b.x0 - 1; i < b.x1; ++i)
            if (i >= b.x0 || j >= b.y0)
                done_[cell(i, j)] = src.sample(i, j, &cells_[cell(i, j) * 4]);
    auto differ = [&](int i, int j, int ni, int nj) {
        return done_[cell(ni, nj)] &&
               double(distance(&cells_[cell(ni, nj) * 4], &cells_[cell(i, j) * 4])) >=
                   s_.threshold;
    };
    for (int j = b.y0; j < b.y1; ++j) {
        for (int i = b.x0; i < b.x1; ++i) {
            if (!done_[cell(i, j)]) continue;
            float scratch[4] = {0, 0, 0, 0};  // the samples are only asked for
            if (differ(i, j, i - 1, j) || differ(i, j, i, j - 1) ||
                (i + 1 < b.x1 && differ(i, j, i + 1, j)) ||
                (j + 1 < b.y1 && differ(i, j, i, j + 1)))
                supersample(i, j, src, scratch);
        }
    }
}

bool PixelSampler::method0(const PixelBlock& b, SampleSource& src, float* out) {
    bool complete = true;
    for (int j = b.y0; j < b.y1; ++j)
        for (int i = b.x0; i < b.x1; ++i, out += 4) complete &= src.sample(i, j, out);
    return complete;
}

// The D x D sub-samples of pixel (i, j) added to its centre sample in `colour`, then
// averaged: offsets built by repeated addition, jittered by the nominal position. Every
// sub-sample is asked for; false when one was missing.
bool PixelSampler::supersample(int i, int j, SampleSource& src, float* colour) {
    const int D = s_.depth;
    const double step = 1.0 / D, range = 0.5 - step * 0.5;
    const double js = s_.jitter / D;
    float c[4];
    bool complete = true;
    for (double yy = -range; yy <= range + 1e-10; yy += step) {
        for (double xx = -range; xx <= range + 1e-10; xx += step) {
            const double sx = i + xx, sy = j + yy;
            bool have;
            if (js > 0) {
                Real rx, ry;
                pov_jitter(sx, sy, rx, ry);
                have = src.sample(sx + rx * js, sy + ry * js, c);
            } else {
                have = src.sample(sx, sy, c);
            }
            complete &= have;
            if (have)
                for (int k = 0; k < 4; ++k) colour[k] += c[k];
        }
    }
    divide(colour, double(D * D + 1));
    return complete;
}

bool PixelSampler::method1(const PixelBlock& b, SampleSource& src, float* out) {
    // Cells (w + 1) x (h + 1): row 0 and column 0 are the border above and to the left,
    // traced again by this block and never supersampled.
    const int w = b.width(), h = b.height(), stride = w + 1;
    cells_.resize(size_t(stride) * size_t(h + 1) * 4);
    done_.assign(size_t(stride) * size_t(h + 1), 0);
    auto at = [&](int i, int j) {
        return &cells_[(size_t(j - b.y0 + 1) * size_t(stride) + size_t(i - b.x0 + 1)) *
                       4];
    };
    auto done = [&](int i, int j) -> uint8_t& {
        return done_[size_t(j - b.y0 + 1) * size_t(stride) + size_t(i - b.x0 + 1)];
    };
    // Without a sample, the block stops where a decision needs it.
    bool complete = true;
    for (int i = b.x0; i < b.x1; ++i) {
        complete &= src.sample(i, b.y0 - 1, at(i, b.y0 - 1));
        done(i, b.y0 - 1) = 1;
    }
    for (int j = b.y0; j < b.y1; ++j) {
        complete &= src.sample(b.x0 - 1, j, at(b.x0 - 1, j));
        done(b.x0 - 1, j) = 1;
        for (int i = b.x0; i < b.x1; ++i) {
            float* centre = at(i, j);
            complete &= src.sample(i, j, centre);
            if (!complete) return false;
            // Compared with the neighbours as they are now (perhaps already averaged).
            const bool left = double(distance(at(i - 1, j), centre)) >= s_.threshold;
            const bool up = double(distance(at(i, j - 1), centre)) >= s_.threshold;
            const bool do_left = left && !done(i - 1, j);
            const bool do_up = up && !done(i, j - 1);
            if (do_left) complete &= supersample(i - 1, j, src, at(i - 1, j));
            if (do_up) complete &= supersample(i, j - 1, src, at(i, j - 1));
            if (left || up) complete &= supersample(i, j, src, centre);
            if (!complete) return false;
            if (do_left) done(i - 1, j) = 1;
            if (do_up) done(i, j - 1) = 1;
            if (left || up) done(i, j) = 1;
        }
    }
    for (int j = b.y0; j < b.y1; ++j)
        for (int i = b.x0; i < b.x1; ++i, out += 4) std::copy_n(at(i, j), 4, out);
    return true;
}

bool PixelSampler::method2(const PixelBlock& b, SampleSource& src, float* out) {
    // Every pixel corner of the block, unjittered (a neighbouring block traces its own,
    // with the same values).
    const int w = b.width(), h = b.height(), stride = w + 1;
    cells_.resize(size_t(stride) * size_t(h + 1) * 4);
    auto corner = [&](int i, int j) {
        return &cells_[(size_t(j - b.y0) * size_t(stride) + size_t(i - b.x0)) * 4];
    };
    bool complete = true;
    for (int j = b.y0; j <= b.y1; ++j)
        for (int i = b.x0; i <= b.x1; ++i)
            complete &= src.sample(i - 0.5, j - 0.5, corner(i, j));
    if (!complete) return false;
    const int D = s_.depth;
    const size_t full = size_t(1) << D, side = full + 1;
    const double js = s_.jitter / double(full + 1);
    lattice_.resize(side * side * 4);
    traced_.resize(side * side, 0);
    auto point = [&](size_t x, size_t y) { return &lattice_[(y * side + x) * 4]; };
    auto ensure = [&](size_t x, size_t y, double nx, double ny) {
        if (traced_[y * side + x] == stamp_) return true;
        bool have;
        if (js > 0) {
            Real rx, ry;
            pov_jitter(nx, ny, rx, ry);
            have = src.sample(nx + rx * js, ny + ry * js, point(x, y));
        } else {
            have = src.sample(nx, ny, point(x, y));
        }
        if (have) traced_[y * side + x] = stamp_;
        return have;
    };
    // The square centred at (cx, cy) with half side d, lattice corner (bx, by) and
    // lattice side `step`: its four corners' mean, or its quarters' when two corners
    // differ by the threshold and levels remain. False when a square that splits lacks
    // one of its new samples (all of them are asked for; its quarters are not entered).
    auto subdivide = [&](auto&& self, double cx, double cy, double d, size_t bx,
                         size_t by, size_t step, int level, float* result) -> bool {
        const float* c[4] = {point(bx, by), point(bx, by + step), point(bx + step, by),
                             point(bx + step, by + step)};  // TL, BL, TR, BR
        bool split = false;
        for (int p = 0; p < 4 && level > 0 && !split; ++p)
            for (int q = p + 1; q < 4 && !split; ++q)
                split = double(distance(c[p], c[q])) >= s_.threshold;
        if (!split) {
            for (int k = 0; k < 4; ++k) result[k] = c[0][k] + c[1][k] + c[2][k] + c[3][k];
            divide(result, 4.0);
            return true;
        }
        const size_t half = step / 2;
        bool have = ensure(bx, by + half, cx - d, cy);
        have &= ensure(bx + half, by, cx, cy - d);
        have &= ensure(bx + step, by + half, cx + d, cy);
        have &= ensure(bx + half, by + step, cx, cy + d);
        have &= ensure(bx + half, by + half, cx, cy);
        if (!have) return false;
        const double d2 = d / 2;
        float q[4][4] = {};  // (filled by the calls; GCC cannot tell)
        bool done = self(self, cx - d2, cy - d2, d2, bx, by, half, level - 1, q[0]);
        done &= self(self, cx - d2, cy + d2, d2, bx, by + half, half, level - 1, q[1]);
        done &= self(self, cx + d2, cy - d2, d2, bx + half, by, half, level - 1, q[2]);
        done &=
            self(self, cx + d2, cy + d2, d2, bx + half, by + half, half, level - 1, q[3]);
        for (int k = 0; k < 4; ++k) result[k] = q[0][k] + q[1][k] + q[2][k] + q[3][k];
        divide(result, 4.0);
        return done;
    };
    for (int j = b.y0; j < b.y1; ++j) {
        for (int i = b.x0; i < b.x1; ++i, out += 4) {
            if (++stamp_ == 0) {  // a new pixel: nothing traced (stamps wrapped: clear)
                std::fill(traced_.begin(), traced_.end(), 0);
                stamp_ = 1;
            }
            std::copy_n(corner(i, j), 4, point(0, 0));
            std::copy_n(corner(i, j + 1), 4, point(0, full));
            std::copy_n(corner(i + 1, j), 4, point(full, 0));
            std::copy_n(corner(i + 1, j + 1), 4, point(full, full));
            traced_[0] = traced_[full] = traced_[full * side] =
                traced_[full * side + full] = stamp_;
            complete &= subdivide(subdivide, i, j, 0.5, 0, 0, full, D - 1, out);
        }
    }
    return complete;
}

}  // namespace povwall::trace
