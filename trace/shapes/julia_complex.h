// The hypercomplex functions of julia_fractal (exp ... atanh, pwr): a complex function
// applied to both complex parts of the duplex form, with POV-Ray 3.7's branch choices.
#pragma once

#include <array>

#include "core/scene.h"

namespace povwall::trace {

using Quad = std::array<Real, 4>;  // x, y, z, w

struct Complex {
    Real re = 0, im = 0;
};

// f(z) for one of the complex functions (Function::Exp ... Function::Pwr). Where POV-Ray
// leaves its result unassigned (atanh of exactly +-1, a tan/tanh pole hit exactly), `out`
// keeps what it held.
void complex_function(JuliaFractal::Function f, const Complex& exponent, const Complex& z,
                      Complex& out);

// f(q) for the hypercomplex q: q splits into a = (x - w) + i(y + z) and
// b = (x + w) + i(y - z), both go through f, and the parts recombine.
Quad hypercomplex_function(const JuliaFractal& j, const Quad& q);

}  // namespace povwall::trace
