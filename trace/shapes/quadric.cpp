#include "trace/shapes/quadric.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

Real quadric_value(const Quadric& q, const Point3& p) {
    const Real a = q.square.x, b = q.square.y, c = q.square.z;
    const Real d = q.mixed.x, e = q.mixed.y, f = q.mixed.z;
    const Real g = q.linear.x, h = q.linear.y, i = q.linear.z;
    return p.x * (a * p.x + d * p.y + g) + p.y * (b * p.y + f * p.z + h) +
           p.z * (c * p.z + e * p.x + i) + q.constant;
}

void shape_hits(const Quadric& q, const LocalRay& r, ShapeHits& out) {
    // The world ray as given (the quadric has no transform): its roots are world depths.
    const Point3& o = r.origin;
    const Vector3& v = r.direction;
    const Real A = q.square.x, B = q.square.y, C = q.square.z;
    const Real D = q.mixed.x, E = q.mixed.y, F = q.mixed.z;
    const Real G = q.linear.x, H = q.linear.y, I = q.linear.z;
    const Real a =
        v.x * (A * v.x + D * v.y + E * v.z) + v.y * (B * v.y + F * v.z) + (v.z * C) * v.z;
    const Real b = v.x * (A * o.x + 0.5 * (D * o.y + E * o.z + G)) +
                   v.y * (B * o.y + 0.5 * (D * o.x + F * o.z + H)) +
                   v.z * (C * o.z + 0.5 * (E * o.x + F * o.y + I));
    const Real c = o.x * (A * o.x + D * o.y + E * o.z + G) +
                   o.y * (B * o.y + F * o.z + H) + o.z * (C * o.z + I) + q.constant;
    Real depth[2];
    if (a != 0) {
        const Real disc = b * b - a * c;
        if (disc <= 0) return;  // tangent rays miss
        const Real s = std::sqrt(disc);
        depth[0] = (-b + s) / a;
        depth[1] = (-b - s) / a;
    } else {
        if (b == 0) return;
        depth[0] = (-0.5 * c) / b;
        depth[1] = kMaxDistance;
    }
    const size_t first = out.size();
    for (Real t : depth) {
        if (t > kQuadricDepthTolerance && t < kMaxDistance)
            out.push_back({t, {o.x + t * v.x, o.y + t * v.y, o.z + t * v.z}, 0});
    }
    if (out.size() == first + 2 && out[first + 1].t < out[first].t)
        std::swap(out[first], out[first + 1]);
}

Vector3 shape_normal(const Quadric& q, const ShapeHit& h) {
    const Point3& p = h.p;
    const Vector3 n{
        (2 * q.square.x) * p.x + q.mixed.x * p.y + q.mixed.y * p.z + q.linear.x,
        q.mixed.x * p.x + (2 * q.square.y) * p.y + q.mixed.z * p.z + q.linear.y,
        q.mixed.y * p.x + q.mixed.z * p.y + (2 * q.square.z) * p.z + q.linear.z};
    if (!(dot(n, n) > 0))
        return {1, 0, 0};  // POV-Ray's normal where the gradient vanishes
    return n;
}

bool shape_inside(const Quadric& q, const Point3& p) { return quadric_value(q, p) <= 0; }

// POV-Ray inverts a quadric by negating its coefficients: its surface stays inside.
bool shape_inside_inverted(const Quadric& q, const Point3& p) {
    return quadric_value(q, p) >= 0;
}

// Every hit the ray can have: the surface may leave POV-Ray's box (only the ray must
// meet the box), so nothing tighter is safe.
Bounds3 shape_bounds(const Quadric&) { return Bounds3::everything(); }

PovBBox shape_pov_bbox(const Quadric& q, const CompactTransform&) {
    PovBBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = q.box_lo[a];
        b.len[a] = q.box_len[a];
    }
    return b;
}

bool shape_oracle_first(const Quadric& q, const OracleRay& r, OracleBest& best) {
    // The same quadratic in 50 digits (the quadric's space is the world).
    const V3& o = r.o;
    const V3& v = r.d;
    const HP A = q.square.x, B = q.square.y, C = q.square.z;
    const HP D = q.mixed.x, E = q.mixed.y, F = q.mixed.z;
    const HP G = q.linear.x, H = q.linear.y, I = q.linear.z;
    const HP a = A * v.x * v.x + B * v.y * v.y + C * v.z * v.z + D * v.x * v.y +
                 E * v.x * v.z + F * v.y * v.z;
    const HP b = 2 * (A * o.x * v.x + B * o.y * v.y + C * o.z * v.z) +
                 D * (o.x * v.y + o.y * v.x) + E * (o.x * v.z + o.z * v.x) +
                 F * (o.y * v.z + o.z * v.y) + G * v.x + H * v.y + I * v.z;
    const HP c = A * o.x * o.x + B * o.y * o.y + C * o.z * o.z + D * o.x * o.y +
                 E * o.x * o.z + F * o.y * o.z + G * o.x + H * o.y + I * o.z + q.constant;
    oracle_quadratic(a, b, c, best, kQuadricDepthTolerance,
                     [](const HP& t) { return t < HP(kMaxDistance); });
    return true;
}

}  // namespace povwall::trace
