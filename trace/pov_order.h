// The order in which POV-Ray 3.7 tests its frame-level objects along a ray, which decides
// exact ties in depth (coincident surfaces): POV-Ray keeps the first intersection found
// and replaces it only by one with a strictly smaller depth (Trace::FindIntersection,
// 3.7:source/backend/render/trace.cpp:204-257; Intersect_BBox_Tree,
// 3.7:source/backend/bounding/bbox.cpp:394-445), so of two surfaces at the same depth the
// object tested first is seen.
//
// - Without the bounding-slab tree (fewer than Bounding_Threshold frame-level objects,
//   light sources included, or bounding off), objects are tested in the order of
//   POV-Ray's object list: the scene's order, plain unions opened into their children
//   (Parser::Link_To_Frame, 3.7:source/backend/parser/parse.cpp:9624-9730).
// - With it (bounding method 1, the default), a best-first walk of the tree: a binary
//   min-heap keyed by where the ray enters each node's single-precision box
//   (Check_And_Enqueue), infinite nodes keyed -MAX_DISTANCE. The infinite objects sit in
//   the root's first child, so they are all tested before any finite object; finite
//   objects are tested in the order their boxes are entered, and objects filed under the
//   same key come out in the order the heap's sift-up and sift-down leave them (a new
//   element rises only past strictly larger keys; removal moves the last element to the
//   top and sinks it past strictly smaller children, preferring the right child on equal
//   keys). The tree is POV-Ray's sort_and_split: boxes sorted (stably: glibc's qsort is a
//   merge sort) by the float 2 lo + len along the axis find_axis picks, split where the
//   surface-area heuristic is lowest, groups of at most 4 closed into nodes, level by
//   level.
// This module rebuilds that list and tree from the scene (never its code) and replays the
// walk for one ray: PreparedScene asks it only on an exact tie.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scene.h"
#include "trace/pov_bounds.h"

namespace povwall::trace {

// What POV-Ray's object list needs of a whole scene whose parse kept only some of its
// objects (a black-box worker keeps those in its boxes): every top-level object's
// frame-level boxes, recorded in parse order, kept or left out. With it a worker's ties
// in depth and its slab-tree tests are those of the whole scene, as in one process.
class PovWholeScene {
  public:
    // Every top-level object, in parse order.
    void add(const Object& o, bool kept);

    // The frame-level boxes of all top-level objects, in order.
    const std::vector<PovBBox>& boxes() const { return boxes_; }
    // Whole-scene object i's frame objects: boxes()[first_frame(i), first_frame(i + 1)).
    uint32_t first_frame(size_t i) const {
        return i < first_frame_.size() ? first_frame_[i] : uint32_t(boxes_.size());
    }
    size_t object_count() const { return first_frame_.size(); }
    // The whole-scene index of the k-th kept object (Scene::objects[k]).
    uint32_t whole_index(size_t k) const { return kept_[k]; }
    size_t kept_count() const { return kept_.size(); }

  private:
    std::vector<PovBBox> boxes_;
    std::vector<uint32_t> first_frame_;
    std::vector<uint32_t> kept_;
};

// POV-Ray's object list: the frame-level objects in its order.
struct PovFrameList {
    // The objects when the scene holds them all; else (a worker's part, listed from the
    // whole scene's record) their boxes. Only a tie needs the boxes: they are not
    // computed for a whole scene's list, which every prepare makes.
    std::vector<const Object*> objects;
    std::vector<PovBBox> boxes;
    size_t size() const { return objects.empty() ? boxes.size() : objects.size(); }
    PovBBox box(size_t f) const;
    // Frame index of scene.objects[i] (its first frame-level object when it is a plain
    // union), and of light l's looks_like object (~0u without one).
    std::vector<uint32_t> first_of_object, of_light;
    // Whether POV-Ray builds its bounding-slab tree for this scene.
    bool slab_tree = false;
};

// `bounding_threshold`: POV-Ray's Bounding_Threshold (kPovBoundingOff: bounding off).
// `whole`: the whole scene's record when `scene` holds only some of its objects.
PovFrameList pov_frame_list(const Scene& scene,
                            size_t bounding_threshold = kPovBoundingThreshold,
                            const PovWholeScene* whole = nullptr);

class PovTestOrder {
  public:
    explicit PovTestOrder(const PovFrameList& list);

    // Whether POV-Ray tests frame object `a` before frame object `b` along `ray` (unit
    // direction or not: it is normalised as POV-Ray's rays are). A finite object whose
    // box the ray misses in POV-Ray's arithmetic is never tested: it comes last.
    bool tests_first(const Ray& ray, uint32_t a, uint32_t b) const;

    // With the slab tree, the frame objects in the order POV-Ray tests them along `ray`
    // (those whose box it meets; tests, diagnostics). Without it: empty (list order).
    std::vector<uint32_t> order(const Ray& ray) const;

    bool slab_tree() const { return slab_tree_; }
    size_t node_count() const { return nodes_.size(); }

  private:
    struct Node {
        PovBBox box;
        bool infinite = false;
        uint32_t first = 0, count = 0;  // children in children_; count 0: a leaf
        uint32_t object = ~0u;          // a leaf's frame index
    };
    // Walks the tree for `ray`, calling on_leaf(frame index) in test order until it
    // returns true.
    template <class OnLeaf>
    void walk(const Ray& ray, OnLeaf&& on_leaf) const;

    bool slab_tree_ = false;
    std::vector<Node> nodes_;
    std::vector<uint32_t> children_;
    uint32_t root_ = ~0u;
};

}  // namespace povwall::trace
