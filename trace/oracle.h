// The numerics oracle: the first hit of a ray computed in 50-digit binary floating point
// (boost::multiprecision), with the same acceptance rules as the tracer (POV-Ray's
// per-shape object-space depth tolerances, tangent and parallel cut-offs,
// MIN_ISECT_DEPTH), so any difference from the double-precision fast path is rounding,
// not a rule mismatch.
#pragma once

#include <string>

#include "core/scene.h"

namespace povwall::trace {

struct OracleHit {
    bool hit = false;
    bool supported = true;  // false: the ray met an object the oracle cannot evaluate
    Real t =
        kInfinity;  // world distance along the ray's (not necessarily unit) direction
    const Object* leaf = nullptr;
};

// Shape kind name of a leaf ("sphere", "torus", "mesh", ...).
std::string shape_kind_name(const Object& leaf);

// First surface along `ray` with world t > t_min over all objects a camera ray can see.
// Leaves, meshes and CSG unions are exact; other CSG, clipped and inverse objects are not
// evaluated, and a ray that reaches their bounds before the first hit found is
// unsupported.
OracleHit oracle_first_hit(const Scene& scene, const Ray& ray, Real t_min);

// The oracle's roots of c[4] x^4 + ... + c[0] in (lo, hi], in 50 digits then rounded: the
// reference for the solver accuracy pass.
int oracle_quartic_roots(const Real c[5], Real lo, Real hi, Real roots[4]);

}  // namespace povwall::trace
