#include "trace/csg_children.h"

#include <cmath>
#include <deque>

#include "trace/prepared_scene.h"
#include "trace/ray_use.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

// Fewer children are walked as POV-Ray walks them: a tree would cost more than it saves.
constexpr size_t kIndexedChildren = 16;

// The box widened by a millionth of its magnitudes on each axis: a crossing the shape
// finds, or a point its inside test accepts within the shape's own tolerance, lies inside
// it after rounding.
Bounds3 padded(const Bounds3& b) {
    Bounds3 out = b;
    for (int a = 0; a < 3; ++a) {
        const Real pad =
            1e-6 * (std::fabs(b.lo[a]) + std::fabs(b.hi[a]) + (b.hi[a] - b.lo[a])) +
            1e-12;
        out.lo[a] = b.lo[a] - pad;
        out.hi[a] = b.hi[a] + pad;
    }
    return out;
}

bool usable(const Bounds3& b) {
    if (b.empty() || b.infinite()) return false;
    for (int a = 0; a < 3; ++a)
        if (std::isnan(b.lo[a]) || std::isnan(b.hi[a])) return false;
    return true;
}

// Whether the object held inverted holds every point outside the box of its inside as
// written (object_inside_bounds): true when nothing under it is clipped (a clip is never
// inverted), inverse, or a surface without an inside (inverted, still nothing), so that
// each leaf's inverted inside is the complement of its inside (a sphere's without its
// surface) and each CSG's rule turns over with it.
bool turns_inside_out(const Object& obj) {
    if (!obj.clipped_by.empty() || obj.inverse) return false;
    if (const Csg* csg = std::get_if<Csg>(&obj.shape)) {
        for (const Object& c : csg->children)
            if (!turns_inside_out(c)) return false;
        return true;
    }
    return leaf_invertible(obj) && !leaf_never_inside(obj);
}

void add_boxed(CsgChildIndex::Boxed& boxed, uint32_t child, const Bounds3& box) {
    boxed.children.push_back(child);
    boxed.boxes.push_back(padded(box));
}

std::unique_ptr<CsgChildIndex> build_index(const Csg& csg) {
    auto index = std::make_unique<CsgChildIndex>();
    std::vector<Bounds3> boxes;
    for (uint32_t i = 0; i < csg.children.size(); ++i) {
        const Object& child = csg.children[i];
        index->flagged = index->flagged || child.no_shadow || child.no_image ||
                         child.no_reflection || child.no_radiosity;
        const Bounds3 b = object_world_bounds(child);
        if (!child.bounded_by.empty() || !usable(b)) {
            index->surface_always.push_back(i);
            continue;
        }
        boxes.push_back(padded(b));
        index->surface_children.push_back(i);
    }
    index->surfaces = BoxTree(boxes);
    for (int held = 0; held < 2; ++held) {
        CsgChildIndex::Insides& in = index->insides[held];
        for (uint32_t i = 0; i < csg.children.size(); ++i) {
            const Object& child = csg.children[i];
            const bool inverted = child_held_inverted(csg, i, held == 1);
            if (never_inside(child, inverted)) {
                in.never.push_back(i);
                continue;
            }
            const Bounds3 b = object_inside_bounds(child);
            if (usable(b) && !inverted)
                add_boxed(in.within, i, b);
            else if (usable(b) && inverted && turns_inside_out(child))
                add_boxed(in.outside, i, b);
            else
                in.anywhere.push_back(i);
        }
        in.within.tree = BoxTree(in.within.boxes);
        in.outside.tree = BoxTree(in.outside.boxes);
    }
    return index;
}

}  // namespace

bool never_inside(const Object& obj, bool inverted) {
    inverted = inverted != obj.inverse;
    const Csg* csg = std::get_if<Csg>(&obj.shape);
    if (!csg) return leaf_never_inside(obj);
    // As inside_unclipped: none of an empty CSG; a union-like rule needs one child
    // inside, an intersection-like rule every child.
    if (csg->children.empty()) return true;
    const bool any = pov_csg(csg->kind, inverted) != PovCsg::Intersection;
    for (size_t i = 0; i < csg->children.size(); ++i) {
        const bool never =
            never_inside(csg->children[i], child_held_inverted(*csg, i, inverted));
        if (never != any) return !any;
    }
    return any;
}

void index_csg_children(const Object& obj) {
    const Csg* csg = std::get_if<Csg>(&obj.shape);
    if (!csg) return;
    for (const Object& child : csg->children) index_csg_children(child);
    if (csg->children.size() >= kIndexedChildren)
        csg->child_index.get_or_make([&] { return build_index(*csg); });
}

void CsgChildIndex::Boxed::holding(const Point3& p, std::vector<uint32_t>& scratch,
                                   std::vector<uint32_t>& out) const {
    scratch.clear();
    out.clear();
    tree.point_candidates(p, scratch);
    for (uint32_t e : scratch) {
        const Bounds3& b = boxes[e];
        if (p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y &&
            p.z >= b.lo.z && p.z <= b.hi.z)
            out.push_back(e);
    }
}

const CsgChildIndex* csg_child_index(const Csg& csg) { return csg.child_index.get(); }

CsgScratch& csg_scratch(int depth) {
    // A deque: references to earlier levels stay valid as deeper ones are added.
    thread_local std::deque<CsgScratch> levels;
    while (levels.size() <= size_t(depth)) levels.emplace_back();
    return levels[size_t(depth)];
}

}  // namespace povwall::trace
