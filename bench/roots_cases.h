// Ray-torus quartics for the solver benchmark and accuracy pass: rays from 3 to 12 major
// radii away, aimed at random points of the tube (so most hit, many at grazing angles),
// for a range of minor/major ratios. Deterministic (fixed seed).
#pragma once

#include <random>
#include <vector>

#include "trace/roots.h"
#include "trace/shapes/shape.h"

namespace povwall::bench {

struct QuarticCase {
    trace::TorusQuartic q;
    Point3 origin;
    Vector3 dir;
};

inline std::vector<QuarticCase> torus_cases(double ratio, int count, unsigned seed = 7) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    Torus torus;
    torus.major = 1;
    torus.minor = ratio;
    std::vector<QuarticCase> out;
    while (int(out.size()) < count) {
        double a = 2 * M_PI * u(rng), b = 2 * M_PI * u(rng);
        Point3 target{(1 + ratio * std::cos(b)) * std::cos(a), ratio * std::sin(b),
                      (1 + ratio * std::cos(b)) * std::sin(a)};
        // Half the rays graze: origins close to the torus plane.
        double el = (u(rng) < 0.5 ? 0.02 : 1.0) * (u(rng) - 0.5) * M_PI;
        double az = 2 * M_PI * u(rng), dist = 3 + 9 * u(rng);
        Point3 origin{dist * std::cos(el) * std::cos(az), dist * std::sin(el),
                      dist * std::cos(el) * std::sin(az)};
        // Jitter the aim by a fraction of the tube so some rays just miss.
        Vector3 jitter{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
        Vector3 dir = normalize(target + jitter * (ratio * 0.5) - origin);
        QuarticCase c;
        c.origin = origin;
        c.dir = dir;
        if (trace::torus_quartic(torus, origin, dir, c.q)) out.push_back(c);
    }
    return out;
}

inline const double kRatios[] = {1e-4, 1e-3, 1e-2, 0.1, 0.5, 0.999};

}  // namespace povwall::bench
