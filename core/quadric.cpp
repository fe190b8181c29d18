#include "core/quadric.h"

#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "core/quadric_bounds.h"

namespace povwall {
namespace {

constexpr Real kHalfHuge = 1e10;  // BOUND_HUGE / 2
constexpr Real kCriticalLength = 1e6;

// Make_BBox_from_min_max: the corner and the lengths (subtracted in double) in float.
void store_box(Quadric& q, const Vector3& lo, const Vector3& hi) {
    for (int a = 0; a < 3; ++a) {
        q.box_lo[a] = float(lo[a]);
        q.box_len[a] = float(hi[a] - lo[a]);
    }
}

void store_infinite_box(Quadric& q) {
    for (int a = 0; a < 3; ++a) {
        q.box_lo[a] = float(-kHalfHuge);
        q.box_len[a] = float(2 * kHalfHuge);
    }
}

// BOUNDS_VOLUME: the float lengths multiplied in float.
float box_volume(const Quadric& q) { return q.box_len[0] * q.box_len[1] * q.box_len[2]; }

}  // namespace

void quadric_transform(Quadric& q, const Transform& t) {
    // POV-Ray's row-vector 4x4 inverse: a point is [x y z 1], the image p Mi.
    const Matrix34& inv = t.inverse_matrix();
    Real mi[4][4];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) mi[r][c] = inv.m[c][r];
        mi[r][3] = 0;
    }
    for (int c = 0; c < 3; ++c) mi[3][c] = inv.m[c][3];
    mi[3][3] = 1;
    // Q(p) = p U p^T with U upper triangular.
    const Real u[4][4] = {{q.square.x, q.mixed.x, q.mixed.y, q.linear.x},
                          {0, q.square.y, q.mixed.z, q.linear.y},
                          {0, 0, q.square.z, q.linear.z},
                          {0, 0, 0, q.constant}};
    Real v[4][4], w[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            v[r][c] = mi[r][0] * u[0][c] + mi[r][1] * u[1][c] + mi[r][2] * u[2][c] +
                      mi[r][3] * u[3][c];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            w[r][c] = v[r][0] * mi[c][0] + v[r][1] * mi[c][1] + v[r][2] * mi[c][2] +
                      v[r][3] * mi[c][3];
    q.square = {w[0][0], w[1][1], w[2][2]};
    q.mixed = {w[0][1] + w[1][0], w[0][2] + w[2][0], w[1][2] + w[2][1]};
    q.linear = {w[0][3] + w[3][0], w[1][3] + w[3][1], w[2][3] + w[3][2]};
    q.constant = w[3][3];
    // Recompute_BBox: the box's corners through the transform, clamped to +-1e10.
    Vector3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (int corner = 0; corner < 8; ++corner) {
        Point3 p;
        for (int a = 0; a < 3; ++a)
            p[a] = Real(q.box_lo[a]) + ((corner >> a) & 1 ? Real(q.box_len[a]) : 0.0);
        const Point3 m = t.point(p);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], m[a]);
            hi[a] = std::max(hi[a], m[a]);
        }
    }
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::max(lo[a], -kHalfHuge);
        hi[a] = std::min(hi[a], kHalfHuge);
    }
    store_box(q, lo, hi);
}

