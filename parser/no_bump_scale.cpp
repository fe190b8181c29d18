// POV-Ray 3.7 keeps DONT_SCALE_BUMPS_FLAG on the texture or normal it was written in and
// ORs it into the parts below when the scene's textures are finished: a texture's flag
// into its normal and into the first texture of each texture_map entry (its top layer),
// a normal's into its normal_map entries. The flag of an entry is never cleared by an
// outer texture without it.
#include "parser/no_bump_scale.h"

namespace povwall::parser {

void set_no_bump_scale(Normal& normal) {
    normal.pattern.edit().no_bump_scale = true;
    for (Normal& entry : normal.list) set_no_bump_scale(entry);
}

void set_no_bump_scale(Texture& texture) {
    if (texture.map_pattern) {
        texture.map_pattern->no_bump_scale = true;
        // POV-Ray's material_map textures are finished without the flag.
        if (texture.map_pattern->kind == PatternKind::MaterialMap) return;
        for (LayeredTexture& entry : texture.map.edit().entries) {
            if (!entry.empty()) set_no_bump_scale(entry.back());
        }
        return;
    }
    if (texture.normal) set_no_bump_scale(*texture.normal);
}

}  // namespace povwall::parser
