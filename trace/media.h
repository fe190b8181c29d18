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

class PhotonMap;

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
    // Light groups (POV-Ray's ComputeMediaLightInterval): a stretch is lit by the lights
    // of the object it ends on, the global ones unless that object's group turned them
    // off; a ray that hits nothing sees the global lights only (light_group 0).
    bool global_lights = true;
    uint32_t light_group = 0;
    MediaLightProbe* probe = nullptr;
    // Sample every position method 3's refinement might ask for (whatever the samples
    // say): how black boxes learn which shadow rays a stretch may need.
    bool every_sample = false;
    // A photon in flight (POV-Ray's IsPhotonRay): the lights split it into intervals
    // as a viewing ray, but its samples gather no scattered light.
    bool photon = false;
    // The media photon map (PhotonMap::media()): every sample of scattering media, lit
    // or not, gathers the photons around it too.
    const PhotonMap* media_photons = nullptr;
};

// The media `list` over [t0, t1] of `ray` (unit direction). A shadow ray gathers only
// extinction (its `add` stays 0). Random positions (method 1, jitter) come from a hash of
// the ray and the sample, so every render mode draws the same ones. A viewing ray
// through scattering media needs `lights` with a probe.
MediaEffect media_effect(std::span<const Media* const> list, const Ray& ray, Real t0,
                         Real t1, bool shadow, const PatternEnv& env,
                         const MediaLights* lights = nullptr);

// A photon crossing media in the photon pass that stores media photons (POV-Ray's
// ComputeMediaAndDepositPhotons): where each sample interval is sampled and what is
// stored there.
class MediaPhotonSink {
  public:
    // The photons' spacing at unit distance from the light (POV-Ray's photonSpread),
    // the distance the photon has come before this stretch, the spacing factor and the
    // most steps per interval (`media steps, factor`), the jitter of the steps.
    double spread_at_unit = 0, travelled = 0, spacing_factor = 1;
    // From a parallel light: the spacing is spread_at_unit everywhere (no distance).
    bool parallel = false;
    int max_steps = 0;
    float step_jitter = 0;
    virtual Real draw() = 0;  // uniform in [0, 1): a step's jitter
    // A media photon at `at`, `along` the stretch, with `colour` (before the light's
    // fade and the spread's scaling).
    virtual void store(const Point3& at, Real along, const Rgb& colour) = 0;

  protected:
    ~MediaPhotonSink() = default;
};

// The media `list` over [0, t1] of a photon `ray` with `colour`, storing media photons
// into `sink` (only where the media scatter and some media collects them), evenly
// spaced and jittered along each sample interval; returns the photon's colour
// afterwards, dimmed by the extinction of those samples (no emission: POV-Ray's method
// 2 on the stored steps). POV-Ray leaves media without absorption or scattering alone.
Rgb deposit_media_photons(std::span<const Media* const> list, const Ray& ray, Real t1,
                          const MediaLights& lights, const PatternEnv& env,
                          const Rgb& colour, MediaPhotonSink& sink);

// Whether any media of `list` dims what lies behind it (a shadow ray then needs it).
bool media_has_extinction(std::span<const Media* const> list);

// POV-Ray's phase value of `list` for light arriving along `to_light` and seen along
// `view` (both unit): the mean over the list of each media's phase function (1 for a
// media that does not scatter), without 1/(4 pi).
float media_phase(std::span<const Media* const> list, const Vector3& to_light,
                  const Vector3& view);

}  // namespace povwall::trace
