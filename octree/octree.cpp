// Octree builder: recursive subdivision with exact cell/primitive overlap tests (through
// the caller's callback; octree/overlap.h offers CGAL-backed ones) and a surface-area
// cost estimate. The top levels are split serially, the subtrees below are built in
// parallel into private arrays and stitched into the flat node array afterwards.
#include "octree/octree.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <thread>

#include "core/memory.h"

namespace povwall::octree {
namespace {

bool finite_box(const Bounds3& b) {
    for (int a = 0; a < 3; ++a) {
        if (!(std::fabs(b.lo[a]) < kInfinity && std::fabs(b.hi[a]) < kInfinity))
            return false;
    }
    return !b.empty();
}

Bounds3 child_box(const Bounds3& box, const Point3& mid, unsigned c) {
    Bounds3 cb;
    for (int a = 0; a < 3; ++a) {
        bool high = c & (1u << a);
        cb.lo[a] = high ? mid[a] : box.lo[a];
        cb.hi[a] = high ? box.hi[a] : mid[a];
    }
    return cb;
}

using Node = Octree::Node;

// A subtree left for a worker thread: its root node (already in the global array) and
// ids.
struct Task {
    uint32_t node = 0;
    Bounds3 box;
    int depth = 0;
    uint64_t allowance = 0;  // the references the subtree may add (Builder::build)
    std::vector<uint32_t> ids;
    // Filled by the worker: local node 0 is the task root.
    Octree::NodeArray nodes;
    std::vector<uint32_t> leaf_ids;
    int max_depth = 0;
};

class Builder {
  public:
    Builder(const BuildInput& in, const BuildOptions& opt, Real min_cell)
        : in_(in), opt_(opt), min_cell_(min_cell) {}

    // Builds the subtree of nodes[index] (already allocated) over `ids`, adding at most
    // `allowance` references beyond ids.size() (the reference budget, shared out by each
    // split to its children in proportion to their references: a subtree never starves
    // another, and the tree does not depend on the order threads build it in). At
    // spawn_depth the node is handed to `tasks` instead (null: never).
    void build(Octree::NodeArray& nodes, std::vector<uint32_t>& out, uint32_t index,
               std::vector<uint32_t>& ids, const Bounds3& box, int depth,
               uint64_t allowance, int& max_depth, std::vector<Task>* tasks,
               int spawn_depth) {
        max_depth = std::max(max_depth, depth);
        if (tasks && depth == spawn_depth) {
            Task t;
            t.node = index;
            t.box = box;
            t.depth = depth;
            t.allowance = allowance;
            t.ids = std::move(ids);
            tasks->push_back(std::move(t));
            return;
        }
        std::array<std::vector<uint32_t>, 8> kids;
        if (!split(ids, box, depth, allowance, kids)) {
            nodes[index] = Node{uint32_t(out.size()), uint32_t(ids.size())};
            out.insert(out.end(), ids.begin(), ids.end());
            return;
        }
        size_t total = 0;
        for (const auto& k : kids) total += k.size();
        // What the split adds comes out of the allowance (split() kept it within); one
        // whose exact tests dropped references gives them back.
        const uint64_t left = allowance + ids.size() - total;
        std::vector<uint32_t>().swap(ids);
        const uint32_t first = uint32_t(nodes.size());
        nodes[index] = Node{first, Octree::kInner};
        nodes.resize(first + 8);
        const Point3 mid = box.centre();
        for (unsigned c = 0; c < 8; ++c) {
            const uint64_t share =
                total ? uint64_t(double(left) * double(kids[c].size()) / double(total))
                      : 0;
            build(nodes, out, first + c, kids[c], child_box(box, mid, c), depth + 1,
                  share, max_depth, tasks, spawn_depth);
        }
    }

    uint64_t exact_tests() const { return exact_tests_; }
    uint64_t exact_rejected() const { return exact_rejected_; }
    uint64_t inseparable_leaves() const { return inseparable_; }
    uint64_t budget_leaves() const { return budget_leaves_; }

  private:
    // True when the ids are copies: they have at most leaf_primitives distinct bounds,
    // more than two ids per distinct bounds on average. Splitting cannot separate equal
    // bounds (copies of one part placed at one transform), so these cells would stay this
    // full to the deepest level. (Two per bounds is left to the split: the two triangles
    // of a quad share their bounds but the exact test separates them.)
    bool copies(const std::vector<uint32_t>& ids) const {
        const size_t most = size_t(std::max(opt_.leaf_primitives, 1));
        const Bounds3* seen[64];
        size_t distinct = 0;
        for (uint32_t id : ids) {
            const Bounds3& b = in_.bounds[id];
            bool known = false;
            for (size_t k = 0; k < distinct && !known; ++k)
                known = seen[k]->lo == b.lo && seen[k]->hi == b.hi;
            if (known) continue;
            if (distinct == most || distinct == 64) return false;
            seen[distinct++] = &b;
        }
        return ids.size() > 2 * distinct;
    }