void quadric_compute_bbox(Quadric& q, const Vector3& clip_min, const Vector3& clip_max) {
    Vector3 cmin = clip_min, cmax = clip_max;
    auto snap = [](Real x) { return std::fabs(x) < kPovEpsilon ? 0.0 : x; };
    Real sa = snap(q.square.x), sb = snap(q.square.y), sc = snap(q.square.z);
    const Real hxy = snap(q.mixed.x / 2), hxz = snap(q.mixed.y / 2),
               hyz = snap(q.mixed.z / 2);
    Real gx = snap(q.linear.x / 2), gy = snap(q.linear.y / 2), gz = snap(q.linear.z / 2);
    Real k = snap(q.constant);
    const float old_volume = box_volume(q);
    if (hxy != 0 || hxz != 0 || hyz != 0) {
        // Mixed terms: only the clip range, when smaller.
        const Real vol = (cmax.x - cmin.x) * (cmax.y - cmin.y) * (cmax.z - cmin.z);
        if (vol < old_volume) store_box(q, cmin, cmax);
        return;
    }
    // The "centre" (POV-Ray's paraboloid centre has the wrong sign: its bug 1).
    Vector3 t{0, 0, 0};
    if (gx != 0 || gy != 0 || gz != 0) {
        auto centre = [&](Real s, Real g) {
            if (s != 0) return -g / s;
            if (g != 0) return k / (2 * g);
            return 0.0;
        };
        t = {centre(sa, gx), centre(sb, gy), centre(sc, gz)};
        gx += sa * t.x;
        gy += sb * t.y;
        gz += sc * t.z;
        k -= t.x * (sa * t.x + 2 * gx) + t.y * (sb * t.y + 2 * gy) +
             t.z * (sc * t.z + 2 * gz);
    }
    Vector3 nmin(-kHalfHuge), nmax(kHalfHuge);
    cmin = cmin - t;
    cmax = cmax - t;
    if (sa < 0) {
        sa = -sa, gx = -gx, sb = -sb, gy = -gy, sc = -sc, gz = -gz, k = -k;
    }
    const Real lo_x = cmin.x, hi_x = cmax.x, lo_y = cmin.y, hi_y = cmax.y, lo_z = cmin.z,
               hi_z = cmax.z;
    if (sa > 0 && sb > 0 && sc > 0 && k < 0) {  // ellipsoid
        const Real rx = std::sqrt(-k / sa), ry = std::sqrt(-k / sb),
                   rz = std::sqrt(-k / sc);
        nmin = {-rx, -ry, -rz};
        nmax = {rx, ry, rz};
    }
    if (sa == 0 && sb > 0 && sc > 0 && k < 0) {  // cylinder along x
        const Real ry = std::sqrt(-k / sb), rz = std::sqrt(-k / sc);
        nmin.y = -ry, nmax.y = ry, nmin.z = -rz, nmax.z = rz;
    }
    if (sa > 0 && sb == 0 && sc > 0 && k < 0) {  // cylinder along y
        const Real rx = std::sqrt(-k / sa), rz = std::sqrt(-k / sc);
        nmin.x = -rx, nmax.x = rx, nmin.z = -rz, nmax.z = rz;
    }
    if (sa > 0 && sb > 0 && sc == 0 && k < 0) {  // cylinder along z
        const Real rx = std::sqrt(-k / sa), ry = std::sqrt(-k / sb);
        nmin.x = -rx, nmax.x = rx, nmin.y = -ry, nmax.y = ry;
    }
    // Cones: the widest cross-section at the ends of the clip range along the axis.
    auto widest = [](Real lo, Real hi, Real num, Real den) {
        return std::max(std::fabs(lo * num / den), std::fabs(hi * num / den));
    };
    if (sa > 0 && sb < 0 && sc < 0 && k == 0) {  // cone along x
        const Real a = std::sqrt(1 / sa), b = std::sqrt(-1 / sb), c = std::sqrt(-1 / sc);
        const Real ry = widest(lo_x, hi_x, b, a), rz = widest(lo_x, hi_x, c, a);
        nmin.y = -ry, nmax.y = ry, nmin.z = -rz, nmax.z = rz;
    }
    if (sa > 0 && sb < 0 && sc > 0 && k == 0) {  // cone along y
        const Real a = std::sqrt(1 / sa), b = std::sqrt(-1 / sb), c = std::sqrt(1 / sc);
        const Real rx = widest(lo_y, hi_y, a, b), rz = widest(lo_y, hi_y, c, b);
        nmin.x = -rx, nmax.x = rx, nmin.z = -rz, nmax.z = rz;
    }
    if (sa > 0 && sb > 0 && sc < 0 && k == 0) {  // cone along z
        const Real a = std::sqrt(1 / sa), b = std::sqrt(1 / sb), c = std::sqrt(-1 / sc);
        const Real rx = widest(lo_z, hi_z, a, c), ry = widest(lo_z, hi_z, b, c);
        nmin.x = -rx, nmax.x = rx, nmin.y = -ry, nmax.y = ry;
    }
    // Hyperboloids: POV-Ray's radius assumes |J| = 1 (its bug 2).
    if (sa > 0 && sb < 0 && sc < 0 && k > 0) {  // along x
        Real ry = 0, rz = 0;
        for (Real x : {lo_x, hi_x}) {
            const Real d = 1 + sa * (x * x);
            ry = std::max(ry, std::sqrt(-d / sb));
            rz = std::max(rz, std::sqrt(-d / sc));
        }
        nmin.y = -ry, nmax.y = ry, nmin.z = -rz, nmax.z = rz;
    }
    if (sa > 0 && sb < 0 && sc > 0 && k < 0) {  // along y
        Real rx = 0, rz = 0;
        for (Real y : {lo_y, hi_y}) {
            const Real d = 1 - sb * (y * y);
            rx = std::max(rx, std::sqrt(d / sa));
            rz = std::max(rz, std::sqrt(d / sc));
        }
        nmin.x = -rx, nmax.x = rx, nmin.z = -rz, nmax.z = rz;
    }
    if (sa > 0 && sb > 0 && sc < 0 && k < 0) {  // along z
        Real rx = 0, ry = 0;
        for (Real z : {lo_z, hi_z}) {
            const Real d = 1 - sc * (z * z);
            rx = std::max(rx, std::sqrt(d / sa));
            ry = std::max(ry, std::sqrt(d / sb));
        }
        nmin.x = -rx, nmax.x = rx, nmin.y = -ry, nmax.y = ry;
    }
    // Paraboloids: the side the surface opens to.
    auto parabola = [](Real g, Real s, Real lo, Real hi) {
        return std::max(std::sqrt(std::fabs(((2 * g) * lo) / s)),
                        std::sqrt(std::fabs(((2 * g) * hi) / s)));
    };
    if (sa == 0 && gx != 0 && sb * sc > 0 && k == 0) {  // along x
        const Real xl = gx * sb < 0 ? std::max(0.0, lo_x) : lo_x;
        const Real xh = gx * sb > 0 ? std::min(0.0, hi_x) : hi_x;
        const Real ry = parabola(gx, sb, xl, xh), rz = parabola(gx, sc, xl, xh);
        nmin.y = -ry, nmax.y = ry, nmin.z = -rz, nmax.z = rz;
        if (gx * sb < 0) nmin.x = std::max(0.0, lo_x);
        if (gx * sb > 0) nmax.x = std::min(0.0, hi_x);
    }
    if (sb == 0 && gy != 0 && sa * sc > 0 && k == 0) {  // along y
        const Real yl = gy > 0 ? lo_y : std::max(0.0, lo_y);
        const Real yh = gy < 0 ? hi_y : std::min(0.0, hi_y);
        const Real rx = parabola(gy, sa, yl, yh), rz = parabola(gy, sc, yl, yh);
        nmin.x = -rx, nmax.x = rx, nmin.z = -rz, nmax.z = rz;
        if (gy < 0) nmin.y = std::max(0.0, lo_y);
        if (gy > 0) nmax.y = std::min(0.0, hi_y);
    }
    if (sc == 0 && gz != 0 && sa * sb > 0 && k == 0) {  // along z
        const Real zl = gz < 0 ? std::max(lo_z, 0.0) : lo_z;
        const Real zh = gz > 0 ? std::min(0.0, hi_z) : hi_z;
        const Real rx = parabola(gz, sa, zl, zh), ry = parabola(gz, sb, zl, zh);
        nmin.x = -rx, nmax.x = rx, nmin.y = -ry, nmax.y = ry;
        if (gz < 0) nmin.z = std::max(lo_z, 0.0);
        if (gz > 0) nmax.z = std::min(hi_z, 0.0);
    }
    for (int a = 0; a < 3; ++a) {
        nmin[a] = std::max(nmin[a], cmin[a]);
        nmax[a] = std::min(nmax[a], cmax[a]);
    }
    const Real vol = (nmax.x - nmin.x) * (nmax.y - nmin.y) * (nmax.z - nmin.z);
    if (vol < old_volume) {
        q.automatic_bounds = true;
        store_box(q, nmin + t, nmax + t);
        for (int a = 0; a < 3; ++a) {
            if (Real(q.box_len[a]) > kCriticalLength) {
                store_infinite_box(q);
                break;
            }
        }
    }
}

