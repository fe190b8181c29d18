// `no_bump_scale` handed down as POV-Ray 3.7 does when it finishes a scene's textures
// (Post_Textures, Post_Tnormal): the flag written in a normal or a texture reaches every
// normal pattern below it, where the tracer reads it (PatternSpec::no_bump_scale).
#pragma once

#include "core/scene.h"

namespace povwall::parser {

// `normal { ... no_bump_scale }`: the normal's pattern and, through its normal_map (or
// list of normals), the entries' patterns.
void set_no_bump_scale(Normal& normal);

// `texture { ... no_bump_scale }` on one texture layer: a plain texture's normal, or a
// patterned texture's map pattern (the map's space is one the normal goes through) and
// the top layer of each map entry; a material_map keeps it on its own pattern only.
void set_no_bump_scale(Texture& texture);

}  // namespace povwall::parser
