// `povwall check-numerics`: the fast path's first hits on the camera rays against the
// oracle (trace/oracle.h), per shape kind, plus the non-finite pixels of a render.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/scene.h"

namespace povwall::trace {

struct ShapeKindNumerics {
    uint64_t rays = 0;          // camera rays whose first hit (either path) is this kind
    uint64_t hit_miss = 0;      // one path hits, the other misses
    uint64_t other_object = 0;  // both hit, different objects at different distances
    uint64_t compared = 0;      // both hit the same object
    double max_rel_error = 0, median_rel_error = 0;
};

enum class PixelVerdict : uint8_t { Agree, Disagree, Unsupported };

struct NumericsReport {
    std::map<std::string, ShapeKindNumerics> kinds;
    uint64_t rays = 0, unsupported = 0, nonfinite_pixels = 0;
    std::vector<PixelVerdict> verdict;  // per pixel, row-major
};

// A fast hit agrees with the oracle when both miss, or their distances agree to this
// relative error (same object, or coincident faces where either is right).
constexpr double kOracleAgreement = 1e-6;

NumericsReport check_numerics(const Scene& scene, int width, int height);

}  // namespace povwall::trace
