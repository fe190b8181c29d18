// lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N [,]
//         <r0, h0> [,] <r1, h1> ... modifiers }
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_lathe(Object& out) {
    // Any number of spline keywords: the last one counts.
    LatheSplineKind kind = LatheSplineKind::Linear;
    for (;;) {
        if (accept_word("linear_spline"))
            kind = LatheSplineKind::Linear;
        else if (accept_word("quadratic_spline"))
            kind = LatheSplineKind::Quadratic;
        else if (accept_word("cubic_spline"))
            kind = LatheSplineKind::Cubic;
        else if (accept_word("bezier_spline"))
            kind = LatheSplineKind::Bezier;
        else
            break;
    }
    require_operand("the number of points of the lathe");
    const Token count_at = peek();
    const int n = parse_int();
    switch (kind) {
        case LatheSplineKind::Linear:
            if (n < 2)
                error(count_at,
                      "Lathe with linear splines must have at least two points");
            break;
        case LatheSplineKind::Quadratic:
            if (n < 3)
                error(count_at,
                      "Lathe with quadratic splines must have at least three points");
            break;
        case LatheSplineKind::Cubic:
            // POV-Ray's message says "Prism" here.
            if (n < 4)
                error(count_at,
                      "Lathe with cubic splines must have at least four points");
            break;
        case LatheSplineKind::Bezier:
            if (n % 4 != 0 || n < 0)
                error(count_at,
                      "Lathe with Bezier splines must have four points per segment");
            // POV-Ray accepts 0: a lathe without segments, never hit.
            if (n == 0) unsupported(count_at, "a lathe without segments");
            break;
    }
    std::vector<ProfilePoint> points;
    for (int i = 0; i < n; ++i) {
        accept_punct(',');
        const Token at = peek();
        const ProfilePoint p = parse_uv_vector();
        // Only the end points may have a negative radius.
        if (i > 0 && i < n - 1 && p.x < 0) error(at, "Incorrect point in lathe");
        points.push_back(p);
    }
    out.shape =
        Lathe{std::make_shared<LatheSpline>(make_lathe_spline(kind, points)), false};
}

}  // namespace povwall::parser
