// blob { [threshold T] components [object modifiers] }, as POV-Ray 3.7's Parse_Blob and
// Parse_Blob_Element_Mods (notes: shape-blob.md section 1):
//   component S, R, <C>
//   sphere { <C>, R, [strength] S  component modifiers }
//   cylinder { <B>, <A>, R, [strength] S  component modifiers }
// Every comma is optional; `threshold` may come between components. Component
// modifiers: translate, rotate, scale, matrix, transform (moving its texture too),
// texture, pigment, normal, finish.
#include <algorithm>
#include <cmath>

#include "core/pov_frame.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

// POV-Ray's Compute_Coordinate_Transform(base, axis, 1, 1).
Transform cylinder_frame(const Point3& base, Vector3 up) {
    return pov_coordinate_transform(base, up, 1, 1);
}

}  // namespace

void Interpreter::parse_blob_component_modifiers(BlobElement& e, LayeredTexture& tex) {
    using Kind = TransformStep::Kind;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        Transform tr;
        TransformStep step;
        if (try_transform(t, tr, &step)) {
            // Every step moves the component's texture too.
            transform_textures(tex, tr);
            const Vector3& v = step.amount;
            if (e.kind == BlobElementKind::Sphere) {
                // POV-Ray moves a sphere's centre (and scales its radius) in place until
                // a non-uniform scale, a matrix or a transform gives it a matrix.
                if (step.kind == Kind::Translate) {
                    e.origin = e.origin + v;
                    continue;
                }
                if (step.kind == Kind::Rotate) {
                    e.origin = tr.point(e.origin);
                    continue;
                }
                if (step.kind == Kind::Scale && v.x == v.y && v.x == v.z) {
                    e.origin = e.origin * v.x;
                    e.rad2 *= v.x * v.x;
                    continue;
                }
                e.kind = BlobElementKind::Ellipsoid;
                e.transform = tr;
                continue;
            }
            e.transform = e.transform.then(tr);
            continue;
        }
        if (is_word(t, "texture")) {
            link_textures(tex, parse_texture_block(), t);
            continue;
        }
        if (is_word(t, "pigment") || is_word(t, "normal") || is_word(t, "finish")) {
            // As on an object: the top layer, made from the default texture if none.
            if (tex.empty())
                tex.push_back(default_texture_);
            else if (tex.back().map_pattern)
                error(t, "cannot layer over a patterned texture");
            Texture& top = tex.back();
            if (is_word(t, "pigment"))
                parse_pigment_into(top.pigment);
            else if (is_word(t, "finish"))
                parse_finish_into(top.finish);
            else
                parse_normal_into(top.normal);
            continue;
        }
        expected("a blob component modifier or '}'", t);
    }
}

void Interpreter::parse_blob(Object& out) {
    Real threshold = 1.0;
    std::vector<BlobElement> components;
    std::vector<LayeredTexture> textures;  // per component
    // `, radius, [strength] s` of a sphere or cylinder component.
    auto radius_and_strength = [this](BlobElement& e) {
        accept_punct(',');
        const Real r = parse_float();
        e.rad2 = r * r;
        accept_punct(',');
        accept_word("strength");
        e.c[2] = parse_float();
    };
    for (;;) {
        const Token t = peek();
        if (is_word(t, "threshold")) {
            next();
            threshold = parse_float();
        } else if (is_word(t, "component")) {
            next();
            BlobElement e;
            e.c[2] = parse_float();
            accept_punct(',');
            const Real r = parse_float();
            e.rad2 = r * r;
            accept_punct(',');
            e.origin = parse_vector();
            components.push_back(e);
            textures.emplace_back();
        } else if (is_word(t, "sphere")) {
            next();
            expect_punct('{', "after sphere");
            BlobElement e;
            e.origin = parse_vector();
            radius_and_strength(e);
            LayeredTexture tex;
            parse_blob_component_modifiers(e, tex);
            components.push_back(e);
            textures.push_back(std::move(tex));
        } else if (is_word(t, "cylinder")) {
            next();
            expect_punct('{', "after cylinder");
            BlobElement e;
            e.kind = BlobElementKind::Cylinder;
            const Point3 base = parse_vector();
            accept_punct(',');
            const Point3 apex = parse_vector();
            radius_and_strength(e);
            Vector3 axis = apex - base;
            e.len = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
            if (e.len < 1e-10) error(t, "Degenerate cylindrical component in blob.");
            axis = axis * (1.0 / e.len);
            e.transform = cylinder_frame(base, axis);
            LayeredTexture tex;
            parse_blob_component_modifiers(e, tex);
            components.push_back(e);
            textures.push_back(std::move(tex));
        } else {
            break;
        }
    }
    if (components.empty()) error(peek(), "Need at least one component in a blob.");
    Blob blob;
    blob.data = std::make_shared<BlobData>(make_blob(threshold, components));
    // The element textures in the elements' order (reversed, three per cylinder).
    const bool textured = std::any_of(textures.begin(), textures.end(),
                                      [](const LayeredTexture& t) { return !t.empty(); });
    if (textured) {
        for (size_t i = components.size(); i-- > 0;) {
            const int copies = components[i].kind == BlobElementKind::Cylinder ? 3 : 1;
            for (int k = 0; k < copies; ++k) blob.element_textures.push_back(textures[i]);
        }
    }
    out.shape = std::move(blob);
}

}  // namespace povwall::parser
