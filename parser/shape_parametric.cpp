// parametric { function { X } [,] function { Y } [,] function { Z } <u1, v1> [,] <u2, v2>
//   [accuracy A] [max_gradient G] [precompute N [,] [x] [,] [y] [,] [z]]
//   [contained_by { box { C1, C2 } | sphere { C, R } }] modifiers }, as POV-Ray 3.7's
// Parse_Parametric: the rectangle's corners sorted per coordinate, no check on accuracy
// or max_gradient, the precompute tree made when the object's options end.
#include <algorithm>

#include "core/parametric.h"
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_parametric(Object& out, const Token& keyword) {
    Parametric par;
    for (int i = 0; i < 3; ++i) {
        if (i) accept_punct(',');
        // `function { ... }`, or the braces alone (POV-Ray's Parse_FunctionContent).
        accept_word("function");
        par.functions[i] = parse_function_block(true);
    }
    const ProfilePoint lo = parse_uv_vector();
    accept_punct(',');
    const ProfilePoint hi = parse_uv_vector();
    par.umin = std::min(lo.x, hi.x);
    par.umax = std::max(lo.x, hi.x);
    par.vmin = std::min(lo.y, hi.y);
    par.vmax = std::max(lo.y, hi.y);
    bool precompute_axis[3] = {false, false, false};
    int precompute_depth = 1;
    Token precompute_at = keyword;
    for (;;) {
        const Token t = peek();
        if (is_word(t, "accuracy")) {
            next();
            par.accuracy = parse_float();
        } else if (is_word(t, "max_gradient")) {
            next();
            par.max_gradient = parse_float();
        } else if (is_word(t, "precompute")) {
            next();
            precompute_at = t;
            // An int from the float as C converts it (the range is checked below).
            const double d = parse_float();
            precompute_depth = d > -1e9 && d < 1e9 ? int(d) : 0;
            // x, y and z in that order, each optional (a later one given first ends the
            // list), commas optional; a repeated precompute adds to the axes.
            static constexpr std::string_view kAxes[] = {"x", "y", "z"};
            for (int a = 0; a < 3; ++a) {
                accept_punct(',');
                if (accept_word(kAxes[a])) precompute_axis[a] = true;
            }
        } else if (is_word(t, "contained_by")) {
            next();
            parse_contained_by(par.sphere_container, par.corner1, par.corner2, par.centre,
                               par.radius);
        } else {
            break;
        }
    }
    if (precompute_axis[0] || precompute_axis[1] || precompute_axis[2]) {
        if (precompute_depth < 1 || precompute_depth > 20)
            error(precompute_at, "Precompute: invalid depth");
        const FunctionHooks& hooks = parse_time_hooks();
        par.precompute = std::make_shared<const ParametricPrecompute>(
            make_parametric_precompute(par, precompute_axis, precompute_depth, hooks));
    }
    out.shape = std::move(par);
}

}  // namespace povwall::parser
