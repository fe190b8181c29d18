#include "trace/shapes/box.h"

#include <algorithm>
#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

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

bool box_span_pov(const Point3& lo, const Point3& hi, const Point3& o, const Vector3& dir,
                  Real& tmin_out, Real& tmax_out, int& fmin_out, int& fmax_out) {
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
            if (o[a] < lo[a] || o[a] > hi[a]) return false;
            continue;
        }
        const bool down = dir[a] < 0;
        const int enter_face = down ? 2 * a + 1 : 2 * a,
                  leave_face = down ? 2 * a : 2 * a + 1;
        const Real close = a == 0 ? 0 : kBoxCloseTolerance;
        const Real leave = ((down ? lo[a] : hi[a]) - o[a]) / dir[a];
        if (leave < tmin) return false;
        if (leave <= tmax - close) {
            tmax = leave;
            fmax = leave_face;
        } else if (a > 0 && leave <= tmax + close && more_direct(a, fmax)) {
            fmax = leave_face;
        }
        const Real enter = ((down ? hi[a] : lo[a]) - o[a]) / dir[a];
        if (enter >= tmin + close) {
            if (enter > tmax) return false;
            tmin = enter;
            fmin = enter_face;
        } else if (a > 0 && enter >= tmin - close && more_direct(a, fmin)) {
            fmin = enter_face;
        }
    }
    if (tmax < kBoxTolerance) return false;
    tmin_out = tmin, tmax_out = tmax, fmin_out = fmin, fmax_out = fmax;
    return true;
}

void intersect_box_pov(const Box& b, const Point3& o, const Vector3& dir,
                       Crossings& out) {
    const Point3 lo = min(b.corner1, b.corner2), hi = max(b.corner1, b.corner2);
    Real tmin, tmax;
    int fmin, fmax;
    if (!box_span_pov(lo, hi, o, dir, tmin, tmax, fmin, fmax)) return;
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

void shape_hits(const Box& b, const LocalRay& r, ShapeHits& out) {
    // The box works along the untouched direction: its crossings are world distances.
    Crossings cs;
    intersect_box_pov(b, r.origin, r.direction, cs);
    for (int i = 0; i < cs.n; ++i)
        out.push_back({cs.c[i].t, r.origin + r.direction * cs.c[i].t, cs.c[i].face});
}

Vector3 shape_normal(const Box& b, const ShapeHit& h) { return box_normal(b, h.face); }

bool shape_inside(const Box& b, const Point3& p) { return inside_box(b, p); }

Bounds3 shape_bounds(const Box& b) {
    return {min(b.corner1, b.corner2), max(b.corner1, b.corner2)};
}

PovBBox shape_pov_bbox(const Box& b, const CompactTransform& xf) {
    return pov_transformed_bbox(shape_bounds(b), xf);
}

bool shape_oracle_first(const Box& s, const OracleRay& r, OracleBest& best) {
    const HP eps = kPovEpsilon;
    Point3 lo = min(s.corner1, s.corner2), hi = max(s.corner1, s.corner2);
    HP tmin = -std::numeric_limits<HP>::infinity(), tmax = -tmin;
    for (int a = 0; a < 3; ++a) {
        HP oa = r.o[a], da = r.d[a];
        if (abs(da) < eps) {
            if (oa < lo[a] || oa > hi[a]) return true;
            continue;
        }
        HP t1 = (lo[a] - oa) / da, t2 = (hi[a] - oa) / da;
        if (t1 > t2) std::swap(t1, t2);
        tmin = std::max(tmin, t1);
        tmax = std::min(tmax, t2);
        if (tmin > tmax) return true;
    }
    best.offer(tmin, kBoxTolerance);
    best.offer(tmax, kBoxTolerance);
    return true;
}

}  // namespace povwall::trace
