#include "trace/shapes/sphere.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

void intersect_sphere(const Sphere& s, const Point3& o, const Vector3& dir,
                      Crossings& out) {
    Vector3 oc = s.centre - o;
    Real tca = dot(oc, dir);
    Real t2hc = s.radius * s.radius - dot(oc, oc) + tca * tca;
    // POV-Ray needs a half chord above EPSILON: tangent rays miss.
    if (!(t2hc > kPovEpsilon)) return;
    Real th = std::sqrt(t2hc);
    Real t1 = tca - th, t2 = tca + th;
    // Depths along a unit direction in the sphere's own space (an ellipsoid's), kept
    // below MAX_DISTANCE as POV-Ray's Sphere::All_Intersections keeps them.
    if (t1 > kSphereTolerance && t1 < kMaxDistance) out.add(t1, 0);
    if (t2 > kSphereTolerance && t2 < kMaxDistance) out.add(t2, 0);
}

Vector3 sphere_normal(const Sphere& s, const Point3& p) {
    return (p - s.centre) / s.radius;
}

bool inside_sphere(const Sphere& s, const Point3& p) {
    Vector3 d = p - s.centre;
    return dot(d, d) < s.radius * s.radius;
}

void shape_hits(const Sphere& s, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_sphere(s, r.origin, r.unit, cs);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Sphere& s, const ShapeHit& h) { return sphere_normal(s, h.p); }

bool shape_inside(const Sphere& s, const Point3& p) { return inside_sphere(s, p); }

// POV-Ray's inverted sphere is strictly outside: its surface is in neither.
bool shape_inside_inverted(const Sphere& s, const Point3& p) {
    Vector3 d = p - s.centre;
    return dot(d, d) > s.radius * s.radius;
}

Bounds3 shape_bounds(const Sphere& s) {
    // A negative radius is the same surface (POV-Ray squares it). POV-Ray's own box of
    // it is inverted, so its slab tree never enters it, until a transform it keeps
    // (a non-uniform scale, a matrix) turns the corners into a valid box
    // (shape_pov_bbox): the extent here is the surface's either way.
    const Vector3 r(std::fabs(s.radius));
    return {s.centre - r, s.centre + r};
}

PovBBox shape_pov_bbox(const Sphere& s, const CompactTransform& xf) {
    // Translation, rotation and uniform scaling move the centre and the radius (no
    // transform kept): the box is centre +- radius. From the first other transform on,
    // the box is the cube's then, under the transforms that followed.
    if (const SpherePovMatrix* m = s.pov_matrix.get()) {
        const Vector3 r(m->radius);
        return pov_transformed_bbox({m->centre - r, m->centre + r}, m->rest);
    }
    Real scale = 1;
    if (xf.is_identity() || is_similarity(xf, scale))
        return pov_sphere_bbox(xf.point(s.centre), s.radius * scale);
    return pov_transformed_bbox(shape_bounds(s), xf);
}

bool shape_oracle_first(const Sphere& s, const OracleRay& r, OracleBest& best) {
    V3 oc = V3(s.centre) - r.o;
    HP tca = dot(oc, r.d);
    HP t2hc = HP(s.radius) * s.radius - dot(oc, oc) + tca * tca;
    if (!(t2hc > HP(kPovEpsilon))) return true;
    HP th = sqrt(t2hc);
    for (const HP& t : {tca - th, tca + th})
        if (t < HP(kMaxDistance)) best.offer(t, kSphereTolerance);
    return true;
}

}  // namespace povwall::trace
