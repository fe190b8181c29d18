#include "trace/intersect.h"

#include <algorithm>
#include <cmath>

#include "trace/roots.h"

namespace povwall::trace {

Real round_to_float(Real x) { return Real(float(x)); }

void intersect_sphere(const Sphere& s, const Point3& o, const Vector3& dir,
                      Crossings& out) {
    Vector3 oc = s.centre - o;
    Real tca = dot(oc, dir);
    Real t2hc = s.radius * s.radius - dot(oc, oc) + tca * tca;
    // POV-Ray needs a half chord above EPSILON: tangent rays miss.
    if (!(t2hc > kPovEpsilon)) return;
    Real th = std::sqrt(t2hc);
    Real t1 = tca - th, t2 = tca + th;
    if (t1 > kSphereTolerance) out.add(t1, 0);
    if (t2 > kSphereTolerance) out.add(t2, 0);
}

Vector3 sphere_normal(const Sphere& s, const Point3& p) {
    return (p - s.centre) / s.radius;
}

bool inside_sphere(const Sphere& s, const Point3& p) {
    Vector3 d = p - s.centre;
    return dot(d, d) < s.radius * s.radius;
}

void intersect_box(const Box& b, const Point3& o, const Vector3& dir, Crossings& out) {
    Point3 lo = min(b.corner1, b.corner2), hi = max(b.corner1, b.corner2);
    Real tmin = -kInfinity, tmax = kInfinity;
    int fmin = -1, fmax = -1;
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(dir[a]) < kPovEpsilon) {
            if (o[a] < lo[a] || o[a] > hi[a]) return;
            continue;
        }
        Real t1 = (lo[a] - o[a]) / dir[a], t2 = (hi[a] - o[a]) / dir[a];
        int f1 = 2 * a, f2 = 2 * a + 1;  // even: low face, odd: high face
        if (t1 > t2) {
            std::swap(t1, t2);
            std::swap(f1, f2);
        }
        if (t1 > tmin) {
            tmin = t1;
            fmin = f1;
        }
        if (t2 < tmax) {
            tmax = t2;
            fmax = f2;
        }
        if (tmin > tmax) return;
    }
    if (tmax < kBoxTolerance) return;
    if (tmin > kBoxTolerance) out.add(tmin, fmin);
    if (tmax > kBoxTolerance) out.add(tmax, fmax);
}

void intersect_box_pov(const Box& b, const Point3& o, const Vector3& dir,
                       Crossings& out) {
    const Point3 lo = min(b.corner1, b.corner2), hi = max(b.corner1, b.corner2);
    Real tmin = 0, tmax = kBoxBoundHuge;
    int fmin = -1, fmax = -1;
    // Whether a face of `axis` is met more head-on than the face `current` (which lies on
    // an earlier axis): y is weighed against x, z against the current face's axis.
    auto more_direct = [&](int axis, int current) {
        const int other = axis == 1 ? 0 : current / 2;
        if (axis == 2 && current < 0) return false;
        return std::fabs(dir[axis]) > std::fabs(dir[other]);
    };
    for (int a = 0; a < 3; ++a) {
        if (!(dir[a] < -kPovEpsilon || dir[a] > kPovEpsilon)) {
            if (o[a] < lo[a] || o[a] > hi[a]) return;
            continue;
        }
        const bool down = dir[a] < 0;
        const int enter_face = down ? 2 * a + 1 : 2 * a,
                  leave_face = down ? 2 * a : 2 * a + 1;
        const Real close = a == 0 ? 0 : kBoxCloseTolerance;
        const Real leave = ((down ? lo[a] : hi[a]) - o[a]) / dir[a];
        if (leave < tmin) return;
        if (leave <= tmax - close) {
            tmax = leave;
            fmax = leave_face;
        } else if (a > 0 && leave <= tmax + close && more_direct(a, fmax)) {
            fmax = leave_face;
        }
        const Real enter = ((down ? hi[a] : lo[a]) - o[a]) / dir[a];
        if (enter >= tmin + close) {
            if (enter > tmax) return;
            tmin = enter;
            fmin = enter_face;
        } else if (a > 0 && enter >= tmin - close && more_direct(a, fmin)) {
            fmin = enter_face;
        }
    }
    if (tmax < kBoxTolerance) return;
    if (tmin > kBoxTolerance) out.add(tmin, fmin);
    out.add(tmax, fmax);
}

