// julia_fractal { C [max_iteration N | slice V, D | precision P | quaternion |
// hypercomplex | sqr | cube | reciprocal | pwr(X, Y) | exp | ln | sin | asin | cos | acos
// | tan | atan | sinh | asinh | cosh | acosh | tanh | atanh]... }, as POV-Ray 3.7's
// Parse_Julia_Fractal and its set-up (bounding radius, escape value).
#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

using Function = JuliaFractal::Function;

// The float functions POV-Ray takes as hypercomplex functions.
constexpr std::pair<std::string_view, Function> kComplexFunctions[] = {
    {"exp", Function::Exp},     {"ln", Function::Ln},       {"sin", Function::Sin},
    {"asin", Function::Asin},   {"cos", Function::Cos},     {"acos", Function::Acos},
    {"tan", Function::Tan},     {"atan", Function::Atan},   {"sinh", Function::Sinh},
    {"asinh", Function::Asinh}, {"cosh", Function::Cosh},   {"acosh", Function::Acosh},
    {"tanh", Function::Tanh},   {"atanh", Function::Atanh},
};

}  // namespace

void Interpreter::parse_julia_fractal(Object& out, const Token& keyword) {
    JuliaFractal j;
    {
        const Numeric c = parse_numeric();
        for (int k = 0; k < 4; ++k) j.c[size_t(k)] = c.size == 1 ? c.c[0] : c.c[k];
    }
    for (;;) {
        const Token t = peek();
        // POV-Ray reads a float here as a wrong fractal keyword (its float functions too,
        // below).
        if (t.kind == TokenKind::Number) expected("fractal keyword", t);
        if (t.kind != TokenKind::Word) break;
        const std::string_view w = t.text;
        if (w == "max_iteration") {
            next();
            j.max_iteration = std::max(1, int(std::floor(parse_float())));
        } else if (w == "slice") {
            next();
            const Token at = peek();
            const Numeric v = parse_numeric();
            Real s[4];
            for (int k = 0; k < 4; ++k) s[k] = v.size == 1 ? v.c[0] : v.c[k];
            const Real len2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3];
            if (len2 < 1e-10) error(at, "Slice vector is zero.");
            if (std::fabs(s[3]) < 1e-10) error(at, "Slice t component is zero.");
            const Real len = std::sqrt(len2);
            for (int k = 0; k < 4; ++k) j.slice[size_t(k)] = s[k] / len;
            accept_punct(',');
            j.slice_distance = parse_float();
        } else if (w == "precision") {
            next();
            j.precision = 1 / std::max(1.0, parse_float());
        } else if (w == "quaternion") {
            next();
            j.algebra = JuliaFractal::Algebra::Quaternion;
        } else if (w == "hypercomplex") {
            next();
            j.algebra = JuliaFractal::Algebra::Hypercomplex;
        } else if (w == "sqr") {
            next();
            j.function = JuliaFractal::Function::Sqr;
        } else if (w == "cube") {
            next();
            j.function = JuliaFractal::Function::Cube;
        } else if (w == "reciprocal") {
            next();
            j.function = JuliaFractal::Function::Reciprocal;
        } else if (w == "pwr") {
            next();
            expect_punct('(');
            j.exponent[0] = parse_float();
            accept_punct(',');
            j.exponent[1] = parse_float();
            expect_punct(')');
            j.function = Function::Pwr;
        } else {
            const auto* f =
                std::find_if(std::begin(kComplexFunctions), std::end(kComplexFunctions),
                             [&](const auto& e) { return e.first == w; });
            if (f != std::end(kComplexFunctions)) {
                next();
                j.function = f->second;
                continue;
            }
            if (starts_float(t)) expected("fractal keyword", t);
            break;
        }
    }
    if (j.algebra == JuliaFractal::Algebra::Quaternion && j.function != Function::Sqr &&
        j.function != Function::Cube)
        error(keyword, "Illegal function: quaternion only supports sqr and cube");
    if (j.algebra == JuliaFractal::Algebra::Quaternion) {
        const Real r = std::min(2.0, 1 +
                                         std::sqrt(j.c[0] * j.c[0] + j.c[1] * j.c[1] +
                                                   j.c[2] * j.c[2] + j.c[3] * j.c[3]) +
                                         1e-7);
        j.radius2 = r * r;
        j.exit_value = r * r + 1e-7;
    } else {
        j.radius2 = 16;
        j.exit_value = 16;
    }
    out.shape = j;
}

}  // namespace povwall::parser
