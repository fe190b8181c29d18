#include "trace/shapes/mesh.h"

#include <algorithm>
#include <vector>

#include "trace/shapes/oracle_math.h"
#include "trace/shapes/triangle.h"

namespace povwall::trace {

void mesh_face_corners(const Mesh& m, const Mesh::Face& f, Point3 (&p)[3]) {
    for (int k = 0; k < 3; ++k) p[k] = single_precision(m.vertices[f.v[k]]);
}

namespace {
bool has_inside(const Mesh& m) {
    return m.inside_vector && dot(*m.inside_vector, *m.inside_vector) != 0;
}

// A face's crossing: its distance along the mesh's unit ray, and where its box starts.
struct FaceCrossing {
    Real box_entry;
    Real t;
    int face;
};

// POV-Ray walks a mesh's box tree nearest box first and, for a mesh without
// inside_vector, stops at the first box that starts beyond the last hit it kept
// (Mesh::intersect_bbox_tree): the triangles behind are never tested, and a CSG that
// drops the nearest hit sees nothing of them. A box never starts after the boxes inside
// it, so the walk meets the triangles in the order their own boxes start (each the float
// box of its corners, as the tree's Check_And_Enqueue tests it) and only the crossed
// ones change where it stops: the kept hits follow from the crossings alone. A ray
// POV-Ray restarted (a shadow ray past a see-through surface) walks from there.
void nearest_walk_hits(const Mesh& m, const LocalRay& r, const Vector3& unit,
                       const ShapeClip* clip, ShapeHits& out) {
    thread_local std::vector<FaceCrossing> crossed;
    crossed.clear();
    const PovRay box_ray(r.origin, unit);
    for (size_t i = 0; i < m.faces.size(); ++i) {
        Point3 p[3];
        mesh_face_corners(m, m.faces[i], p);
        Crossings cs;
        intersect_triangle(p, r.origin, unit, cs);
        // Behind where POV-Ray's ray starts: not met (the boxes' order is the same
        // from there).
        if (!cs.n || !(cs.c[0].t / r.length > r.restart)) continue;
        Bounds3 box;
        for (const Point3& q : p) box.extend(q);
        Real entry = 0;
        // A box the float test misses is never entered, as in POV-Ray.
        if (!slab_tree_entry(pov_bbox(box), box_ray, entry)) continue;
        crossed.push_back({entry, cs.c[0].t, int(i)});
    }
    std::stable_sort(crossed.begin(), crossed.end(),
                     [](const FaceCrossing& a, const FaceCrossing& b) {
                         return a.box_entry < b.box_entry;
                     });
    Real last_kept = kInfinity;
    for (const FaceCrossing& c : crossed) {
        if (c.box_entry > last_kept) break;
        const Real world_t = c.t / r.length;
        if (clip && !clip->keeps(clip->context, world_t)) continue;
        out.push_back({world_t, r.origin + unit * c.t, c.face});
        last_kept = c.t;
    }
}
}  // namespace

bool mesh_stops_at_nearest(const Mesh& m) { return m.hierarchy && !has_inside(m); }

void shape_hits(const Mesh& m, const LocalRay& r, const ShapeClip* clip, ShapeHits& out) {
    // Divided (not multiplied by the reciprocal) as meshes in CSG always were.
    const Vector3 dn = r.direction / r.length;
    if (mesh_stops_at_nearest(m)) return nearest_walk_hits(m, r, dn, clip, out);
    for (size_t i = 0; i < m.faces.size(); ++i) {
        Point3 p[3];
        mesh_face_corners(m, m.faces[i], p);
        Crossings cs;
        intersect_triangle(p, r.origin, dn, cs);
        if (cs.n && (!clip || clip->keeps(clip->context, cs.c[0].t / r.length)))
            out.push_back({cs.c[0].t / r.length, r.origin + dn * cs.c[0].t, int(i)});
    }
}

void shape_hits(const Mesh& m, const LocalRay& r, ShapeHits& out) {
    shape_hits(m, r, nullptr, out);
}

Vector3 shape_normal(const Mesh& m, const ShapeHit& h) {
    const Mesh::Face& f = m.faces[size_t(h.face)];
    Point3 p[3];
    mesh_face_corners(m, f, p);
    if (f.n[0] < 0 || f.n[1] < 0 || f.n[2] < 0) return pov_triangle_normal(p);
    // A smooth face (in CSG or clipped, as outside them): its unit vertex normals
    // interpolated at the hit, in the mesh's own space as POV-Ray's.
    Vector3 n[3];
    for (int k = 0; k < 3; ++k) n[k] = normalize(m.normals[size_t(f.n[k])]);
    return normalize(smooth_triangle_normal(p, n, h.p));
}

// POV-Ray's Mesh::Inside answers false for a mesh without inside_vector before it looks
// at the inverted flag: such a mesh holds nothing, inverted or not.
bool shape_inside_inverted(const Mesh& m, const Point3& q) {
    return has_inside(m) && !shape_inside(m, q);
}

bool shape_inside(const Mesh& m, const Point3& q) {
    if (!has_inside(m)) return false;
    const Vector3 dir = normalize(*m.inside_vector);
    int crossed = 0;
    for (const auto& f : m.faces) {
        Point3 p[3];
        mesh_face_corners(m, f, p);
        Crossings cs;
        intersect_triangle(p, q, dir, cs);
        crossed += cs.n;
    }
    return crossed % 2 == 1;
}

Bounds3 shape_bounds(const Mesh& m) {
    Bounds3 b;
    for (const auto& p : m.vertices) b.extend(p);
    return b;
}

PovBBox shape_pov_bbox(const Mesh& m, const CompactTransform& xf) {
    // Vertices are single precision; the box of the mesh's own space goes through the
    // transform.
    Bounds3 b;
    for (const Point3& p : m.vertices) b.extend(single_precision(p));
    if (b.empty()) return pov_infinite_bbox();
    return pov_transformed_bbox(b, xf);
}

bool shape_oracle_first(const Mesh& m, const OracleRay& r, OracleBest& best) {
    for (const auto& f : m.faces) {
        Point3 p[3];
        mesh_face_corners(m, f, p);
        V3 q[3] = {V3(p[0]), V3(p[1]), V3(p[2])};
        oracle_triangle(q, r, best);
    }
    return true;
}

}  // namespace povwall::trace
