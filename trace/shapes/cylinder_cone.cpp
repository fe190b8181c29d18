#include "trace/shapes/cylinder_cone.h"

#include <algorithm>
#include <cmath>

#include "trace/roots.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

namespace {

struct AxisFrame {
    Vector3 axis;
    Real len;
};
AxisFrame axis_of(const Point3& base, const Point3& cap) {
    Vector3 a = cap - base;
    Real l = length(a);
    return {l > 0 ? a / l : Vector3{0, 1, 0}, l};
}

}  // namespace

namespace {

bool is_unit_cylinder(const Cylinder& c) {
    return c.radius == 1 && c.base.x == 0 && c.base.y == 0 && c.base.z == 0 &&
           c.cap.x == 0 && c.cap.y == 0 && c.cap.z == 1;
}

// The crossings of a unit cylinder or cone in POV-Ray's push order, handed on ascending.
struct UnitShapeCrossings {
    Real t[4];
    int face[4];
    int n = 0;
    void add(Real k, int f) {
        t[n] = k;
        face[n++] = f;
    }
    // The cap at z = 1 (radius 1, face 2), then the base at z = `base_z` (radius^2
    // `base_r2`, face 1), as Cone::Intersect meets them.
    void caps(const Point3& p, const Vector3& d, Real base_z, Real base_r2) {
        if (!(std::fabs(d.z) > kPovEpsilon)) return;
        for (const Real h : {1.0, base_z}) {
            const Real k = (h - p.z) / d.z;
            const Real u = p.x + k * d.x, v = p.y + k * d.y;
            if (u * u + v * v <= (h == 1.0 ? 1.0 : base_r2) && k > kConeTolerance &&
                k < kMaxDistance)
                add(k, h == 1.0 ? 2 : 1);
        }
    }
    void emit(Crossings& out) {
        for (int i = 1; i < n; ++i)
            for (int j = i; j > 0 && t[j] < t[j - 1]; --j) {
                std::swap(t[j], t[j - 1]);
                std::swap(face[j], face[j - 1]);
            }
        for (int i = 0; i < n; ++i) out.add(t[i], face[i]);
    }
};

// The unit cylinder (x^2 + y^2 = 1, 0 <= z <= 1; `dir` unit) in POV-Ray's arithmetic
// (Cone::Intersect with CYLINDER_FLAG): the parser puts every cylinder in this form with
// POV-Ray's frame as its transform, so crossings come out with POV-Ray's bits.
void intersect_unit_cylinder(bool open, const Point3& p, const Vector3& d,
                             Crossings& out) {
    UnitShapeCrossings hits;
    const Real a = d.x * d.x + d.y * d.y;
    if (a > kPovEpsilon) {
        const Real b = p.x * d.x + p.y * d.y;
        const Real c = p.x * p.x + p.y * p.y - 1.0;
        Real disc = b * b - a * c;
        if (disc >= 0.0) {
            disc = std::sqrt(disc);
            for (const Real k : {(-b + disc) / a, (-b - disc) / a}) {
                const Real z = p.z + k * d.z;
                if (k > kConeTolerance && k < kMaxDistance && z >= 0.0 && z <= 1.0)
                    hits.add(k, 0);
            }
        }
    }
    if (!open) hits.caps(p, d, 0.0, 1.0);
    hits.emit(out);
}

}  // namespace

void intersect_cylinder(const Cylinder& c, const Point3& o, const Vector3& dir,
                        Crossings& out) {
    if (is_unit_cylinder(c)) return intersect_unit_cylinder(c.open, o, dir, out);
    // Zero radius (exporters write them): a line, never hit; its normal would be 0/0.
    if (c.radius == 0) return;
    AxisFrame f = axis_of(c.base, c.cap);
    Vector3 u = o - c.base;
    Real dp = dot(dir, f.axis), up = dot(u, f.axis);
    Vector3 dperp = dir - f.axis * dp, uperp = u - f.axis * up;
    Real roots[2];
    Real tmp[4];
    int faces[4];
    int n = 0;
    int k = solve_quadratic(dot(dperp, dperp), 2 * dot(dperp, uperp),
                            dot(uperp, uperp) - c.radius * c.radius, roots);
    for (int i = 0; i < k; ++i) {
        Real h = up + roots[i] * dp;
        if (h >= 0 && h <= f.len) {
            tmp[n] = roots[i];
            faces[n++] = 0;
        }
    }
    if (!c.open && std::fabs(dp) > kPovEpsilon) {
        for (int cap = 0; cap < 2; ++cap) {
            Real t = ((cap ? f.len : 0) - up) / dp;
            Vector3 q = uperp + dperp * t;
            if (dot(q, q) <= c.radius * c.radius) {
                tmp[n] = t;
                faces[n++] = 1 + cap;
            }
        }
    }
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (tmp[j] < tmp[i]) {
                std::swap(tmp[i], tmp[j]);
                std::swap(faces[i], faces[j]);
            }
    for (int i = 0; i < n; ++i) {
        if (tmp[i] > kConeTolerance) out.add(tmp[i], faces[i]);
    }
}

