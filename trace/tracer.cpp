#include "trace/tracer.h"

#include <cmath>

#include "trace/radiosity/pretrace.h"
#include "trace/subsurface.h"

namespace povwall::trace {
Tracer::Tracer(const PreparedScene& scene)
    : scene_(scene), forward_(!scene.plan().parent_tracking) {
    scene.init_context(ctx_);
    if (const auto& r = scene.scene().settings.radiosity)
        default_importance_ = r->default_importance;
    attach_radiosity();
    if (scene.scene().settings.subsurface) {
        subsurface_ = std::make_unique<SubsurfaceTracer>(*this, ctx_);
        ctx_.subsurface = subsurface_.get();
    }
}

void Tracer::attach_radiosity() {
    if (const radiosity::RadiosityRender* r = scene_.radiosity()) {
        radiosity_ = std::make_unique<RadiosityGatherer>(*this, r->frame, &r->cache,
                                                         radiosity::kFinalPass);
        ctx_.radiosity = radiosity_.get();
    }
}

Tracer::~Tracer() = default;

void Tracer::begin_block() {
    if (radiosity_) radiosity_->begin_final_block();
}

TraceResult Tracer::trace(const TraceRay& ray) {
    if (!forward_) return trace_at(ray, 0);
    ForwardSum sum;
    trace_forward(ray, Rgb(1.0f), 1.0f, 0, sum);
    return {Rgb(float(sum.r), float(sum.g), float(sum.b)), float(sum.transmit)};
}

bool Tracer::nearest_hit(const TraceRay& ray, Hit& hit, Real& probe) {
    probe = ray.depth <= tie_levels_ ? tie_tolerance_ : 0;
    ctx_.tie_tolerance = probe;
    const bool found = scene_.closest_hit(ray.ray, 0, kInfinity, ray.use, hit, ctx_,
                                          ray.radiosity_depth > 0);
    ctx_.tie_tolerance = 0;
    if (found && probe > 0 && on_pattern_boundary(scene_, hit, probe))
        ++ctx_.pattern_ties;
    return found;
}

Rgb Tracer::shadow_filter(const ChildRay& shadow, Real probe) {
    if (shadow.unoccluded) return Rgb(1.0f);
    ++counters_.shadow;
    ctx_.tie_tolerance = probe;
    const Rgb filter = shadow_transmittance(scene_, shadow, ctx_);
    ctx_.tie_tolerance = 0;
    return filter;
}

TraceResult Tracer::trace_at(const TraceRay& ray, size_t level) {
    if (refuse_ray(ray, scene_.scene().settings, counters_)) return {};
    count_ray(ray, counters_);
    Hit hit;
    Real probe = 0;
    const bool found = nearest_hit(ray, hit, probe);
    return shade_at(ray, found, hit, probe, level);
}

Rgb Tracer::trace_radiosity_sample(const TraceRay& ray, float queried, Real& depth,
                                   float& importance) {
    depth = kInfinity;
    importance = default_importance_;
    if (refuse_ray(ray, scene_.scene().settings, counters_)) return {};
    Hit hit;
    Real probe = 0;
    const bool found = nearest_hit(ray, hit, probe);
    if (found) {
        depth = hit.t;
        const float own = hit.material ? hit.material->radiosity_importance : 0.0f;
        if (own > 0) importance = own;
    }
    if (importance < queried) return {};
    count_ray(ray, counters_);
    const size_t saved = level_in_use_;
    const TraceResult r = shade_at(ray, found, hit, probe, level_in_use_ + 1);
    level_in_use_ = saved;
    return r.colour;
}

TraceResult Tracer::trace_nested(const TraceRay& ray) {
    const size_t saved = level_in_use_;
    const TraceResult r = trace_at(ray, level_in_use_ + 1);
    level_in_use_ = saved;
    return r;
}

TraceResult Tracer::shade_at(const TraceRay& ray, bool found, const Hit& hit, Real probe,
                             size_t level) {
    if (!found) return miss_colour(scene_, ray, &ctx_);
    if (records_.size() <= level) {
        records_.resize(level + 1);
        results_.resize(level + 1);
    }
    level_in_use_ = level;
    spawn_children(scene_, ray, hit, records_[level], &ctx_);
    // records_ may grow in the recursion below: index, don't hold references across
    // calls.
    size_t n = records_[level].children.size();
    results_[level].resize(n);
    for (size_t i = 0; i < n; ++i) {
        const ChildRay child = records_[level].children[i];
        TraceResult r;
        if (child.kind == ChildRay::Kind::Shadow) {
            r.colour = shadow_filter(child, probe);
        } else {
            r = trace_at(child.trace, level + 1);
        }
        results_[level][i] = r;
    }
    return combine_children(records_[level], results_[level].data());
}

// The same steps as BoxHost::process_ray without parents, and the same arithmetic.
void Tracer::trace_forward(const TraceRay& ray, const Rgb& contribution,
                           float transmit_contribution, size_t level, ForwardSum& sum) {
    if (refuse_ray(ray, scene_.scene().settings, counters_)) return;  // black, opaque
    count_ray(ray, counters_);
    Hit hit;
    Real probe = 0;
    if (!nearest_hit(ray, hit, probe)) {
        const TraceResult m = miss_colour(scene_, ray, &ctx_);
        sum.add(contribution * m.colour, transmit_contribution * m.transmit);
        return;
    }
    if (records_.size() <= level) {
        records_.resize(level + 1);
        results_.resize(level + 1);
    }
    level_in_use_ = level;
    spawn_children(scene_, ray, hit, records_[level], &ctx_);
    {
        // Fog along this ray is affine (add + mul x colour): its added part is this
        // ray's, its factor goes into every child's contribution.
        const ShadingRecord& rec = records_[level];
        sum.add(contribution * (rec.fog.add + rec.fog.mul * rec.local),
                transmit_contribution * rec.fog.add_transmit);
    }
    // records_ may grow in the recursion below: index, don't hold references across
    // calls.
    const size_t n = records_[level].children.size();
    for (size_t i = 0; i < n; ++i) {
        const ChildRay child = records_[level].children[i];
        const FogEffect& fog = records_[level].fog;
        const Rgb child_contribution = contribution * fog.mul * child.coeff;
        if (child.kind == ChildRay::Kind::Shadow) {
            sum.add(child_contribution * shadow_filter(child, probe), 0.0f);
            continue;
        }
        const float child_transmit =
            child.kind == ChildRay::Kind::Transmission
                ? transmit_contribution * fog.mul_transmit * child.transmit_factor
                : 0.0f;
        trace_forward(child.trace, child_contribution, child_transmit, level + 1, sum);
    }
}

}  // namespace povwall::trace
