// What a radiosity gather does at each recursion depth, derived from the scene's
// settings as POV-Ray 3.7 derives them (SceneRadiositySettings::GetRecursionSettings):
// fewer rays, fewer samples to reuse, looser error bounds and reuse spacing the deeper
// the bounce, and the trace level and weight its sample rays start from.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/scene.h"

namespace povwall::trace::radiosity {

struct RecursionSettings {
    int rays_per_sample = 0;        // sample rays shot per gather (at least 5)
    int reuse_count = 0;            // nearest_count at depth 0, then 2, then 1
    double error_bound_factor = 1;  // x2 per bounce
    double min_reuse_factor = 0;    // minimum_reuse x2 per bounce
    double max_reuse_factor = 0;    // maximum_reuse x2 per bounce
    // Cache addressing: an entry is filed by its radius of influence divided by this
    // (1 at the top level, so no reusable entry is missed; 8 deeper).
    double overfill_factor = 1;
    int trace_level = 0;  // POV-Ray's trace level of the sample rays (1.5 per bounce)
    double weight = 1;    // their adc weight: (brightness / 2) per bounce
    double max_error_bound = 0;  // error_bound x error_bound_factor
};

inline std::vector<RecursionSettings> recursion_settings(const RadiositySettings& s) {
    std::vector<RecursionSettings> out(size_t(s.recursion_limit));
    for (int d = 0; d < s.recursion_limit; ++d) {
        RecursionSettings& r = out[size_t(d)];
        const double two_d = std::pow(2.0, double(d));
        r.rays_per_sample = std::max(5, int(s.count * std::pow(0.5, double(d))));
        r.reuse_count = d == 0   ? s.nearest_count
                        : d == 1 ? std::min(2, s.nearest_count)
                                 : 1;
        r.error_bound_factor = two_d;
        r.min_reuse_factor = double(s.minimum_reuse) * two_d;
        r.max_reuse_factor = double(s.maximum_reuse) * two_d;
        r.overfill_factor = d == 0 ? 1.0 : 8.0;
        r.trace_level = int(1.5 * (double(d) + 1));
        r.weight = std::pow(0.5 * double(s.brightness), double(d) + 1);
        r.max_error_bound = double(s.error_bound) * r.error_bound_factor;
    }
    return out;
}

}  // namespace povwall::trace::radiosity
