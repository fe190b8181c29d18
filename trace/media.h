// Participating media along a ray (POV-Ray 3.7's `media { }`): what a stretch of media
// does to the colour arriving from its far end, as POV-Ray samples and integrates it
// (methods 1, 2 and 3, intervals, density patterns). The effect is affine in that
// colour (colour * mul + add), so it composes with fog and lets the children of a hit
// still combine linearly (trace/shading.h).
#pragma once

#include <span>

#include "core/scene.h"
#include "trace/pattern.h"

namespace povwall::trace {

struct MediaEffect {
    Rgb mul{1.0f}, add{0.0f};
    float mul_transmit = 1;  // POV-Ray scales the transmit by the grey of mul
};

// The media `list` over [t0, t1] of `ray` (unit direction). A shadow ray gathers only
// extinction (its `add` stays 0). Random positions (method 1, jitter) come from a hash of
// the ray and the sample, so every render mode draws the same ones.
MediaEffect media_effect(std::span<const Media* const> list, const Ray& ray, Real t0,
                         Real t1, bool shadow, const PatternEnv& env);

// Whether any media of `list` dims what lies behind it (a shadow ray then needs it).
bool media_has_extinction(std::span<const Media* const> list);

}  // namespace povwall::trace
