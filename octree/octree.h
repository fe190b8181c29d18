// Octree over bounded primitives. The tracer owns the primitives; the octree only knows
// their ids, bounds, and (at build time) an exact overlap test per primitive.
//
// Contract used by trace/:
// - build(BuildInput): per-primitive world bounds plus an optional exact "does primitive
// id
//   touch this cell" callback (octree/overlap.h has exact ones for spheres, boxes and
//   triangles). Cells hold only the primitives that really overlap them (closed cells).
// - traverse(ray, t_min, t_max&, visit) calls `visit(ids, count, t_max)` for the leaves
// the
//   ray crosses, front to back (non-decreasing entry distance). `visit` tests those
//   primitives, may shrink t_max (the closest hit so far) and returns true to stop
//   (any-hit queries). Traversal ends as soon as the next leaf starts beyond t_max. A
//   primitive may sit in several leaves: callers use a Mailbox so it is intersected once
//   per ray (in large scenes rarely twice, never skipped).
// - Rays with a NaN or infinite component visit nothing; zero direction components, rays
//   starting inside and rays running exactly along cell planes are handled exactly.
// Additions: BuildStats (per build, for --stats), BuildOptions::threads, leaf_entry()
// (entry distance passed to visit_with_entry for tests and diagnostics).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <new>
#include <vector>

#include "core/math.h"

namespace povwall::octree {

/// Up to 64^3 cells (2 MB of 8-byte node copies) in the dense top.
constexpr int kDenseTopMax = 6;

struct BuildOptions {
    /// Deepest level (root = 0); also bounded by kMaxDepth.
    int max_depth = 16;
    /// A cell holding this many primitives or fewer stays a leaf.
    int leaf_primitives = 8;
    /// Fewer bounded primitives than this: one flat list, no tree. Measured with
    /// povwall_bench BM_Small (docs/performance.md): below this the flat loop wins.
    int flat_threshold = 24;
    /// Cost of one node step in units of one primitive test, for the split decision.
    /// Measured on sphere scenes (BM_Octree): 8 beats 0.3..4 by 10-25% at 1e3..1e5.
    Real traversal_cost = 8;
    /// Build threads; 0 = hardware concurrency.
    int threads = 0;
    /// Most references (ids in leaves) the tree may hold: this multiple of the bounded
    /// primitives plus reference_slack. Each split shares what is left of it out to its
    /// children in proportion to their references, and a split that would go beyond its
    /// cell's share leaves the cell a leaf: a crowded region cannot spend the budget of
    /// the others, and the tree does not depend on the build's threads. A safety net for
    /// primitives that cannot be separated (heavy overlap); the usual trees hold 1-9
    /// references per primitive.
    Real max_references_per_primitive = 32;
    /// Added to the budget above, so that small scenes are never cut short.
    uint64_t reference_slack = uint64_t(1) << 16;
    /// Deepest level kept as a dense array of cells, walked by stepping from cell to
    /// cell (0 = off). Used down to a level above which every node is inner or an empty
    /// leaf; see Octree::build_dense_top and Octree::top_level().
    int dense_top_max = kDenseTopMax;
};

struct BuildInput {
    /// World bounds per primitive id. Empty bounds (lo > hi) are left out of the tree.
    std::vector<Bounds3> bounds;
    /// Exact "does primitive `id` touch closed `cell`" test; null: bounds overlap only.
    /// Called only for primitives whose bounds straddle several children, possibly from
    /// several build threads at once, so it must be thread-safe.
    std::function<bool(uint32_t id, const Bounds3& cell)> overlaps;
    /// Cost of testing each primitive, in units of one simple primitive test (a
    /// triangle's); empty: 1 each. The split decision weighs references by it, so cells
    /// of costly shapes (CSG, lathes, text) are cut finer.
    std::vector<float> cost;
};

struct BuildStats {
    int nodes = 0, leaves = 0, depth = 0;
    uint64_t references = 0;   // ids stored in leaves
    uint64_t exact_tests = 0;  // overlap callback calls
    uint64_t exact_rejected =
        0;              // cell references the exact test removed (bounds overlapped)
    bool flat = false;  // below flat_threshold: a single leaf, no tree
    // Cells left as leaves because their primitives cannot be told apart: at most
    // leaf_primitives distinct bounds among them (identical copies), or a split would
    // have copied every reference into several children and separated nothing.
    uint64_t inseparable_leaves = 0;
    // Cells left as leaves because the reference budget was spent.
    uint64_t budget_leaves = 0;
    int threads = 1;    // threads the build ran on (BuildOptions::threads, at most)
    int dense_top = 0;  // levels walked as a dense array of cells (0: none)
    double seconds = 0;
};

/// Per-thread "already tested for this ray" stamps, so a primitive spanning several
/// leaves is intersected once per ray. One per thread; call next_ray() before each
/// traversal. Up to kSlots primitives every id has its own slot. Above that a slot per
/// id outgrows the L1 cache and most checks missed it (1e6 spheres: about a third of the
/// ray's cache misses), so ids share kSlots direct-mapped slots instead: a ray checks a
/// few dozen ids, mostly neighbours in the spatial numbering. A clash only forgets an
/// id: that primitive may be tested again (same answer), never skipped.
class Mailbox {
  public:
    static constexpr size_t kSlots = 512;
    void resize(size_t primitives) {
        size_ = primitives;
        size_t slots = 1;
        while (slots < primitives && slots < kSlots) slots *= 2;
        slot_.assign(slots, 0);
        mask_ = uint32_t(slots - 1);
    }
    size_t size() const { return size_; }
    void next_ray() {
        if (++ray_ == 0) {  // wrapped after 2^32 rays: clear and restart
            std::fill(slot_.begin(), slot_.end(), 0);
            ray_ = 1;
        }
    }
    /// True the first time `id` is seen for the current ray (above kSlots primitives:
    /// or again after a clash).
    bool first_visit(uint32_t id) {
        // Ray and id in one word: a slot matches only its own id on this ray.
        const uint64_t key = uint64_t(ray_) << 32 | id;
        uint64_t& slot = slot_[id & mask_];
        if (slot == key) return false;
        slot = key;
        return true;
    }

