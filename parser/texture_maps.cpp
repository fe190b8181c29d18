// material_map { IMAGE [once | interpolate | map_type | repeat | offset]... texture {}
// texture {}... } (POV-Ray 3.7's Parse_Material_Map) and the places uv_mapping cannot be.
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_material_map(const Token& keyword, Texture& into) {
    PatternSpec spec;
    spec.kind = PatternKind::MaterialMap;
    spec.image = parse_image_block(keyword, nullptr, ImageBlock::MaterialMap);
    TextureMap map;
    for (;;) {
        const Token t = next();
        if (is_punct(t, '}')) break;
        if (!is_word(t, "texture")) expected("texture or '}' in material_map", t);
        map.entries.push_back(parse_texture_block());
    }
    if (map.entries.empty()) expected("a texture in material_map", peek());
    into = Texture{};
    into.map_pattern = spec;
    into.map = std::move(map);
}

namespace {

bool uses_uv_mapping(const Pigment& p) {
    if (p.pattern->kind == PatternKind::UvMapping) return true;
    if (p.pattern->pigment && uses_uv_mapping(*p.pattern->pigment)) return true;
    for (const Pigment& sub : p.maps->list)
        if (uses_uv_mapping(sub)) return true;
    return false;
}

}  // namespace

void Interpreter::refuse_uv_mapping(const Pigment& p, const Token& at,
                                    std::string_view where) {
    // POV-Ray stops the render there ("The 'uv_mapping' pattern cannot be used as part
    // of a pigment function!"): no surface, no coordinates.
    if (uses_uv_mapping(p))
        error(at, "the uv_mapping pattern cannot be used in " + std::string(where));
}

}  // namespace povwall::parser
