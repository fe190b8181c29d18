// The single-process driver: traces a ray by calling spawn_children / combine_children
// recursively (the distributed back end drives the same two steps through messages).
#pragma once

#include <algorithm>

#include "trace/shading.h"

namespace povwall::trace {

// Rays traced, by kind, with POV-Ray's two render statistics about the ray tree: the
// rays refused for their weight (adc_bailout: its "Saved") and the deepest trace level a
// ray was traced at (its "Max Level", 1 for camera rays). Every driver counts with these.
struct TraceCounters {
    uint64_t camera = 0, reflected = 0, refracted = 0, shadow = 0;
    uint64_t adc_saved = 0;
    int max_level = 0;
    uint64_t rays() const { return camera + reflected + refracted + shadow; }
    TraceCounters& operator+=(const TraceCounters& o) {
        camera += o.camera;
        reflected += o.reflected;
        refracted += o.refracted;
        shadow += o.shadow;
        adc_saved += o.adc_saved;
        max_level = std::max(max_level, o.max_level);
        return *this;
    }
};

// POV-Ray's entry test of a ray (TraceRay): refused past max_trace_level or below
// adc_bailout, when it is black and opaque. A refusal for its weight is counted.
inline bool refuse_ray(const TraceRay& ray, const GlobalSettings& g, TraceCounters& c) {
    if (ray.depth <= g.max_trace_level && ray.weight >= g.adc_bailout) return false;
    if (ray.weight < g.adc_bailout) ++c.adc_saved;
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
            ++c.refracted;
            break;
        case RayUse::Shadow:
            return;
    }
    c.max_level = std::max(c.max_level, ray.depth);
}

class Tracer {
  public:
    explicit Tracer(const PreparedScene& scene);
    TraceResult trace(const TraceRay& ray);
    const TraceCounters& counters() const { return counters_; }
    uint64_t intersection_tests() const { return ctx_.tests; }

  private:
    TraceResult trace_at(const TraceRay& ray, size_t level);

    const PreparedScene& scene_;
    RayContext ctx_;
    TraceCounters counters_;
    // Records and result buffers reused per recursion level: no allocation per ray.
    std::vector<ShadingRecord> records_;
    std::vector<std::vector<TraceResult>> results_;
};

}  // namespace povwall::trace
