// Which children of a CSG with many children a ray or a point can concern. POV-Ray
// tests every child of a CSG for every ray, and in a merge every sibling's inside for
// every crossing: a transparent merge of 10^4 triangles (an exporter's molecular surface)
// costs 10^4 surface tests and 10^8 inside tests a ray. The index answers the same
// questions from box trees over the children: the crossings and inside tests it leaves
// out are those that cannot exist, and the rest run in the children's order, so the image
// is the one the full walk gives.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/box_tree.h"
#include "core/scene.h"

namespace povwall::trace {

struct CsgChildIndex {
    // Children whose surface lies in a finite box (object_world_bounds, padded): the ray
    // meets them only where its line meets the box. `surface_children[e]`: the child of
    // tree element e.
    BoxTree surfaces;
    std::vector<uint32_t> surface_children;
    // Every other child (unbounded, bounded_by, an empty box), in order.
    std::vector<uint32_t> surface_always;

    // Children boxed with the box of each (padded), the tree over them.
    struct Boxed {
        BoxTree tree;
        std::vector<uint32_t> children;
        std::vector<Bounds3> boxes;
        // The children (of these) whose box holds p, in no particular order.
        void holding(const Point3& p, std::vector<uint32_t>& scratch,
                     std::vector<uint32_t>& out) const;
    };
    // The children's insides as the CSG's rule tests them, per how the CSG is held (0: as
    // written, 1: inverted; each child then held as the rule holds it).
    struct Insides {
        Boxed within;   // inside only within its box (a solid held as written)
        Boxed outside;  // inside everywhere outside its box (a solid held inverted)
        std::vector<uint32_t> anywhere;  // the rest that can be inside (a plane, ...)
        std::vector<uint32_t> never;     // never inside (a triangle, ...)
    };
    Insides insides[2];
    // Some child has no_shadow, no_image, no_reflection or no_radiosity: a ray may leave
    // it out of a merge's tests (csg_skips).
    bool flagged = false;
};

// Builds the index of every CSG under `obj` with enough children to gain from one
// (once; by any thread). Called when a scene is prepared: the children are final then.
void index_csg_children(const Object& obj);

// The CSG's index, or null when it has none (few children, or not prepared).
const CsgChildIndex* csg_child_index(const Csg& csg);

// Whether POV-Ray finds no point inside `obj` held this way (`inverted`: once more
// inverted, as a difference's later part or an inverted CSG's child): a surface with no
// inside, or a CSG whose rule leaves none.
bool never_inside(const Object& obj, bool inverted);

// Scratch lists for a walk over an indexed CSG, one set per nesting level of the walks
// under way on this thread (no allocation per ray once warm).
struct CsgScratch {
    std::vector<uint32_t> children, candidates, holding;
};
CsgScratch& csg_scratch(int depth);

// The nesting level of the indexed walk entered (when `entered`) for its lifetime.
class CsgScratchLevel {
  public:
    explicit CsgScratchLevel(bool entered) : entered_(entered) {
        if (entered_) depth = levels()++;
    }
    ~CsgScratchLevel() {
        if (entered_) --levels();
    }
    CsgScratchLevel(const CsgScratchLevel&) = delete;
    CsgScratchLevel& operator=(const CsgScratchLevel&) = delete;
    int depth = 0;

  private:
    static int& levels() {
        thread_local int n = 0;
        return n;
    }
    bool entered_;
};

// No child but `except` is left out.
inline constexpr size_t kNoChild = size_t(-1);

// A merge-like rule (POV-Ray's union and merge): whether some child j other than `except`
// and not skipped(j) holds p, inside(j) telling whether it does. Children that cannot
// hold p are not asked (the order asked is unspecified).
template <class Skipped, class Inside>
bool inside_any_child(const CsgChildIndex& index, bool inverted, const Point3& p,
                      size_t except, Skipped&& skipped, Inside&& inside) {
    const CsgChildIndex::Insides& in = index.insides[inverted ? 1 : 0];
    auto asked = [&](size_t j) { return j != except && !skipped(j); };
    for (uint32_t j : in.anywhere)
        if (asked(j) && inside(size_t(j))) return true;
    const CsgScratchLevel level(true);
    CsgScratch& s = csg_scratch(level.depth);
    // A child held inverted holds every point outside its box.
    if (!in.outside.children.empty()) {
        in.outside.holding(p, s.candidates, s.holding);
        size_t asked_holding = 0;
        for (uint32_t e : s.holding) asked_holding += asked(in.outside.children[e]);
        size_t asked_all = 0;
        if (index.flagged) {
            for (uint32_t j : in.outside.children) asked_all += asked(j);
        } else {
            asked_all = in.outside.children.size() -
                        (except != kNoChild &&
                         std::binary_search(in.outside.children.begin(),
                                            in.outside.children.end(), uint32_t(except)));
        }
        if (asked_all > asked_holding) return true;
        for (uint32_t e : s.holding) {
            const size_t j = in.outside.children[e];
            if (asked(j) && inside(j)) return true;
        }
    }
    if (!in.within.children.empty()) {
        in.within.holding(p, s.candidates, s.holding);
        for (uint32_t e : s.holding) {
            const size_t j = in.within.children[e];
            if (asked(j) && inside(j)) return true;
        }
    }
    return false;
}

// An intersection-like rule (POV-Ray's intersection, difference and inverted merge):
// whether every child other than `except` holds p, inside(j) telling whether it does.
// Children that must hold p are not asked.
template <class Inside>
bool inside_every_child(const CsgChildIndex& index, bool inverted, const Point3& p,
                        size_t except, Inside&& inside) {
    const CsgChildIndex::Insides& in = index.insides[inverted ? 1 : 0];
    for (uint32_t j : in.never)
        if (j != except) return false;
    // Every child is asked unless its box answers: a walk of the box tree would find the
    // same boxes at a higher cost (the children of an intersection mostly overlap: a
    // column of 20 prisms spent 40 % of its time in tree walks that left none out).
    auto holds = [&](const Bounds3& b) {
        return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y &&
               p.z >= b.lo.z && p.z <= b.hi.z;
    };
    // Every solid held as written must have p in its box.
    const CsgChildIndex::Boxed& within = in.within;
    for (size_t e = 0; e < within.children.size(); ++e)
        if (within.children[e] != except && !holds(within.boxes[e])) return false;
    for (size_t e = 0; e < within.children.size(); ++e) {
        const size_t j = within.children[e];
        if (j != except && !inside(j)) return false;
    }
    // One held inverted holds p outside its box for sure.
    const CsgChildIndex::Boxed& outside = in.outside;
    for (size_t e = 0; e < outside.children.size(); ++e) {
        const size_t j = outside.children[e];
        if (j != except && holds(outside.boxes[e]) && !inside(j)) return false;
    }
    for (uint32_t j : in.anywhere)
        if (j != except && !inside(size_t(j))) return false;
    return true;
}

}  // namespace povwall::trace
