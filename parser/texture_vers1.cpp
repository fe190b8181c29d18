// The texture of POV-Ray 1.0 and 2.0 scenes (language version below 3.0), as POV-Ray
// 3.7 reads it (Parse_Vers1_Texture): the pigment, normal and finish items are written
// straight in the texture, `texture { marble turbulence 0.5 colour_map {..} phong 1 }`.
// A pattern keyword there sets only the pigment's type, keeping its map, turbulence and
// transforms; the normal and finish items each set one field.
#include <algorithm>
#include <string>
#include <string_view>

#include "core/pattern_lists.h"
#include "parser/interpreter.h"
#include "parser/no_bump_scale.h"

namespace povwall::parser {

namespace {

// POV-Ray names a token by its canonical spelling in its warnings.
std::string canonical_name(std::string_view w) {
    if (w == "colour") return "color";
    if (w == "colour_map") return "color_map";
    if (w == "quick_colour") return "quick_color";
    return std::string(w);
}

bool is_colour_word(std::string_view w) {
    return w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" ||
           w == "rgbft" || w == "red" || w == "green" || w == "blue" || w == "filter" ||
           w == "transmit" || w == "alpha";
}

struct NamedPattern {
    std::string_view name;
    PatternKind kind;
};

// The kind `w` names in `table`, if it is there.
template <size_t N>
bool find_pattern(const NamedPattern (&table)[N], std::string_view w, PatternKind& kind) {
    for (const NamedPattern& e : table) {
        if (w == e.name) {
            kind = e.kind;
            return true;
        }
    }
    return false;
}

// The patterns Parse_Vers1_Texture reads (mandel aside, see below) and the pigment
// type each sets.
bool vers1_pigment_pattern(std::string_view w, PatternKind& kind) {
    static constexpr NamedPattern kNames[] = {
        {"agate", PatternKind::Agate},      {"bozo", PatternKind::Bozo},
        {"granite", PatternKind::Granite},  {"leopard", PatternKind::Leopard},
        {"marble", PatternKind::Marble},    {"onion", PatternKind::Onion},
        {"spotted", PatternKind::Spotted},  {"wood", PatternKind::Wood},
        {"gradient", PatternKind::Gradient}};
    return find_pattern(kNames, w, kind);
}

// The block patterns, which take a colour list.
bool vers1_list_pattern(std::string_view w, PatternKind& kind) {
    static constexpr NamedPattern kNames[] = {{"checker", PatternKind::Checker},
                                              {"hexagon", PatternKind::Hexagon},
                                              {"square", PatternKind::Square},
                                              {"triangular", PatternKind::Triangular}};
    return find_pattern(kNames, w, kind);
}

// The normal patterns, each followed by its amount.
bool vers1_normal_pattern(std::string_view w, PatternKind& kind) {
    static constexpr NamedPattern kNames[] = {{"bumps", PatternKind::Bumps},
                                              {"dents", PatternKind::Dents},
                                              {"ripples", PatternKind::Ripples},
                                              {"waves", PatternKind::Waves},
                                              {"wrinkles", PatternKind::Wrinkles}};
    return find_pattern(kNames, w, kind);
}

}  // namespace

void Interpreter::parse_vers1_texture_body(LayeredTexture& layers, char terminator) {
    const Token& first = peek();
    NestingGuard guard(*this, first);
    // Whether the pigment has a type (POV-Ray's NO_PATTERN otherwise): from 1.5 on a
    // texture must end with one. An identifier's pigment is taken as typed (povwall
    // keeps no such mark on it), the default texture's when #default gave one.
    bool pigment_typed = default_pigment_given_;
    bool plain = true;
    if (is_word(first, "tiles")) {
        const Token t = next();
        parse_tiles(t, layers);
        plain = false;
    } else if (is_word(first, "material_map")) {
        const Token t = next();
        layers.assign(1, default_texture_);
        parse_material_map(t, layers.back());
        plain = false;
    } else if (const Value* v = first.kind == TokenKind::Word ? lookup(first) : nullptr;
               v && std::holds_alternative<std::shared_ptr<LayeredTexture>>(*v)) {
        next();
        layers = *std::get<std::shared_ptr<LayeredTexture>>(*v);
        pigment_typed = true;
        plain = !layers.back().map_pattern;
    } else {
        layers.assign(1, default_texture_);
    }
    if (!plain) {
        parse_texture_transforms(layers, terminator);
        return;
    }
    // Pigment, normal and finish identifiers first; each replaces the part.
    for (;;) {
        const Token& t = peek();
        const Value* v = t.kind == TokenKind::Word ? lookup(t) : nullptr;
        if (!v) break;
        Texture& top = layers.back();
        if (auto p = std::get_if<std::shared_ptr<Pigment>>(v)) {
            top.pigment = **p;
            pigment_typed = true;
        } else if (auto f = std::get_if<std::shared_ptr<Finish>>(v)) {
            top.finish = shared_finish(**f);
        } else if (auto n = std::get_if<std::shared_ptr<Normal>>(v)) {
            top.normal = **n;
        } else {
            break;
        }
        next();
    }
    const bool from_150 = language_version() >= 150;
    // Below 1.5 POV-Ray says where each item belongs.
    auto warn_state = [&](const Token& t, std::string_view belongs) {
        if (from_150) return;
        warn(t, "Found '" + canonical_name(t.text) + "' that should be in '" +
                    std::string(belongs) + "' statement.");
    };
    // A normal item on a texture without a normal starts one from the default texture's.
    bool normal_untyped = false;
    auto normal = [&]() -> Normal& {
        HeapOptional<Normal>& n = layers.back().normal;
        if (!n) {
            n = default_texture_.normal ? *default_texture_.normal : Normal{};
            normal_untyped = !default_texture_.normal;
        }
        return *n;
    };
    auto edit_finish = [&](auto&& edit) {
        Texture& top = layers.back();
        Finish f = *top.finish;
        edit(f);
        f.raw_diffuse = f.diffuse;
        f.raw_diffuse_back = f.diffuse_back;
        top.finish = shared_finish(f);
    };
    auto classic_turbulence = [](PatternSpec& spec) -> Warp* {
        for (Warp& wp : spec.warps) {
            if (wp.kind == Warp::Kind::Turbulence && wp.classic) return &wp;
        }
        return nullptr;
    };
    Token end;
    bool no_bump_scale = false;
    for (;;) {
        Token t = next();
        if (is_punct(t, terminator)) {
            end = t;
            if (no_bump_scale) set_no_bump_scale(layers.back());
            break;
        }
        Transform tr;
        if (try_transform(t, tr)) {
            transform_textures(layers, tr);
            continue;
        }
        Texture& top = layers.back();
        Pigment& p = top.pigment;
        const std::string_view w =
            t.kind == TokenKind::Word ? t.text : std::string_view();
        PatternKind kind{};
        if (w == "pigment") {
            parse_pigment_into(p);
            pigment_typed = true;
        } else if (w == "normal") {
            parse_normal_into(top.normal);
        } else if (w == "finish") {
            parse_finish_into(top.finish);
        } else if (vers1_pigment_pattern(w, kind)) {
            // The type alone: marble and wood keep the wave they had (a ramp), where
            // `pigment { marble }` takes the triangle wave.
            warn_state(t, "pigment");
            PatternSpec& spec = p.pattern.edit();
            spec.kind = kind;
            if (kind == PatternKind::Agate) spec.scalar = 1;  // agate_turb
            if (kind == PatternKind::Gradient) spec.vector = parse_vector();
            pigment_typed = true;
        } else if (w == "mandel") {
            // POV-Ray sets the iterations alone, leaving the fractal's colouring as it
            // was, which povwall does not model.
            unsupported(t, "mandel written straight in a POV-Ray 1.0/2.0 texture");
        } else if (vers1_list_pattern(w, kind)) {
            warn_state(t, "pigment");
            PatternSpec& spec = p.pattern.edit();
            spec.kind = kind;
            spec.frequency = 0;
            PigmentMaps& maps = p.maps.edit();
            maps.colour_map.clear();
            maps.map_values.clear();
            maps.list.clear();
            // Up to the pattern's count of colours, each followed by an optional comma;
            // the missing ones are the pattern's default colours (the evaluator's).
            const int count = pattern_list_size(kind);
            for (int i = 0; i < count; ++i) {
                const Token& n = peek();
                const bool colour =
                    (n.kind == TokenKind::Word && is_colour_word(n.text)) ||
                    n.kind == TokenKind::Number || is_punct(n, '<') ||
                    (n.kind == TokenKind::Word && lookup(n) &&
                     std::holds_alternative<Numeric>(*lookup(n)));
                if (!colour) break;
                Pigment entry;
                entry.colour = parse_colour_value();
                maps.list.push_back(entry);
                accept_punct(',');
            }
            pigment_typed = true;
        } else if (w == "image_map") {
            warn_state(t, "pigment");
            PatternSpec& spec = p.pattern.edit();
            spec.kind = PatternKind::ImageMap;
            spec.frequency = 0;
            spec.image = parse_image_block(t, nullptr);
            pigment_typed = true;
        } else if (w == "color_map" || w == "colour_map") {
            warn_state(t, "pigment");
            const PatternKind k = p.pattern->kind;
            if (from_150 && (pattern_list_size(k) || k == PatternKind::ImageMap ||
                             (k == PatternKind::Solid && pigment_typed)))
                warn(t, "Cannot use color map with this pigment type.");
            PigmentMaps& maps = p.maps.edit();
            maps.map_values.clear();
            maps.list.clear();
            maps.colour_map = parse_colour_map_block();
        } else if (w == "quick_color" || w == "quick_colour") {
            warn_state(t, "pigment");
            p.maps.edit().quick_colour = parse_colour_value();
        } else if (w == "turbulence" || w == "omega" || w == "lambda") {
            try_pattern_modifier(t, p.pattern);
        } else if (w == "octaves") {
            try_pattern_modifier(t, p.pattern);
            Warp* turb = classic_turbulence(p.pattern.edit());
            turb->octaves = std::clamp(turb->octaves, 1, 10);
        } else if ((t.kind == TokenKind::Word && is_colour_word(w)) ||
                   (t.kind == TokenKind::Word && lookup(t) &&
                    std::holds_alternative<Numeric>(*lookup(t)))) {
            if (is_colour_word(w)) warn_state(t, "pigment");
            unget(t);
            if (p.pattern->kind != PatternKind::Solid)
                p.pattern.edit().kind = PatternKind::Solid;
            p.colour = parse_colour_value();
            pigment_typed = true;
        } else if (vers1_normal_pattern(w, kind)) {
            warn_state(t, "normal");
            Normal& n = normal();
            n.pattern.edit().kind = kind;
            n.amount = parse_single();
            normal_untyped = false;
        } else if (w == "bump_map") {
            warn_state(t, "normal");
            Normal& n = normal();
            n.pattern.edit().kind = PatternKind::ImageMap;
            n.pattern.edit().frequency = 0;
            n.pattern.edit().image = parse_image_block(t, &n);
            normal_untyped = false;
        } else if (w == "frequency" || w == "phase") {
            warn_state(t, "normal");
            Normal& n = normal();
            const PatternKind k = n.pattern->kind;
            if (from_150 && k != PatternKind::Ripples && k != PatternKind::Waves)
                warn(t, "Cannot use " + std::string(w) + " with this normal.");
            const Real value = parse_single();
            if (w == "frequency")
                n.pattern.edit().frequency = value;
            else
                n.pattern.edit().phase = value;
        } else if (w == "ambient") {
            warn_state(t, "finish");
            const float a = float(parse_float());
            edit_finish([&](Finish& f) { f.ambient = Rgb(a); });
        } else if (w == "brilliance") {
            warn_state(t, "finish");
            const float b = float(parse_float());
            edit_finish([&](Finish& f) { f.brilliance = b; });
        } else if (w == "diffuse") {
            warn_state(t, "finish");
            const float d = float(parse_float());
            edit_finish([&](Finish& f) { f.diffuse = d; });
        } else if (w == "reflection") {
            warn_state(t, "finish");
            const float r = float(parse_float());
            edit_finish([&](Finish& f) {
                f.reflection_min = Rgb(r);
                f.reflection_max = Rgb(r);
                f.reflection_falloff = 1;
            });
        } else if (w == "phong") {
            warn_state(t, "finish");
            const float v = float(parse_float());
            edit_finish([&](Finish& f) { f.phong = v; });
        } else if (w == "phong_size") {
            warn_state(t, "finish");
            const float v = float(parse_float());
            edit_finish([&](Finish& f) { f.phong_size = v; });
        } else if (w == "specular") {
            warn_state(t, "finish");
            const float v = float(parse_float());
            edit_finish([&](Finish& f) { f.specular = v; });
        } else if (w == "roughness") {
            // Kept as written, as finish { roughness } keeps it (POV-Ray stores 1/r).
            warn_state(t, "finish");
            const float v = float(parse_float());
            if (v == 0) warn(t, "Zero roughness used.");
            edit_finish([&](Finish& f) { f.roughness = v; });
        } else if (w == "metallic") {
            warn_state(t, "finish");  // no amount in this form
            edit_finish([&](Finish& f) { f.metallic = 1; });
        } else if (w == "crand") {
            warn_state(t, "finish");
            const float v = float(parse_float());
            edit_finish([&](Finish& f) { f.crand = v; });
        } else if (starts_float(t)) {
            unget(t);
            const float v = float(parse_float());
            if (from_150) warn(t, "Should use crand keyword in finish statement.");
            edit_finish([&](Finish& f) { f.crand = v; });
        } else if (w == "ior" || w == "refraction") {
            // Moved into the object's interior when it is placed (finish_object).
            warn_state(t, "interior");
            const float v = float(parse_float());
            const std::string compat =
                "\n  Use of this syntax may not be backwards compatible with earlier "
                "versions of POV-Ray.\n  The #version directive or +MV switch will not "
                "help.";
            if (w == "ior") {
                warn(t,
                     "Index of refraction value should be specified in 'interior{...}' "
                     "statement." +
                         compat);
                edit_finish([&](Finish& f) { f.legacy_ior = v; });
            } else {
                warn(t,
                     "Refraction value unnecessary to turn on refraction.\nTo attenuate, "
                     "the fade_power and fade_distance keywords should be specified in "
                     "'interior{...}' statement." +
                         compat);
                edit_finish([&](Finish& f) { f.legacy_refraction = v; });
            }
        } else if (const Value* v = t.kind == TokenKind::Word ? lookup(t) : nullptr;
                   v && std::holds_alternative<std::shared_ptr<LayeredTexture>>(*v)) {
            warn(t, "Texture identifier overwriting previous values.");
            layers = *std::get<std::shared_ptr<LayeredTexture>>(*v);
            pigment_typed = true;
            normal_untyped = false;
            // POV-Ray goes on editing a patterned texture's (absent) parts.
            if (layers.back().map_pattern)
                unsupported(t,
                            "a patterned texture identifier after items in a POV-Ray "
                            "1.0/2.0 texture");
        } else if (is_word(t, "no_bump_scale")) {
            // Handed to the normal when the texture ends (POV-Ray reads it, and only
            // transforms, after the items).
            no_bump_scale = true;
        } else {
            expected("a texture item or '" + std::string(1, terminator) + "'", t);
        }
    }
    if (from_150 && !pigment_typed && !in_default_)
        error(end, "Expected 'pigment identifier', " + std::string(1, terminator) +
                       " found instead");
    // POV-Ray stops on a normal without a type ("No normal type given.").
    if (normal_untyped) error(end, "No normal type given.");
}

}  // namespace povwall::parser
