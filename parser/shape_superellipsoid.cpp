// superellipsoid { <e, n> modifiers }
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_superellipsoid(Object& out) {
    // POV-Ray reads a UV vector: a float stands for both; e, n <= 0 are not checked.
    require_operand("the superellipsoid's exponents");
    Token at = peek();
    Numeric v = parse_express();
    if (v.size > 2) error(at, "UV_Vector expected but vector or color expression found");
    Superellipsoid s;
    s.east_west = v.c[0];
    s.north_south = v.size == 1 ? v.c[0] : v.c[1];
    out.shape = s;
}

}  // namespace povwall::parser