    // Distributes `ids` over the 8 children; false: this cell stays a leaf.
    bool split(const std::vector<uint32_t>& ids, const Bounds3& box, int depth,
               uint64_t allowance, std::array<std::vector<uint32_t>, 8>& kids) {
        const size_t n = ids.size();
        auto cost_of = [&](uint32_t id) {
            return in_.cost.empty() ? Real(1) : Real(in_.cost[id]);
        };
        Real cost = 0;
        for (uint32_t id : ids) cost += cost_of(id);
        if ((n <= size_t(opt_.leaf_primitives) && cost <= Real(opt_.leaf_primitives)) ||
            n <= 1 || depth >= opt_.max_depth)
            return false;
        const Vector3 size = box.diagonal();
        if (std::min({size.x, size.y, size.z}) <= min_cell_) return false;
        if (copies(ids)) {
            ++inseparable_;
            return false;
        }
        const Point3 mid = box.centre();
        Bounds3 child_boxes[8];
        for (unsigned c = 0; c < 8; ++c) child_boxes[c] = child_box(box, mid, c);
        uint64_t tests = 0, rejected = 0;
        size_t total = 0;
        Real total_cost = 0;
        for (uint32_t id : ids) {
            const Bounds3& b = in_.bounds[id];
            // Closed cells: a primitive touching the mid-plane belongs to both sides.
            // Child c lies on the high side of axis a when bit a of c is set; per axis,
            // the children on a touched side, and the children touched on every axis.
            constexpr unsigned kLowSide[3] = {0x55, 0x33, 0x0f};
            unsigned touched = 0xff;
            for (int a = 0; a < 3; ++a) {
                touched &= (b.lo[a] <= mid[a] ? kLowSide[a] : 0u) |
                           (b.hi[a] >= mid[a] ? ~kLowSide[a] & 0xffu : 0u);
            }
            // One child only: the primitive touches this cell, so it touches that child.
            bool single = (touched & (touched - 1)) == 0;
            for (unsigned c = 0; c < 8; ++c) {
                if (!(touched & (1u << c))) continue;
                if (!single && in_.overlaps) {
                    ++tests;
                    if (!in_.overlaps(id, child_boxes[c])) {
                        ++rejected;
                        continue;
                    }
                }
                kids[c].push_back(id);
                ++total;
                total_cost += cost_of(id);
            }
        }
        exact_tests_ += tests;
        exact_rejected_ += rejected;
        // Surface-area estimate: a ray crossing this cell crosses each child with
        // probability 1/4. Split when the expected tests drop by more than the extra node
        // steps cost; this stops when children barely reduce the references (everything
        // crossing the centre: 8 copies each). The one-level estimate ignores that
        // children split further, so a split that about breaks even (a row of primitives
        // cut by two mid-planes: 4 copies each) is taken too, provided every child is
        // clearly smaller (else primitives covering whole cells would be split forever).
        size_t max_child = 0, min_filled = n, filled = 0;
        for (const auto& k : kids) {
            max_child = std::max(max_child, k.size());
            if (!k.empty()) {
                ++filled;
                min_filled = std::min(min_filled, k.size());
            }
        }
        auto stay_leaf = [&] {
            for (auto& k : kids) std::vector<uint32_t>().swap(k);
            return false;
        };
        // Every child that gets anything gets everything, in several copies: the split
        // separates nothing (nested or heavily overlapping primitives) and only
        // multiplies references.
        if (filled > 1 && min_filled == n) {
            ++inseparable_;
            return stay_leaf();
        }
        const Real leaf_cost = cost;
        const Real split_cost = opt_.traversal_cost * 2 + 0.25 * total_cost;
        const bool pays = split_cost < leaf_cost;
        const bool breaks_even = split_cost < leaf_cost * 1.25 && max_child * 4 <= n * 3;
        if (!pays && !breaks_even) return stay_leaf();
        // The references this split adds, against the subtree's share of the budget.
        if (total > n && uint64_t(total - n) > allowance) {
            ++budget_leaves_;
            return stay_leaf();
        }
        return true;
    }

