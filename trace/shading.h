// Shading, written once as two steps so that every back end uses the same code:
//
//   spawn_children():   from a hit, the local colour and the child rays to trace (one
//   shadow
//                       ray per light, a reflection per reflective texture layer, one
//                       refraction/transmission ray), each with the coefficient it
//                       contributes with;
//   combine_children(): from the children's results, the colour.
//
// The single-process tracer calls them recursively; a black box of the distributed back
// end calls spawn_children() when a ray hits and combine_children() when the results are
// in.
//
// Linearity: colour = fog.add + fog.mul * (local + sum_i coeff_i * result_i), where every
// coeff_i and the fog terms are fixed at spawn time, so most children can forward
// `parent weight * coeff` to the pixel without a waiting parent. The non-linear cases
// are:
//   - reflection children with `exponent` != 1: coeff * pow(result, 1/exponent);
//   - the alpha channel (transmit): transmit_factor * child transmit, scaled by fog;
//   - area-light shadow children: one child stands for POV-Ray's whole adaptive sample
//   grid,
//     whose refinement depends on sample results (evaluated as a unit by
//     shadow_transmittance()).
// Shadow children of point lights return a transmittance (product of filters and interior
// fades), which multiplies the light's contribution: linear in that transmittance.
#pragma once

#include <cstdint>
#include <vector>

#include "trace/interior_stack.h"
#include "trace/prepared_scene.h"
#include "trace/spectral.h"

