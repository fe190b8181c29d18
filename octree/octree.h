// Spatial index over bounded primitives. The tracer owns the primitives; the octree only
// knows their ids, bounds, and (at build time) an exact overlap test per primitive.
//
// Contract used by trace/: traverse() calls `visit(ids, count, t_max)` for leaves in
// front-to-back order along the ray; `visit` tests those primitives, may shrink t_max (the
// closest hit so far) and returns true to stop early (any-hit queries). Traversal ends when
// the next leaf starts beyond t_max. A primitive may appear in several leaves.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/math.h"

namespace povwall::octree {

struct BuildOptions {
    int max_depth = 10;
    int leaf_primitives = 8;     // split a cell holding more than this
    int flat_threshold = 16;     // fewer primitives than this: one flat list, no tree
};

struct BuildInput {
    std::vector<Bounds3> bounds;  // world bounds per primitive id
    // Exact "does primitive `id` touch `cell`" test; null: bounds overlap only.
    std::function<bool(uint32_t id, const Bounds3& cell)> overlaps;
};

struct BuildStats {
    int nodes = 0, leaves = 0, depth = 0;
    uint64_t references = 0;
    double seconds = 0;
};

class Octree {
public:
    void build(const BuildInput& input, const BuildOptions& options = {});
    const Bounds3& bounds() const { return bounds_; }
    const BuildStats& stats() const { return stats_; }
    size_t primitive_count() const { return primitive_count_; }

    template <class Visit>
    void traverse(const Ray& ray, Real t_min, Real& t_max, Visit&& visit) const;

private:
    // Placeholder layout: a single leaf. Replaced by the real octree (issue 6).
    Bounds3 bounds_;
    std::vector<uint32_t> all_ids_;
    size_t primitive_count_ = 0;
    BuildStats stats_;
};

template <class Visit>
void Octree::traverse(const Ray& ray, Real t_min, Real& t_max, Visit&& visit) const {
    if (all_ids_.empty()) return;
    visit(all_ids_.data(), all_ids_.size(), t_max);
}

}  // namespace povwall::octree