    const BuildInput& in_;
    const BuildOptions& opt_;
    const Real min_cell_;
    std::atomic<uint64_t> exact_tests_{0}, exact_rejected_{0};
    std::atomic<uint64_t> inseparable_{0}, budget_leaves_{0};
};

}  // namespace

void Octree::build(const BuildInput& input, const BuildOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    nodes_.clear();
    ids_.clear();
    stats_ = {};
    top_.clear();
    top_level_ = 0;
    primitive_count_ = input.bounds.size();
    bounds_ = Bounds3{};
    std::vector<uint32_t> all;
    all.reserve(input.bounds.size());
    for (uint32_t i = 0; i < input.bounds.size(); ++i) {
        // Unbounded primitives are the caller's to test on every ray.
        if (!finite_box(input.bounds[i])) continue;
        bounds_.extend(input.bounds[i]);
        all.push_back(i);
    }
    if (all.empty()) return;
    const Bounds3 tight = bounds_;
    // Give every axis extent (flat scenes) so cells have volume and mid-planes separate.
    const Vector3 ext = bounds_.diagonal();
    const Real ext_max = std::max({ext.x, ext.y, ext.z});
    Real mag = 0;
    for (int a = 0; a < 3; ++a) {
        mag = std::max({mag, std::fabs(bounds_.lo[a]), std::fabs(bounds_.hi[a])});
    }
    const Real pad = std::max({ext_max * 1e-6, mag * 1e-12, 1e-300});
    // Every axis also grows by a few ulps of the coordinates: a ray that only touches
    // the root (along an edge or at a corner, where the slab parameters computed with
    // the reciprocal direction can cross by an ulp) must still reach the leaf there.
    // A black box's tree ends where its region does, and rays leave one box and enter
    // the next exactly on that wall; a surface crossing on the wall must be found.
    const Real touch = std::max(mag * 1e-13, 1e-300);
    for (int a = 0; a < 3; ++a) {
        const Real grow = ext[a] < pad ? pad : touch;
        bounds_.lo[a] -= grow;
        bounds_.hi[a] += grow;
    }
    // No axis of the root is shorter than a quarter of the longest: every split halves
    // all three axes, so a thin axis of a root shaped like the scene (a floor of objects
    // 100 wide and 1 high) would be cut into slivers long before the wide ones separate
    // anything, each object copied into every sliver. A quarter, not a cube: roots up to
    // that flat keep their complete top levels (the dense top walk), which the seed
    // scene's (3:1) needs; the lathe and text fields gain the same from 4 as from 1
    // (docs/performance.md). The root grows up from the scene's low corner, so the scene
    // does not sit on the new mid-planes.
    const Real side = std::max({bounds_.hi.x - bounds_.lo.x, bounds_.hi.y - bounds_.lo.y,
                                bounds_.hi.z - bounds_.lo.z});
    for (int a = 0; a < 3; ++a)
        bounds_.hi[a] = std::max(bounds_.hi[a], bounds_.lo[a] + side / 4);
    // The primitives' own box, padded as a flat axis of the root is, within the root:
    // where it is much smaller than the root (a field of objects 100 wide and 1.5 high
    // under a root 25 high), traversal walks only the rays' stretch inside it.
    clip_ = false;
    for (int a = 0; a < 3; ++a) {
        clip_lo_[a] = std::max(bounds_.lo[a], tight.lo[a] - pad);
        clip_hi_[a] = std::min(bounds_.hi[a], tight.hi[a] + pad);
        const Real root_extent = bounds_.hi[a] - bounds_.lo[a];
        if (clip_hi_[a] - clip_lo_[a] < root_extent * 0.75) clip_ = true;
    }
    BuildOptions opt = options;
    opt.max_depth = std::clamp(opt.max_depth, 0, kMaxDepth);
    if (int(all.size()) < opt.flat_threshold) {
        opt.max_depth = 0;
        stats_.flat = true;
    }
    // Cells narrower than this lose their mid-plane to rounding.
    const Real min_cell = mag * 1e-13;
    const uint64_t budget =
        uint64_t(std::max(0.0, opt.max_references_per_primitive) * Real(all.size())) +
        opt.reference_slack;
    Builder builder(input, opt, min_cell);
    nodes_.push_back(Node{});
    int threads =
        opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
    threads = std::max(threads, 1);
    std::vector<Task> tasks;
    int max_depth = 0;
    // 64 subtrees (depth 2) keep a few threads busy despite uneven scenes.
    const int spawn_depth = threads > 1 ? 2 : -1;
    builder.build(nodes_, ids_, 0, all, bounds_, 0,
                  budget - std::min<uint64_t>(budget, all.size()), max_depth,
                  threads > 1 ? &tasks : nullptr, spawn_depth);
    if (!tasks.empty()) {
        std::atomic<size_t> next{0};
        auto work = [&] {
            for (size_t i; (i = next.fetch_add(1)) < tasks.size();) {
                Task& t = tasks[i];
                t.nodes.resize(1);
                t.max_depth = t.depth;
                builder.build(t.nodes, t.leaf_ids, 0, t.ids, t.box, t.depth, t.allowance,
                              t.max_depth, nullptr, -1);
            }
        };
        std::vector<std::thread> pool;
        for (int i = 1; i < std::min<int>(threads, int(tasks.size())); ++i) {
            pool.emplace_back(work);
        }
        stats_.threads = int(pool.size()) + 1;
        work();
        for (auto& th : pool) th.join();
        for (Task& t : tasks) {
            const uint32_t node_base =
                uint32_t(nodes_.size()) - 1;  // local i -> base + i
            const uint32_t id_base = uint32_t(ids_.size());
            auto relocate = [&](Node n) {
                if (n.count == kInner) {
                    n.first += node_base;
                } else {
                    n.first += id_base;
                }
                return n;
            };
            nodes_[t.node] = relocate(t.nodes[0]);
            for (size_t i = 1; i < t.nodes.size(); ++i)
                nodes_.push_back(relocate(t.nodes[i]));
            ids_.insert(ids_.end(), t.leaf_ids.begin(), t.leaf_ids.end());
            max_depth = std::max(max_depth, t.max_depth);
            t = Task{};
        }
    }
    for (const Node& n : nodes_) {
        if (n.count != kInner) {
            ++stats_.leaves;
            stats_.references += n.count;
        }
    }
    build_dense_top(opt.dense_top_max);
    // Large trees are walked at random: their nodes and references on 2 MB pages.
    move_to_huge_pages(nodes_);
    move_to_huge_pages(ids_);
    stats_.nodes = int(nodes_.size());
    stats_.depth = max_depth;
    stats_.dense_top = top_level_;
    stats_.exact_tests = builder.exact_tests();
    stats_.exact_rejected = builder.exact_rejected();
    stats_.inseparable_leaves = builder.inseparable_leaves();
    stats_.budget_leaves = builder.budget_leaves();
    stats_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Octree::build_dense_top(int max_level) {
    // The deepest level K, up to max_level, whose 8^K cells can each stand for one node:
    // above K every node is inner or an empty leaf (copied into each cell of K it
    // covers, so the grid walk steps over it), and at least half of the cells of K that
    // meet the clip box are real nodes of level K. Without the second rule a root with
    // a few dense corners would be walked cell by cell across its empty middle, where
    // the descent crosses it in a few large leaves. Below two levels the descent it
    // saves costs less than the stepping.
    struct Entry {
        Node node;
        uint32_t x, y, z;  // cell coordinates at the current level
        bool real;         // a node of this level, not an empty leaf copied down
    };
    std::vector<Entry> level{{nodes_[0], 0, 0, 0, true}}, best;
    int best_k = 0;
    const Real root_lo[3] = {bounds_.lo.x, bounds_.lo.y, bounds_.lo.z};
    const Real root_ext[3] = {bounds_.hi.x - bounds_.lo.x, bounds_.hi.y - bounds_.lo.y,
                              bounds_.hi.z - bounds_.lo.z};
    for (int k = 1; k <= max_level; ++k) {
        std::vector<Entry> next;
        next.reserve(level.size() * 8);
        bool admissible = true;
        for (const Entry& e : level) {
            if (e.node.count != kInner && e.node.count != 0) {
                admissible = false;
                break;
            }
            for (uint32_t c = 0; c < 8; ++c) {
                const bool inner = e.node.count == kInner;
                next.push_back({inner ? nodes_[e.node.first + c] : e.node,
                                e.x << 1 | (c & 1u), e.y << 1 | (c >> 1 & 1u),
                                e.z << 1 | (c >> 2 & 1u), inner});
            }
        }
        if (!admissible) break;
        level.swap(next);
        // Cells of level k meeting the clip box, and how many of them are real nodes.
        const Real cells = Real(1u << k);
        uint32_t lo_cell[3], hi_cell[3];
        for (int a = 0; a < 3; ++a) {
            auto cell_of = [&](Real v) {
                const Real r = std::floor((v - root_lo[a]) / root_ext[a] * cells);
                return uint32_t(std::clamp(r, Real(0), cells - 1));
            };
            lo_cell[a] = cell_of(clip_lo_[a]);
            hi_cell[a] = cell_of(clip_hi_[a]);
        }
        size_t meeting = 0, real = 0;
        for (const Entry& e : level) {
            const uint32_t v[3] = {e.x, e.y, e.z};
            bool meets = true;
            for (int a = 0; a < 3; ++a)
                meets = meets && v[a] >= lo_cell[a] && v[a] <= hi_cell[a];
            meeting += meets;
            real += meets && e.real;
        }
        if (k >= 2 && 2 * real >= meeting) {
            best_k = k;
            best = level;
        }
    }
    if (best_k < 2) return;
    const uint32_t side = 1u << best_k;
    top_.assign(size_t(side) * side * side, Node{});
    for (const Entry& e : best) top_[e.x | e.y << best_k | e.z << (2 * best_k)] = e.node;
    top_level_ = best_k;
}

}  // namespace povwall::octree