namespace povwall::trace {

// A ray to trace, with what exact POV-Ray semantics need to know about it.
struct TraceRay {
    Ray ray;        // unit direction
    int depth = 1;  // 1 for camera rays; refused when above max_trace_level
    // Passed straight through a surface between equal indices of refraction (POV-Ray's
    // continued ray): it keeps its parent's depth, and is refused already at
    // max_trace_level, where POV-Ray's level test meets it.
    bool continued = false;
    float weight = 1;  // adc_bailout weight
    RayUse use = RayUse::Camera;
    // Radiosity bounces above this ray (0: the camera's ray tree). Its children keep
    // it; rays under a radiosity sample ray see no fog, media or area-light grid
    // (POV-Ray's radiosity quality flags) and gather at the next recursion level.
    uint8_t radiosity_depth = 0;
    int max_level = 0;       // > 0: its max_trace_level (a radiosity gather's)
    float adc_bailout = -1;  // >= 0: its adc_bailout (radiosity's)
    // The wavelength band of a ray split by dispersion; its descendants keep it.
    RayBand band;
    InteriorStack interiors;
};

struct TraceResult {
    Rgb colour;
    float transmit = 0;  // how much of the background shows through (alpha output)
};

struct ChildRay {
    enum class Kind : uint8_t { Shadow, Reflection, Transmission } kind = Kind::Shadow;
    TraceRay trace;
    Real t_max = kInfinity;  // shadow rays: distance to the light
    int light = -1;
    Rgb coeff{1.0f};            // contribution factor of the child's result
    float exponent = 1;         // reflection: result is coeff * pow(child, 1/exponent)
    float transmit_factor = 0;  // transmission: share of the child's transmit that shows
    // Area-light shadow: the child stands for POV-Ray's whole adaptive sample grid of
    // light `light`; its result is the grid's averaged transmittance. The grid refinement
    // depends on sample results (a documented non-linear case), so it is evaluated as one
    // unit.
    bool area = false;
    Rgb light_colour{1.0f};  // attenuated light colour (area-light refinement threshold)
    // The render plan proved nothing can block this shadow ray: its result is 1 without a
    // query (kept as a child so the colour is summed exactly as when traced).
    bool unoccluded = false;
    // A reflection made by total internal reflection (the photon pass follows it as
    // refraction, as POV-Ray does).
    bool internal_reflection = false;
    // Shadow rays: the lit surface collects photons, so a blocker that refracts this
    // light's photons shadows fully (its caustic is in the photon map).
    bool photon_caustics = false;
};

// Fog along a ray of known length: the ray's colour c becomes add + mul * c (affine, so
// the children still combine linearly). Identity when the scene has no fog.
struct FogEffect {
    Rgb add{0.0f}, mul{1.0f};
    float add_transmit = 0, mul_transmit = 1;
};
FogEffect fog_effect(const Scene& scene, const Ray& ray, Real depth);

// Which lights light the media along a ray (light groups, as POV-Ray's
// ComputeMediaLightInterval): those of the object the ray ends on; a ray that hits
// nothing, the global lights.
struct MediaEndLights {
    bool global_lights = true;
    uint32_t light_group = 0;
};

// What lies along a ray up to `depth` does to the colour there: the media of the
// interiors it is in, the atmosphere's media, then fog (POV-Ray's order); identity
// inside a solid (non-hollow) object. The caller checks the quality level.
// Scattering media light their samples with shadow rays traced at once with `ctx`;
// `end` (the object at `depth`) says which lights light them.
FogEffect along_ray_effect(const PreparedScene& scene, const TraceRay& ray, Real depth,
                           MediaEndLights end, RayContext* ctx = nullptr);

class MediaPhotonSink;
// A photon in flight (POV-Ray's PhotonTrace::ComputeLightedTexture): the media of the
// interiors it is in act on its `colour` up to `depth` (the object there, `end`, says
// which lights split the stretch into intervals): their extinction dims it and their
// emission adds to it, as on a viewing ray, but they scatter no light into it; with a
// `sink`, they store media photons instead (deposit_media_photons). The atmosphere's
// media and fog leave photons alone. Returns the photon's colour at `depth`.
Rgb photon_through_media(const PreparedScene& scene, const TraceRay& ray, Real depth,
                         MediaEndLights end, const Rgb& colour, MediaPhotonSink* sink);

// Which shadow ray of a media stretch: the list (0: the interiors' media, 1: the
// atmosphere's), the sample (MediaLightProbe) and the light.
struct MediaSampleKey {
    uint64_t sample;
    uint32_t light;
    uint8_t list;
};

struct ShadingRecord {
    Rgb local;                 // ambient and emission: needs no child
    float local_transmit = 0;  // a missed ray's own transmit (spawn_miss)
    std::vector<ChildRay> children;
    FogEffect fog;  // applied to the combined colour
    // Black boxes: children from media_first on are the shadow rays of the media
    // samples along the ray (media_samples[i] says which is children[media_first + i]);
    // replay_media() sets `fog` from their results (media_replay: scattering media
    // were met). The stretch ends at media_depth (a hit) or is a ray that missed
    // everything (media_miss).
    std::vector<MediaSampleKey> media_samples;
    size_t media_first = 0;
    Real media_depth = 0;
    MediaEndLights media_lights;
    bool media_miss = false, media_replay = false;
    void clear() {
        local = Rgb{};
        local_transmit = 0;
        children.clear();
        fog = FogEffect{};
        media_samples.clear();
        media_first = 0;
        media_depth = 0;
        media_lights = {};
        media_miss = false;
        media_replay = false;
    }
};

// Where the light of scattering media samples comes from: shadow rays traced at once
// with `trace` (the single-process tracer); in black boxes, shadow children appended to
// `collect` at spawn time for every sample refinement may ask for, read back by
// `replay` from `results` (`order`: media_samples' indices sorted by key).
struct MediaShadows {
    RayContext* trace = nullptr;
    ShadingRecord* collect = nullptr;
    const ShadingRecord* replay = nullptr;
    const TraceResult* results = nullptr;
    const uint32_t* order = nullptr;
};

// Black boxes, once a record's children are in: its effect along the ray from its media
// samples' shadow results (POV-Ray's adaptive rule on them; the single-process tracer's
// value).
void replay_media(const PreparedScene& scene, const TraceRay& ray, ShadingRecord& record,
                  const TraceResult* results);

// Black boxes: a ray that hits nothing where the atmosphere scatters light needs shadow
// rays from its media samples: `out` is its record (local: the sky; children: those
// shadow rays). False when miss_colour() gives its colour at once.
bool spawn_miss(const PreparedScene& scene, const TraceRay& ray, ShadingRecord& out);

// Step 1. `ray` hit `hit`; fills `out` (cleared first).
// `ctx`: see along_ray_effect(); without one (black boxes), the media samples' shadow
// rays are more children (ShadingRecord::media_samples).
void spawn_children(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
                    ShadingRecord& out, RayContext* ctx = nullptr);
// The same without the effects along the ray (fog, media and their lights' shadow
// rays): a photon's path, which takes the media on the photon itself
// (photon_through_media), needs only the surface's children.
void spawn_surface_children(const PreparedScene& scene, const TraceRay& ray,
                            const Hit& hit, ShadingRecord& out, RayContext& ctx);

// Step 2. `results[i]` is the result of `record.children[i]`: the traced colour for
// reflection/transmission, the light's transmittance (rgb) for shadow rays.
TraceResult combine_children(const ShadingRecord& record, const TraceResult* results);

// Shadow ray state carried from box to box: the product of filters met so far, where the
// search resumes (absolute distance along the ray: the origin is never moved), and the
// transparent objects the ray is inside of (for their interior fade).
struct ShadowState {
    Rgb filter{1.0f};
    Real t_min = 1e-3;  // POV-Ray's SHADOW_TOLERANCE
    Real last_hit = 0;  // distance of the previous crossing (fade is per stretch)
    bool blocked = false;
    InteriorStack inside;  // start with the lit ray's interiors
    int light = -1;        // the light it goes to (for the box's last-blocker cache)
    bool photon_caustics = false;  // see ChildRay::photon_caustics
    // Media and fog dim it: false under a radiosity sample ray unless the radiosity
    // block says `media on` (POV-Ray's radiosity quality flags).
    bool volume = true;
};
// Whether media and fog act along `ray`: always, except under a radiosity sample ray
// when the radiosity block leaves `media` off (its default).
bool sees_volume(const Scene& scene, const TraceRay& ray);
// Advances `state` over hits with t in [state.t_min, min(segment_end, light_distance -
// 1e-3)). Returns true once the light is fully blocked.
bool shadow_segment(const PreparedScene& scene, const Ray& ray, Real segment_end,
                    Real light_distance, ShadowState& state, RayContext& ctx);
// The rest of an unblocked shadow ray, from its last crossing to the light: the
// atmosphere's media dim it when the light has media_attenuation (POV-Ray's
// TraceShadowRay).
void shadow_last_leg(const PreparedScene& scene, const Ray& ray, Real light_distance,
                     ShadowState& state);

// Tie probe (trace/ties.h): whether `hit` lies on a jump of its surface's pigment (or
// texture map) pattern: the colours just above and just below the surface, `tolerance`
// (relative to the point's size, at least 1) away along the normal, differ by more than
// 0.1 in a channel. The last bits of the hit point then pick the colour (a gradient's
// wrap exactly at a box's face).
bool on_pattern_boundary(const PreparedScene& scene, const Hit& hit, Real tolerance);

// Transmittance toward a light (shadow ray), POV-Ray's rules: hits in (1e-3, distance -
// 1e-3), filters multiply, opaque blocks, interior fade between entering and leaving. For
// an area light (`shadow.area`), the adaptive grid average (TraceAreaLightShadowRay's
// rules: corners first, quadrants refined while level < adaptive or corners differ by >
// 0.1).
Rgb shadow_transmittance(const PreparedScene& scene, const ChildRay& shadow,
                         RayContext& ctx);

// An area light's sample grid as seen from one lit point (the shadow child's origin):
// where each sample is, and POV-Ray's adaptive average of sample transmittances. The
// single-process tracer samples what the adaptive rule asks for; black boxes trace every
// sample as a shadow ray of its own and average them once all are in (the same value:
// the rule reads only samples it asks for).
struct AreaGrid {
    AreaGrid(const Scene& scene, const ChildRay& shadow);
    size_t samples() const { return size_t(n1) * size_t(n2); }
    // The shadow ray toward sample (u, v) and the distance to it; false when the point
    // is the sample itself (transmittance 1). With `jitter` the sample moves within its
    // cell by up to half a cell each way, as POV-Ray's; POV-Ray draws the offsets from a
    // per-thread random sequence (no two of its renders agree), ours are a hash of the
    // lit point, the light and the sample, so every render mode gives the same image.
    bool sample_ray(int u, int v, Ray& ray, Real& distance) const;
    // The adaptive average of `samples` (u-major, n1 x n2).
    Rgb average(const Rgb* samples) const;

    const Light& light;
    int light_index;
    const AreaLight& area;
    Point3 at;
    int n1, n2;
    Vector3 axis1, axis2;
    Rgb light_colour;
};

// POV-Ray 3.7's interior fade after `distance` inside a medium (camera/secondary rays and
// shadow rays differ in one test, hence the flag).
Rgb interior_attenuation(const Interior& in, Real distance, bool shadow_ray);

// Colour of a ray that hits nothing (background or sky_sphere), fog included.
// The atmosphere's media act only on a hollow ray (not inside a solid object), as
// POV-Ray.
// `ctx`: see along_ray_effect().
TraceResult miss_colour(const PreparedScene& scene, const TraceRay& ray,
                        RayContext* ctx = nullptr);

}  // namespace povwall::trace