Vector3 cylinder_normal(const Cylinder& c, const Point3& p, int face) {
    if (face == 0 && is_unit_cylinder(c))
        return {p.x, p.y, 0.0};  // POV-Ray's Cone::Normal
    AxisFrame f = axis_of(c.base, c.cap);
    if (face == 1) return -f.axis;
    if (face == 2) return f.axis;
    Vector3 u = p - c.base;
    return u - f.axis * dot(u, f.axis);
}

bool inside_cylinder(const Cylinder& c, const Point3& p) {
    // POV-Ray's Cone::Inside, in the unit cylinder's terms (radius and length 1) with its
    // EPSILON margin: a point on a closed cylinder's surface is outside, on an open one's
    // inside (a cutaway texture's inside tests meet such points:
    // trace/cutaway_textures.h).
    const Real margin = c.open ? kPovEpsilon : -kPovEpsilon;
    AxisFrame f = axis_of(c.base, c.cap);
    Vector3 u = p - c.base;
    Real h = dot(u, f.axis);
    Vector3 perp = u - f.axis * h;
    const Real z = h / f.len, w2 = dot(perp, perp) / (c.radius * c.radius);
    return !(w2 > 1 + margin || z < -margin || z > 1 + margin);
}

namespace {

// The parser's form of every cone (pov_cone_frame): x^2 + y^2 = z^2 from z = dist (the
// base's radius) to 1.
bool is_unit_cone(const Cone& c) {
    return c.cap_radius == 1 && c.cap.x == 0 && c.cap.y == 0 && c.cap.z == 1 &&
           c.base.x == 0 && c.base.y == 0 && c.base.z == c.base_radius &&
           c.base_radius >= 0 && c.base_radius < 1;
}

// The unit cone in POV-Ray's arithmetic (Cone::Intersect; `d` unit).
void intersect_unit_cone(const Cone& c, const Point3& p, const Vector3& d,
                         Crossings& out) {
    const Real dist = c.base_radius;
    UnitShapeCrossings hits;
    auto side = [&](Real k) {
        const Real z = p.z + k * d.z;
        if (k > kConeTolerance && k < kMaxDistance && z >= dist && z <= 1.0)
            hits.add(k, 0);
    };
    const Real a = d.x * d.x + d.y * d.y - d.z * d.z;
    const Real b = d.x * p.x + d.y * p.y - d.z * p.z;
    const Real cc = p.x * p.x + p.y * p.y - p.z * p.z;
    if (std::fabs(a) < kPovEpsilon) {
        if (std::fabs(b) > kPovEpsilon) side(-0.5 * cc / b);
    } else {
        Real disc = b * b - a * cc;
        if (disc >= 0.0) {
            disc = std::sqrt(disc);
            side((-b - disc) / a);
            side((-b + disc) / a);
        }
    }
    if (!c.open) hits.caps(p, d, dist, dist * dist);
    hits.emit(out);
}

}  // namespace

void intersect_cone(const Cone& c, const Point3& o, const Vector3& dir, Crossings& out) {
    if (is_unit_cone(c)) return intersect_unit_cone(c, o, dir, out);
    if (c.base_radius == 0 && c.cap_radius == 0)
        return;  // a line, as a zero-radius cylinder
    AxisFrame f = axis_of(c.base, c.cap);
    Real k = (c.cap_radius - c.base_radius) / f.len;
    Vector3 u = o - c.base;
    Real dp = dot(dir, f.axis), up = dot(u, f.axis);
    Vector3 dperp = dir - f.axis * dp, uperp = u - f.axis * up;
    // |uperp + t dperp|^2 = (r0 + k (up + t dp))^2
    Real r_at0 = c.base_radius + k * up;
    Real a = dot(dperp, dperp) - k * k * dp * dp;
    Real b = 2 * (dot(dperp, uperp) - r_at0 * k * dp);
    Real cc = dot(uperp, uperp) - r_at0 * r_at0;
    Real roots[2];
    Real tmp[4];
    int faces[4];
    int n = 0;
    int m = solve_quadratic(a, b, cc, roots);
    for (int i = 0; i < m; ++i) {
        Real h = up + roots[i] * dp;
        if (h >= 0 && h <= f.len && c.base_radius + k * h >= 0) {
            tmp[n] = roots[i];
            faces[n++] = 0;
        }
    }
    if (!c.open && std::fabs(dp) > kPovEpsilon) {
        for (int cap = 0; cap < 2; ++cap) {
            Real r = cap ? c.cap_radius : c.base_radius;
            Real t = ((cap ? f.len : 0) - up) / dp;
            Vector3 q = uperp + dperp * t;
            if (dot(q, q) <= r * r) {
                tmp[n] = t;
                faces[n++] = 1 + cap;
            }
        }
    }
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (tmp[j] < tmp[i]) {
                std::swap(tmp[i], tmp[j]);
                std::swap(faces[i], faces[j]);
            }
    for (int i = 0; i < n; ++i) {
        if (tmp[i] > kConeTolerance) out.add(tmp[i], faces[i]);
    }
}

