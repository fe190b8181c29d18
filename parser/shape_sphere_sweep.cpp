// sphere_sweep { linear_spline | cubic_spline | b_spline [,] N
//                ([,] <centre> [,] radius){N} [tolerance T] modifiers }
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_sphere_sweep(Object& out) {
    const Token kind_at = peek();
    SweepSpline spline = SweepSpline::Linear;
    if (accept_word("linear_spline"))
        spline = SweepSpline::Linear;
    else if (accept_word("cubic_spline"))
        spline = SweepSpline::CatmullRom;
    else if (accept_word("b_spline"))
        spline = SweepSpline::BSpline;
    else
        error(kind_at, "Invalid type of interpolation");
    accept_punct(',');
    require_operand("the number of spheres of the sphere_sweep");
    const Token count_at = peek();
    const int n = parse_int();
    if (n < 2 || (spline != SweepSpline::Linear && n < 4))
        error(count_at, "Too few modeling spheres for interpolation type");
    std::vector<SweepSphere> spheres;
    for (int i = 0; i < n; ++i) {
        accept_punct(',');
        SweepSphere s;
        s.centre = parse_vector();
        accept_punct(',');
        s.radius = parse_float();
        spheres.push_back(s);
    }
    SphereSweep sweep;
    if (accept_word("tolerance")) sweep.tolerance = parse_float();
    sweep.data =
        std::make_shared<SphereSweepData>(make_sphere_sweep(spline, std::move(spheres)));
    out.shape = std::move(sweep);
}

}  // namespace povwall::parser
