#include "trace/tracer.h"

#include <cmath>

namespace povwall::trace {
Tracer::Tracer(const PreparedScene& scene) : scene_(scene) { scene.init_context(ctx_); }

TraceResult Tracer::trace(const TraceRay& ray) { return trace_at(ray, 0); }

TraceResult Tracer::trace_at(const TraceRay& ray, size_t level) {
    if (refuse_ray(ray, scene_.scene().settings, counters_)) return {};
    count_ray(ray, counters_);
    Hit hit;
    const Real probe = ray.depth <= tie_levels_ ? tie_tolerance_ : 0;
    ctx_.tie_tolerance = probe;
    const bool found = scene_.closest_hit(ray.ray, 0, kInfinity, ray.use, hit, ctx_);
    ctx_.tie_tolerance = 0;
    if (!found) return miss_colour(scene_, ray, &ctx_);
    if (probe > 0 && on_pattern_boundary(scene_, hit, probe)) ++ctx_.pattern_ties;
    if (records_.size() <= level) {
        records_.resize(level + 1);
        results_.resize(level + 1);
    }
    spawn_children(scene_, ray, hit, records_[level], &ctx_);
    // records_ may grow in the recursion below: index, don't hold references across
    // calls.
    size_t n = records_[level].children.size();
    results_[level].resize(n);
    for (size_t i = 0; i < n; ++i) {
        const ChildRay child = records_[level].children[i];
        TraceResult r;
        if (child.kind == ChildRay::Kind::Shadow) {
            if (child.unoccluded) {
                r.colour = Rgb(1.0f);
            } else {
                ++counters_.shadow;
                ctx_.tie_tolerance = probe;
                r.colour = shadow_transmittance(scene_, child, ctx_);
                ctx_.tie_tolerance = 0;
            }
        } else {
            r = trace_at(child.trace, level + 1);
        }
        results_[level][i] = r;
    }
    return combine_children(records_[level], results_[level].data());
}

}  // namespace povwall::trace
