// blob { [threshold T] components [object modifiers] }, as POV-Ray 3.7's Parse_Blob and
// Parse_Blob_Element_Mods (notes: shape-blob.md section 1):
//   component S, R, <C>
//   sphere { <C>, R, [strength] S  component modifiers }
//   cylinder { <B>, <A>, R, [strength] S  component modifiers }
// Every comma is optional; `threshold` may come between components.
#include <cmath>

#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

// POV-Ray's Compute_Coordinate_Transform(base, axis, 1, 1): the rotation about
// (-axis.y, axis.x, 0) by acos(axis.z) that takes z to `axis` (its inverse the
// transpose), then the translation to `base`.
Transform cylinder_frame(const Point3& base, Vector3 up) {
    Vector3 k;
    if (std::fabs(up.z) > 1.0 - 1e-10) {
        k = {1, 0, 0};
        up.z = up.z < 0 ? -1.0 : 1.0;
    } else {
        k = {-up.y, up.x, 0};
    }
    const Vector3 v = normalize(k);
    const Real angle = std::acos(up.z);
    const Real c = std::cos(angle), s = std::sin(angle);
    // p[r][c] with POV-Ray's row-vector convention (a point is p times the matrix).
    const Real p[3][3] = {
        {v.x * v.x + c * (1.0 - v.x * v.x), v.x * v.y * (1.0 - c) + v.z * s,
         v.x * v.z * (1.0 - c) - v.y * s},
        {v.x * v.y * (1.0 - c) - v.z * s, v.y * v.y + c * (1.0 - v.y * v.y),
         v.y * v.z * (1.0 - c) + v.x * s},
        {v.x * v.z * (1.0 - c) + v.y * s, v.y * v.z * (1.0 - c) - v.x * s,
         v.z * v.z + c * (1.0 - v.z * v.z)}};
    Matrix34 fwd, inv;
    for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) {
            fwd.m[col][r] = p[r][col];
            inv.m[r][col] = p[r][col];
        }
    return Transform::from_matrices(fwd, inv).then(Transform::translate(base));
}

}  // namespace

void Interpreter::parse_blob_component_modifiers(BlobElement& e) {
    using Kind = TransformStep::Kind;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        Transform tr;
        TransformStep step;
        if (try_transform(t, tr, &step)) {
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
        if (is_word(t, "texture") || is_word(t, "pigment") || is_word(t, "normal") ||
            is_word(t, "finish"))
            unsupported(t, "a texture on a blob component");
        expected("a blob component modifier or '}'", t);
    }
}

void Interpreter::parse_blob(Object& out) {
    Real threshold = 1.0;
    std::vector<BlobElement> components;
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
        } else if (is_word(t, "sphere")) {
            next();
            expect_punct('{', "after sphere");
            BlobElement e;
            e.origin = parse_vector();
            accept_punct(',');
            const Real r = parse_float();
            e.rad2 = r * r;
            accept_punct(',');
            accept_word("strength");
            e.c[2] = parse_float();
            parse_blob_component_modifiers(e);
            components.push_back(e);
        } else if (is_word(t, "cylinder")) {
            next();
            expect_punct('{', "after cylinder");
            BlobElement e;
            e.kind = BlobElementKind::Cylinder;
            const Point3 base = parse_vector();
            accept_punct(',');
            const Point3 apex = parse_vector();
            accept_punct(',');
            const Real r = parse_float();
            e.rad2 = r * r;
            accept_punct(',');
            accept_word("strength");
            e.c[2] = parse_float();
            Vector3 axis = apex - base;
            e.len = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
            if (e.len < 1e-10) error(t, "Degenerate cylindrical component in blob.");
            axis = axis * (1.0 / e.len);
            e.transform = cylinder_frame(base, axis);
            parse_blob_component_modifiers(e);
            components.push_back(e);
        } else {
            break;
        }
    }
    if (components.empty()) error(peek(), "Need at least one component in a blob.");
    Blob blob;
    blob.data = std::make_shared<BlobData>(make_blob(threshold, components));
    out.shape = std::move(blob);
}

}  // namespace povwall::parser