Vector3 cone_normal(const Cone& c, const Point3& p, int face) {
    if (face == 0 && is_unit_cone(c)) return {p.x, p.y, -p.z};  // POV-Ray's Cone::Normal
    AxisFrame f = axis_of(c.base, c.cap);
    if (face == 1) return -f.axis;
    if (face == 2) return f.axis;
    Real k = (c.cap_radius - c.base_radius) / f.len;
    Vector3 u = p - c.base;
    Real h = dot(u, f.axis);
    Vector3 perp = u - f.axis * h;
    Real r = c.base_radius + k * h;
    Real pl = length(perp);
    if (pl == 0) return -f.axis;
    return perp / pl * 1.0 - f.axis * k * (r / std::max(r, 1e-300)) * 1.0;
}

bool inside_cone(const Cone& c, const Point3& p) {
    if (is_unit_cone(c)) {  // POV-Ray's Cone::Inside as it is written
        const Real margin = c.open ? kPovEpsilon : -kPovEpsilon;
        const Real w2 = p.x * p.x + p.y * p.y, z2 = p.z * p.z;
        return !(w2 > z2 + margin || p.z < c.base_radius - margin || p.z > 1.0 + margin);
    }
    // POV-Ray's Cone::Inside in its cone space: the tip at z = 0, the wider end at z = 1
    // with radius 1, the narrower at z = dist, and the same EPSILON margin as the
    // cylinder's (a closed cone's surface is outside, an open one's inside). Radii within
    // EPSILON make it a cylinder.
    const bool cap_wider = c.cap_radius > c.base_radius;
    const Real wide = cap_wider ? c.cap_radius : c.base_radius;
    const Real narrow = cap_wider ? c.base_radius : c.cap_radius;
    const Point3& narrow_end = cap_wider ? c.base : c.cap;
    AxisFrame f = axis_of(narrow_end, cap_wider ? c.cap : c.base);
    const Real margin = c.open ? kPovEpsilon : -kPovEpsilon;
    const Vector3 u = p - narrow_end;
    const Real h = dot(u, f.axis);
    const Vector3 perp = u - f.axis * h;
    const Real tip = narrow * f.len / (wide - narrow);  // the tip's distance before it
    const Real length = tip + f.len;
    if (wide - narrow < kPovEpsilon || (wide - narrow) * f.len / length < kPovEpsilon) {
        const Real z = h / f.len, w2 = dot(perp, perp) / (c.cap_radius * c.cap_radius);
        return !(w2 > 1 + margin || z < -margin || z > 1 + margin);
    }
    const Real z = (h + tip) / length, w2 = dot(perp, perp) / (wide * wide);
    return !(w2 > z * z + margin || z < tip / length - margin || z > 1 + margin);
}

void shape_hits(const Cylinder& c, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_cylinder(c, r.origin, r.unit, cs);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Cylinder& c, const ShapeHit& h) {
    return cylinder_normal(c, h.p, h.face);
}

bool shape_inside(const Cylinder& c, const Point3& p) { return inside_cylinder(c, p); }

Bounds3 shape_bounds(const Cylinder& c) {
    Bounds3 b;
    b.extend(c.base);
    b.extend(c.cap);
    b.lo -= Vector3(c.radius);
    b.hi += Vector3(c.radius);
    return b;
}

namespace {

// The world box of two discs about the axis from p0 to p1, of radii r0 and r1, under xf.
Bounds3 turned_discs_bounds(const Point3& p0, Real r0, const Point3& p1, Real r1,
                            const Transform& xf) {
    const AxisFrame f = axis_of(p0, p1);
    // Two unit vectors across the axis.
    const Vector3 helper =
        std::fabs(f.axis.x) < 0.9 ? Vector3{1, 0, 0} : Vector3{0, 1, 0};
    const Vector3 u = normalize(cross(f.axis, helper)), v = cross(f.axis, u);
    const Vector3 wu = xf.vector(u), wv = xf.vector(v);
    const Point3 e0 = xf.point(p0), e1 = xf.point(p1);
    Bounds3 b;
    for (int a = 0; a < 3; ++a) {
        const Real reach = std::sqrt(wu[a] * wu[a] + wv[a] * wv[a]);
        const Real reach0 = reach * std::fabs(r0), reach1 = reach * std::fabs(r1);
        // A margin far above the rounding of the crossings (relative 1e-16).
        const Real slack =
            1e-9 * (std::fabs(e0[a]) + std::fabs(e1[a]) + std::max(reach0, reach1));
        b.lo[a] = std::min(e0[a] - reach0, e1[a] - reach1) - slack;
        b.hi[a] = std::max(e0[a] + reach0, e1[a] + reach1) + slack;
    }
    return b;
}

}  // namespace

