#include "trace/cutaway_textures.h"

#include <algorithm>

#include "trace/object_inside.h"
#include "trace/ray_use.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

// Whether POV-Ray sees part i of a CSG node inverted (`inverted`: the node is): the
// part's own inverse, and a difference's later parts, which it inverts.
bool part_inverted(const Object& node, bool inverted, size_t i) {
    const Csg& csg = std::get<Csg>(node.shape);
    const Object& c = csg.children[i];
    const bool cut =
        csg.kind == CsgKind::Difference && i > 0 && std::holds_alternative<Csg>(c.shape);
    return (inverted != c.inverse) != cut;
}

// One walk over a CSG node's tree for a point: every textured leaf advances `next` (the
// blend's material index) whether it is taken or not.
struct BlendWalk {
    const BlobTextureBlend& blend;
    const Point3& p;
    std::vector<const Material*>& materials;
    std::vector<float>& w;
    size_t next = 0;

    void pass_over(const Object& o) {
        if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
            for (const Object& c : csg->children) pass_over(c);
        } else if (!o.texture.empty()) {
            ++next;
        }
    }

    void collect(const Object& node, bool inverted) {
        const Csg& csg = std::get<Csg>(node.shape);
        // An inverted difference is a merge to POV-Ray (Morph).
        const bool difference = csg.kind == CsgKind::Difference && !inverted;
        const size_t first = w.size();
        for (size_t i = 0; i < csg.children.size(); ++i) {
            const Object& c = csg.children[i];
            // A difference's later parts were cut away: their textures never show.
            if ((difference && i > 0) || !inside_unclipped(c, p)) {
                pass_over(c);
            } else if (std::holds_alternative<Csg>(c.shape)) {
                collect(c, part_inverted(node, inverted, i));
            } else if (!c.texture.empty()) {
                materials.push_back(blend.elements[next++]);
                w.push_back(1.0f);
            }
        }
        if (difference) return;
        // In POV-Ray's precision (single-precision colour values).
        const float share = 1.0f / std::max(float(w.size() - first), 1.0f);
        for (size_t k = first; k < w.size(); ++k) w[k] = share;
    }
};

// for_each_leaf_and_csg below `o` (`inverted`: POV-Ray sees o inverted).
void visit(const Object& o, bool inverted, const Object* named,
           const std::function<void(const Object&, const Object*)>& f) {
    const Csg* csg = std::get_if<Csg>(&o.shape);
    if (!csg) return f(o, named);
    if (!named &&
        (pov_csg(csg->kind, inverted) != PovCsg::Union || !o.clipped_by.empty()))
        named = &o;
    for (size_t i = 0; i < csg->children.size(); ++i)
        visit(csg->children[i], part_inverted(o, inverted, i), named, f);
}

}  // namespace

void for_each_leaf_and_csg(const Object& frame_object,
                           const std::function<void(const Object&, const Object*)>& f) {
    visit(frame_object, frame_object.inverse, nullptr, f);
}

void cutaway_textured_leaves(const Object& csg_node, std::vector<const Object*>& out) {
    if (const Csg* csg = std::get_if<Csg>(&csg_node.shape)) {
        for (const Object& c : csg->children) cutaway_textured_leaves(c, out);
    } else if (!csg_node.texture.empty()) {
        out.push_back(&csg_node);
    }
}

size_t cutaway_material_count(const Object& frame_object) {
    size_t n = 0;
    std::vector<const Object*> leaves;
    for_each_leaf_and_csg(frame_object, [&](const Object& leaf, const Object* csg) {
        if (!csg || !leaf.texture.empty()) return;
        leaves.clear();
        cutaway_textured_leaves(*csg, leaves);
        n += leaves.size();
    });
    return n;
}

int cutaway_texture_weights(const BlobTextureBlend& b, const Point3& p, float min_weight,
                            std::vector<const Material*>& materials,
                            std::vector<float>& w) {
    materials.clear();
    w.clear();
    BlendWalk walk{b, p, materials, w};
    walk.collect(*b.blob, b.blob->inverse);
    size_t kept = 0;
    for (size_t i = 0; i < w.size(); ++i) {
        if (w[i] < min_weight) continue;
        materials[kept] = materials[i];
        w[kept++] = w[i];
    }
    materials.resize(kept);
    w.resize(kept);
    return int(kept);
}

}  // namespace povwall::trace
