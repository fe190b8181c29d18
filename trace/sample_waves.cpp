#include "trace/sample_waves.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "trace/focal_blur.h"

namespace povwall::trace {
namespace {

// The bilinear blend of the traced corners among c[4] (x0y0, x1y0, x0y1, x1y1; null:
// not traced) at (fx, fy), renormalised over those present; false if none is.
bool bilinear(const float* const (&c)[4], float fx, float fy, float* rgbt) {
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

// Samples by exact position: those traced, and after them those asked for since the
// last wave (the next wave). While `estimating`, a sample not traced yet is still asked
// for but answered with a guess: the blend of the four pixel centres around it.
class SampleCache final : public SampleSource {
  public:
    bool estimating = false;
    bool sample(Real x, Real y, float* rgbt) override {
        const size_t i = find_or_add(x, y, -1);
        if (i < traced_) {
            std::copy_n(&rgbt_[i * 4], 4, rgbt);
            return true;
        }
        return estimating && estimate(x, y, rgbt);
    }
    // Ray `ray` of a focal-blurred sample (never guessed).
    bool focal_ray(Real x, Real y, int ray, float* rgbt) {
        const size_t i = find_or_add(x, y, ray);
        if (i >= traced_) return false;
        std::copy_n(&rgbt_[i * 4], 4, rgbt);
        return true;
    }
    void want(const SamplePosition& p) { find_or_add(p.x, p.y, p.ray); }
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

    // The first wave's lattice (pixel centres, or +AM2's corners: `offset` -0.5) over
    // `area` grown by one on each side, in a dense table; the other positions hashed.
    void set_lattice(const PixelBlock& area, Real offset) {
        offset_ = offset;
        gx0_ = area.x0 - 1, gy0_ = area.y0 - 1;
        gw_ = area.width() + 3, gh_ = area.height() + 3;
        lattice_.assign(size_t(gw_) * size_t(gh_), kNone);
    }

  private:
    static constexpr uint32_t kNone = ~uint32_t(0);
    // The lattice entry of (x, y), or null when it lies off the lattice.
    uint32_t* on_lattice(Real x, Real y, int ray) {
        if (ray >= 0) return nullptr;
        const Real gx = x - offset_, gy = y - offset_;
        if (gx != std::floor(gx) || gy != std::floor(gy)) return nullptr;
        const Real i = gx - gx0_, j = gy - gy0_;
        if (i < 0 || j < 0 || i >= gw_ || j >= gh_) return nullptr;
        return &lattice_[size_t(j) * size_t(gw_) + size_t(i)];
    }
    // Open addressing, linear probing, on the bits of the two doubles.
    struct Slot {
        uint64_t x = 0, y = 0;
        int32_t ray = -1;
        uint32_t index = kNone;
    };
    static size_t hash(uint64_t x, uint64_t y, int32_t ray) {
        // splitmix64's finaliser over the words mixed.
        uint64_t h =
            x * 0x9e3779b97f4a7c15ull ^
            (y + 0x632be59bd9b4e019ull + uint64_t(uint32_t(ray)) * 0xd6e8feb86659fd93ull);
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
        return size_t(h ^ (h >> 31));
    }
    // The entry of (x, y), new (kNone) if absent: find_or_add() fills it at once.
    uint32_t& hashed(Real x, Real y, int ray) {
        if ((hashed_count_ + 1) * 2 > slots_.size()) grow();
        const uint64_t bx = std::bit_cast<uint64_t>(x), by = std::bit_cast<uint64_t>(y);
        const size_t mask = slots_.size() - 1;
        for (size_t k = hash(bx, by, ray) & mask;; k = (k + 1) & mask) {
            Slot& s = slots_[k];
            if (s.index == kNone) {
                s.x = bx, s.y = by, s.ray = ray;
                ++hashed_count_;
                return s.index;
            }
            if (s.x == bx && s.y == by && s.ray == ray) return s.index;
        }
    }
    void grow() {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(std::max<size_t>(1024, old.size() * 2), Slot{});
        const size_t mask = slots_.size() - 1;
        for (const Slot& s : old) {
            if (s.index == kNone) continue;
            size_t k = hash(s.x, s.y, s.ray) & mask;
            while (slots_[k].index != kNone) k = (k + 1) & mask;
            slots_[k] = s;
        }
    }
    uint32_t& entry(Real x, Real y, int ray) {
        if (uint32_t* e = on_lattice(x, y, ray)) return *e;
        return hashed(x, y, ray);
    }
    // A sample's one ray (guesses never use focal-blur rays).
    uint32_t find(Real x, Real y) {
        if (const uint32_t* e = on_lattice(x, y, -1)) return *e;
        if (slots_.empty()) return kNone;
        const uint64_t bx = std::bit_cast<uint64_t>(x), by = std::bit_cast<uint64_t>(y);
        const size_t mask = slots_.size() - 1;
        for (size_t k = hash(bx, by, -1) & mask;; k = (k + 1) & mask) {
            const Slot& s = slots_[k];
            if (s.index == kNone) return kNone;
            if (s.x == bx && s.y == by && s.ray == -1) return s.index;
        }
    }
    const float* traced(Real x, Real y) {
        const uint32_t i = find(x, y);
        return i < traced_ ? &rgbt_[size_t(i) * 4] : nullptr;
    }
    bool estimate(Real x, Real y, float* rgbt) {
        const Real x0 = std::floor(x), y0 = std::floor(y);
        const float fx = float(x - x0), fy = float(y - y0);
        const float* c[4] = {traced(x0, y0), traced(x0 + 1, y0), traced(x0, y0 + 1),
                             traced(x0 + 1, y0 + 1)};
        return bilinear(c, fx, fy, rgbt);
    }
    size_t find_or_add(Real x, Real y, int ray) {
        uint32_t& e = entry(x, y, ray);
        if (e == kNone) {
            e = uint32_t(positions_.size());
            positions_.push_back({x, y, ray});
        }
        return e;
    }
    Real offset_ = 0;
    int gx0_ = 0, gy0_ = 0, gw_ = 0, gh_ = 0;
    std::vector<uint32_t> lattice_;
    std::vector<Slot> slots_;
    size_t hashed_count_ = 0;
    std::vector<SamplePosition> positions_;
    std::vector<float> rgbt_;  // of the first traced_ positions
    size_t traced_ = 0;
    std::vector<SamplePosition> wave_;
    std::vector<float> colours_;
};

// Focal-blurred samples: each the average of its rays, asked of the cache by (position,
// ray), batch by batch (the rays the camera does not have are never asked for). Each
// sample's progress is kept by position (a wave's replay adds only its new batch); while
// the cache is `estimating`, a sample whose rays are not all in is guessed as the cache
// guesses plain samples (from the finished samples at the pixel centres around it), so
// that +AM1's chains of decisions take few waves here too.
class FocalSamples final : public SampleSource {
  public:
    FocalSamples(SampleCache& cache, const FocalBlur& blur,
                 const RenderSettings& settings)
        : cache_(cache),
          blur_(blur),
          settings_(settings),
          may_miss_(blur.camera().kind == Camera::Kind::Fisheye ||
                    blur.camera().kind == Camera::Kind::Omnimax ||
                    blur.camera().kind == Camera::Kind::Mesh) {}
    bool sample(Real x, Real y, float* rgbt) override {
        const Key key{std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y)};
        FocalProgress& progress = progress_[key];
        const bool complete = continue_focal_rays(
            blur_,
            [&](int k, float* c) {
                if (may_miss_ &&
                    !focal_blur_ray(blur_, x, y, k, settings_.width, settings_.height))
                    return RayAnswer::NoRay;
                return cache_.focal_ray(x, y, k, c) ? RayAnswer::Traced
                                                    : RayAnswer::Missing;
            },
            progress, rgbt);
        if (complete) return true;
        if (pending_keys_.insert(key).second) pending_.push_back({x, y});
        return cache_.estimating && estimate(x, y, rgbt);
    }
    // After a wave: every sample asked for and not finished asks for its next batch of
    // rays, whether or not a replay reaches it (a block's replay stops at its first
    // unfinished decision, which would otherwise make its samples go one at a time).
    void advance() {
        float rgbt[4];
        for (const SamplePosition& p : pending_) {
            pending_keys_.erase(
                Key{std::bit_cast<uint64_t>(p.x), std::bit_cast<uint64_t>(p.y)});
        }
        std::vector<SamplePosition> asked;
        asked.swap(pending_);
        for (const SamplePosition& p : asked) sample(p.x, p.y, rgbt);
    }

  private:
    struct Key {
        uint64_t x, y;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            return std::hash<uint64_t>()(k.x * 0x9e3779b97f4a7c15ull ^ k.y);
        }
    };
    // The colour of a finished sample at (x, y), or null.
    const float* finished(Real x, Real y, float* rgbt) const {
        auto it =
            progress_.find(Key{std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y)});
        if (it == progress_.end() || !it->second.finished) return nullptr;
        focal_mean(blur_, it->second, rgbt);
        return rgbt;
    }
    bool estimate(Real x, Real y, float* rgbt) const {
        const Real x0 = std::floor(x), y0 = std::floor(y);
        const float fx = float(x - x0), fy = float(y - y0);
        float corner[4][4];
        const float* c[4] = {finished(x0, y0, corner[0]), finished(x0 + 1, y0, corner[1]),
                             finished(x0, y0 + 1, corner[2]),
                             finished(x0 + 1, y0 + 1, corner[3])};
        return bilinear(c, fx, fy, rgbt);
    }
    SampleCache& cache_;
    const FocalBlur& blur_;
    const RenderSettings& settings_;
    // Only these kinds lack rays somewhere (camera_ray_shifted); the others need no
    // camera ray made to know that it exists.
    const bool may_miss_;
    std::unordered_map<Key, FocalProgress, KeyHash> progress_;
    std::vector<SamplePosition> pending_;  // asked for, not finished (in pending_keys_)
    std::unordered_set<Key, KeyHash> pending_keys_;
};

}  // namespace

