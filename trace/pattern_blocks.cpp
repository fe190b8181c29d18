// The block patterns square, triangular and cubic (entry indices 0..3 or 0..5, like
// checker and hexagon) and the cubic warp, as POV-Ray 3.7 defines them (pattern.cpp and
// warps.cpp of 3.7-stable read for semantics).
#include <cmath>

#include "core/math_constants.h"
#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

// The face of the cube around the origin that `p` looks through: 0 +x, 1 +y, 2 +z,
// 3 -x, 4 -y, 5 -z; ties go to the first in that order.
int cube_face(const Point3& p) {
    const Real ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    if (p.x >= 0 && p.x >= ay && p.x >= az) return 0;
    if (p.y >= 0 && p.y >= ax && p.y >= az) return 1;
    if (p.z >= 0 && p.z >= ax && p.z >= ay) return 2;
    if (p.x < 0 && p.x <= -ay && p.x <= -az) return 3;
    if (p.y < 0 && p.y <= -ax && p.y <= -az) return 4;
    return 5;
}

}  // namespace

Real square_value(const Point3& p) {
    const bool odd_x = int(std::floor(p.x)) & 1, odd_z = int(std::floor(p.z)) & 1;
    if (odd_x) return odd_z ? 2 : 3;
    return odd_z ? 1 : 0;
}

// Equilateral triangles of unit side in x-z, six around each vertex at the origin's
// lattice, numbered 0..5 counter-clockwise.
Real triangular_value(const Point3& p) {
    // Fold into the 3 x sqrt(3) rectangle that repeats, then into its lower half.
    Real xs = p.x - 3.0 * std::floor(p.x / 3.0);
    Real zs = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    const int column = int(std::floor(xs));
    xs -= column;
    const bool upper = zs >= kSqrt3Half;
    if (upper) zs = kSqrt3 - zs;
    // Which of the three triangles of the unit column: below both rising and falling
    // edges (0), left of the rising one (3), right of the falling one (1).
    int answer = 1;
    const Real rest = 1.0 - xs;
    if (xs != 0.0 && rest != 0.0) {
        const bool below_rising = zs / xs < kSqrt3, below_falling = zs / rest < kSqrt3;
        if (below_rising && below_falling)
            answer = 0;
        else if (below_falling)
            answer = 1;
        else if (below_rising)
            answer = 3;
        else
            answer =
                0;  // on both edges at once, a single point (POV-Ray leaves it unset)
    }
    Real value = (answer & 1) ? std::fmod(answer + 2.0 * column, 6.0)
                              : std::fmod(6.0 + answer - 2.0 * column, 6.0);
    return upper ? 5.0 - value : value;
}

Real cubic_value(const Point3& p) { return Real(cube_face(p)); }

// Each face of the cube onto its cell of a cross in x-y (x in quarters, y in thirds),
// the distance along the face direction in z.
Point3 cubic_warp(const Point3& p) {
    const Real x = p.x, y = p.y, z = p.z;
    constexpr Real kThird = 1.0 / 3.0;
    switch (cube_face(p)) {
        case 0:
            return {0.75 - 0.25 * (z / x + 1.0) / 2.0,
                    kThird + kThird * (y / x + 1.0) / 2.0, x};
        case 1:
            return {0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - kThird * (z / y + 1.0) / 2.0,
                    y};
        case 2:
            return {0.25 + 0.25 * (x / z + 1.0) / 2.0,
                    kThird + kThird * (y / z + 1.0) / 2.0, z};
        case 3:
            return {0.25 * (z / -x + 1.0) / 2.0, kThird + kThird * (y / -x + 1.0) / 2.0,
                    -x};
        case 4:
            return {0.25 + 0.25 * (x / -y + 1.0) / 2.0, kThird * (z / -y + 1.0) / 2.0,
                    -y};
        default:
            return {1.0 - 0.25 * (x / -z + 1.0) / 2.0,
                    kThird + kThird * (y / -z + 1.0) / 2.0, -z};
    }
}

}  // namespace povwall::trace::detail
