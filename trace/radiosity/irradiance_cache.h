// The irradiance cache of radiosity: the samples gathered so far (a point, its normal,
// the light arriving there and how far it may be reused), and POV-Ray 3.7's reuse rule
// (RadiosityCache::AverageNearBlock): which samples near a point may stand for it, and
// their weighted average.
//
// Which entries a lookup considers at all is POV-Ray's octree rule (octree.cpp): an entry
// is filed in the node of its sphere of influence (its harmonic mean distance times the
// depth's address factor), the smallest cube of side 2^L, L from the float exponent of
// the sphere's diameter, whose box widened by half a side on every face holds the
// sphere; a lookup sees the entries of the nodes whose widened box holds the point. At
// the top level that is every entry the reuse rule can accept; deeper (address factor
// error bound / 8) only the near ones, so deeper bounces gather more often than a plain
// distance search would let them. Nodes are kept in a hash map per (level, depth); a
// lookup visits levels, nodes and each node's entries in a fixed order, so the sum (and
// the image) depends only on what was inserted in which order, never on threads.
#pragma once

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "core/colour.h"
#include "core/math.h"

namespace povwall::trace::radiosity {

// Pass numbers: pretrace passes count from 1; the final render is kFinalPass.
constexpr int kFinalPass = 255;

struct CacheEntry {
    Point3 point;
    Vector3 normal;      // the normal it was gathered about
    Vector3 to_nearest;  // direction of the nearest surface a sample ray met
    Rgb illuminance;
    float harmonic_mean = 0;  // harmonic mean distance of the sample rays' hits (clamped)
    float nearest = 0;        // distance of the nearest one
    float quality = 1;        // how much of it came from good samples (its weight factor)
    uint8_t depth = 0;        // radiosity recursion depth it serves
    uint8_t pass = 0;         // pretrace pass that gathered it
};

// A weighted sum of reusable entries.
struct Reuse {
    Rgb weighted_sum;
    double weights = 0;
};

class IrradianceCache {
  public:
    // `address_factors[d]`: entries of depth d are filed by harmonic_mean times this
    // (RecursionSettings max_error_bound / overfill_factor).
    explicit IrradianceCache(std::vector<double> address_factors = {});
    void insert(const CacheEntry& e);
    // Adds to `out` the entries of `depth` that may be reused at `point` with normal
    // `normal` under `error_bound`; `final_top_level`: the final pass's top-level
    // lookups weigh with POV-Ray's smooth (pseudo-sigmoid) curve, the others linearly.
    void accumulate(const Point3& point, const Vector3& normal, double error_bound,
                    int depth, bool final_top_level, Reuse& out) const;
    size_t size() const { return entries_.size(); }
    const std::vector<CacheEntry>& entries() const { return entries_; }
    void clear();

  private:
    struct CellKey {
        int64_t x, y, z;
        int16_t level;
        uint8_t depth;
        bool operator==(const CellKey&) const = default;
    };
    struct CellHash {
        size_t operator()(const CellKey& k) const;
    };
    // The octree node of a sphere (POV-Ray's ot_index_sphere).
    static CellKey node_of(const Point3& centre, double radius, uint8_t depth);
    std::vector<double> address_factors_;
    std::vector<CacheEntry> entries_;
    std::unordered_map<CellKey, std::vector<uint32_t>, CellHash> cells_;
    // Levels in use per depth, ascending (the lookup's order).
    std::vector<std::vector<int>> levels_;
};

}  // namespace povwall::trace::radiosity
