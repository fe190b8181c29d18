// Octree over bounded primitives. The tracer owns the primitives; the octree only knows
// their ids, bounds, and (at build time) an exact overlap test per primitive.
//
// traverse() calls `visit(ids, count, t_max)` for the leaves the ray crosses, front to back;
// `visit` tests those primitives, may shrink t_max (the closest hit so far) and returns true
// to stop (any-hit queries). Leaves starting beyond t_max are never visited. A primitive may
// sit in several leaves: callers that care use a mailbox (see Mailbox below).
#pragma once

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
    void build_node(uint32_t node, std::vector<uint32_t>& ids, int depth, const BuildInput& in,
                    const BuildOptions& opt);
    static bool slab(const Bounds3& b, const Point3& o, const Vector3& inv_d, Real t0, Real t1,
                     Real& enter, Real& exit);

    std::vector<Node> nodes_;
    std::vector<uint32_t> ids_;
    Bounds3 bounds_;
    size_t primitive_count_ = 0;
    BuildStats stats_;
};

inline bool Octree::slab(const Bounds3& b, const Point3& o, const Vector3& inv_d, Real t0,
                         Real t1, Real& enter, Real& exit) {
    for (int a = 0; a < 3; ++a) {
        Real lo = (b.lo[a] - o[a]) * inv_d[a];
        Real hi = (b.hi[a] - o[a]) * inv_d[a];
        if (lo > hi) std::swap(lo, hi);
        // NaN (0 * inf when the origin lies on a slab plane) must not shrink the interval.
        if (lo > t0) t0 = lo;
        if (hi < t1) t1 = hi;
        if (t0 > t1) return false;
    }
    enter = t0;
    exit = t1;
    return true;
}

template <class Visit>
void Octree::traverse(const Ray& ray, Real t_min, Real& t_max, Visit&& visit) const {
    if (nodes_.empty()) return;
    Vector3 inv_d{1 / ray.direction.x, 1 / ray.direction.y, 1 / ray.direction.z};
    Real enter, exit;
    if (!slab(nodes_[0].box, ray.origin, inv_d, t_min, t_max, enter, exit)) return;
    struct Item {
        uint32_t node;
        Real enter;
    };
    Item stack[8 * 32 + 8];
    int top = 0;
    stack[top++] = {0, enter};
    while (top > 0) {
        Item it = stack[--top];
        if (it.enter > t_max) continue;
        const Node& n = nodes_[it.node];
        if (n.leaf) {
            if (n.count && visit(&ids_[n.first], size_t(n.count), t_max)) return;
            continue;
        }
        Item kids[8];
        int k = 0;
        for (uint32_t c = 0; c < 8; ++c) {
            const Node& child = nodes_[n.first + c];
            if (child.leaf && child.count == 0) continue;
            Real e0, e1;
            if (slab(child.box, ray.origin, inv_d, t_min, t_max, e0, e1)) {
                kids[k++] = {n.first + c, e0};
            }
        }
        // Push farthest first so the nearest child is popped next.
        for (int i = 1; i < k; ++i) {
            Item v = kids[i];
            int j = i - 1;
            while (j >= 0 && kids[j].enter < v.enter) {
                kids[j + 1] = kids[j];
                --j;
            }
            kids[j + 1] = v;
        }
        for (int i = 0; i < k; ++i) stack[top++] = kids[i];
    }
}

}  // namespace povwall::octree