Vector3 box_normal(const Box& b, int face) {
    Vector3 n{0, 0, 0};
    int axis = face / 2;
    n[axis] = (face & 1) ? 1 : -1;
    // A box given with swapped corners still has outward normals.
    return n;
}

bool inside_box(const Box& b, const Point3& p) {
    Point3 lo = min(b.corner1, b.corner2), hi = max(b.corner1, b.corner2);
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
           p.z <= hi.z;
}

void intersect_plane(const Plane& p, const Point3& o, const Vector3& dir, Crossings& out,
                     Real min_t) {
    Real nd = dot(p.normal, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = (p.distance - dot(p.normal, o)) / nd;
    if (t > min_t && t < kMaxDistance) out.add(t, 0);
}

bool inside_plane(const Plane& pl, const Point3& p) {
    return dot(pl.normal, p) < pl.distance;
}

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

void intersect_cylinder(const Cylinder& c, const Point3& o, const Vector3& dir,
                        Crossings& out) {
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
    AxisFrame f = axis_of(c.base, c.cap);
    if (face == 1) return -f.axis;
    if (face == 2) return f.axis;
    Vector3 u = p - c.base;
    return u - f.axis * dot(u, f.axis);
}

bool inside_cylinder(const Cylinder& c, const Point3& p) {
    AxisFrame f = axis_of(c.base, c.cap);
    Vector3 u = p - c.base;
    Real h = dot(u, f.axis);
    Vector3 perp = u - f.axis * h;
    return h >= 0 && h <= f.len && dot(perp, perp) < c.radius * c.radius;
}

void intersect_cone(const Cone& c, const Point3& o, const Vector3& dir, Crossings& out) {
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
    AxisFrame f = axis_of(c.base, c.cap);
    Real k = (c.cap_radius - c.base_radius) / f.len;
    Vector3 u = p - c.base;
    Real h = dot(u, f.axis);
    if (h < 0 || h > f.len) return false;
    Vector3 perp = u - f.axis * h;
    Real r = c.base_radius + k * h;
    return dot(perp, perp) < r * r;
}

void intersect_disc(const Disc& d, const Point3& o, const Vector3& dir, Crossings& out,
                    Real min_t) {
    Vector3 n = normalize(d.normal);
    Real nd = dot(n, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = dot(n, d.centre - o) / nd;
    if (t <= min_t) return;
    Vector3 q = o + dir * t - d.centre;
    Real r2 = dot(q, q);
    if (r2 <= d.radius * d.radius && r2 >= d.hole_radius * d.hole_radius) out.add(t, 0);
}

void intersect_triangle(const Point3 p[3], const Point3& o, const Vector3& dir,
                        Crossings& out, Real min_t) {
    Vector3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    Vector3 pv = cross(dir, e2);
    Real det = dot(e1, pv);
    if (std::fabs(det) < 1e-300) return;
    Real inv = 1 / det;
    Vector3 tv = o - p[0];
    Real u = dot(tv, pv) * inv;
    if (u < 0 || u > 1) return;
    Vector3 qv = cross(tv, e1);
    Real v = dot(dir, qv) * inv;
    if (v < 0 || u + v > 1) return;
    Real t = dot(e2, qv) * inv;
    if (t > min_t) out.add(t, 0);
}

bool degenerate_polygon(const Polygon& poly) {
    const auto& pts = poly.points;
    const size_t k = pts.size();
    if (k < 3) return true;
    const Point3& o = pts[0];
    size_t i = 1;
    Vector3 u;
    for (; i < k; ++i) {
        u = pts[i] - o;
        if (dot(u, u) > kPovEpsilon) break;
    }
    if (i == k) return true;
    for (++i; i < k; ++i) {
        const Vector3 v = pts[i] - o, w = cross(u, v);
        if (dot(v, v) > kPovEpsilon && dot(w, w) > kPovEpsilon) return false;
    }
    return true;
}

Vector3 smooth_triangle_normal(const Point3 (&corner)[3], const Vector3* n,
                               const Point3& q) {
    // Barycentric interpolation of the vertex normals.
    Vector3 e1 = corner[1] - corner[0], e2 = corner[2] - corner[0], w = q - corner[0];
    Real d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    Real d20 = dot(w, e1), d21 = dot(w, e2);
    Real den = d00 * d11 - d01 * d01;
    if (den == 0) return cross(e1, e2);
    Real v = (d11 * d20 - d01 * d21) / den, u2 = (d00 * d21 - d01 * d20) / den;
    return n[0] * (1 - v - u2) + n[1] * v + n[2] * u2;
}

Vector3 polygon_normal(const Polygon& poly) {
    // Newell's method: robust for any planar loop, whatever its first points are.
    Vector3 n{0, 0, 0};
    const size_t k = poly.points.size();
    for (size_t i = 0; i < k; ++i) {
        const Point3& a = poly.points[i];
        const Point3& b = poly.points[(i + 1) % k];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return normalize(n);
}

Vector3 pov_polygon_normal(const Polygon& poly) {
    const Vector3 newell = polygon_normal(poly);
    const std::vector<Point3>& p = poly.points;
    constexpr Real kEpsilon = 1e-10;  // POV-Ray's EPSILON
    size_t i = 1;
    while (i < p.size() && dot(p[i] - p[0], p[i] - p[0]) <= kEpsilon) ++i;
    if (i >= p.size()) return newell;
    const Vector3 u = p[i] - p[0];
    for (++i; i < p.size(); ++i) {
        const Vector3 v = p[i] - p[0], w = cross(u, v);
        if (dot(v, v) > kEpsilon && dot(w, w) > kEpsilon)
            return dot(w, newell) < 0 ? -newell : newell;
    }
    return newell;
}

void intersect_polygon(const Polygon& poly, const Point3& o, const Vector3& dir,
                       Crossings& out) {
    const size_t k = poly.points.size();
    if (k < 3) return;
    Vector3 n = polygon_normal(poly);
    Real nd = dot(n, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = dot(n, poly.points[0] - o) / nd;
    if (!(t > kPolygonTolerance) || t > kMaxDistance) return;
    Point3 p = o + dir * t;
    // Project on the plane of the two axes the normal is least aligned with.
    int drop = 0;
    if (std::fabs(n.y) > std::fabs(n[drop])) drop = 1;
    if (std::fabs(n.z) > std::fabs(n[drop])) drop = 2;
    const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
    bool inside = false;
    for (size_t i = 0; i < k; ++i) {
        const Point3& a = poly.points[i];
        const Point3& b = poly.points[(i + 1) % k];
        if ((a[v] > p[v]) != (b[v] > p[v])) {
            Real x = a[u] + (p[v] - a[v]) / (b[v] - a[v]) * (b[u] - a[u]);
            if (p[u] < x) inside = !inside;
        }
    }
    if (inside) out.add(t, 0);
}

// ------------------------------------------------------------------ torus

bool torus_quartic(const Torus& tor, const Point3& o0, const Vector3& dir,
                   TorusQuartic& q, Real min_t) {
    const Real R = tor.major, r = tor.minor;
    const Real bound = R + r;
    const Real tc = -dot(o0, dir);
    const Real closest2 = dot(o0 + dir * tc, o0 + dir * tc);
    if (closest2 > bound * bound) return false;
    // Start from just outside the bounding sphere to keep the quartic well conditioned,
    // as POV-Ray does.
    q.shift = 0;
    if (dot(o0, o0) > (R + 2 * r) * (R + 2 * r))
        q.shift = std::max(0.0, tc - (R + 2 * r));
    const Point3 o = o0 + dir * q.shift;
    const Real R2 = R * R, r2 = r * r;
    // (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2): the torus lies in the xz plane around y.
    const Real dd = dot(dir, dir), od = dot(o, dir), oo = dot(o, o);
    const Real oxz = o.x * o.x + o.z * o.z, odxz = o.x * dir.x + o.z * dir.z;
    const Real dxz = dir.x * dir.x + dir.z * dir.z;
    const Real e = oo + R2 - r2;
    q.c[4] = dd * dd;
    q.c[3] = 4 * dd * od;
    q.c[2] = 2 * dd * e + 4 * od * od - 4 * R2 * dxz;
    q.c[1] = 4 * od * e - 8 * R2 * odxz;
    q.c[0] = e * e - 4 * R2 * oxz;
    // Every crossing lies inside the bounding sphere: solve only over that chord.
    const Real half_chord = std::sqrt(std::max(0.0, bound * bound - closest2));
    const Real slack = 1e-9 * (bound + std::fabs(tc));
    q.lo = std::max(min_t - q.shift, tc - q.shift - half_chord - slack);
    q.hi = tc - q.shift + half_chord + slack;
    return q.lo < q.hi;
}

namespace {

// POV-Ray's thick-cylinder pre-test of a torus (Torus::Test_Thick_Cylinder): the ray
// meets the cap planes y = +-r inside the ring R - r .. R + r, or the outer or inner
// cylinder between the caps, ahead of its origin (EPSILON < k < MAX_DISTANCE).
bool meets_thick_cylinder(const Torus& tor, const Point3& p, const Vector3& d) {
    const Real h1 = -tor.minor, h2 = tor.minor;
    const Real r1 =
        tor.major < tor.minor ? 0 : (tor.major - tor.minor) * (tor.major - tor.minor);
    const Real r2 = (tor.major + tor.minor) * (tor.major + tor.minor);
    auto ahead = [](Real k) { return k > kPovEpsilon && k < kMaxDistance; };
    if (std::fabs(d.y) < kPovEpsilon) {
        if (p.y < h1 || p.y > h2) return false;
    } else {
        for (Real h : {h2, h1}) {
            const Real k = (h - p.y) / d.y;
            const Real u = p.x + k * d.x, v = p.z + k * d.z;
            if (ahead(k) && u * u + v * v >= r1 && u * u + v * v <= r2) return true;
        }
    }
    const Real a = d.x * d.x + d.z * d.z;
    if (!(a > kPovEpsilon)) return false;
    const Real b = p.x * d.x + p.z * d.z;
    for (Real rr : {r2, r1}) {
        Real disc = b * b - a * (p.x * p.x + p.z * p.z - rr);
        if (!(disc >= 0)) continue;
        disc = std::sqrt(disc);
        for (Real k : {(-b + disc) / a, (-b - disc) / a}) {
            const Real h = p.y + k * d.y;
            if (ahead(k) && h >= h1 && h <= h2) return true;
        }
    }
    return false;
}

// POV-Ray's root elimination (Solve_Polynomial with ROOT_TOLERANCE 1e-4): the quartic in
// t, monic, about the point `closer` along the ray (the origin moved to 2r outside the
// bounding sphere, as POV-Ray moves it). When its constant term is below 1e-4 times its
// linear one (a root within about 1e-4 of that point: a ray leaving the surface, or a
// torus whose minor radius is about that small), the constant is dropped and the cubic
// left is solved instead. Returns false when no elimination happens; else `out` holds
// the cubic's roots as crossings (for a torus that small they are not on its surface:
// POV- Ray shades it at those points).
bool torus_root_elimination(const Torus& tor, const Point3& o, const Vector3& dir,
                            Crossings& out, Real min_t) {
    const Real R2 = tor.major * tor.major, r2 = tor.minor * tor.minor;
    const Real bound = tor.major + 2 * tor.minor;
    Real closer = 0;
    Point3 p = o;
    const Real dist2 = dot(o, o);
    if (dist2 > bound * bound) {
        closer = std::sqrt(dist2) - bound;
        p = o + dir * closer;
    }
    const Real k1 = p.x * p.x + p.z * p.z + p.y * p.y - R2 - r2;
    const Real k2 = p.x * dir.x + p.z * dir.z + p.y * dir.y;
    const Real c1 = 4 * k2;
    const Real c2 = 2 * (k1 + 2 * (k2 * k2 + R2 * dir.y * dir.y));
    const Real c3 = 4 * (k2 * k1 + 2 * R2 * p.y * dir.y);
    const Real c4 = k1 * k1 + 4 * R2 * (p.y * p.y - r2);
    if (!(c3 != 0 && std::fabs(c4 / c3) < kTorusTolerance)) return false;
    if (!meets_thick_cylinder(tor, o, dir))
        return true;  // POV-Ray's pre-test fails first
    Real roots[3];
    const int n = solve_cubic(c1, c2, c3, roots);
    Real t[3];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const Real d = roots[i] + closer;
        if (d > min_t && d < kMaxDistance) t[m++] = d;
    }
    for (int i = 1; i < m; ++i)  // ascending
        for (int j = i; j > 0 && t[j] < t[j - 1]; --j) std::swap(t[j], t[j - 1]);
    for (int i = 0; i < m; ++i) out.add(t[i], 0);
    return true;
}

}  // namespace

void intersect_torus(const Torus& tor, const Point3& o, const Vector3& dir,
                     Crossings& out, Real min_t) {
    if (torus_root_elimination(tor, o, dir, out, min_t)) return;
    TorusQuartic q;
    if (!torus_quartic(tor, o, dir, q, min_t)) return;
    Real roots[4];
    int n = solve_quartic(q.c, q.lo, q.hi, roots);
    // The quartic's coefficients are rounded sums of large terms, so its exact roots are
    // off by ~1e-12 on thin tori. Newton on the surface's signed distance along the ray
    // (condition ~1 near the surface) recovers the last digits; a step may not cross half
    // way to a neighbouring root, so close pairs stay apart.
    auto distance = [&](Real t, Real& slope) {
        const Point3 p = o + dir * t;
        const Real rho = std::sqrt(p.x * p.x + p.z * p.z);
        const Real ring = rho - tor.major;
        const Real d = std::sqrt(ring * ring + p.y * p.y);
        if (rho == 0 || d == 0) {
            slope = 0;
            return d - tor.minor;
        }
        const Vector3 grad{ring * p.x / (rho * d), p.y / d, ring * p.z / (rho * d)};
        slope = dot(grad, dir);
        return d - tor.minor;
    };
    for (int i = 0; i < n; ++i) {
        Real reach = 0.5 * (q.hi - q.lo);
        if (i > 0) reach = std::min(reach, 0.5 * (roots[i] - roots[i - 1]));
        if (i + 1 < n) reach = std::min(reach, 0.5 * (roots[i + 1] - roots[i]));
        const Real t0 = roots[i] + q.shift;
        Real t = t0, slope;
        const Real g = distance(t, slope);
        // One step: the solver's root is ~1e-12 off and Newton converges quadratically.
        if (g != 0 && slope != 0) {
            const Real nt = t - g / slope;
            Real nslope;
            if (std::isfinite(nt) && std::fabs(nt - t0) <= reach &&
                std::fabs(distance(nt, nslope)) < std::fabs(g))
                t = nt;
        }
        if (t > min_t) out.add(t, 0);
    }
}

Vector3 torus_normal(const Torus& tor, const Point3& p) {
    Real d = std::sqrt(p.x * p.x + p.z * p.z);
    if (!(d > kPovEpsilon)) return p;  // POV-Ray: no ring point, the normal is p itself
    Point3 ring{p.x * tor.major / d, 0, p.z * tor.major / d};
    return p - ring;
}

bool inside_torus(const Torus& tor, const Point3& p) {
    Real d = std::sqrt(p.x * p.x + p.z * p.z) - tor.major;
    return d * d + p.y * p.y < tor.minor * tor.minor;
}

}  // namespace povwall::trace
