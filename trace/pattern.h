// Pattern evaluation: pigments, normals and texture-map selection at a world-space point.
// Every PatternSpec carries its own pattern->world transform (the parser composes object
// transforms into it), so callers pass world points.
#pragma once

#include "core/scene.h"

namespace povwall::trace {

struct PatternEnv {
    int noise_generator = 2;  // global_settings noise_generator, used when a pattern says 0
};

// The pattern's value in [0,1] at `world` (after warps, wave type, frequency and phase).
Real evaluate_pattern(const PatternSpec& spec, const Point3& world, const PatternEnv& env);

// The pigment's colour (rgbft) at `world`.
Colour evaluate_pigment(const Pigment& pigment, const Point3& world, const PatternEnv& env);

// `normal` (unit, world space) perturbed by the normal pattern at `world`; returns unit length.
Vector3 perturb_normal(const Normal& normal, const Point3& world, const Vector3& geometric,
                       const PatternEnv& env);

}  // namespace povwall::trace
