#include "trace/oracle.h"

#include <iterator>
#include <variant>

#include "trace/prepared_scene.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

// The inverse of the object's forward matrix, in 50 digits (not the double inverse the
// tracer uses), so near-singular transforms show up as errors of the fast path.
OracleRay to_object(const Transform& xf, const Ray& ray) {
    const Matrix34& f = xf.forward();
    HP m[3][3], t[3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[r][c] = f.m[r][c];
        t[r] = f.m[r][3];
    }
    HP det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    HP inv[3][3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            inv[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
        }
    }
    V3 po(ray.origin), pd(ray.direction);
    HP rel[3] = {po.x - t[0], po.y - t[1], po.z - t[2]};
    V3 o, d;
    HP* oo[3] = {&o.x, &o.y, &o.z};
    HP* dd[3] = {&d.x, &d.y, &d.z};
    for (int r = 0; r < 3; ++r) {
        *oo[r] = inv[r][0] * rel[0] + inv[r][1] * rel[1] + inv[r][2] * rel[2];
        *dd[r] = inv[r][0] * pd.x + inv[r][1] * pd.y + inv[r][2] * pd.z;
    }
    HP len = sqrt(dot(d, d));
    HP wlen = sqrt(dot(pd, pd));
    return {o, d * (HP(1) / len), wlen / len};
}

// Where the ray enters an object's world bounds (t_min if it starts inside), +inf if it
// misses them; generous by 1e-9 relative so rounding never hides an object.
Real bounds_entry(const Object& o, const Ray& ray, Real t_min) {
    const Bounds3 b = object_world_bounds(o);
    Real t0 = t_min, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        const Real pad = 1e-9 * (std::fabs(b.lo[a]) + std::fabs(b.hi[a]) + 1);
        const Real lo = b.lo[a] - pad, hi = b.hi[a] + pad;
        if (ray.direction[a] == 0) {
            if (ray.origin[a] < lo || ray.origin[a] > hi) return kInfinity;
            continue;
        }
        Real ta = (lo - ray.origin[a]) / ray.direction[a];
        Real tb = (hi - ray.origin[a]) / ray.direction[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return kInfinity;
    }
    return t0;
}

// An object the oracle cannot evaluate only makes the ray unsupported if the ray reaches
// its bounds before the oracle's first hit. `frame`: o is one of POV-Ray's frame objects,
// whose no_image a camera ray tests (a union it keeps whole does not test its
// children's on camera rays, ray_use.h).
void object_first(const Object& o, const Ray& ray, Real t_min, OracleHit& out,
                  Real& unsupported_from, bool frame = true) {
    if (frame && o.no_image) return;
    auto give_up = [&] {
        unsupported_from = std::min(unsupported_from, bounds_entry(o, ray, t_min));
    };
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        if (csg->kind != CsgKind::Union || o.inverse || !o.clipped_by.empty()) {
            give_up();
            return;
        }
        for (const Object& c : csg->children)
            object_first(c, ray, t_min, out, unsupported_from,
                         frame && pov_splits_union(o));
        return;
    }
    if (o.inverse || !o.clipped_by.empty()) {
        give_up();
        return;
    }
    OracleRay r = to_object(o.transform, ray);
    OracleBest best;
    best.floor = HP(t_min) / r.world_per_object;
    if (!leaf_oracle_first(o, r, best)) {
        give_up();
        return;
    }
    if (!isfinite(best.t)) return;
    HP tw = best.t * r.world_per_object;
    Real t = static_cast<Real>(tw);
    if (t < out.t) {
        out.t = t;
        out.hit = true;
        out.leaf = &o;
    }
}

}  // namespace

std::string shape_kind_name(const Object& leaf) {
    static const char* names[] = {"sphere",     "box",           "plane",
                                  "cylinder",   "cone",          "torus",
                                  "disc",       "triangle",      "smooth_triangle",
                                  "polygon",    "mesh",          "superellipsoid",
                                  "ovus",       "sor",           "lathe",
                                  "prism",      "bicubic_patch", "julia_fractal",
                                  "glyph",      "height_field",  "sphere_sweep",
                                  "poly",       "quadric",       "blob",
                                  "isosurface", "parametric",    "csg"};
    static_assert(std::variant_size_v<ShapeData> == std::size(names),
                  "one name per shape alternative");
    return names[leaf.shape.index()];
}

OracleHit oracle_first_hit(const Scene& scene, const Ray& ray, Real t_min) {
    OracleHit out;
    Real unsupported_from = kInfinity;
    for (const Object& o : scene.objects)
        object_first(o, ray, std::max(t_min, kMinIsectDepth), out, unsupported_from);
    if (unsupported_from < kInfinity && unsupported_from <= out.t) out.supported = false;
    return out;
}

int oracle_quartic_roots(const Real c[5], Real lo, Real hi, Real roots[4]) {
    SturmPoly<HP> p;
    p.degree = 4;
    for (int i = 0; i < 5; ++i) p.c[i] = HP(c[i]) / HP(c[4]);
    HP r[4];
    int n = sturm_real_roots(p, HP(lo), HP(hi), r, 4);
    for (int i = 0; i < n; ++i) roots[i] = static_cast<Real>(r[i]);
    return n;
}

}  // namespace povwall::trace