Bounds3 cylinder_world_bounds(const Cylinder& c, const Transform& xf) {
    return turned_discs_bounds(c.base, c.radius, c.cap, c.radius, xf);
}

Bounds3 cone_world_bounds(const Cone& c, const Transform& xf) {
    return turned_discs_bounds(c.base, c.base_radius, c.cap, c.cap_radius, xf);
}

PovBBox shape_pov_bbox(const Cylinder& c, const CompactTransform& xf) {
    const Vector3 a = c.cap - c.base;
    const Real len = length(a);
    if (!(len > 0)) return pov_infinite_bbox();
    return pov_bbox(pov_axial_bounds(xf, c.base, a / len, c.radius, len, 0));
}

void shape_hits(const Cone& c, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_cone(c, r.origin, r.unit, cs);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Cone& c, const ShapeHit& h) {
    return cone_normal(c, h.p, h.face);
}

bool shape_inside(const Cone& c, const Point3& p) { return inside_cone(c, p); }

Bounds3 shape_bounds(const Cone& c) {
    Real r = std::max(std::fabs(c.base_radius), std::fabs(c.cap_radius));
    Bounds3 b;
    b.extend(c.base);
    b.extend(c.cap);
    b.lo -= Vector3(r);
    b.hi += Vector3(r);
    return b;
}

PovBBox shape_pov_bbox(const Cone& c, const CompactTransform& xf) {
    // The wider end on top, the frame's origin at the apex of the full cone, the box as
    // wide as the wider end all along (Compute_Cone_Data).
    Point3 base = c.base, cap = c.cap;
    Real r0 = c.base_radius, r1 = c.cap_radius;
    if (r1 < r0) {
        std::swap(base, cap);
        std::swap(r0, r1);
    }
    const Vector3 a = cap - base;
    const Real len = length(a);
    if (!(len > 0)) return pov_infinite_bbox();
    const Vector3 axis = a / len;
    if (std::fabs(r1 - r0) < kPovEpsilon)
        return pov_bbox(pov_axial_bounds(xf, base, axis, r1, len, 0));
    const Real below = r0 * len / (r1 - r0);
    const Real height = below + len;
    return pov_bbox(
        pov_axial_bounds(xf, base - axis * below, axis, r1, height, below / height));
}

namespace {

// Both shapes as a cone of radii r0 (base) to r1 (cap).
void oracle_cone(const Point3& base, const Point3& cap, Real r0, Real r1, bool open,
                 const OracleRay& r, OracleBest& best) {
    const HP eps = kPovEpsilon;
    V3 axis;
    HP len = oracle_axis_frame(V3(base), V3(cap), axis);
    HP k = (HP(r1) - r0) / len;
    V3 u = r.o - V3(base);
    HP dp = dot(r.d, axis), up = dot(u, axis);
    V3 dperp = r.d - axis * dp, uperp = u - axis * up;
    HP rat0 = HP(r0) + k * up;
    auto on_side = [&](const HP& t) {
        HP h = up + t * dp;
        return h >= 0 && h <= len && HP(r0) + k * h >= 0;
    };
    oracle_quadratic(dot(dperp, dperp) - k * k * dp * dp,
                     2 * (dot(dperp, uperp) - rat0 * k * dp),
                     dot(uperp, uperp) - rat0 * rat0, best, kConeTolerance, on_side);
    if (!open && abs(dp) > eps) {
        for (int end = 0; end < 2; ++end) {
            HP rr = end ? r1 : r0;
            HP t = ((end ? len : HP(0)) - up) / dp;
            V3 q = uperp + dperp * t;
            if (dot(q, q) <= rr * rr) best.offer(t, kConeTolerance);
        }
    }
}

}  // namespace

bool shape_oracle_first(const Cylinder& c, const OracleRay& r, OracleBest& best) {
    oracle_cone(c.base, c.cap, c.radius, c.radius, c.open, r, best);
    return true;
}

bool shape_oracle_first(const Cone& c, const OracleRay& r, OracleBest& best) {
    oracle_cone(c.base, c.cap, c.base_radius, c.cap_radius, c.open, r, best);
    return true;
}

}  // namespace povwall::trace
