#include "trace/intersect.h"

#include <algorithm>
#include <cmath>

namespace povwall::trace {

int solve_quadratic(Real a, Real b, Real c, Real roots[2]) {
    if (a == 0) {
        if (b == 0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    Real disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    Real s = std::sqrt(disc);
    // q has the sign of b, so neither root subtracts nearly equal numbers.
    Real q = -0.5 * (b + (b >= 0 ? s : -s));
    Real r0 = q / a, r1 = q != 0 ? c / q : r0;
    roots[0] = std::min(r0, r1);
    roots[1] = std::max(r0, r1);
    return 2;
}

void intersect_sphere(const Sphere& s, const Point3& o, const Vector3& dir, Crossings& out) {
    Vector3 oc = s.centre - o;
    Real tca = dot(oc, dir);
    Real t2hc = s.radius * s.radius - dot(oc, oc) + tca * tca;
    if (t2hc < 0) return;
    Real th = std::sqrt(t2hc);
    Real t1 = tca - th, t2 = tca + th;
    if (t1 > kSphereTolerance) out.add(t1, 0);
    if (t2 > kSphereTolerance) out.add(t2, 0);
}

Vector3 sphere_normal(const Sphere& s, const Point3& p) { return (p - s.centre) / s.radius; }

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

void intersect_plane(const Plane& p, const Point3& o, const Vector3& dir, Crossings& out) {
    Real nd = dot(p.normal, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = (p.distance - dot(p.normal, o)) / nd;
    if (t > kPlaneTolerance && t < kMaxDistance) out.add(t, 0);
}

bool inside_plane(const Plane& pl, const Point3& p) { return dot(pl.normal, p) < pl.distance; }

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

void intersect_cylinder(const Cylinder& c, const Point3& o, const Vector3& dir, Crossings& out) {
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

void intersect_disc(const Disc& d, const Point3& o, const Vector3& dir, Crossings& out) {
    Vector3 n = normalize(d.normal);
    Real nd = dot(n, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = dot(n, d.centre - o) / nd;
    if (t <= kPlaneTolerance) return;
    Vector3 q = o + dir * t - d.centre;
    Real r2 = dot(q, q);
    if (r2 <= d.radius * d.radius && r2 >= d.hole_radius * d.hole_radius) out.add(t, 0);
}

void intersect_triangle(const Point3 p[3], const Point3& o, const Vector3& dir, Crossings& out) {
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
    if (t > kTriangleTolerance) out.add(t, 0);
}

Vector3 smooth_triangle_normal(const SmoothTriangle& tri, const Point3& q) {
    // Barycentric interpolation of the vertex normals.
    Vector3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0], w = q - tri.p[0];
    Real d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    Real d20 = dot(w, e1), d21 = dot(w, e2);
    Real den = d00 * d11 - d01 * d01;
    if (den == 0) return cross(e1, e2);
    Real v = (d11 * d20 - d01 * d21) / den, u2 = (d00 * d21 - d01 * d20) / den;
    return tri.n[0] * (1 - v - u2) + tri.n[1] * v + tri.n[2] * u2;
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

namespace {

int solve_cubic_real(Real a, Real b, Real c, Real roots[3]) {
    // x^3 + a x^2 + b x + c
    Real q = (a * a - 3 * b) / 9, r = (2 * a * a * a - 9 * a * b + 27 * c) / 54;
    Real q3 = q * q * q;
    if (r * r < q3) {
        Real th = std::acos(std::clamp(r / std::sqrt(q3), -1.0, 1.0));
        Real s = -2 * std::sqrt(q);
        roots[0] = s * std::cos(th / 3) - a / 3;
        roots[1] = s * std::cos((th + 2 * kPi) / 3) - a / 3;
        roots[2] = s * std::cos((th - 2 * kPi) / 3) - a / 3;
        return 3;
    }
    Real A = -std::cbrt(std::fabs(r) + std::sqrt(r * r - q3));
    if (r < 0) A = -A;
    Real B = A != 0 ? q / A : 0;
    roots[0] = A + B - a / 3;
    return 1;
}

Real poly4(const Real c[5], Real x) { return (((x + c[3]) * x + c[2]) * x + c[1]) * x + c[0]; }
Real dpoly4(const Real c[5], Real x) { return ((4 * x + 3 * c[3]) * x + 2 * c[2]) * x + c[1]; }

}  // namespace

int solve_quartic(const Real c[5], Real roots[4]) {
    // Depressed quartic y^4 + p y^2 + q y + r with x = y - c3/4.
    Real a = c[3], b = c[2], cc = c[1], d = c[0];
    Real a2 = a * a;
    Real p = b - 3 * a2 / 8;
    Real q = cc - a * b / 2 + a2 * a / 8;
    Real r = d - a * cc / 4 + a2 * b / 16 - 3 * a2 * a2 / 256;
    int n = 0;
    Real ys[4];
    if (std::fabs(q) < 1e-14) {
        // Biquadratic.
        Real z[2];
        int k = solve_quadratic(1, p, r, z);
        for (int i = 0; i < k; ++i) {
            if (z[i] >= 0) {
                Real s = std::sqrt(z[i]);
                ys[n++] = s;
                ys[n++] = -s;
            }
        }
    } else {
        // Resolvent cubic: m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0, take the largest root > 0.
        Real m3[3];
        int k = solve_cubic_real(p, p * p / 4 - r, -q * q / 8, m3);
        Real m = m3[0];
        for (int i = 1; i < k; ++i) m = std::max(m, m3[i]);
        if (m <= 0) m = 1e-300;
        Real s = std::sqrt(2 * m);
        Real z[2];
        int k1 = solve_quadratic(1, s, p / 2 + m - q / (2 * s), z);
        for (int i = 0; i < k1; ++i) ys[n++] = z[i];
        int k2 = solve_quadratic(1, -s, p / 2 + m + q / (2 * s), z);
        for (int i = 0; i < k2; ++i) ys[n++] = z[i];
    }
    for (int i = 0; i < n; ++i) {
        Real x = ys[i] - a / 4;
        // Newton polishing: the closed form loses digits on stiff (thin) tori.
        for (int it = 0; it < 4; ++it) {
            Real fx = poly4(c, x), dfx = dpoly4(c, x);
            if (dfx == 0) break;
            Real nx = x - fx / dfx;
            if (!std::isfinite(nx)) break;
            if (std::fabs(poly4(c, nx)) > std::fabs(fx)) break;
            x = nx;
        }
        roots[i] = x;
    }
    std::sort(roots, roots + n);
    return n;
}

void intersect_torus(const Torus& tor, const Point3& o0, const Vector3& dir, Crossings& out) {
    Real R = tor.major, r = tor.minor;
    // Start from just outside the bounding sphere to keep the quartic well conditioned,
    // as POV-Ray does.
    Real bound = R + r;
    Real tc = -dot(o0, dir);
    Real closest2 = dot(o0 + dir * tc, o0 + dir * tc);
    if (closest2 > bound * bound) return;
    Real shift = 0;
    if (dot(o0, o0) > (R + 2 * r) * (R + 2 * r)) shift = std::max(0.0, tc - (R + 2 * r));
    Point3 o = o0 + dir * shift;
    Real R2 = R * R, r2 = r * r;
    Real py2 = o.y * o.y, dy2 = dir.y * dir.y, pdy = o.y * dir.y;
    Real k1 = dot(o, o) - py2 - 0 + 0;  // x^2+z^2 part of |o|^2
    Real k2 = dot(o, dir) - pdy;
    Real dd = dot(dir, dir);
    // (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2), torus in the xz plane around y.
    Real od = dot(o, dir), oo = dot(o, o);
    Real e = oo + R2 - r2;
    Real c[5];
    c[4] = dd * dd;
    c[3] = 4 * dd * od;
    c[2] = 2 * dd * e + 4 * od * od - 4 * R2 * (dd - dy2);
    c[1] = 4 * od * e - 8 * R2 * k2;
    c[0] = e * e - 4 * R2 * k1;
    Real norm[5] = {c[0] / c[4], c[1] / c[4], c[2] / c[4], c[3] / c[4], 1};
    Real roots[4];
    int n = solve_quartic(norm, roots);
    for (int i = 0; i < n; ++i) {
        Real t = roots[i] + shift;
        if (t > kTorusTolerance) out.add(t, 0);
    }
}

Vector3 torus_normal(const Torus& tor, const Point3& p) {
    Real d = std::sqrt(p.x * p.x + p.z * p.z);
    if (d == 0) return {0, 1, 0};
    Point3 ring{p.x * tor.major / d, 0, p.z * tor.major / d};
    return p - ring;
}

bool inside_torus(const Torus& tor, const Point3& p) {
    Real d = std::sqrt(p.x * p.x + p.z * p.z) - tor.major;
    return d * d + p.y * p.y < tor.minor * tor.minor;
}

}  // namespace povwall::trace
