// POV-Ray 3.7's cutaway_textures: in an intersection or difference with the flag, a part
// given no texture keeps none (parser/objects.cpp, stays_untextured), and where a ray
// meets its surface POV-Ray takes the textures of the CSG's textured parts the point lies
// in, evaluated there (CSG::Determine_Textures on the hit's CSG).
//
// Which CSG: POV-Ray's hit remembers the outermost CSG node around the leaf that passed
// it on as its own crossing (an intersection, difference or merge, or a union with
// clipped_by); its textured parts are the candidates. Which parts: a difference looks
// only at its first part; any other node at each part the point is inside (that part's
// own inside test, its clipped_by left out), going down into CSG parts and taking a
// leaf's texture when it has one. Weights: the textures a non-difference node collected
// (down through its parts) share 1 equally; a difference leaves its first part's as
// they are (1 for a leaf). None found: the surface is black and blocks light.
//
// The surface keeps everything else of its own leaf (normal, interior, light groups,
// flags): each candidate texture is a material of the hit leaf with that texture, and
// shading blends them through Material::blob_blend, whose `blob` is then the CSG node
// (see blob_texture_weights), so every back end shades them with the same code.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "trace/prepared_scene.h"

namespace povwall::trace {

// Calls f(leaf, csg) for each leaf of `frame_object`, depth first, with the CSG node
// POV-Ray's hits on that leaf name (null: none): the outermost whose class, after the
// inversions above and on it (CSG::Invert's Morph), is an intersection or merge, or a
// union with clipped_by.
void for_each_leaf_and_csg(const Object& frame_object,
                           const std::function<void(const Object&, const Object*)>& f);

// The leaves with a texture under `csg_node`, in the order the materials of a cutaway
// blend follow (depth first, children in order).
void cutaway_textured_leaves(const Object& csg_node, std::vector<const Object*>& out);

// How many materials the cutaway blends of the untextured leaves in `frame_object` add
// (PreparedScene reserves its materials up front).
size_t cutaway_material_count(const Object& frame_object);

// The textures of a cutaway surface at world point `p` (b.blob is the CSG node), as
// blob_texture_weights gives them: materials and weights, those below `min_weight` left
// out (as POV-Ray skips them), in the candidates' order; returns their count.
int cutaway_texture_weights(const BlobTextureBlend& b, const Point3& p, float min_weight,
                            std::vector<const Material*>& materials,
                            std::vector<float>& w);

}  // namespace povwall::trace
