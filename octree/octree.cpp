#include "octree/octree.h"

#include <chrono>

namespace povwall::octree {
namespace {

bool boxes_overlap(const Bounds3& a, const Bounds3& b) {
    return a.lo.x <= b.hi.x && a.hi.x >= b.lo.x && a.lo.y <= b.hi.y && a.hi.y >= b.lo.y &&
           a.lo.z <= b.hi.z && a.hi.z >= b.lo.z;
}

}  // namespace

void Octree::build(const BuildInput& input, const BuildOptions& options) {
    auto start = std::chrono::steady_clock::now();
    nodes_.clear();
    ids_.clear();
    stats_ = {};
    primitive_count_ = input.bounds.size();
    bounds_ = Bounds3{};
    for (const Bounds3& b : input.bounds) bounds_.extend(b);
    if (input.bounds.empty()) return;
    // Pad flat scenes so every cell has volume.
    Vector3 d = bounds_.diagonal();
    Real pad = std::max({d.x, d.y, d.z}) * 1e-6 + 1e-9;
    bounds_.lo -= Vector3(pad);
    bounds_.hi += Vector3(pad);
    std::vector<uint32_t> all(input.bounds.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    nodes_.push_back(Node{bounds_});
    BuildOptions opt = options;
    if (int(all.size()) < opt.flat_threshold) opt.max_depth = 0;
    opt.max_depth = std::min(opt.max_depth, 30);
    build_node(0, all, 0, input, opt);
    for (const Node& n : nodes_) {
        if (n.leaf) {
            ++stats_.leaves;
            stats_.references += n.count;
        }
    }
    stats_.nodes = int(nodes_.size());
    stats_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Octree::build_node(uint32_t node, std::vector<uint32_t>& ids, int depth,
                        const BuildInput& in, const BuildOptions& opt) {
    stats_.depth = std::max(stats_.depth, depth);
    if (depth >= opt.max_depth || int(ids.size()) <= opt.leaf_primitives) {
        nodes_[node].first = uint32_t(ids_.size());
        nodes_[node].count = uint32_t(ids.size());
        nodes_[node].leaf = true;
        ids_.insert(ids_.end(), ids.begin(), ids.end());
        return;
    }
    const Bounds3 box = nodes_[node].box;
    const Point3 mid = box.centre();
    std::vector<uint32_t> child_ids[8];
    size_t total = 0;
    for (int c = 0; c < 8; ++c) {
        Bounds3 cb;
        cb.lo = {(c & 1) ? mid.x : box.lo.x, (c & 2) ? mid.y : box.lo.y, (c & 4) ? mid.z : box.lo.z};
        cb.hi = {(c & 1) ? box.hi.x : mid.x, (c & 2) ? box.hi.y : mid.y, (c & 4) ? box.hi.z : mid.z};
        for (uint32_t id : ids) {
            if (!boxes_overlap(in.bounds[id], cb)) continue;
            if (in.overlaps && !in.overlaps(id, cb)) continue;
            child_ids[c].push_back(id);
        }
        total += child_ids[c].size();
    }
    // Splitting pays only when the children hold clearly fewer references than a leaf here.
    if (total > ids.size() * 4) {
        nodes_[node].first = uint32_t(ids_.size());
        nodes_[node].count = uint32_t(ids.size());
        nodes_[node].leaf = true;
        ids_.insert(ids_.end(), ids.begin(), ids.end());
        return;
    }
    uint32_t first = uint32_t(nodes_.size());
    nodes_[node].leaf = false;
    nodes_[node].first = first;
    nodes_[node].count = 0;
    for (int c = 0; c < 8; ++c) {
        Bounds3 cb;
        cb.lo = {(c & 1) ? mid.x : box.lo.x, (c & 2) ? mid.y : box.lo.y, (c & 4) ? mid.z : box.lo.z};
        cb.hi = {(c & 1) ? box.hi.x : mid.x, (c & 2) ? box.hi.y : mid.y, (c & 4) ? box.hi.z : mid.z};
        nodes_.push_back(Node{cb});
    }
    ids.clear();
    ids.shrink_to_fit();
    for (int c = 0; c < 8; ++c) build_node(first + c, child_ids[c], depth + 1, in, opt);
}

}  // namespace povwall::octree
