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
    uint64_t h = uint64_t(k.x) * 0x9e3779b97f4a7c15ull;
    h ^= uint64_t(k.y) * 0xc2b2ae3d27d4eb4full + (h << 6) + (h >> 2);
    h ^= uint64_t(k.z) * 0x165667b19e3779f9ull + (h << 6) + (h >> 2);
    h ^= (uint64_t(uint16_t(k.level)) << 8 | k.depth) * 0x27d4eb2f165667c5ull;
    return size_t(h ^ (h >> 29));
}

namespace {

// POV-Ray's octree works on coordinates shifted by this, so that node numbers are
// positive.
constexpr double kOctreeBias = 10000000.;

// Whether `p` lies in node `i` of side `side` widened by half a side on each face
// (POV-Ray's ot_point_in_node), along one axis.
bool in_node(double p, int64_t i, double side) {
    return std::fabs(p + kOctreeBias - (double(i) + 0.5) * side) < side;
}

}  // namespace

IrradianceCache::CellKey IrradianceCache::node_of(const Point3& c, double radius,
                                                  uint8_t depth) {
    const Point3 lo = c - Vector3{radius, radius, radius};
    const Point3 hi = c + Vector3{radius, radius, radius};
    const double diameter = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    // The largest power of two not above the diameter, as a float (POV-Ray clears the
    // float's mantissa); a zero diameter takes side 1.
    const float d = float(diameter);
    int level = 0;
    if (d > 0 && std::isfinite(d)) level = std::ilogb(d);
    double side = std::ldexp(1.0, level);
    const Point3 mid = (lo + hi) * 0.5;
    CellKey k{int64_t(std::floor((mid.x + kOctreeBias) / side)),
              int64_t(std::floor((mid.y + kOctreeBias) / side)),
              int64_t(std::floor((mid.z + kOctreeBias) / side)), int16_t(level), depth};
    auto holds = [&](const Point3& p) {
        return in_node(p.x, k.x, side) && in_node(p.y, k.y, side) &&
               in_node(p.z, k.z, side);
    };
    // Up to the parent until the sphere's box fits (POV-Ray's ot_parent; the bias keeps
    // the numbers positive).
    while ((!holds(lo) || !holds(hi)) && k.level < 1000) {
        k.x = k.x >= 0 ? k.x >> 1 : (k.x + 1) / 2;
        k.y = k.y >= 0 ? k.y >> 1 : (k.y + 1) / 2;
        k.z = k.z >= 0 ? k.z >> 1 : (k.z + 1) / 2;
        ++k.level;
        side *= 2;
    }
    return k;
}

void IrradianceCache::insert(const CacheEntry& e) {
    const uint32_t index = uint32_t(entries_.size());
    entries_.push_back(e);
    const double factor =
        e.depth < address_factors_.size() ? address_factors_[e.depth] : 1.0;
    const CellKey key = node_of(e.point, double(e.harmonic_mean) * factor, e.depth);
    const int level = key.level;
    // Filed under the cells of a grid of the node's side shifted by half a side: node i's
    // widened box, [(i - 0.5) side, (i + 1.5) side) per axis, is cells i and i + 1, so
    // a lookup finds every node that may hold its point in the one cell it falls in.
    for (int64_t dz = 0; dz < 2; ++dz)
        for (int64_t dy = 0; dy < 2; ++dy)
            for (int64_t dx = 0; dx < 2; ++dx)
                cells_[CellKey{key.x + dx, key.y + dy, key.z + dz, key.level, key.depth}]
                    .push_back(index);
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
    // Per level, the cell of the shifted grid (see insert()) that holds P: j with
    // (j - 0.5) side <= P + bias < (j + 0.5) side. Its entries' nodes hold P in their
    // widened boxes, but for P on a box's lower face (open there), where each candidate's
    // node is tested as POV-Ray does.
    const double p[3] = {P.x + kOctreeBias, P.y + kOctreeBias, P.z + kOctreeBias};
    for (int level : levels_[size_t(depth)]) {
        const double side = std::ldexp(1.0, level);
        int64_t j[3];
        bool on_face = false;
        for (int a = 0; a < 3; ++a) {
            j[a] = int64_t(std::floor(p[a] / side + 0.5));
            if (p[a] < (double(j[a]) - 0.5) * side) --j[a];
            if (p[a] >= (double(j[a]) + 0.5) * side) ++j[a];
            on_face = on_face || p[a] == (double(j[a]) - 0.5) * side;
        }
        auto it = cells_.find(CellKey{j[0], j[1], j[2], int16_t(level), uint8_t(depth)});
        if (it == cells_.end()) continue;
        for (uint32_t i : it->second) {
            const CacheEntry& b = entries_[i];
            if (on_face) {
                const double factor =
                    b.depth < address_factors_.size() ? address_factors_[b.depth] : 1.0;
                const CellKey k =
                    node_of(b.point, double(b.harmonic_mean) * factor, b.depth);
                if (!in_node(P.x, k.x, side) || !in_node(P.y, k.y, side) ||
                    !in_node(P.z, k.z, side))
                    continue;
            }
            visit(b);
        }
    }
}

}  // namespace povwall::trace::radiosity
