// Expressions in loop bodies and macros, compiled once per source position.
//
// A `#while` body is re-read token by token on every iteration, as POV-Ray does; most of
// those tokens are arithmetic (`<(2 * rand(R) - 1) * Half, ...>`). The first time an
// expression at a given token is read inside a loop or macro, it is compiled into a
// small stack program, if it only uses numbers, numeric identifiers, the operators,
// parentheses, vector literals, `rand()`, the float functions (`sin`, `pow`, ...) and
// the constants (`pi`, `x`, `clock`, ...). Later reads check the
// program's guards (each identifier still holds a number, each keyword is still unbound)
// and run it, skipping the tokens. Anything else (a string, a macro call, a directive
// inside the expression, a function) is left to ExpressionParser, which remains the
// definition of the language: a program must give exactly its result.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "core/function.h"
#include "parser/source.h"
#include "parser/value.h"

namespace povwall::parser {

// Binary operators, shared by ExpressionParser and the programs so both read the same
// grammar. Levels from loosest to tightest; all are left-associative.
enum : int {
    kNotAnOperator = 0,
    kOrLevel,
    kAndLevel,
    kComparisonLevel,
    kSumLevel,
    kProductLevel
};
enum class BinaryOpCode : uint8_t { Or, And, Eq, Ne, Lt, Le, Gt, Ge, Add, Sub, Mul, Div };
struct BinaryOp {
    int level = kNotAnOperator;
    BinaryOpCode code = BinaryOpCode::Add;
};
// `no_gt`: inside a vector literal, where '>' closes the vector.
BinaryOp binary_op(const Token& t, bool no_gt);
Numeric apply_binary(BinaryOpCode code, const Numeric& a, const Numeric& b);

// `a op b` in place when both are plain floats and the operator is arithmetic (the common
// case, and what apply_binary gives, without its promotion loop); false otherwise.
// Inline so that compiled programs skip the call.
inline bool apply_to_floats(BinaryOpCode code, Numeric& a, const Numeric& b) {
    if (a.size != 1 || b.size != 1 || a.colour || b.colour || code < BinaryOpCode::Add)
        return false;
    const double y = b.c[0];
    switch (code) {
        case BinaryOpCode::Add:
            a.c[0] += y;
            break;
        case BinaryOpCode::Sub:
            a.c[0] -= y;
            break;
        case BinaryOpCode::Mul:
            a.c[0] *= y;
            break;
        default:
            a.c[0] /= y;
            break;
    }
    a.c[1] = a.c[2] = a.c[3] = a.c[4] = 0;
    return true;
}

// The built-in functions of floats (`sin(A)`, `pow(A, B)`): the argument of a
// one-argument function is a full expression, those of two-argument ones sums (as
// POV-Ray's Parse_Float_Param and Parse_Float_Param2), commas between them optional; each
// contributes its first element.
using FloatFunction = FloatBuiltin;
const FloatFunction* find_float_function(std::string_view name);  // null: not one

struct ExpressionProgram {
    enum class Code : uint8_t {
        Constant,  // push constants[arg]
        Variable,  // push the value of numeric_syms[arg]
        Negate,
        Not,
        Binary,  // pop b, pop a, push a op b
        Vector,  // pop arg components, push their first elements as a vector
        Rand,    // pop the stream number, push its next draw; arg: token of the argument
        Call,    // pop `function->arity` arguments, push function->fn of them
    };
    struct Instruction {
        Code code;
        BinaryOpCode op = BinaryOpCode::Add;
        uint32_t arg = 0;
        const FloatFunction* function = nullptr;
    };
    std::vector<Instruction> code;
    std::vector<Numeric> constants;
    std::vector<uint32_t> numeric_syms;  // each must be bound to a number when run
    std::vector<uint32_t> keyword_syms;  // each must be unbound when run
    size_t end = 0;                      // token index after the expression
    int nesting = 0;  // ExpressionParser levels it stands for (parentheses, components)
    static constexpr int kMaxStack = 32;
};

}  // namespace povwall::parser
