// isosurface { function { F } [contained_by { box { C1, C2 } | sphere { C, R } }]
//   [threshold T] [accuracy A] [max_gradient G] [max_trace N | all_intersections]
//   [evaluate P0, P1, P2] [open]
//   modifiers }, as POV-Ray 3.7's Parse_Isosurface (notes: shape-isosurface.md section
//   1).
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_contained_by(bool& sphere, Point3& corner1, Point3& corner2,
                                     Point3& centre, Real& radius) {
    // At most one box or sphere; an empty block keeps the container.
    expect_punct('{', "after contained_by");
    if (accept_word("box")) {
        expect_punct('{', "after box");
        Point3 c1 = parse_vector();
        accept_punct(',');
        Point3 c2 = parse_vector();
        expect_punct('}', "after the box's corners");
        for (int a = 0; a < 3; ++a)
            if (c1[a] > c2[a]) std::swap(c1[a], c2[a]);
        sphere = false;
        corner1 = c1;
        corner2 = c2;
    } else if (accept_word("sphere")) {
        expect_punct('{', "after sphere");
        centre = parse_vector();
        accept_punct(',');
        radius = parse_float();
        expect_punct('}', "after the sphere's radius");
        sphere = true;
    }
    expect_punct('}', "to close contained_by");
}

void Interpreter::parse_isosurface(Object& out, const Token& keyword) {
    Isosurface iso;
    const Token f = next();
    if (!is_word(f, "function")) expected("'function'", f);
    iso.function = parse_function_block(true);
    iso.gradients = std::make_shared<IsosurfaceGradients>();
    iso.gradients->function_at = sources_.location(f);
    constexpr int kMaxTrace = 10;  // ISOSURFACE_MAXTRACE
    for (;;) {
        const Token t = peek();
        if (is_word(t, "contained_by")) {
            next();
            parse_contained_by(iso.sphere_container, iso.corner1, iso.corner2, iso.centre,
                               iso.radius);
        } else if (is_word(t, "threshold")) {
            next();
            iso.threshold = parse_float();
        } else if (is_word(t, "accuracy")) {
            next();
            iso.accuracy = parse_float();
        } else if (is_word(t, "max_gradient")) {
            next();
            iso.max_gradient = parse_float();
        } else if (is_word(t, "max_trace")) {
            next();
            // POV-Ray keeps it as a short (a C cast of the float); past a short's range
            // it is clamped here (POV-Ray's cast is undefined there).
            const double v = parse_float();
            iso.max_trace = v >= 32767.0   ? 32767
                            : v > -32768.0 ? int(short(v))
                                           : (v == v ? -32768 : 0);
        } else if (is_word(t, "all_intersections")) {
            next();
            iso.max_trace = kMaxTrace;
        } else if (is_word(t, "open")) {
            next();
            iso.closed = false;
        } else if (is_word(t, "evaluate")) {
            next();
            iso.evaluate = true;
            for (int i = 0; i < 3; ++i) {
                if (i) accept_punct(',');
                iso.eval_param[i] = parse_float();
            }
        } else {
            break;
        }
    }
    if (iso.accuracy <= 0.0) {
        warn(keyword, "Isosurface 'accuracy' is not positive. Using 0.001 (default).");
        iso.accuracy = 0.001;
    }
    if (iso.max_gradient <= 0.0) {
        warn(keyword, "Isosurface 'max_gradient' is not positive. Using 1.1 (default).");
        iso.max_gradient = 1.1;
    }
    if (iso.max_trace > kMaxTrace) {
        warn(keyword, "Isosurface 'max_trace' exceeds maximum of 10. Using maximum.");
        iso.max_trace = kMaxTrace;
    }
    if (iso.max_trace < 1) {
        warn(keyword, "Isosurface 'max_trace' is not positive. Using 1 (default).");
        iso.max_trace = 1;
    }
    out.shape = std::move(iso);
}

}  // namespace povwall::parser