  private:
    std::vector<uint64_t> slot_;
    size_t size_ = 0;
    uint32_t mask_ = 0, ray_ = 0;
};

/// Deepest level the traversal stack holds; cells are then 2^-24 of the root, far below
/// any useful size, so deeper builds are never needed.
constexpr int kMaxDepth = 24;

class Octree {
  public:
    /// A cell's real-space bounds (plain arrays: Bounds3's initialisers cost per ray).
    struct Cell {
        Real lo[3], hi[3];
    };
    void build(const BuildInput& input, const BuildOptions& options = {});
    /// Root cell (the primitives' bounds, padded so every axis has extent).
    const Bounds3& bounds() const { return bounds_; }
    const BuildStats& stats() const { return stats_; }
    size_t primitive_count() const { return primitive_count_; }

    template <class Visit>
    void traverse(const Ray& ray, Real t_min, Real& t_max, Visit&& visit) const {
        traverse_with_entry(ray, t_min, t_max,
                            [&](const uint32_t* ids, size_t n, Real& t, Real) {
                                return visit(ids, n, t);
                            });
    }
    /// As traverse(); in trees too large for the caches, `prefetch_leaf(first)` is called
    /// ahead of time for a leaf that will likely be visited next, with the position of
    /// its first id in ids(), so that the caller fetches its own per-reference data.
    template <class Visit, class PrefetchLeaf>
    void traverse(const Ray& ray, Real t_min, Real& t_max, Visit&& visit,
                  PrefetchLeaf&& prefetch_leaf) const {
        traverse_with_entry(
            ray, t_min, t_max,
            [&](const uint32_t* ids, size_t n, Real& t, Real) {
                return visit(ids, n, t);
            },
            prefetch_leaf);
    }
    /// As traverse(), with the leaf's entry distance along the ray as fourth argument.
    struct NoPrefetch {
        void operator()(uint32_t) const {}
    };
    template <class Visit, class PrefetchLeaf = NoPrefetch>
    void traverse_with_entry(const Ray& ray, Real t_min, Real& t_max, Visit&& visit,
                             PrefetchLeaf&& prefetch_leaf = NoPrefetch{}) const;

