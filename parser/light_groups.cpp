// light_group { }: POV-Ray 3.7's light groups (parse.cpp Parse_Light_Group,
// lightgrp.cpp). A light group is a union whose own light sources light only its objects;
// with `global_lights off` (the default) the scene's other lights do not light them.
// Every object still casts shadows for every light. How POV-Ray settles nesting,
// reproduced here when the object is placed:
// - a leaf is lit by the lights of its innermost enclosing group that has both lights and
//   objects (Promote_Local_Lights stops at a group that already has its lights, and does
//   nothing for a group without lights or without objects);
// - whether a leaf sees the global lights is the outermost group's `global_lights`
//   (each group sets it on all its CSG descendants after its inner groups did);
// - a group's own lights (direct children, not those of a union inside it) are never
//   global, even in a group without objects.
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

// `object { LightId }` parses as an empty CSG carrying the light (objects.cpp); in a
// light group that object is the light itself, one of the group's lights.
bool is_light_holder(const Object& o) {
    const Csg* csg = std::get_if<Csg>(&o.shape);
    return csg && csg->children.empty() && !csg->lights.empty() && !csg->light_group;
}

bool has_looks_like(const Object& o) {
    const Csg* csg = std::get_if<Csg>(&o.shape);
    if (!csg) return false;
    for (const Light& l : csg->lights)
        if (!l.looks_like.empty()) return true;
    for (const Object& c : csg->children)
        if (has_looks_like(c)) return true;
    return false;
}

}  // namespace

void Interpreter::parse_light_group(const Token& keyword, Object& out) {
    expect_punct('{', "after 'light_group'");
    Csg csg;
    csg.kind = CsgKind::Union;
    csg.light_group = true;
    csg.global_lights = false;
    for (;;) {
        Token c = peek();
        if (c.kind != TokenKind::Word) break;
        next();
        if (is_word(c, "light_source") && !light_block_names_object()) {
            csg.lights.push_back(parse_light_block());
            continue;
        }
        Object child;
        // A declared light or object written bare, as POV-Ray's Parse_Object reads the
        // group's members (exporters write them so).
        const Value* declared = lookup(c);
        if (auto l = declared ? std::get_if<std::shared_ptr<Light>>(declared) : nullptr) {
            csg.lights.push_back(**l);
            continue;
        }
        if (auto o =
                declared ? std::get_if<std::shared_ptr<Object>>(declared) : nullptr) {
            child = **o;
            child.loc = sources_.location(c);
        } else if (!try_parse_object(c, child)) {
            unget(c);
            break;
        }
        if (is_light_holder(child)) {
            for (Light& l : std::get<Csg>(child.shape).lights)
                csg.lights.push_back(std::move(l));
        } else {
            csg.children.push_back(std::move(child));
        }
    }
    // Which lights light a looks_like object inside a group follows rules of POV-Ray's
    // light tree that povwall does not model.
    for (const Light& l : csg.lights)
        if (!l.looks_like.empty()) unsupported(keyword, "looks_like in a light_group");
    for (const Object& o : csg.children)
        if (has_looks_like(o)) unsupported(keyword, "looks_like in a light_group");
    out.shape = std::move(csg);
    close_csg_box(out);  // POV-Ray's Compute_BBox of the group, before its transforms
    // Only transforms, global_lights and photons follow the objects (POV-Ray does not
    // take the other object modifiers here).
    for (;;) {
        Token m = next();
        if (is_punct(m, '}')) break;
        Transform tr;
        TransformStep step;
        if (try_transform(m, tr, &step)) {
            apply_transform(out, tr, step);
        } else if (is_word(m, "global_lights")) {
            bool on = true;
            if (starts_float(peek())) on = parse_float() > 0.5;
            std::get<Csg>(out.shape).global_lights = on;
        } else if (is_word(m, "photons")) {
            unsupported(m, "photons");
        } else {
            expected("an object, light_source, transformation, global_lights or '}'", m);
        }
    }
}

void Interpreter::assign_light_groups(Object& obj) {
    // `outer_global`: the outermost enclosing group's global_lights (none: no group);
    // `group`: the number of the innermost enclosing group with lights and objects.
    auto visit = [&](auto& self, Object& o, std::optional<bool> outer_global,
                     uint32_t group) -> void {
        Csg* csg = std::get_if<Csg>(&o.shape);
        if (!csg) {
            if (outer_global) o.global_lights = *outer_global;
            o.light_group = group;
            return;
        }
        if (csg->light_group) {
            if (!outer_global) outer_global = csg->global_lights;
            if (!csg->lights.empty()) {
                const uint32_t number = ++light_groups_;
                for (Light& l : csg->lights) l.light_group = number;
                if (!csg->children.empty()) group = number;
            }
        }
        for (Object& c : csg->children) self(self, c, outer_global, group);
    };
    visit(visit, obj, std::nullopt, 0);
}

}  // namespace povwall::parser
