// User functions (`function { ... }`), compiled by the parser into a small stack program
// over doubles and run wherever they are needed: SDL calls while parsing, the function
// pattern while rendering. Plain data; no allocation and no virtual call per evaluation.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"
#include "core/spline.h"

namespace povwall {

struct PatternSpec;
struct Pigment;
struct Colour;

// Patterns and pigments are evaluated in trace/, which core cannot call: the caller
// passes these hooks (null: such a function gives 0).
struct FunctionHooks {
    Real (*pattern)(const PatternSpec& spec, const Point3& p,
                    const void* context) = nullptr;
    // The pigment's rgbft at `p`, written to `out`.
    void (*pigment)(const Pigment& pigment, const Point3& p, const void* context,
                    float out[5]) = nullptr;
    const void* context = nullptr;
    // Parse time only: gives the hooks the global settings parsed so far, which POV-Ray
    // evaluates patterns with (a render's context holds the scene's already).
    void (*use_settings)(const void* context, int noise_generator,
                         int number_of_waves) = nullptr;
    int noise_generator = 2;  // global_settings noise_generator, for f_noise3d
    // When set, sum/prod iterations left; at 0 every loop stops (a parse-time call
    // reports it instead of hanging on `sum(i, 0, 1e18, i)`).
    uint64_t* iterations_left = nullptr;
};

// The float built-ins shared by SDL expressions and the function language (`sin(A)`,
// `pow(A, B)`).
struct FloatBuiltin {
    std::string_view name;
    int arity;
    double (*fn)(const double*);
};
const FloatBuiltin* find_float_builtin(std::string_view name);  // null: not one

struct FunctionProgram {
    enum class Op : uint8_t {
        Constant,   // push constants[index]
        Parameter,  // push args[index]
        Add,
        Subtract,
        Multiply,
        Divide,
        Negate,
        // POV-Ray's three-way comparison: an unordered pair (NaN) compares as greater.
        Less,
        LessEqual,
        Equal,
        NotEqual,
        GreaterEqual,
        Greater,
        And,
        Or,
        Builtin,  // builtins[index], with its arity of operands
        Int,
        Div,  // C's cast to a 32-bit int (of the operand, of a / b)
        Min,
        Max,  // two operands; min takes a NaN, max keeps the running value
        // select(a, b, c[, d]) as POV-Ray compiles it: only the chosen branch runs.
        // Branch pops a and goes to branches[index][a < 0 ? 0 : a == 0 ? 1 : 2] (an
        // unordered a, NaN, to 2; a three-argument select's 1 and 2 are the same);
        // each branch but the last ends in a Jump to the code after the select.
        Branch,
        Jump,                // to code[index]
        Call,                // callees[index] with its parameter count of operands
        SplineComponent,     // splines[index] at the operand, component `component`
        Pattern,             // patterns[index] at the three operands
        PigmentComponent,    // pigments[index] at the three operands; component 5: gray
        Internal,            // functions.inc's internal(index), 3 + internal_extra(index)
        TransformComponent,  // transforms[index] of the three operands, `component`
        // sum/prod(i, lo, hi, body): callees[index] (this function's parameters and i)
        // for i = lo, lo + 1, ... while i <= hi; pops lo and hi
        Sum,
        Product,
    };
    struct Instruction {
        Op op;
        uint8_t component = 0;
        uint32_t index = 0;
    };
    std::vector<Instruction> code;
    std::vector<double> constants;
    std::vector<std::array<uint32_t, 3>> branches;  // Branch's targets
    std::vector<const FloatBuiltin*> builtins;
    std::vector<std::string> parameter_names;  // x, y, z unless the scene names them
    std::vector<std::shared_ptr<const FunctionProgram>> callees;
    std::vector<std::shared_ptr<const Spline>> splines;
    std::vector<std::shared_ptr<const PatternSpec>> patterns;
    std::vector<std::shared_ptr<const Pigment>> pigments;
    std::vector<std::shared_ptr<const Transform>> transforms;
    int stack_size = 0;  // deepest operand stack the code reaches
    int call_depth = 1;  // nested evaluate_function calls one evaluation makes
    // Vector functions (their code is empty): `function { spline { ... } }` of one
    // parameter, `function { pigment { ... } }` of x, y, z (rgbft), `function {
    // transform { ... } }` of x, y, z (the transformed point).
    std::shared_ptr<const Spline> spline;
    std::shared_ptr<const Pigment> pigment;
    std::shared_ptr<const Transform> transform;

    int parameter_count() const { return int(parameter_names.size()); }
};

// Deeper programs are refused when compiled, so evaluation needs no allocation.
constexpr int kMaxFunctionStack = 128;
constexpr int kMaxFunctionParameters = 56;  // POV-Ray's limit
// Functions calling functions: each level is a C++ frame of about 1.2 KB.
constexpr int kMaxFunctionCallDepth = 1000;

// functions.inc's internal(n) (core/internal_function.h): how many parameters after x,
// y, z; -1 for an n POV-Ray 3.7 does not have (it has 0 ... 78).
int internal_extra(int n);

// Runs `f` (a float function) on parameter_count() arguments.
double evaluate_function(const FunctionProgram& f, const double* args,
                         const FunctionHooks& hooks);

}  // namespace povwall
