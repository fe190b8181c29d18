// The numerics oracle's arithmetic (50 significant digits), shared by each shape's
// high-precision first-hit routine (shape_oracle_first in trace/shapes/*.h).
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <functional>
#include <limits>

#include "core/math.h"

namespace povwall::trace {

using HP = boost::multiprecision::cpp_bin_float_50;

struct V3 {
    HP x, y, z;
    V3() = default;
    V3(HP a, HP b, HP c) : x(std::move(a)), y(std::move(b)), z(std::move(c)) {}
    explicit V3(const Vector3& v) : x(v.x), y(v.y), z(v.z) {}
    V3 operator+(const V3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    V3 operator-(const V3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    V3 operator*(const HP& s) const { return {x * s, y * s, z * s}; }
    HP operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};
HP dot(const V3& a, const V3& b);
V3 cross(const V3& a, const V3& b);

// Object-space ray with a unit direction; `world_per_object` turns object distances into
// world ones.
struct OracleRay {
    V3 o, d;
    HP world_per_object;
};

// Smallest accepted object-space t, or +inf.
struct OracleBest {
    HP t = std::numeric_limits<HP>::infinity();
    HP floor = 0;  // MIN_ISECT_DEPTH in object units
    void offer(const HP& x, Real tol) {
        if (x > tol && x >= floor && x < t) t = x;
    }
};

// Offers the real roots of a t^2 + b t + c that `keep` accepts.
void oracle_quadratic(const HP& a, const HP& b, const HP& c, OracleBest& best, Real tol,
                      const std::function<bool(const HP&)>& keep);
// Offers the crossing of a triangle (Moller-Trumbore), tolerance kTriangleTolerance.
void oracle_triangle(const V3 p[3], const OracleRay& r, OracleBest& best);
// The unit axis from base to cap (y when they coincide) and the distance between them.
HP oracle_axis_frame(const V3& base, const V3& cap, V3& axis);

}  // namespace povwall::trace
