// julia_fractal { C ... }: the hypercomplex functions (exp ... atanh, pwr) as
// POV-Ray 3.7's Parse_Julia_Fractal reads them, its set-up (radius 4, escape 16) and its
// exact errors.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;
using Function = JuliaFractal::Function;

TEST(ShapeJuliaFractal, ComplexFunctionsAreHypercomplexOnly) {
    const std::pair<const char*, Function> words[] = {
        {"exp", Function::Exp},   {"ln", Function::Ln},
        {"sin", Function::Sin},   {"asin", Function::Asin},
        {"cos", Function::Cos},   {"acos", Function::Acos},
        {"tan", Function::Tan},   {"atan", Function::Atan},
        {"sinh", Function::Sinh}, {"asinh", Function::Asinh},
        {"cosh", Function::Cosh}, {"acosh", Function::Acosh},
        {"tanh", Function::Tanh}, {"atanh", Function::Atanh},
    };
    for (const auto& [word, f] : words) {
        const auto j = only_shape<JuliaFractal>(
            parse(std::string("julia_fractal { <0.1, 0.2, 0.3, 0.4> hypercomplex ") +
                  word + " }"));
        EXPECT_EQ(j.function, f) << word;
        EXPECT_EQ(j.algebra, JuliaFractal::Algebra::Hypercomplex) << word;
        EXPECT_EQ(j.radius2, 16.0) << word;
        EXPECT_EQ(j.exit_value, 16.0) << word;
        EXPECT_EQ(j.max_iteration, 20) << word;
        EXPECT_EQ(j.precision, 1.0 / 20) << word;
        // POV-Ray's set-up refuses them with quaternions (the default algebra).
        EXPECT_EQ(
            error_of(std::string("julia_fractal { 0.5 ") + word + " }"),
            "test.pov:1:1: error: Illegal function: quaternion only supports sqr and "
            "cube")
            << word;
    }
}

TEST(ShapeJuliaFractal, PwrReadsItsComplexExponent) {
    auto j = only_shape<JuliaFractal>(
        parse("julia_fractal { <0.1, 0.2, 0.3, 0.4> hypercomplex pwr(2, -0.5) }"));
    EXPECT_EQ(j.function, Function::Pwr);
    EXPECT_EQ(j.exponent[0], 2.0);
    EXPECT_EQ(j.exponent[1], -0.5);
    j = only_shape<JuliaFractal>(
        parse("julia_fractal { 0.1 pwr(1.5 3) hypercomplex max_iteration 6 }"));
    EXPECT_EQ(j.exponent[0], 1.5);  // the comma is optional
    EXPECT_EQ(j.exponent[1], 3.0);
    EXPECT_EQ(j.max_iteration, 6);
    // The last function named wins; the exponent stays.
    j = only_shape<JuliaFractal>(
        parse("julia_fractal { 0.1 hypercomplex pwr(2, 1) sin }"));
    EXPECT_EQ(j.function, Function::Sin);
    EXPECT_EQ(j.exponent[0], 2.0);
    j = only_shape<JuliaFractal>(parse("julia_fractal { 0.1 hypercomplex sin sqr }"));
    EXPECT_EQ(j.function, Function::Sqr);
}

TEST(ShapeJuliaFractal, Errors) {
    EXPECT_EQ(
        error_of("julia_fractal { 0.1 pwr(2, 1) }"),
        "test.pov:1:1: error: Illegal function: quaternion only supports sqr and cube");
    EXPECT_EQ(
        error_of("julia_fractal { 0.1 quaternion reciprocal }"),
        "test.pov:1:1: error: Illegal function: quaternion only supports sqr and cube");
    // POV-Ray: "Expected '(', < found instead".
    EXPECT_EQ(error_of("julia_fractal { 0.1 hypercomplex pwr <2, 1> }"),
              "test.pov:1:38: error: expected '(' but found '<'");
    // Other float functions and floats: "Expected 'fractal keyword', float function
    // 'sqrt' found instead".
    EXPECT_EQ(error_of("julia_fractal { 0.1 hypercomplex sqrt }"),
              "test.pov:1:34: error: expected fractal keyword but found 'sqrt'");
    EXPECT_EQ(error_of("julia_fractal { 0.1 hypercomplex pwr 2, 1 }"),
              "test.pov:1:38: error: expected '(' but found '2'");
    EXPECT_EQ(error_of("julia_fractal { 0.1 precision 10 3 }"),
              "test.pov:1:34: error: expected fractal keyword but found '3'");
    EXPECT_EQ(error_of("julia_fractal { 0.1 slice 0, 1 }"),
              "test.pov:1:27: error: Slice vector is zero.");
    EXPECT_EQ(error_of("julia_fractal { 0.1 slice <1, 0, 0, 0>, 1 }"),
              "test.pov:1:27: error: Slice t component is zero.");
}

}  // namespace
}  // namespace povwall::parser
