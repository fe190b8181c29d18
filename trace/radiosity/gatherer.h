// Radiosity at a surface point, as POV-Ray 3.7 computes it (RadiosityFunction::
// ComputeAmbient and GatherLight): reuse what the irradiance cache holds near the point
// when there is enough of it, else shoot sample rays over the hemisphere (traced with
// the thread's tracer, so the whole shading runs at their hits, radiosity included one
// level down) and file the result in the cache.
//
// One gatherer per tracer (thread). What it reads and where it files depends on the
// phase (docs/radiosity.md):
//   - pretrace pass p: reads the cache of the passes before p (frozen) and the entries
//     its chain of render blocks made in pass p so far; files into the chain's list,
//     which is merged into the cache in chain order once the pass is over;
//   - final render: reads the finished cache and the entries the render block being
//     traced made so far (its pixels in their fixed order), files into the block's list
//     only, so that every pixel depends only on the cache and its block, whatever
//     thread or process renders the block.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/scene.h"
#include "trace/radiosity/irradiance_cache.h"
#include "trace/radiosity/recursion_settings.h"
#include "trace/radiosity/sample_directions.h"
#include "trace/shading.h"

namespace povwall::trace {
class Tracer;
}

namespace povwall::trace::radiosity {

// What every gatherer of a render shares (read only): settings and sample directions.
struct RadiosityFrame {
    RadiosityFrame(const RadiositySettings& settings, const Point3& camera,
                   int max_trace_level);
    RadiositySettings settings;
    std::vector<RecursionSettings> recursion;
    SampleDirections directions;
    Point3 camera;
    int max_trace_level;
    std::vector<double> address_factors() const;
};

}  // namespace povwall::trace::radiosity

namespace povwall::trace {

class RadiosityGatherer {
  public:
    // `cache`: the cache read (null: empty); `pass`: the pretrace pass, or kFinalPass.
    RadiosityGatherer(Tracer& tracer, const radiosity::RadiosityFrame& frame,
                      const radiosity::IrradianceCache* cache, int pass);
    // Pretrace: a new render block starts; its entries go to `block` (its chain's list,
    // read by the lookups too).
    void begin_block(radiosity::IrradianceCache* block) {
        block_ = block;
        restart_directions();
    }
    // Whether a hit of `ray` gathers radiosity (its recursion depth is below the limit).
    bool active_for(const TraceRay& ray) const {
        return ray.radiosity_depth < frame_.settings.recursion_limit;
    }
    // The ambient light at P (POV-Ray's ComputeAmbient): `raw_normal` and `layer_normal`
    // face the ray; `weight` is the ray's weight times what the radiosity can add to it.
    Rgb ambient(const TraceRay& ray, const Point3& P, const Vector3& raw_normal,
                const Vector3& layer_normal, double weight);
    uint64_t gathers() const { return gathers_; }
    // The final render: a new render block starts (its own entries are forgotten).
    void begin_final_block() {
        final_block_.clear();
        block_ = &final_block_;
        restart_directions();
    }

  private:
    void restart_directions() { direction_fresh_.assign(direction_fresh_.size(), 1); }
    double gather(const TraceRay& ray, const Point3& P, const Vector3& raw_normal,
                  const Vector3& normal, Rgb& illuminance);

    Tracer& tracer_;
    const radiosity::RadiosityFrame& frame_;
    const radiosity::IrradianceCache* cache_;
    radiosity::IrradianceCache* block_ = nullptr;
    radiosity::IrradianceCache final_block_;
    int pass_;
    double error_bound_;
    // POV-Ray's ticket.radiosityQuality: how well the cache could answer the lookups
    // made under the sample ray being traced (a sample seen through poorly covered
    // surfaces counts less).
    double quality_ = 1;
    uint64_t gathers_ = 0;
    // Per radiosity depth: where the block's next gather reads the direction pool, and
    // whether the block has gathered at that depth yet.
    std::vector<size_t> next_direction_;
    std::vector<uint8_t> direction_fresh_;
};

}  // namespace povwall::trace