namespace {

// Compute_Plane_Min_Max: an axis-aligned plane bounds its axis by its offset.
void cut_by_plane(const Object& c, const Plane& plane, Vector3& lo, Vector3& hi) {
    const Vector3 n = normalize(c.transform.normal(plane.normal));
    const Point3 on = c.transform.point(plane.normal * plane.distance);
    const Real d = dot(n, on);
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(n[(a + 1) % 3]) < kPovEpsilon &&
            std::fabs(n[(a + 2) % 3]) < kPovEpsilon) {
            if (n[a] > 0)
                hi[a] = std::min(hi[a], d);
            else
                lo[a] = std::max(lo[a], -d);
        }
    }
}

// Cuts [lo, hi] by a float box read back as POV-Ray reads it (lo, lo + len).
void cut_by_box(const float box_lo[3], const float box_len[3], Vector3& lo, Vector3& hi) {
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::max(lo[a], Real(box_lo[a]));
        hi[a] = std::min(hi[a], Real(box_lo[a]) + Real(box_len[a]));
    }
}

// Compute_BBox's step 1: the quadric's own non-inverted clips cut [lo, hi] (a plane by
// its half-space, any other object by its box). False when a clip's box is unknown.
bool cut_by_clips(const std::vector<Object>& clips, const PovBoxOf& box_of, Vector3& lo,
                  Vector3& hi) {
    for (const Object& c : clips) {
        if (c.inverse) continue;
        if (const Plane* plane = std::get_if<Plane>(&c.shape)) {
            cut_by_plane(c, *plane, lo, hi);
        } else if (const Quadric* other = std::get_if<Quadric>(&c.shape)) {
            cut_by_box(other->box_lo, other->box_len, lo, hi);
        } else if (const Box* box = std::get_if<Box>(&c.shape);
                   box && c.transform.is_identity() && c.clipped_by.empty() &&
                   c.bounded_by.empty()) {
            // An untransformed box's BBox: its corners.
            Vector3 bmin, bmax;
            for (int a = 0; a < 3; ++a) {
                bmin[a] = std::min(box->corner1[a], box->corner2[a]);
                bmax[a] = std::max(box->corner1[a], box->corner2[a]);
            }
            float blo[3], blen[3];
            for (int a = 0; a < 3; ++a) {
                blo[a] = float(bmin[a]);
                blen[a] = float(bmax[a] - bmin[a]);
            }
            cut_by_box(blo, blen, lo, hi);
        } else if (box_of) {
            const Csg::PovBox b = box_of(c);
            cut_by_box(b.lo, b.len, lo, hi);
        } else {
            return false;
        }
    }
    return true;
}

}  // namespace

