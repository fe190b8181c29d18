#include "core/bicubic_patch.h"

#include <cmath>

namespace povwall {
namespace {

constexpr Real kBezierEpsilon = 1e-10;  // BEZIER_EPSILON

using Quad = std::array<Point3, 16>;

// De Casteljau at 1/2 of the row a, b, c, d (exact halves, as POV-Ray's).
void split_row(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               Point3 lo[4], Point3 hi[4]) {
    const Point3 h01 = (a + b) * 0.5, h12 = (b + c) * 0.5, h23 = (c + d) * 0.5;
    const Point3 l2 = (h01 + h12) * 0.5, r1 = (h12 + h23) * 0.5;
    const Point3 m = (l2 + r1) * 0.5;
    lo[0] = a;
    lo[1] = h01;
    lo[2] = l2;
    lo[3] = m;
    hi[0] = m;
    hi[1] = r1;
    hi[2] = h23;
    hi[3] = d;
}

// Halves in u (along the first index) or in v (along the second).
void split(const Quad& q, bool along_u, Quad& lo, Quad& hi) {
    for (int k = 0; k < 4; ++k) {
        auto at = [&](int n) -> const Point3& {
            return along_u ? q[4 * n + k] : q[4 * k + n];
        };
        Point3 l[4], h[4];
        split_row(at(0), at(1), at(2), at(3), l, h);
        for (int n = 0; n < 4; ++n) {
            (along_u ? lo[4 * n + k] : lo[4 * k + n]) = l[n];
            (along_u ? hi[4 * n + k] : hi[4 * k + n]) = h[n];
        }
    }
}

// The largest distance of a control point from the plane of three corners; -1 when the
// corners give no plane.
Real flatness_of(const Quad& q) {
    Point3 a, b, c;
    if (length(q[0] - q[3]) < kBezierEpsilon) {
        if (length(q[0] - q[15]) < kBezierEpsilon ||
            length(q[15] - q[12]) < kBezierEpsilon)
            return -1;
        a = q[0];
        b = q[15];
        c = q[12];
    } else {
        if (length(q[3] - q[12]) < kBezierEpsilon) return -1;
        a = q[0];
        b = q[3];
        c = q[12];
    }
    const Vector3 v1 = a - b, v2 = c - b;
    Vector3 n = cross(v1, v2);
    if (dot(n, n) <= kBezierEpsilon * dot(v1, v1) * dot(v2, v2)) return -1;
    n = n / length(n);
    const Real d = -dot(n, a);
    Real worst = 0;
    for (const Point3& p : q) worst = std::max(worst, std::fabs(dot(n, p) + d));
    return worst;
}

BicubicPatchData::Triangle make_triangle(const BicubicPatchData& d, const Point3 (&v)[3],
                                         const Real (&u)[3], const Real (&w)[3]) {
    BicubicPatchData::Triangle t;
    t.v0 = v[0];
    for (int k = 0; k < 3; ++k) {
        t.u[k] = u[k];
        t.v[k] = w[k];
        t.normal[k] = patch_normal(d, u[k], w[k]);
    }
    const Vector3 b0 = v[1] - v[0], b1 = v[2] - v[0];
    Vector3 n = cross(b0, b1);
    if (dot(n, n) <= kBezierEpsilon * dot(b0, b0) * dot(b1, b1)) return t;
    n = n / length(n);
    const Real det = dot(b0, cross(b1, n));
    if (std::fabs(det) < kBezierEpsilon) return t;
    t.e0 = cross(b1, n) / det;
    t.e1 = cross(n, b0) / det;
    t.e2 = cross(b0, b1) / det;
    t.valid = true;
    return t;
}

struct Builder {
    BicubicPatchData& d;

    uint32_t build(const Quad& q, int depth, Real u0, Real u1, Real v0, Real v1) {
        const uint32_t index = uint32_t(d.nodes.size());
        d.nodes.emplace_back();
        Point3 centre{0, 0, 0};
        for (const Point3& p : q) centre = centre + p;
        centre = centre / 16.0;
        Real r2 = 0;
        for (const Point3& p : q) r2 = std::max(r2, dot(p - centre, p - centre));
        d.nodes[index].centre = centre;
        d.nodes[index].radius2 = r2;
        const Real f = flatness_of(q);
        const bool flat = f >= 0 && f < d.flatness;
        const bool split_u = depth < d.u_steps, split_v = depth < d.v_steps;
        if (flat || (!split_u && !split_v)) {
            const Point3 t1[3] = {q[0], q[3], q[15]}, t2[3] = {q[0], q[15], q[12]};
            const Real u1s[3] = {u0, u0, u1}, v1s[3] = {v0, v1, v1};
            const Real u2s[3] = {u0, u1, u1}, v2s[3] = {v0, v1, v0};
            d.nodes[index].leaf = int32_t(d.leaves.size());
            d.leaves.push_back(
                {make_triangle(d, t1, u1s, v1s), make_triangle(d, t2, u2s, v2s)});
            return index;
        }
        const Real um = (u0 + u1) / 2, vm = (v0 + v1) / 2;
        uint32_t children[4];
        int n = 0;
        if (!split_u) {  // v only
            Quad lo, hi;
            split(q, false, lo, hi);
            children[n++] = build(lo, depth + 1, u0, u1, v0, vm);
            children[n++] = build(hi, depth + 1, u0, u1, vm, v1);
        } else if (!split_v) {  // u only
            Quad lo, hi;
            split(q, true, lo, hi);
            children[n++] = build(lo, depth + 1, u0, um, v0, v1);
            children[n++] = build(hi, depth + 1, um, u1, v0, v1);
        } else {
            Quad ulo, uhi, a, b;
            split(q, true, ulo, uhi);
            split(ulo, false, a, b);
            children[n++] = build(a, depth + 1, u0, um, v0, vm);
            children[n++] = build(b, depth + 1, u0, um, vm, v1);
            split(uhi, false, a, b);
            children[n++] = build(a, depth + 1, um, u1, v0, vm);
            children[n++] = build(b, depth + 1, um, u1, vm, v1);
        }
        d.nodes[index].child_count = uint8_t(n);
        for (int k = 0; k < n; ++k) d.nodes[index].child[k] = children[k];
        return index;
    }
};

// Bernstein weights of degree 3 and their derivatives at t.
void bernstein(Real t, Real b[4], Real db[4]) {
    const Real s = 1 - t;
    b[0] = s * s * s;
    b[1] = 3 * t * s * s;
    b[2] = 3 * t * t * s;
    b[3] = t * t * t;
    db[0] = -3 * s * s;
    db[1] = 3 * (s * s - 2 * t * s);
    db[2] = 3 * (2 * t * s - t * t);
    db[3] = 3 * t * t;
}

}  // namespace

Vector3 patch_normal(const BicubicPatchData& d, Real u, Real v) {
    Real bu[4], dbu[4], bv[4], dbv[4];
    bernstein(u, bu, dbu);
    bernstein(v, bv, dbv);
    Vector3 pu{0, 0, 0}, pv{0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Point3& p = d.control[size_t(4 * i + j)];
            pu = pu + p * (dbu[i] * bv[j]);
            pv = pv + p * (bu[i] * dbv[j]);
        }
    }
    const Vector3 n = cross(pu, pv);
    if (dot(n, n) > kBezierEpsilon * dot(pu, pu) * dot(pv, pv)) return n / length(n);
    return {1, 0, 0};
}

void build_patch_pieces(BicubicPatchData& d) {
    d.nodes.clear();
    d.leaves.clear();
    Builder{d}.build(d.control, 0, 0, 1, 0, 1);
}

}  // namespace povwall
