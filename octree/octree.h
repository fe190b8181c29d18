// Octree over bounded primitives. The tracer owns the primitives; the octree only knows
// their ids, bounds, and (at build time) an exact overlap test per primitive.
//
// traverse() calls `visit(ids, count, t_max)` for the leaves the ray crosses, front to back;
// `visit` tests those primitives, may shrink t_max (the closest hit so far) and returns true
// to stop (any-hit queries). Leaves starting beyond t_max are never visited. A primitive may
// sit in several leaves: callers that care use a mailbox (see Mailbox below).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/math.h"

namespace povwall::octree {

struct BuildOptions {
    int max_depth = 10;
    int leaf_primitives = 8;  // split a cell holding more than this
    int flat_threshold = 16;  // fewer primitives than this: one leaf, no tree
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

// Per-thread "already tested for this ray" stamps, so a primitive spanning several leaves is
// intersected once per ray.
class Mailbox {
public:
    void resize(size_t primitives) { stamp_.assign(primitives, 0); }
    void next_ray() {
        if (++ray_ == 0) {  // wrapped: clear and restart
            std::fill(stamp_.begin(), stamp_.end(), 0);
            ray_ = 1;
        }
    }
    // True the first time `id` is seen for the current ray.
    bool first_visit(uint32_t id) {
        if (stamp_[id] == ray_) return false;
        stamp_[id] = ray_;
        return true;
    }

private:
    std::vector<uint32_t> stamp_;
    uint32_t ray_ = 0;
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
    struct Node {
        Bounds3 box;
        uint32_t first = 0;  // leaf: first index into ids_; inner: first of 8 child nodes
        uint32_t count = 0;  // leaf: number of ids; inner: 0
        bool leaf = true;
    };
    template <class Visit>
    void visit_subtree(uint32_t index, const Vector3& t0, const Vector3& t1, unsigned mirror,
                       Real t_min, Real& t_max, Visit& visit, bool& stop) const;
    void build_node(uint32_t node, std::vector<uint32_t>& ids, int depth, const BuildInput& in,
                    const BuildOptions& opt);

    std::vector<Node> nodes_;
    std::vector<uint32_t> ids_;
    Bounds3 bounds_;
    size_t primitive_count_ = 0;
    BuildStats stats_;
};

// Parametric front-to-back traversal after Revelles, Urena and Lastra ("An efficient
// parametric algorithm for octree traversal", 2000): the ray is mirrored so every direction
// component is positive, child order follows from which mid-plane the ray crosses first, and
// no child box is ever intersected explicitly.
template <class Visit>
void Octree::traverse(const Ray& ray, Real t_min, Real& t_max, Visit&& visit) const {
    if (nodes_.empty()) return;
    if (ray.direction.x == 0 && ray.direction.y == 0 && ray.direction.z == 0) return;
    const Bounds3& b = nodes_[0].box;
    Point3 o = ray.origin;
    Vector3 d = ray.direction;
    unsigned mirror = 0;
    for (int a = 0; a < 3; ++a) {
        if (std::isnan(o[a]) || std::isnan(d[a])) return;
        if (d[a] < 0) {
            o[a] = b.lo[a] + b.hi[a] - o[a];
            d[a] = -d[a];
            mirror |= 1u << a;
        }
        // A zero component would give 0/0 on a cell plane through the origin.
        if (d[a] < 1e-300) d[a] = 1e-300;
    }
    Vector3 t0, t1;
    for (int a = 0; a < 3; ++a) {
        t0[a] = (b.lo[a] - o[a]) / d[a];
        t1[a] = (b.hi[a] - o[a]) / d[a];
    }
    if (std::max({t0.x, t0.y, t0.z}) >= std::min({t1.x, t1.y, t1.z})) return;
    bool stop = false;
    visit_subtree(0, t0, t1, mirror, t_min, t_max, visit, stop);
}

template <class Visit>
void Octree::visit_subtree(uint32_t index, const Vector3& t0, const Vector3& t1,
                           unsigned mirror, Real t_min, Real& t_max, Visit& visit,
                           bool& stop) const {
    const Real enter = std::max({t0.x, t0.y, t0.z});
    const Real exit = std::min({t1.x, t1.y, t1.z});
    if (exit < t_min || enter > t_max || enter >= exit) return;
    const Node& n = nodes_[index];
    if (n.leaf) {
        if (n.count && visit(&ids_[n.first], size_t(n.count), t_max)) stop = true;
        return;
    }
    const Vector3 tm = (t0 + t1) * 0.5;
    // First child: the entry plane tells which halves the ray starts in.
    unsigned child = 0;
    if (t0.x > t0.y && t0.x > t0.z) {  // enters through the x = lo plane
        if (tm.y < t0.x) child |= 2;
        if (tm.z < t0.x) child |= 4;
    } else if (t0.y > t0.z) {  // through y = lo
        if (tm.x < t0.y) child |= 1;
        if (tm.z < t0.y) child |= 4;
    } else {  // through z = lo
        if (tm.x < t0.z) child |= 1;
        if (tm.y < t0.z) child |= 2;
    }
    while (child < 8 && !stop) {
        Vector3 c0, c1;
        for (int a = 0; a < 3; ++a) {
            bool high = child & (1u << a);
            c0[a] = high ? tm[a] : t0[a];
            c1[a] = high ? t1[a] : tm[a];
        }
        visit_subtree(n.first + (child ^ mirror), c0, c1, mirror, t_min, t_max, visit, stop);
        // Next child: step along the axis whose exit plane comes first; 8 means "left".
        int axis = (c1.x <= c1.y && c1.x <= c1.z) ? 0 : (c1.y <= c1.z ? 1 : 2);
        child = (child & (1u << axis)) ? 8 : (child | (1u << axis));
    }
}

}  // namespace povwall::octree
