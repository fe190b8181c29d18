#include "trace/radiosity/sample_directions.h"

#include <cmath>

namespace povwall::trace::radiosity {

double radical_inverse(size_t i, unsigned base) {
    double inv = 1.0 / base, f = inv, r = 0;
    while (i > 0) {
        r += double(i % base) * f;
        i /= base;
        f *= inv;
    }
    return r;
}

SampleDirections::SampleDirections(size_t pool_size) {
    directions_.reserve(pool_size);
    for (size_t i = 1; i <= pool_size; ++i) {
        const double r = std::sqrt(radical_inverse(i, 2));
        const double phi = 2 * kPi * radical_inverse(i, 3);
        const double x = r * std::cos(phi), z = r * std::sin(phi);
        const double y = std::sqrt(std::max(0.0, 1 - x * x - z * z));
        directions_.push_back(Vector3{x, y, z});
    }
}

}  // namespace povwall::trace::radiosity
