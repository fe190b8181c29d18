#include "trace/shapes/common.h"

namespace povwall::trace {

Real round_to_float(Real x) { return Real(float(x)); }

}  // namespace povwall::trace