    /// Compact node: a leaf holds ids_[first, first + count), in ascending order; an
    /// inner node (count == kInner) has its 8 children at nodes_[first .. first + 7],
    /// child index = x | y<<1 | z<<2.
    struct Node {
        uint32_t first = 0;
        uint32_t count = 0;
    };
    static constexpr uint32_t kInner = 0xffffffffu;
    /// Trees with more nodes than this (128 KB, their ids about 4 times that) outgrow L2:
    /// the walk then prefetches ahead.
    static constexpr size_t kPrefetchNodes = size_t(1) << 14;
    /// Places element 0 one node before a cache-line boundary: the root is alone at
    /// index 0 and every group of 8 children (index 1 + 8k) then fills exactly one
    /// 64-byte line, so stepping between siblings costs one miss, not two.
    template <class T>
    struct GroupAllocator {
        using value_type = T;
        static constexpr size_t kLine = 64, kShift = kLine - sizeof(T);
        GroupAllocator() = default;
        template <class U>
        GroupAllocator(const GroupAllocator<U>&) {}
        T* allocate(size_t n) {
            auto* raw = static_cast<unsigned char*>(
                ::operator new(n * sizeof(T) + kLine, std::align_val_t(kLine)));
            return reinterpret_cast<T*>(raw + kShift);
        }
        void deallocate(T* p, size_t) {
            ::operator delete(reinterpret_cast<unsigned char*>(p) - kShift,
                              std::align_val_t(kLine));
        }
        template <class U>
        bool operator==(const GroupAllocator<U>&) const {
            return true;
        }
    };
    using NodeArray = std::vector<Node, GroupAllocator<Node>>;
    const NodeArray& nodes() const { return nodes_; }
    const std::vector<uint32_t>& ids() const { return ids_; }
    /// Level K whose 8^K cells are walked directly (0: the walk starts at the root).
    int top_level() const { return top_level_; }

  private:
    // kParallel: some direction component is zero, so mid-plane parameters come from the
    // cell geometry (cells are tracked); otherwise they are the mean of the entry and
    // exit parameters, which needs no geometry. kPrefetch: the tree is larger than
    // kPrefetchNodes, so the walk fetches ahead (below that it sits in L2 and the extra
    // instructions only cost).
    // Walks the subtree below inner node `first` (its first child) whose cell the ray
    // crosses between t0 and t1 (mirrored); true: stop the whole traversal.
    template <bool kParallel, bool kPrefetch, class Visit, class PrefetchLeaf>
    bool walk(const Point3& o, const Vector3& inv, const bool* parallel, unsigned mirror,
              uint32_t first, const Real* t0, const Real* t1, const Cell* cell,
              Real t_min, Real& t_max, Visit& visit, PrefetchLeaf& prefetch_leaf) const;
    // Steps through the cells of level top_level_ (no zero direction component).
    template <bool kPrefetch, class Visit, class PrefetchLeaf>
    void walk_top(const Point3& o, const Vector3& inv, unsigned mirror, const Vector3& t0,
                  const Vector3& t1, Real t_min, Real& t_max, Visit& visit,
                  PrefetchLeaf& prefetch_leaf) const;

    void build_dense_top(int max_level);

