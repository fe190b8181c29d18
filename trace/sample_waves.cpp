#include "trace/sample_waves.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace povwall::trace {
namespace {

// Samples by exact position: those traced, and after them those asked for since the
// last wave (the next wave). While `estimating`, a sample not traced yet is still asked
// for but answered with a guess: the blend of the four pixel centres around it.
class SampleCache final : public SampleSource {
  public:
    bool estimating = false;
    bool sample(Real x, Real y, float* rgbt) override {
        const size_t i = find_or_add(x, y);
        if (i < traced_) {
            std::copy_n(&rgbt_[i * 4], 4, rgbt);
            return true;
        }
        return estimating && estimate(x, y, rgbt);
    }
    void want(const SamplePosition& p) { find_or_add(p.x, p.y); }
    size_t wanted() const { return positions_.size() - traced_; }
    // Traces the samples asked for; returns how many.
    size_t trace_wanted(const TraceWave& trace_wave) {
        wave_.assign(positions_.begin() + ptrdiff_t(traced_), positions_.end());
        colours_.assign(wave_.size() * 4, 0.0f);
        trace_wave(wave_, colours_);
        if (colours_.size() != wave_.size() * 4)
            throw std::logic_error("a wave of samples came back the wrong size");
        rgbt_.resize(positions_.size() * 4);
        std::copy(colours_.begin(), colours_.end(),
                  rgbt_.begin() + ptrdiff_t(traced_ * 4));
        traced_ = positions_.size();
        return wave_.size();
    }

  private:
    struct Key {
        uint64_t x, y;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            // The bits of two doubles mixed (splitmix64's finaliser).
            uint64_t h = k.x * 0x9e3779b97f4a7c15ull ^ (k.y + 0x632be59bd9b4e019ull);
            h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
            h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
            return size_t(h ^ (h >> 31));
        }
    };
    const float* traced(Real x, Real y) const {
        const auto it =
            index_.find(Key{std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y)});
        return it != index_.end() && it->second < traced_ ? &rgbt_[it->second * 4]
                                                          : nullptr;
    }
    bool estimate(Real x, Real y, float* rgbt) const {
        const Real x0 = std::floor(x), y0 = std::floor(y);
        const float fx = float(x - x0), fy = float(y - y0);
        const float* c[4] = {traced(x0, y0), traced(x0 + 1, y0), traced(x0, y0 + 1),
                             traced(x0 + 1, y0 + 1)};
        const float w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        float total = 0;
        std::fill_n(rgbt, 4, 0.0f);
        for (int k = 0; k < 4; ++k) {
            if (!c[k]) continue;
            total += w[k];
            for (int ch = 0; ch < 4; ++ch) rgbt[ch] += w[k] * c[k][ch];
        }
        if (total <= 0) return false;
        for (int ch = 0; ch < 4; ++ch) rgbt[ch] /= total;
        return true;
    }
    size_t find_or_add(Real x, Real y) {
        const auto [it, added] = index_.try_emplace(
            Key{std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y)},
            positions_.size());
        if (added) positions_.push_back({x, y});
        return it->second;
    }
    std::unordered_map<Key, size_t, KeyHash> index_;
    std::vector<SamplePosition> positions_;
    std::vector<float> rgbt_;  // of the first traced_ positions
    size_t traced_ = 0;
    std::vector<SamplePosition> wave_;
    std::vector<float> colours_;
};

}  // namespace

Image render_in_waves(const RenderSettings& settings, const SamplerSettings& sampling,
                      const TraceWave& trace_wave, WaveStats* stats) {
    const PixelBlock area = render_area(settings);
    const std::vector<PixelBlock> blocks = render_blocks(area, settings.block_size);
    PixelSampler sampler(sampling);
    SampleCache cache;
    {
        std::vector<SamplePosition> first;
        sampler.first_samples(area, first);
        for (const SamplePosition& p : first) cache.want(p);
    }
    Image image(settings.width, settings.height);
    std::vector<size_t> open(blocks.size()), still_open;
    for (size_t b = 0; b < blocks.size(); ++b) open[b] = b;
    std::vector<float> rgbt;
    for (int wave = 0; !open.empty(); ++wave) {
        // Every wave finishes at least one block's next pixel or square, so this ends.
        if (cache.wanted() == 0)
            throw std::logic_error(
                "anti-aliasing waves: a block lacks no sample yet stops");
        const size_t traced = cache.trace_wanted(trace_wave);
        if (stats) stats->samples.push_back(traced);
        still_open.clear();
        for (size_t k : open) {
            const PixelBlock& b = blocks[k];
            rgbt.resize(size_t(b.pixels()) * 4);
            if (!sampler.render_block(b, cache, rgbt.data())) {
                still_open.push_back(k);
                continue;
            }
            const float* in = rgbt.data();
            for (int y = b.y0; y < b.y1; ++y)
                for (int x = b.x0; x < b.x1; ++x, in += 4)
                    finish_pixel(in, settings.alpha, image.pixel(x, y));
        }
        if (sampling.method != 1) {  // +AM2: one wave per level of subdivision
            open.swap(still_open);
            continue;
        }
        if (wave == 0)
            for (size_t k : still_open) sampler.ask_likely_samples(blocks[k], cache);
        // Past the first missing sample, a replay with guesses asks for what the
        // decisions would then need (a pixel averaged on a guess, its neighbours compared
        // with that average, ...): chains of such decisions then take one wave, not one
        // per pixel. (For +AM2's levels, guesses asked for 40-100 % more samples and
        // saved no wave.)
        cache.estimating = true;
        for (size_t k : still_open) {
            rgbt.resize(size_t(blocks[k].pixels()) * 4);
            sampler.render_block(blocks[k], cache, rgbt.data());
        }
        cache.estimating = false;
        open.swap(still_open);
    }
    return image;
}

}  // namespace povwall::trace
