// superellipsoid { <e, n> modifiers }
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_superellipsoid(Object& out) {
    // e, n <= 0 are not checked, as in POV-Ray.
    require_operand("the superellipsoid's exponents");
    const ProfilePoint e = parse_uv_vector();
    out.shape = Superellipsoid{e.x, e.y};
}

}  // namespace povwall::parser
