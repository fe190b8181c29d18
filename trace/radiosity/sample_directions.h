// The radiosity sample directions: a fixed, well-spread set of cosine-weighted
// directions about +y, from which each gather takes `count` consecutive ones (POV-Ray
// 3.7 also draws from a fixed pool, `count`'s second value long, 1600 by default).
//
// Ours is our own: the 2-D Halton points of bases 2 and 3 (radical inverses of the
// index, skipping 0) mapped to the unit disc by area (r = sqrt(u), phi = 2 pi v) and
// lifted to the hemisphere (Malley's method), which makes the density cos(theta) / pi.
// Consecutive runs of a Halton sequence are themselves well spread, so a gather of any
// count covers the hemisphere evenly. tests/trace/radiosity_test.cpp checks the
// moments of the set against the cosine distribution's.
#pragma once

#include <cstddef>
#include <vector>

#include "core/math.h"

namespace povwall::trace::radiosity {

class SampleDirections {
  public:
    explicit SampleDirections(size_t pool_size);
    size_t size() const { return directions_.size(); }
    // Direction i of the pool (wrapping), in the frame where +y is the normal.
    const Vector3& operator[](size_t i) const {
        return directions_[i % directions_.size()];
    }

  private:
    std::vector<Vector3> directions_;
};

// The radical inverse of `i` in `base` (the Halton coordinate).
double radical_inverse(size_t i, unsigned base);

}  // namespace povwall::trace::radiosity
