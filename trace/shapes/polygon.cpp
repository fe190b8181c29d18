#include "trace/shapes/polygon.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

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

void shape_hits(const Polygon& p, const LocalRay& r, ShapeHits& out) {
    if (degenerate_polygon(p)) return;
    Crossings cs;
    intersect_polygon(p, r.origin, r.unit, cs);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Polygon& p, const ShapeHit&) { return pov_polygon_normal(p); }

bool shape_inside(const Polygon&, const Point3&) { return false; }

Bounds3 shape_bounds(const Polygon& p) {
    Bounds3 b;
    for (const auto& q : p.points) b.extend(q);
    return b;
}

PovBBox shape_pov_bbox(const Polygon& s, const CompactTransform& xf) {
    Bounds3 b;
    for (const Point3& p : s.points) b.extend(xf.point(p));
    if (b.empty()) return pov_infinite_bbox();
    PovBBox box = pov_bbox(b);
    // A box flat along an axis is widened by SMALL_TOLERANCE each way.
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(box.len[a]) < kSmallTolerance) {
            box.lo[a] = float(Real(box.lo[a]) - kSmallTolerance);
            box.len[a] = float(Real(box.len[a]) + 2 * kSmallTolerance);
        }
    }
    return box;
}

bool shape_oracle_first(const Polygon& s, const OracleRay& r, OracleBest& best) {
    if (s.points.size() < 3 || degenerate_polygon(s)) return true;
    V3 n(polygon_normal(s));
    HP nd = dot(n, r.d);
    if (abs(nd) < HP(kPovEpsilon)) return true;
    HP t = dot(n, V3(s.points[0]) - r.o) / nd;
    if (!(t > kPolygonTolerance) || t > kMaxDistance) return true;
    V3 q = r.o + r.d * t;
    Vector3 nn = polygon_normal(s);
    int drop = 0;
    if (std::fabs(nn.y) > std::fabs(nn[drop])) drop = 1;
    if (std::fabs(nn.z) > std::fabs(nn[drop])) drop = 2;
    const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
    bool inside = false;
    for (size_t i = 0; i < s.points.size(); ++i) {
        V3 a(s.points[i]), b(s.points[(i + 1) % s.points.size()]);
        if ((a[v] > q[v]) != (b[v] > q[v])) {
            HP x = a[u] + (q[v] - a[v]) / (b[v] - a[v]) * (b[u] - a[u]);
            if (q[u] < x) inside = !inside;
        }
    }
    if (inside) best.offer(t, kPolygonTolerance);
    return true;
}

}  // namespace povwall::trace
