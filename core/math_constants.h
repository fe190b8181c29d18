// Numeric constants that several files of POV-Ray's geometry and pattern code share, in
// one place: a unity build (POVWALL_UNITY) compiles those files as one translation unit.
#pragma once

#include "core/math.h"

namespace povwall {

constexpr Real kPovEpsilon = 1e-10;  // POV-Ray's EPSILON
constexpr Real kSqrt3 = 1.7320508075688772935;
constexpr Real kSqrt3Half = 0.86602540378443864676;

}  // namespace povwall
