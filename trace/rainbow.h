// Rainbows (`rainbow { }`, POV-Ray 3.7's Trace::ComputeRainbow): on a viewing ray in
// hollow space, each rainbow whose band the ray's direction falls in blends the colour
// arriving along the ray toward its colour map's colour there, more with distance. The
// effect is affine in that colour (as fog's), so it composes with media and fog.
#pragma once

#include "core/scene.h"
#include "trace/pattern.h"

namespace povwall::trace {

struct RainbowEffect {
    Rgb add{0.0f}, mul{1.0f};
    float mul_transmit = 1;
};

// The scene's rainbows on `ray` (unit direction) whose hit is `depth` away (POV-Ray's
// 2e10 for a ray that hits nothing). `jitter` moves the band by a random amount: ours is
// a hash of the ray, the same in every render mode.
RainbowEffect rainbow_effect(const Scene& scene, const Ray& ray, Real depth,
                             const PatternEnv& env);

}  // namespace povwall::trace
