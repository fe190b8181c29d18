#include "trace/pattern.h"

namespace povwall::trace {

// Placeholder until the pattern library lands (issue 5): solid pigments only.
Real evaluate_pattern(const PatternSpec& spec, const Point3& world, const PatternEnv& env) {
    return 0;
}

Colour evaluate_pigment(const Pigment& pigment, const Point3& world, const PatternEnv& env) {
    return pigment.colour;
}

Vector3 perturb_normal(const Normal& normal, const Point3& world, const Vector3& geometric,
                       const PatternEnv& env) {
    return geometric;
}

}  // namespace povwall::trace