    NodeArray nodes_;
    // The dense top: a copy of each cell's node at level top_level_, x | y<<K | z<<2K.
    std::vector<Node> top_;
    int top_level_ = 0;
    std::vector<uint32_t> ids_;
    Bounds3 bounds_;
    // The primitives' own box, padded (Octree::build): traversal walks only the part of
    // a ray inside it. clip_: it is smaller than the root on some axis.
    Real clip_lo_[3] = {}, clip_hi_[3] = {};
    bool clip_ = false;
    size_t primitive_count_ = 0;
    BuildStats stats_;
};

// Parametric front-to-back traversal after Revelles, Urena and Lastra ("An efficient
// parametric algorithm for octree traversal", 2000). Per axis, t0/t1 are the parameters
// where the ray crosses a cell's entry and exit planes, i.e. the ray is mirrored so every
// direction component is positive (real child = mirrored child ^ mirror). Each plane's
// parameter is computed once, at the cell where it is the mid-plane, and handed down, so
// neighbouring cells agree exactly. Child boxes are never intersected; the next child
// follows from the exit plane. Zero direction components get t = -inf/+inf, never 0 *
// inf.
template <class Visit, class PrefetchLeaf>
void Octree::traverse_with_entry(const Ray& ray, Real t_min, Real& t_max, Visit&& visit,
                                 PrefetchLeaf&& prefetch_leaf) const {
    if (nodes_.empty()) return;
    const Point3 o = ray.origin;
    const Vector3& dir = ray.direction;
    // Any NaN or infinite component makes this NaN (inf * 0 is NaN): such rays visit
    // nothing, in O(1). std::max/min would silently drop NaNs further down.
    const Real poison = (o.x + o.y + o.z + dir.x + dir.y + dir.z) * 0;
    if (poison != 0) return;
    const Real dmax = std::max({std::fabs(dir.x), std::fabs(dir.y), std::fabs(dir.z)});
    if (!(dmax > 0)) return;
    if (!(t_min <= t_max)) return;
    Vector3 inv, t0, t1;
    bool parallel[3];
    bool any_parallel = false;
    unsigned mirror = 0;
    for (int a = 0; a < 3; ++a) {
        const Real d = ray.direction[a];
        // A component this small moves the ray less than an ulp across the scene.
        parallel[a] = std::fabs(d) <= dmax * 1e-20;
        if (parallel[a]) {
            any_parallel = true;
            inv[a] = 0;
            const bool inside = o[a] >= bounds_.lo[a] && o[a] <= bounds_.hi[a];
            t0[a] = inside ? -kInfinity : kInfinity;
            t1[a] = inside ? kInfinity : -kInfinity;
            continue;
        }
        inv[a] = 1 / d;
        if (d < 0) mirror |= 1u << a;
        const Real ta = (bounds_.lo[a] - o[a]) * inv[a],
                   tb = (bounds_.hi[a] - o[a]) * inv[a];
        t0[a] = d < 0 ? tb : ta;
        t1[a] = d < 0 ? ta : tb;
    }
    const Real enter = std::max({t0.x, t0.y, t0.z}), exit = std::min({t1.x, t1.y, t1.z});
    if (!(enter <= exit) || exit < t_min || enter > t_max) return;
    if (nodes_[0].count != kInner) {
        const Node& n = nodes_[0];
        if (n.count) visit(&ids_[n.first], size_t(n.count), t_max, enter);
        return;
    }
    // The walk covers only the stretch of the ray inside the primitives' own box: the
    // root can be far larger (no axis shorter than a quarter of the longest), and rays
    // would walk its empty cells to its far side. Every crossing of a primitive lies in
    // its bounds, so in that box; the margins (relative 1e-12 of the distances, and the
    // box's own padding) cover the rounding of these parameters. The caller's t_max
    // still gets what visit leaves in it.
    Real walk_min = t_min, clip_hi = kInfinity;
    if (clip_) {
        Real near = -kInfinity, far = kInfinity;
        for (int a = 0; a < 3; ++a) {
            if (parallel[a]) {
                if (o[a] < clip_lo_[a] || o[a] > clip_hi_[a]) return;
                continue;
            }
            const Real ta = (clip_lo_[a] - o[a]) * inv[a],
                       tb = (clip_hi_[a] - o[a]) * inv[a];
            near = std::max(near, (mirror >> a & 1u) ? tb : ta);
            far = std::min(far, (mirror >> a & 1u) ? ta : tb);
        }
        near -= std::fabs(near) * 1e-12;
        far += std::fabs(far) * 1e-12;
        if (!(near <= far) || far < t_min || near > t_max) return;
        walk_min = std::max(t_min, near);
        clip_hi = far;
    }
    Real walk_max = std::min(t_max, clip_hi);
    auto clipped_visit = [&](const uint32_t* ids, size_t n, Real& walk_t, Real entry) {
        const bool stop = visit(ids, n, t_max, entry);
        walk_t = std::min(t_max, clip_hi);
        return stop;
    };
    const bool large = nodes_.size() > kPrefetchNodes;
    // Mid-plane parameters of the whole tree, computed below from t0/t1 alone; an
    // infinite one (a component just above the parallel cut) takes the geometric walk.
    const bool finite = std::fabs(t0.x) + std::fabs(t0.y) + std::fabs(t0.z) +
                            std::fabs(t1.x) + std::fabs(t1.y) + std::fabs(t1.z) <
                        kInfinity;
    if (top_level_ > 0 && !any_parallel && finite) {
        if (large) {
            walk_top<true>(o, inv, mirror, t0, t1, walk_min, walk_max, clipped_visit,
                           prefetch_leaf);
        } else {
            walk_top<false>(o, inv, mirror, t0, t1, walk_min, walk_max, clipped_visit,
                            prefetch_leaf);
        }
        return;
    }
    const Real rt0[3] = {t0.x, t0.y, t0.z}, rt1[3] = {t1.x, t1.y, t1.z};
    const Cell root{{bounds_.lo.x, bounds_.lo.y, bounds_.lo.z},
                    {bounds_.hi.x, bounds_.hi.y, bounds_.hi.z}};
    const uint32_t first = nodes_[0].first;
    if (any_parallel) {
        if (large) {
            walk<true, true>(o, inv, parallel, mirror, first, rt0, rt1, &root, walk_min,
                             walk_max, clipped_visit, prefetch_leaf);
        } else {
            walk<true, false>(o, inv, parallel, mirror, first, rt0, rt1, &root, walk_min,
                              walk_max, clipped_visit, prefetch_leaf);
        }
    } else if (large) {
        walk<false, true>(o, inv, parallel, mirror, first, rt0, rt1, &root, walk_min,
                          walk_max, clipped_visit, prefetch_leaf);
    } else {
        walk<false, false>(o, inv, parallel, mirror, first, rt0, rt1, &root, walk_min,
                           walk_max, clipped_visit, prefetch_leaf);
    }
}

// The top levels of a tree that is complete there, walked as the grid they are
// (Amanatides and Woo's stepping): a ray's first cell follows from its entry parameter in
// O(1) instead of a descent through K levels, which is what grows with the scene. The
// planes of level K are t0 + (t1 - t0) * j / 2^K per (mirrored) axis, each computed once
// per ray and shared by the two cells it separates, so no ray slips between cells; below
// level K the walk splits those cells at their parameters' midpoints as usual.
template <bool kPrefetch, class Visit, class PrefetchLeaf>
void Octree::walk_top(const Point3& o, const Vector3& inv, unsigned mirror,
                      const Vector3& t0v, const Vector3& t1v, Real t_min, Real& t_max,
                      Visit& visit, PrefetchLeaf& prefetch_leaf) const {
    const int k = top_level_;
    const int side = 1 << k;
    const Real step = Real(1) / Real(side);  // exact: a power of two
    const Real t0[3] = {t0v.x, t0v.y, t0v.z}, t1[3] = {t1v.x, t1v.y, t1v.z};
    const Real span[3] = {t1[0] - t0[0], t1[1] - t0[1], t1[2] - t0[2]};
    auto plane = [&](int a, int j) {
        return j >= side ? t1[a] : t0[a] + span[a] * (Real(j) * step);
    };
    // The entry-plane rule of the walk below, at max(entry, t_min): the cell left of the
    // first plane that is not before the start.
    const Real start = std::max({t0[0], t0[1], t0[2], t_min});
    int j[3];
    Real c0[3], c1[3];
    for (int a = 0; a < 3; ++a) {
        const Real r = (start - t0[a]) / span[a] * Real(side);
        int ja = r > 0 ? int(std::min(r, Real(side - 1))) : 0;
        while (ja > 0 && !(plane(a, ja) < start)) --ja;
        while (ja < side - 1 && plane(a, ja + 1) < start) ++ja;
        j[a] = ja;
        c0[a] = plane(a, ja);
        c1[a] = plane(a, ja + 1);
    }
    // Real cell index from mirrored ones: a mirrored axis counts from the far side.
    const int flip[3] = {(mirror & 1u) ? side - 1 : 0, (mirror & 2u) ? side - 1 : 0,
                         (mirror & 4u) ? side - 1 : 0};
    for (;;) {
        const Real enter = std::max({c0[0], c0[1], c0[2]});
        const Real exit = std::min({c1[0], c1[1], c1[2]});
        if (enter > t_max) return;
        const int axis =
            (c1[0] <= c1[1] && c1[0] <= c1[2]) ? 0 : (c1[1] <= c1[2] ? 1 : 2);
        // The next cell's children or ids, fetched while this cell is walked.
        if constexpr (kPrefetch) {
            if (j[axis] + 1 < side) {
                int jn[3] = {j[0], j[1], j[2]};
                ++jn[axis];
                const Node& s =
                    top_[uint32_t(jn[0] ^ flip[0]) | uint32_t(jn[1] ^ flip[1]) << k |
                         uint32_t(jn[2] ^ flip[2]) << (2 * k)];
                if (s.count == kInner) {
                    __builtin_prefetch(nodes_.data() + s.first);
                } else {
                    __builtin_prefetch(ids_.data() + s.first);
                    prefetch_leaf(s.first);
                }
            }
        }
        if (!(exit < t_min) && enter <= exit) {
            const uint32_t cell = uint32_t(j[0] ^ flip[0]) |
                                  uint32_t(j[1] ^ flip[1]) << k |
                                  uint32_t(j[2] ^ flip[2]) << (2 * k);
            const Node n = top_[cell];
            if (n.count != kInner) {
                if (n.count && visit(&ids_[n.first], size_t(n.count), t_max, enter))
                    return;
            } else if (walk<false, kPrefetch>(o, inv, nullptr, mirror, n.first, c0, c1,
                                              nullptr, t_min, t_max, visit,
                                              prefetch_leaf)) {
                return;
            }
        }
        if (++j[axis] == side) return;
        c0[axis] = c1[axis];
        c1[axis] = plane(axis, j[axis] + 1);
    }
}

template <bool kParallel, bool kPrefetch, class Visit, class PrefetchLeaf>
bool Octree::walk(const Point3& o, const Vector3& inv, const bool* parallel,
                  unsigned mirror, uint32_t first, const Real* root_t0,
                  const Real* root_t1, const Cell* root_cell, Real t_min, Real& t_max,
                  Visit& visit, PrefetchLeaf& prefetch_leaf) const {
    // Plain arrays, not Vector3: its default member initialisers would zero the whole
    // stack on every ray.
    struct Frame {
        Real t0[3], tm[3], t1[3];
        uint32_t first;  // the node's first child
        unsigned child;  // next mirrored child to visit; 8 = done
    };
    Frame stack[kMaxDepth + 1];
    // Cells are tracked only when a mid-plane parameter needs the geometry.
    Cell cells[kParallel ? kMaxDepth + 1 : 1];
    // Mid-plane parameters of a frame's cell and its first child (the entry-plane rule).
    // The rule is applied at max(entry, t_min): a ray starting inside the cell begins in
    // the child holding its start, skipping the children behind it in O(1).
    auto open = [&](Frame& f, const Cell& cell) {
        for (int a = 0; a < 3; ++a) {
            if constexpr (kParallel) {
                const Real mid = (cell.lo[a] + cell.hi[a]) * 0.5;
                if (parallel[a]) {
                    f.tm[a] = o[a] < mid ? kInfinity : -kInfinity;
                } else {
                    f.tm[a] = (mid - o[a]) * inv[a];
                }
            } else {
                f.tm[a] = (f.t0[a] + f.t1[a]) * 0.5;
            }
        }
        const Real enter = std::max({f.t0[0], f.t0[1], f.t0[2], t_min});
        f.child = unsigned(f.tm[0] < enter) | unsigned(f.tm[1] < enter) << 1 |
                  unsigned(f.tm[2] < enter) << 2;
    };
    for (int a = 0; a < 3; ++a) {
        stack[0].t0[a] = root_t0[a];
        stack[0].t1[a] = root_t1[a];
    }
    if constexpr (kParallel) cells[0] = *root_cell;
    stack[0].first = first;
    open(stack[0], cells[0]);
    int top = 0;
    while (top >= 0) {
        Frame& f = stack[top];
        if (f.child >= 8) {
            --top;
            continue;
        }
        const unsigned c = f.child;
        Real c0[3], c1[3];
        for (int a = 0; a < 3; ++a) {
            const bool high = c & (1u << a);
            c0[a] = high ? f.tm[a] : f.t0[a];
            c1[a] = high ? f.t1[a] : f.tm[a];
        }
        // Next sibling: step across the exit plane that comes first; leaving the parent
        // through its own far plane ends this frame.
        const int axis =
            (c1[0] <= c1[1] && c1[0] <= c1[2]) ? 0 : (c1[1] <= c1[2] ? 1 : 2);
        f.child = (c & (1u << axis)) ? 8 : (c | (1u << axis));
        const Real enter = std::max({c0[0], c0[1], c0[2]});
        const Real exit = std::min({c1[0], c1[1], c1[2]});
        // Front to back: every later cell starts at or after this one.
        if (enter > t_max) return true;
        if (exit < t_min || !(enter <= exit)) continue;
        const unsigned real = c ^ mirror;
        const Node n = nodes_[f.first + real];
        // The next sibling's node sits in the line just read; fetching what it points to
        // (its children or its ids) now overlaps that miss with this child's work, which
        // matters once the tree outgrows the caches. After the last sibling (child 8) it
        // fetches a sibling in vain.
        if constexpr (kPrefetch) {
            const Node& s = nodes_[f.first + ((f.child & 7) ^ mirror)];
            if (s.count == kInner) {
                __builtin_prefetch(nodes_.data() + s.first);
            } else {
                __builtin_prefetch(ids_.data() + s.first);
                prefetch_leaf(s.first);
            }
        }
        if (n.count != kInner) {
            if (n.count && visit(&ids_[n.first], size_t(n.count), t_max, enter))
                return true;
            continue;
        }
        Frame& g = stack[top + 1];
        for (int a = 0; a < 3; ++a) {
            g.t0[a] = c0[a];
            g.t1[a] = c1[a];
        }
        g.first = n.first;
        if constexpr (kParallel) {
            const Cell& pc = cells[top];
            Cell& cc = cells[top + 1];
            for (int a = 0; a < 3; ++a) {
                const Real mid = (pc.lo[a] + pc.hi[a]) * 0.5;
                const bool high = real & (1u << a);
                cc.lo[a] = high ? mid : pc.lo[a];
                cc.hi[a] = high ? pc.hi[a] : mid;
            }
            open(g, cc);
        } else {
            open(g, cells[0]);
        }
        ++top;
    }
    return false;
}

}  // namespace povwall::octree
