// The camera samples of each pixel, as POV-Ray 3.7 takes them: the image cut into render
// blocks (+BS), one sample per pixel centre, or adaptive anti-aliasing decided per block
// (+AM1: a fresh border row and column per block, left and upper neighbours compared;
// +AM2: corners per block and recursive subdivision), with POV-Ray's jitter (a fixed
// function of the sample position). Every driver (one process, screen tiles) renders a
// block with the same code, so a block's pixels do not depend on who rendered it.
// Semantics: notes/aa-blocks.md (written from POV-Ray's sources).
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace povwall {
struct Scene;
}

namespace povwall::trace {

struct RenderSettings;

// A rectangle of pixels [x0, x1) x [y0, y1).
struct PixelBlock {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    int pixels() const { return width() * height(); }
};

// The render area [x0, x1) x [y0, y1) cut into POV-Ray's blocks: anchored at the area's
// top-left corner, `block_size` (clamped as POV-Ray: at least 4, at most the area's
// longer side) on a side, smaller at the right and bottom; in POV-Ray's order (rows of
// blocks from the top).
int clamped_block_size(int block_size, const PixelBlock& area);
std::vector<PixelBlock> render_blocks(const PixelBlock& area, int block_size);

// The render area of `settings` (+SR/+ER/+SC/+EC within the image).
PixelBlock render_area(const RenderSettings& settings);

// How the anti-aliasing compares colours: R, G, B raised to `exponent` (after max(0, x))
// unless `identity`, as POV-Ray's AA gamma curve combined with the scene's working gamma.
struct AaEncoding {
    bool identity = false;
    float exponent = 0.4f;
    bool srgb_decode = false;  // an sRGB working space: linearised first
};
AaEncoding aa_encoding(float antialias_gamma, const Scene& scene);

// POV-Ray's jitter of a sample at nominal position (x, y) (in its pixel coordinates:
// pixel i's centre at i): each component in [-0.5, 0.5), from its hash and jitter tables.
void pov_jitter(Real x, Real y, Real& jx, Real& jy);
// POV-Ray's pseudo-random integer of `v` (0..4095): its hash table at v's low 12 bits.
int pov_hash(int v);

// A camera sample's position in POV-Ray's pixel coordinates (pixel (i, j)'s centre is
// (i, j)). The sampler computes every position the same way whichever block or pixel
// asks, so equal positions are equal bit for bit.
struct SamplePosition {
    Real x = 0, y = 0;
    // Focal blur: which of the sample's rays (focal_blur.h); -1: the sample's one ray.
    int ray = -1;
};

// Traces one camera sample at POV-Ray pixel position (x, y) into rgbt: red, green, blue,
// transmit. False when the sample is not at hand (a source filled in waves, which notes
// the position as wanted); rgbt is then unspecified.
class SampleSource {
  public:
    virtual bool sample(Real x, Real y, float* rgbt) = 0;

  protected:
    ~SampleSource() = default;
};

struct SamplerSettings {
    int method = 0;  // 0: one sample per pixel; 1, 2: POV-Ray's +AM1, +AM2
    double threshold = 0.3;
    int depth = 3;
    double jitter = 0;  // amount (0: none)
    AaEncoding encoding;
};
SamplerSettings sampler_settings(const RenderSettings& settings, const Scene& scene);

// Renders blocks; holds the scratch space of one thread (no allocation per block once
// grown).
class PixelSampler {
  public:
    explicit PixelSampler(const SamplerSettings& settings) : s_(settings) {}
    // The block's pixels, row by row, as rgbt into `out` (block.pixels() * 4 floats).
    // False when a sample the block needs is missing from `source` (`out` is then
    // unspecified): +AM1 stops at the first decision that needs it, after asking for
    // every sample already decided on; +AM2 asks for all the samples of the next level
    // of every square that splits, and finishes no pixel that lacks one.
    bool render_block(const PixelBlock& block, SampleSource& source, float* out);

    // For renderers that trace samples in waves (sample_waves.h). The samples every
    // block of `area` starts with: pixel centres (+AM1 also the row above and the column
    // left of the area, which the first blocks take as borders), or +AM2's pixel
    // corners.
    void first_samples(const PixelBlock& area, std::vector<SamplePosition>& out) const;
    // Asks `source` for the samples the block probably needs beyond those it holds:
    // +AM1's supersamples of each pixel whose centre differs from a neighbour's centre
    // that the block compares it with (the comparisons with neighbours already averaged
    // are left to the replay). Nothing for the other methods.
    void ask_likely_samples(const PixelBlock& block, SampleSource& source);

  private:
    float distance(const float* a, const float* b) const;
    bool method0(const PixelBlock& b, SampleSource& src, float* out);
    bool method1(const PixelBlock& b, SampleSource& src, float* out);
    bool method2(const PixelBlock& b, SampleSource& src, float* out);
    bool supersample(int i, int j, SampleSource& src, float* colour);
    SamplerSettings s_;
    std::vector<float> cells_;    // method 1: the block and its border; method 2: corners
    std::vector<uint8_t> done_;   // method 1: supersampled (or border)
    std::vector<float> lattice_;  // method 2: one pixel's samples
    std::vector<uint32_t> traced_;  // method 2: lattice points traced for pixel `stamp_`
    uint32_t stamp_ = 0;
};

}  // namespace povwall::trace
