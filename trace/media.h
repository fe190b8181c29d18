// Participating media along a ray (POV-Ray 3.7's `media { }`): what a stretch of media
// does to the colour arriving from its far end, as POV-Ray samples and integrates it
// (methods 1, 2 and 3, intervals, density patterns, lit intervals and scattering). The
// effect is affine in that colour (colour * mul + add), so it composes with fog and lets
// the children of a hit still combine linearly (trace/shading.h).
#pragma once

#include <cstdint>
#include <span>

#include "core/scene.h"
#include "trace/pattern.h"

namespace povwall::trace {

struct MediaEffect {
    Rgb mul{1.0f}, add{0.0f};
    float mul_transmit = 1;  // POV-Ray scales the transmit by the grey of mul
};

// The light reaching a media sample point (POV-Ray's TestShadow there): light `light`'s
// colour at `at` after its own attenuation (spot cone, fade) and the shadow test toward
// it; `to_light` gets the unit direction toward it. Black when nothing arrives.
// `sample` numbers the sample within the stretch (the same in every render mode).
class MediaLightProbe {
  public:
    virtual Rgb arriving(size_t light, const Point3& at, Vector3& to_light,
                         uint64_t sample) = 0;

  protected:
    ~MediaLightProbe() = default;
};

// The lights as media see them: `lights` split a viewing ray into lit and unlit
// intervals (whether or not a media scatters, as POV-Ray); `probe` lights the samples
// of scattering media.
struct MediaLights {
    std::span<const Light> lights;
    MediaLightProbe* probe = nullptr;
    // Sample every position method 3's refinement might ask for (whatever the samples
    // say): how black boxes learn which shadow rays a stretch may need.
    bool every_sample = false;
};

// The media `list` over [t0, t1] of `ray` (unit direction). A shadow ray gathers only
// extinction (its `add` stays 0). Random positions (method 1, jitter) come from a hash of
// the ray and the sample, so every render mode draws the same ones. A viewing ray
// through scattering media needs `lights` with a probe.
MediaEffect media_effect(std::span<const Media* const> list, const Ray& ray, Real t0,
                         Real t1, bool shadow, const PatternEnv& env,
                         const MediaLights* lights = nullptr);

// Whether any media of `list` dims what lies behind it (a shadow ray then needs it).
bool media_has_extinction(std::span<const Media* const> list);

// POV-Ray's phase value of `list` for light arriving along `to_light` and seen along
// `view` (both unit): the mean over the list of each media's phase function (1 for a
// media that does not scatter), without 1/(4 pi).
float media_phase(std::span<const Media* const> list, const Vector3& to_light,
                  const Vector3& view);

}  // namespace povwall::trace
