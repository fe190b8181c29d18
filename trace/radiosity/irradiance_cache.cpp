#include "trace/radiosity/irradiance_cache.h"

#include <algorithm>
#include <cmath>

namespace povwall::trace::radiosity {
namespace {

// POV-Ray 3.7's constants of the reuse rule.
constexpr double kNearEpsilon = 1e-6;    // below: the points coincide
constexpr double kInFrontLimit = -0.05;  // an old point this far in front is not reused
constexpr double kWeightEpsilon = 1e-3;  // weights below are dropped

}  // namespace

IrradianceCache::IrradianceCache(std::vector<double> address_factors)
    : address_factors_(std::move(address_factors)) {}

size_t IrradianceCache::CellHash::operator()(const CellKey& k) const {
    uint64_t h = uint64_t(uint32_t(k.x)) * 0x9e3779b97f4a7c15ull;
    h ^= uint64_t(uint32_t(k.y)) * 0xc2b2ae3d27d4eb4full + (h << 6) + (h >> 2);
    h ^= uint64_t(uint32_t(k.z)) * 0x165667b19e3779f9ull + (h << 6) + (h >> 2);
    h ^= (uint64_t(uint16_t(k.level)) << 8 | k.depth) * 0x27d4eb2f165667c5ull;
    return size_t(h ^ (h >> 29));
}

int IrradianceCache::level_for(double radius) {
    if (!(radius > 0)) return -60;
    return std::clamp(int(std::ceil(std::log2(radius))), -60, 60);
}

void IrradianceCache::insert(const CacheEntry& e) {
    const uint32_t index = uint32_t(entries_.size());
    entries_.push_back(e);
    const double factor =
        e.depth < address_factors_.size() ? address_factors_[e.depth] : 1.0;
    const int level = level_for(double(e.harmonic_mean) * factor);
    const double cell = std::ldexp(1.0, level);
    const CellKey key{int32_t(std::floor(e.point.x / cell)),
                      int32_t(std::floor(e.point.y / cell)),
                      int32_t(std::floor(e.point.z / cell)), int16_t(level), e.depth};
    cells_[key].push_back(index);
    if (levels_.size() <= e.depth) levels_.resize(size_t(e.depth) + 1);
    std::vector<int>& levels = levels_[e.depth];
    auto it = std::lower_bound(levels.begin(), levels.end(), level);
    if (it == levels.end() || *it != level) levels.insert(it, level);
}

void IrradianceCache::clear() {
    entries_.clear();
    cells_.clear();
    levels_.clear();
}

void IrradianceCache::accumulate(const Point3& P, const Vector3& N, double bound,
                                 int depth, bool final_top_level, Reuse& out) const {
    if (size_t(depth) >= levels_.size()) return;
    auto visit = [&](const CacheEntry& b) {
        const Vector3 delta = P - b.point;
        const double square_dist = dot(delta, delta);
        const double quick = double(b.harmonic_mean) * bound;
        if (!(square_dist < quick * quick)) return;
        const double dist = std::sqrt(square_dist);
        double ri = b.harmonic_mean;
        const bool apart = dist > kNearEpsilon;
        Vector3 delta_unit{0, 0, 0};
        if (apart) {
            delta_unit = delta * (1 / dist);
            // Toward the nearest surface seen from the entry, its reach shrinks.
            const double c = dot(b.to_nearest, delta_unit);
            if (c > 0) ri = c * double(b.nearest) + (1 - c) * ri;
        }
        if (!(dist < ri * bound)) return;
        const double dir_diff = dot(N, b.normal);
        const double error = dist / ri + 2 * std::sqrt(std::fabs(1 - dir_diff));
        if (!(error < bound)) return;
        double in_front = 1;
        if (apart) {
            const Vector3 half = N + b.normal;
            in_front = dot(delta_unit, half) / length(half);
        }
        if (!(in_front > kInFrontLimit)) return;
        double t = error / bound;
        double w;
        if (final_top_level && b.depth == 0)
            w = t < 0.5 ? 1 - (2 * t) * (2 * t) / 2 : ((1 - t) * 2) * ((1 - t) * 2) / 2;
        else
            w = 1 - t;
        if (in_front <= 0) w *= 1 - in_front / kInFrontLimit;
        if (!(w > kWeightEpsilon)) return;
        w *= double(b.quality);
        out.weighted_sum += b.illuminance * float(w);
        out.weights += w;
    };
    for (int level : levels_[size_t(depth)]) {
        const double cell = std::ldexp(1.0, level);
        const int32_t cx = int32_t(std::floor(P.x / cell));
        const int32_t cy = int32_t(std::floor(P.y / cell));
        const int32_t cz = int32_t(std::floor(P.z / cell));
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto it = cells_.find(CellKey{cx + dx, cy + dy, cz + dz,
                                                  int16_t(level), uint8_t(depth)});
                    if (it == cells_.end()) continue;
                    for (uint32_t i : it->second) visit(entries_[i]);
                }
    }
}

}  // namespace povwall::trace::radiosity