Image render_in_waves(const RenderSettings& settings, const SamplerSettings& sampling,
                      const TraceWave& trace_wave, WaveStats* stats,
                      const FocalBlur* blur) {
    const PixelBlock area = render_area(settings);
    const std::vector<PixelBlock> blocks = render_blocks(area, settings.block_size);
    PixelSampler sampler(sampling);
    SampleCache cache;
    cache.set_lattice(area, sampling.method == 2 ? -0.5 : 0.0);
    std::optional<FocalSamples> focal;
    if (blur) focal.emplace(cache, *blur, settings);
    SampleSource& source = focal ? static_cast<SampleSource&>(*focal) : cache;
    {
        std::vector<SamplePosition> first;
        sampler.first_samples(area, first);
        float unused[4];
        for (const SamplePosition& p : first) {
            if (focal)
                focal->sample(p.x, p.y, unused);  // wants the first batch of its rays
            else
                cache.want(p);
        }
    }
    Image image(settings.width, settings.height);
    std::vector<size_t> open(blocks.size()), still_open;
    for (size_t b = 0; b < blocks.size(); ++b) open[b] = b;
    std::vector<float> rgbt;
    for (int wave = 0; !open.empty(); ++wave) {
        // Every wave finishes at least one block's next pixel or square, so this ends.
        // (Only the first wave may be empty: focal blur where the camera has no ray.)
        if (cache.wanted() == 0 && wave > 0)
            throw std::logic_error(
                "anti-aliasing waves: a block lacks no sample yet stops");
        if (cache.wanted() > 0) {
            const size_t traced = cache.trace_wanted(trace_wave);
            if (stats) stats->samples.push_back(traced);
        }
        if (focal) focal->advance();
        still_open.clear();
        for (size_t k : open) {
            const PixelBlock& b = blocks[k];
            rgbt.resize(size_t(b.pixels()) * 4);
            if (!sampler.render_block(b, source, rgbt.data())) {
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
            for (size_t k : still_open) sampler.ask_likely_samples(blocks[k], source);
        // Past the first missing sample, a replay with guesses asks for what the
        // decisions would then need (a pixel averaged on a guess, its neighbours compared
        // with that average, ...): chains of such decisions then take one wave, not one
        // per pixel. (For +AM2's levels, guesses asked for 40-100 % more samples and
        // saved no wave.)
        cache.estimating = true;
        for (size_t k : still_open) {
            rgbt.resize(size_t(blocks[k].pixels()) * 4);
            sampler.render_block(blocks[k], source, rgbt.data());
        }
        cache.estimating = false;
        open.swap(still_open);
    }
    return image;
}

}  // namespace povwall::trace