bool quadric_clip_bounds(Quadric& q, const std::vector<Object>& clips) {
    return quadric_clip_bounds(q, clips, PovBoxOf{});
}

bool quadric_clip_bounds(Quadric& q, const std::vector<Object>& clips,
                         const PovBoxOf& box_of) {
    Vector3 lo(-2e10), hi(2e10);
    if (!cut_by_clips(clips, box_of, lo, hi)) return false;
    // Compute_BBox's step 1 (the clips cut the BOUND_HUGE range), then the rest.
    quadric_compute_bbox(q, lo, hi);
    return true;
}

bool quadric_csg_bounds_impl(std::vector<Object>& children,
                             const std::vector<bool>& inverted) {
    return quadric_csg_bounds_impl(children, inverted, PovBoxOf{});
}

bool quadric_csg_bounds_impl(std::vector<Object>& children,
                             const std::vector<bool>& inverted, const PovBoxOf& box_of) {
    Vector3 lo(-2e10), hi(2e10);
    for (size_t i = 0; i < children.size(); ++i) {
        const Object& c = children[i];
        if (std::holds_alternative<Quadric>(c.shape)) continue;
        if (inverted[i] || std::holds_alternative<HeightField>(c.shape)) continue;
        if (const Plane* plane = std::get_if<Plane>(&c.shape)) {
            cut_by_plane(c, *plane, lo, hi);
        } else if (box_of) {
            const Csg::PovBox b = box_of(c);
            cut_by_box(b.lo, b.len, lo, hi);
        } else {
            return false;
        }
    }
    for (size_t i = 0; i < children.size(); ++i) {
        Quadric* q = std::get_if<Quadric>(&children[i].shape);
        if (!q || inverted[i]) continue;
        // Compute_BBox(range) cuts the range by the quadric's own clips first.
        Vector3 qlo = lo, qhi = hi;
        if (!cut_by_clips(*children[i].clipped_by, box_of, qlo, qhi)) return false;
        quadric_compute_bbox(*q, qlo, qhi);
        cut_by_box(q->box_lo, q->box_len, lo, hi);
    }
    return true;
}

}  // namespace povwall
