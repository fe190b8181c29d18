// What every leaf shape shares: POV-Ray's depth tolerances, the fixed-size crossing list
// of the low-level kernels, and the ray and hit types of the shape layer (shape.h).
#pragma once

#include <vector>

#include "core/scene.h"

namespace povwall::trace {

// POV-Ray's minimum accepted hit depths (see docs/pov-semantics notes): per shape, then
// 1e-4 world distance for every hit. Each shape applies its own in the space its
// 3.7 code does: world distance for the box, disc, triangle, plane and torus (their depth
// is compared after the division by the transformed direction's length, or the direction
// is never normalised), object space along a unit direction for the ellipsoid, cone,
// cylinder and polygon.
constexpr Real kSphereTolerance = 1e-6;
constexpr Real kBoxTolerance = 1e-6;
constexpr Real kPlaneTolerance = 1e-6;
constexpr Real kConeTolerance = 1e-9;
constexpr Real kTorusTolerance = 1e-4;
constexpr Real kTriangleTolerance = 1e-6;
constexpr Real kPolygonTolerance = 1e-8;
constexpr Real kMinIsectDepth = 1e-4;
constexpr Real kPovEpsilon = 1e-10;
constexpr Real kMaxDistance = 1e7;

struct Crossing {
    Real t;
    int face;  // shape-specific: which surface part (for the normal)
};

// Up to this many crossings per kernel call (a torus has 4).
constexpr int kMaxCrossings = 4;
struct Crossings {
    Crossing c[kMaxCrossings];
    int n = 0;
    void add(Real t, int face) {
        if (n < kMaxCrossings) c[n++] = {t, face};
    }
};

// `x` rounded to single precision. Out of line on purpose: inlined into a Vector3 built
// from three such values, GCC 12.2's SLP vectorizer at -O3 drops the round trip of two of
// them (the double -> float -> double pair comes out unchanged).
Real round_to_float(Real x);
// A mesh vertex as POV-Ray stores it: single precision (SNGL_VECT, Mesh_Hash_Vertex).
inline Point3 single_precision(const Point3& p) {
    return {round_to_float(p.x), round_to_float(p.y), round_to_float(p.z)};
}

// A world ray in a leaf shape's own space (through the object's inverse transform).
struct LocalRay {
    Point3 origin;
    Vector3 direction;        // not normalised: its parameter is the world ray's
    Vector3 unit;             // direction * (1 / length), as POV-Ray's VInverseScaleEq
    Real length;              // |direction|: object units per world unit
    bool transformed = true;  // false: the object has no transform (the world ray)
    // The object is a part of a CSG object. Some POV-Ray shapes stop at their first hit
    // otherwise (the nearest but for its depth tolerances).
    bool csg_child = false;
    // The query keeps only the nearest crossing with a world distance in [want_lo,
    // want_hi) (a closest-hit or shadow test outside CSG): the shape may leave out
    // crossings it proves lie beyond want_hi, or beyond a crossing it returns that lies
    // in that range.
    bool nearest_only = false;
    Real want_lo = 0, want_hi = kInfinity;
    // With nearest_only: the query asks only whether there is a crossing in that range
    // (a shadow ray); the shape may stop at the first it finds there.
    bool any_crossing = false;
    // The world distance where POV-Ray's ray starts (RayFlags::restart).
    Real restart = 0;
    // Whether a crossing at world distance t ends the search (any_crossing).
    bool ends_search(Real t) const {
        return nearest_only && any_crossing && t >= want_lo && t < want_hi;
    }
};

// An object's clip, for the shapes that test it inside their search (as POV-Ray's
// isosurface and mesh do): whether it keeps the crossing at world distance t.
struct ShapeClip {
    bool (*keeps)(const void* context, Real t);
    const void* context;
};

// One crossing of a leaf shape's surface.
struct ShapeHit {
    Real t;    // world distance along the ray
    Point3 p;  // the point in the shape's space, computed in the shape's arithmetic
    int face;  // which surface part (for the normal)
    // Where on that part, when the normal needs it (a lathe's or prism wall's spline t;
    // a patch triangle's barycentric coordinates).
    Real param = 0, param2 = 0;
    // The normal, for shapes that find it with the hit (julia_fractal: it needs the
    // iteration at the hit point).
    Vector3 normal{0, 0, 0};
    // p is where the crossing is, though not at distance t along the ray (julia_fractal's
    // later crossings, whose depth lags in POV-Ray).
    bool own_point = false;
};
using ShapeHits = std::vector<ShapeHit>;

// Appends a kernel's crossings, found along `r.unit` (object-space distances), as hits.
inline void add_unit_crossings(const Crossings& cs, const LocalRay& r, ShapeHits& out) {
    for (int i = 0; i < cs.n; ++i)
        out.push_back(
            {cs.c[i].t / r.length, r.origin + r.unit * cs.c[i].t, cs.c[i].face});
}

}  // namespace povwall::trace
