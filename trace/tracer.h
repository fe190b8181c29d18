// The single-process driver: traces a ray by calling spawn_children / combine_children
// recursively (the distributed back end drives the same two steps through messages).
#pragma once

#include "trace/shading.h"

namespace povwall::trace {

struct TraceCounters {
    uint64_t camera = 0, reflected = 0, refracted = 0, shadow = 0;
    TraceCounters& operator+=(const TraceCounters& o) {
        camera += o.camera;
        reflected += o.reflected;
        refracted += o.refracted;
        shadow += o.shadow;
        return *this;
    }
};

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
