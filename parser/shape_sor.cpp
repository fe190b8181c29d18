// sor { N [,] <r0, h0> [,] <r1, h1> ... [open] modifiers }
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_sor(const Token& keyword, Object& out) {
    require_operand("the number of points of the sor");
    const Token count_at = peek();
    const int n = parse_int();
    if (n < 4) error(count_at, "Surface of revolution must have at least four points");
    std::vector<ProfilePoint> points;
    for (int i = 0; i < n; ++i) {
        accept_punct(',');
        const Token at = peek();
        const ProfilePoint p = parse_uv_vector();
        // Radii are never negative; heights rise strictly from the second point to the
        // last but one (the first and last only set the end slopes).
        if (p.x < 0 || (i > 1 && i < n - 1 && p.y <= points.back().y))
            error(at, "Incorrect point in surface of revolution");
        points.push_back(p);
    }
    Sor sor;
    // POV-Ray reads `open` only here, right after the points.
    if (accept_word("open")) sor.open = true;
    auto spline = std::make_shared<SorSpline>();
    if (std::string problem = make_sor_spline(points, *spline); !problem.empty())
        error(keyword, problem);
    sor.spline = std::move(spline);
    out.shape = std::move(sor);
}

}  // namespace povwall::parser
