// Each shape's surface coordinates, read from POV-Ray 3.7's UVCoord methods (spheres.cpp,
// boxes.cpp, torus.cpp, lathe.cpp, sor.cpp, ovus.cpp, bezier.cpp, mesh.cpp and the
// default in objects.cpp) for their semantics; an independent implementation.
#include "trace/uv_mapping.h"

#include <cmath>

#include "core/math_constants.h"
#include "trace/pattern_internal.h"
#include "trace/shapes/common.h"
#include "trace/shapes/sor.h"

namespace povwall::trace {
namespace {

// The turn from +x towards +z of (x, z) as a fraction in [0, 1); 0 on the y axis.
Real turn_about_y(Real x, Real z) {
    const Real len2 = x * x + z * z;
    if (!(len2 > kPovEpsilon)) return 0;
    Real theta;
    if (z == 0.0) {
        theta = x > 0 ? 0.0 : kPi;
    } else {
        theta = std::acos(x / std::sqrt(len2));
        if (z < 0.0) theta = 2 * kPi - theta;
    }
    return theta / (2 * kPi);
}

// Longitude and latitude of direction d (a sphere's and an ovus's mapping).
Point3 longitude_latitude(Vector3 d) {
    const Real len = length(d);
    if (len == 0.0) return {0, 0, 0};  // POV-Ray leaves the result unset here
    d = d / len;
    return {turn_about_y(d.x, d.z), 0.5 + std::asin(d.y) / kPi, 0};
}

// A box keeps no matrix while it is only moved and scaled (the parser moves its corners
// as POV-Ray does): its mapping works in world space then, else in the box's own.
Point3 box_uv(const Box& b, const Object& o, const Hit& hit) {
    const Point3 c1 = b.corner1, c2 = b.corner2;
    Point3 p =
        o.transform.is_identity() ? hit.point : o.transform.inverse_point(hit.point);
    const int face = hit.face;
    const Point3 lo = min(c1, c2), hi = max(c1, c2);
    for (int a = 0; a < 3; ++a) p[a] = (p[a] - lo[a]) / (hi[a] - lo[a]);
    // A cube unfolded into a 4 x 3 grid, no face mirrored seen from outside.
    switch (face) {
        case 0:  // -x
            return {p.z / 4.0, 1.0 / 3.0 + p.y / 3.0, 0};
        case 1:  // +x
            return {3.0 / 4.0 - p.z / 4.0, 1.0 / 3.0 + p.y / 3.0, 0};
        case 2:  // -y
            return {1.0 / 4.0 + p.x / 4.0, p.z / 3.0, 0};
        case 3:  // +y
            return {1.0 / 4.0 + p.x / 4.0, 3.0 / 3.0 - p.z / 3.0, 0};
        case 4:  // -z
            return {1.0 - p.x / 4.0, 1.0 / 3.0 + p.y / 3.0, 0};
        default:  // +z
            return {1.0 / 4.0 + p.x / 4.0, 1.0 / 3.0 + p.y / 3.0, 0};
    }
}

Point3 torus_uv(const Torus& t, const Point3& p) {
    const Real u = 1.0 - (std::atan2(p.z, p.x) + kPi) / (2 * kPi);
    const Real ring = std::sqrt(p.x * p.x + p.z * p.z) - t.major;
    const Real v = (std::atan2(p.y, ring) + kPi) / (2 * kPi);
    return {u, v, 0};
}

Point3 lathe_uv(const Lathe& l, const Point3& p, const Hit& hit) {
    const Real segments = Real(l.spline->segments.size());
    const Real v = std::min(1.0, (hit.param + Real(hit.face)) / segments);
    return {turn_about_y(p.x, p.z), v, 0};
}

Point3 sor_uv(const Sor& s, const Point3& p, const Hit& hit) {
    const SorSpline& sp = *s.spline;
    const Real radius = std::sqrt(p.x * p.x + p.z * p.z);
    Real v;
    if (hit.face == kSorBase) {  // base cap: 0 at the rim, -1 on the axis
        v = radius / std::sqrt(sp.base_radius2) - 1;
    } else if (hit.face == kSorCap) {  // top cap: 1 at the rim, 2 on the axis
        v = -radius / std::sqrt(sp.cap_radius2) + 2;
    } else {
        const BoundingCylinders::Segment& bc = sp.cylinders.segments[size_t(hit.face)];
        const Real h1 = sp.cylinders.heights[bc.h1], h2 = sp.cylinders.heights[bc.h2];
        const Real per_segment = 1.0 / Real(sp.segments.size());
        v = (p.y - h1) / (h2 - h1) * per_segment + Real(hit.face) * per_segment;
    }
    return {turn_about_y(p.x, p.z), v, 0};
}

Point3 patch_uv(const BicubicPatch& b, const Hit& hit) {
    const BicubicPatchData& d = *b.data;
    const auto& t = d.leaves[size_t(hit.face / 2)][size_t(hit.face % 2)];
    const Real a = hit.param, c = hit.param2, r = 1 - a - c;
    const Real u = r * t.u[0] + a * t.u[1] + c * t.u[2];
    const Real v = r * t.v[0] + a * t.v[1] + c * t.v[2];
    // Bilinear in the corners' uv_vectors: v along the first edge, u across.
    const auto& st = d.uv_vectors;
    Real lo[2], hi[2];
    for (int k = 0; k < 2; ++k) {
        lo[k] = st[0][k] + v * (st[1][k] - st[0][k]);
        hi[k] = st[3][k] + v * (st[2][k] - st[3][k]);
    }
    return {lo[0] + u * (hi[0] - lo[0]), lo[1] + u * (hi[1] - lo[1]), 0};
}

// The weight of corner a at p: 1 at a, 0 on the side b-c (POV-Ray's projection).
Real corner_weight(const Point3& a, const Point3& b, const Point3& c, const Point3& p) {
    const Vector3 opposite = c - b, adjacent = c - a;
    const Vector3 toward =
        opposite * (dot(adjacent, opposite) / dot(opposite, opposite)) - adjacent;
    return 1 + dot(p - a, toward) / dot(toward, toward);
}

Point3 mesh_uv(const Mesh& m, const Object& o, const Hit& hit) {
    if (m->uv_faces.empty() || size_t(hit.face) >= m->uv_faces.size()) return {0, 0, 0};
    const Mesh::Face& f = m->faces[size_t(hit.face)];
    const Point3 p =
        o.transform.is_identity() ? hit.point : o.transform.inverse_point(hit.point);
    const Point3 v1 = single_precision(m->vertices[f.v[0]]),
                 v2 = single_precision(m->vertices[f.v[1]]),
                 v3 = single_precision(m->vertices[f.v[2]]);
    const Real w[3] = {corner_weight(v1, v2, v3, p), corner_weight(v2, v1, v3, p),
                       corner_weight(v3, v1, v2, p)};
    const auto& idx = m->uv_faces[size_t(hit.face)];
    Point3 uv{0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        uv.x += w[k] * m->uvs[idx[size_t(k)]][0];
        uv.y += w[k] * m->uvs[idx[size_t(k)]][1];
    }
    return uv;
}

}  // namespace

Point3 surface_uv(const Hit& hit) {
    const Object* o = hit.material ? hit.material->object : nullptr;
    if (!o) return {hit.point.x, hit.point.y, 0};
    auto local = [&] {
        return o->transform.is_identity() ? hit.point
                                          : o->transform.inverse_point(hit.point);
    };
    if (const Sphere* s = std::get_if<Sphere>(&o->shape))
        return longitude_latitude(local() - s->centre);
    if (const Box* b = std::get_if<Box>(&o->shape)) return box_uv(*b, *o, hit);
    if (const Torus* t = std::get_if<Torus>(&o->shape)) return torus_uv(*t, local());
    if (const Lathe* l = std::get_if<Lathe>(&o->shape)) return lathe_uv(*l, local(), hit);
    if (const Sor* s = std::get_if<Sor>(&o->shape)) return sor_uv(*s, local(), hit);
    if (const Ovus* v = std::get_if<Ovus>(&o->shape)) {
        const Point3 p = local();
        return longitude_latitude({p.x, p.y - v->top_radius / 2.0, p.z});
    }
    if (const BicubicPatch* b = std::get_if<BicubicPatch>(&o->shape))
        return patch_uv(*b, hit);
    if (const Mesh* m = std::get_if<Mesh>(&o->shape)) return mesh_uv(*m, *o, hit);
    // A parametric's hit keeps the (u, v) of the piece it was found in.
    if (std::holds_alternative<Parametric>(o->shape)) return {hit.param, hit.param2, 0};
    // Shapes without coordinates of their own: the world point's x and y.
    return {hit.point.x, hit.point.y, 0};
}

}  // namespace povwall::trace

namespace povwall::trace::detail {

Point3 uv_of(const PatternEnv& env) {
    return env.surface && env.surface->hit ? surface_uv(*env.surface->hit)
                                           : Point3{0, 0, 0};
}

}  // namespace povwall::trace::detail
