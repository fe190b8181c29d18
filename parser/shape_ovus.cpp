// ovus { bottom_radius [,] top_radius modifiers }
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_ovus(const Token& keyword, Object& out) {
    // POV-Ray checks the radii after reading both: the error points at the second.
    require_operand("the ovus's bottom radius");
    const Real bottom = parse_float();
    accept_punct(',');
    require_operand("the ovus's top radius");
    const Token at = peek();
    const Real top = parse_float();
    if (top < 0 || bottom < 0) error(at, "Both Ovus radii must be positive");
    if (top < 2.0 * bottom) {
        out.shape = make_ovus(bottom, top);
        return;
    }
    // As POV-Ray: a sphere, which it is then (and `sturm` on it is an error).
    warn(keyword,
         "Ovus second radius should be less than twice first radius; substituting a "
         "sphere to ovus as it would be identical & simpler");
    out.shape = Sphere{{0, bottom, 0}, top};
}

}  // namespace povwall::parser
