// The single-process driver: traces a ray by calling spawn_children / combine_children
// recursively (the distributed back end drives the same two steps through messages).
// When the shading is linear it sums the rays' forward contributions instead, as the
// black boxes do without parent tracking.
#pragma once

#include <algorithm>
#include <deque>
#include <memory>

#include "trace/forward_sum.h"
#include "trace/shading.h"

namespace povwall::trace {

// Rays traced, by kind, with POV-Ray's two render statistics about the ray tree: the
// rays refused for their weight (adc_bailout: its "Saved") and the deepest trace level a
// ray was traced at (its "Max Level", 1 for camera rays). Every driver counts with these.
struct TraceCounters {
    uint64_t camera = 0, reflected = 0, refracted = 0, shadow = 0;
    uint64_t radiosity = 0;  // radiosity sample rays
    uint64_t adc_saved = 0;
    int max_level = 0;
    uint64_t rays() const { return camera + reflected + refracted + shadow; }
    TraceCounters& operator+=(const TraceCounters& o) {
        camera += o.camera;
        reflected += o.reflected;
        refracted += o.refracted;
        shadow += o.shadow;
        radiosity += o.radiosity;
        adc_saved += o.adc_saved;
        max_level = std::max(max_level, o.max_level);
        return *this;
    }
};

// POV-Ray's entry test of a ray (TraceRay): refused at max_trace_level or below
// adc_bailout, when it is black and opaque. The level it tests is the parent's: a
// continued ray's depth, one less than any other ray's. A refusal for its weight is
// counted. Rays under a radiosity sample ray carry their own limits
// (TraceRay::max_level, adc_bailout).
inline bool refuse_ray(const TraceRay& ray, const GlobalSettings& g, TraceCounters& c) {
    const int max_level = ray.max_level > 0 ? ray.max_level : g.max_trace_level;
    const float adc = ray.adc_bailout >= 0 ? ray.adc_bailout : g.adc_bailout;
    const int entry_level = ray.continued ? ray.depth : ray.depth - 1;
    if (entry_level < max_level && ray.weight >= adc) return false;
    if (ray.weight < adc) ++c.adc_saved;
    return true;
}

// Counts a ray that passed refuse_ray() (once per ray, however many boxes it crosses).
inline void count_ray(const TraceRay& ray, TraceCounters& c) {
    switch (ray.use) {
        case RayUse::Camera:
            ++c.camera;
            break;
        case RayUse::Reflection:
            ++c.reflected;
            break;
        case RayUse::Refraction:
        case RayUse::ReflectedRefraction:
            ++c.refracted;
            break;
        case RayUse::Radiosity:
            ++c.radiosity;
            break;
        case RayUse::Shadow:
        case RayUse::Query:
        case RayUse::Photon:
        case RayUse::PhotonReflection:
            return;
    }
    c.max_level = std::max(c.max_level, ray.depth);
}

class Tracer {
  public:
    explicit Tracer(const PreparedScene& scene);
    ~Tracer();
    TraceResult trace(const TraceRay& ray);
    const TraceCounters& counters() const { return counters_; }
    const PreparedScene& scene() const { return scene_; }
    uint64_t intersection_tests() const { return ctx_.tests; }
    // Tie probe (trace/ties.h): rays up to trace level `levels` (1: camera rays), and the
    // shadow rays from their hits, look for a second surface within `tolerance`
    // (relative) of their nearest hit; ties() counts the rays that found one.
    void set_tie_probe(Real tolerance, int levels) {
        tie_tolerance_ = tolerance;
        tie_levels_ = levels;
    }
    uint64_t ties() const { return ctx_.ties; }
    // ... and the rays whose nearest hit lies on a jump of its pigment (or texture map)
    // pattern: the surface coincides with a colour boundary (a gradient's wrap exactly
    // at a box's face), so the last bits of the hit point pick the colour.
    uint64_t pattern_ties() const { return ctx_.pattern_ties; }
    // Radiosity (trace/radiosity/gatherer.h): the gatherer the shading of this tracer's
    // hits asks for ambient light (null: none).
    void set_radiosity(RadiosityGatherer* gatherer) { ctx_.radiosity = gatherer; }
    // The final render's gatherer over the scene's finished pretrace (made by the
    // constructor when the pretrace is already there).
    void attach_radiosity();
    // The final render starts a render block: radiosity gathered in it is reused only
    // within it (trace/radiosity/gatherer.h).
    void begin_block();
    // A radiosity sample ray, traced from inside the shading of the ray being traced
    // (POV-Ray's TraceRay with an importance query): `depth` gets the distance to its
    // first hit (infinity: none), `importance` that object's radiosity importance (the
    // scene's default when it hits nothing or has none). Below `queried`, the ray is not
    // shaded (black).
    Rgb trace_radiosity_sample(const TraceRay& ray, float queried, Real& depth,
                               float& importance);
    // A ray traced from inside the shading of the ray being traced (subsurface's light
    // seen through an object): the same entry test and shading as any ray.
    TraceResult trace_nested(const TraceRay& ray);

  private:
    // The nearest hit, with the tie probe of the ray's level (`probe`, 0: none).
    bool nearest_hit(const TraceRay& ray, Hit& hit, Real& probe);
    // What reaches a shadow child's light through what lies between (1: nothing can).
    Rgb shadow_filter(const ChildRay& shadow, Real probe);
    TraceResult trace_at(const TraceRay& ray, size_t level);
    // trace_at() once the nearest hit is known.
    TraceResult shade_at(const TraceRay& ray, bool found, const Hit& hit, Real probe,
                         size_t level);
    // Linear shading (the plan needs no parent tracking): the ray's share of its camera
    // sample, `contribution` times what it sees, added into `sum` as black boxes add it
    // (trace/forward_sum.h), so every driver gives the same bits.
    void trace_forward(const TraceRay& ray, const Rgb& contribution,
                       float transmit_contribution, size_t level, ForwardSum& sum);

    const PreparedScene& scene_;
    bool forward_ = false;
    RayContext ctx_;
    TraceCounters counters_;
    Real tie_tolerance_ = 0;
    int tie_levels_ = 0;
    // Records and result buffers reused per recursion level: no allocation per ray.
    // Deques: a radiosity gather traces from inside spawn_children, which is filling
    // records_[level]; growing must not move it.
    std::deque<ShadingRecord> records_;
    std::deque<std::vector<TraceResult>> results_;
    // The deepest level whose record may be in use (radiosity samples trace below it).
    size_t level_in_use_ = 0;
    float default_importance_ = 1;
    // The final render's gatherer, when the scene's radiosity pretrace is done.
    std::unique_ptr<RadiosityGatherer> radiosity_;
    // Subsurface light transport, when the scene has it (trace/subsurface.h).
    std::unique_ptr<SubsurfaceTracer> subsurface_;
};

}  // namespace povwall::trace
