#include "trace/shapes/mesh.h"

#include <algorithm>
#include <vector>

#include "trace/shapes/oracle_math.h"
#include "trace/shapes/triangle.h"

namespace povwall::trace {

void mesh_face_corners(const Mesh& m, const Mesh::Face& f, Point3 (&p)[3]) {
    for (int k = 0; k < 3; ++k) p[k] = single_precision(m->vertices[f.v[k]]);
}

namespace {
bool has_inside(const Mesh& m) {
    const auto& v = m->inside_vector;
    return v && dot(*v, *v) != 0;
}

// A ray in the mesh's space against the face tree's boxes. The boxes are a face's
// corners; a crossing the triangle test finds lies on the face, so inside them up to the
// rounding of the crossing (in double), which the pad covers: a billionth of the
// magnitudes on that axis, the box's own (one far vertex must not widen every box).
struct TreeRay {
    Point3 origin;
    Vector3 dir;
    Real inv[3];

    TreeRay(const Point3& o, const Vector3& d) : origin(o), dir(d) {
        for (int a = 0; a < 3; ++a) inv[a] = 1.0 / d[a];
    }
    // Whether the ray (t >= 0) may meet the node's box, and from where.
    bool meets(const BoxTree::Node& n, Real& entry) const {
        Real lo = 0, hi = kInfinity;
        for (int a = 0; a < 3; ++a) {
            const Real pad = 1e-9 * (std::fabs(origin[a]) +
                                     std::max(std::fabs(n.lo[a]), std::fabs(n.hi[a])));
            const Real l = n.lo[a] - pad, h = n.hi[a] + pad;
            if (dir[a] == 0) {
                if (origin[a] < l || origin[a] > h) return false;
                continue;
            }
            Real t0 = (l - origin[a]) * inv[a], t1 = (h - origin[a]) * inv[a];
            if (t0 > t1) std::swap(t0, t1);
            lo = std::max(lo, t0);
            hi = std::min(hi, t1);
            if (!(lo <= hi)) return false;
        }
        entry = lo;
        return true;
    }
};

// Where the unit ray from `o` crosses face `fi` (its corners, single precision, in `p`).
bool face_crossing(const Mesh& m, uint32_t fi, const Point3& o, const Vector3& unit,
                   Point3 (&p)[3], Real& t) {
    mesh_face_corners(m, m->faces[fi], p);
    Crossings cs;
    intersect_triangle(p, o, unit, cs);
    if (!cs.n) return false;
    t = cs.c[0].t;
    return true;
}

// Walks the faces whose boxes the ray may meet, depth first, calling face(index).
template <class Face>
void walk_faces(const BoxTree& tree, const TreeRay& ray, Face&& face) {
    tree.walk(
        [&](const BoxTree::Node& n) {
            Real entry;
            return ray.meets(n, entry);
        },
        face);
}

// POV-Ray walks a mesh's box tree nearest box first and, for a mesh without
// inside_vector, stops at the first box that starts beyond the last hit it kept
// (Mesh::intersect_bbox_tree): the triangles behind are never tested, and a CSG that
// drops the nearest hit sees nothing of them. A box never starts after the boxes inside
// it, so the walk meets the triangles in the order their own boxes start (each the float
// box of its corners, as the tree's Check_And_Enqueue tests it; ties by face index) and
// only the crossed ones change where it stops: the kept hits follow from the crossings
// alone. Our tree's boxes are not POV-Ray's: it is walked nearest first too, each box
// entered from a distance no later than any face box inside it starts for POV-Ray's
// float test, so the crossed faces come out in that order and the walk ends where
// POV-Ray's does. A ray POV-Ray restarted (a shadow ray past a see-through surface)
// walks from there.
void nearest_walk_hits(const Mesh& m, const LocalRay& r, const Vector3& unit,
                       const ShapeClip* clip, ShapeHits& out) {
    const BoxTree& tree = m->tree();
    if (tree.empty()) return;
    struct Item {
        Real key;  // a face: where its float box starts; a node: no later than that
        Real t;    // a face's crossing
        uint32_t index;
        bool face;
        // The heap's top is the least: nodes before faces at one distance (they may
        // hold faces starting there), faces by index.
        bool operator<(const Item& o) const {
            if (key != o.key) return key > o.key;
            if (face != o.face) return face;
            return index > o.index;
        }
    };
    thread_local std::vector<Item> heap;
    heap.clear();
    const TreeRay ray(r.origin, unit);
    const PovRay box_ray(r.origin, unit);
    Real far = 0;
    for (int a = 0; a < 3; ++a) far = std::max(far, std::fabs(r.origin[a]));
    const auto& nodes = tree.nodes();
    const auto& order = tree.order();
    auto push_node = [&](uint32_t index) {
        Real entry;
        if (!ray.meets(nodes[index], entry)) return;
        // POV-Ray's float slab test may start a face box up to a few float roundings of
        // the distance (and of the origin) sooner.
        const Real key = entry - 1e-5 * (std::fabs(entry) + far) - 1e-30;
        heap.push_back({key, 0, index, false});
        std::push_heap(heap.begin(), heap.end());
    };
    push_node(0);
    Real last_kept = kInfinity;
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end());
        const Item item = heap.back();
        heap.pop_back();
        if (item.key > last_kept) break;
        if (item.face) {
            const Real world_t = item.t / r.length;
            if (clip && !clip->keeps(clip->context, world_t)) continue;
            out.push_back({world_t, r.origin + unit * item.t, int(item.index)});
            last_kept = item.t;
            // A shadow ray's question is answered by the first kept crossing in its
            // range.
            if (r.ends_search(world_t)) return;
            continue;
        }
        const BoxTree::Node& n = nodes[item.index];
        if (n.count == 0) {
            push_node(item.index + 1);
            push_node(n.first);
            continue;
        }
        for (uint32_t i = n.first; i < n.first + n.count; ++i) {
            const uint32_t fi = order[i];
            Point3 p[3];
            Real t;
            // Behind where POV-Ray's ray starts: not met (the boxes' order is the same
            // from there).
            if (!face_crossing(m, fi, r.origin, unit, p, t) ||
                !(t / r.length > r.restart))
                continue;
            Bounds3 box;
            for (const Point3& q : p) box.extend(q);
            Real entry = 0;
            // A box the float test misses is never entered, as in POV-Ray.
            if (!slab_tree_entry(pov_bbox(box), box_ray, entry)) continue;
            heap.push_back({entry, t, fi, true});
            std::push_heap(heap.begin(), heap.end());
        }
    }
}
// The nearest crossing the walk above keeps, in the world range the query asks for
// (LocalRay::nearest_only: a mesh outside CSG and clips, met by a closest-hit or shadow
// query). Every face the walk keeps ahead of the nearest starts its box no later than
// that crossing, so the walk's stop rule never drops it: the nearest kept crossing is
// the nearest crossing whose float box the ray enters. Found depth first, nearest box
// first, boxes beyond the best crossing so far left out; a shadow query stops at its
// first crossing in range. Ties go to the crossing the walk meets first (the earlier
// box start, then the lower face index).
void nearest_crossing(const Mesh& m, const LocalRay& r, const Vector3& unit,
                      ShapeHits& out) {
    const BoxTree& tree = m->tree();
    if (tree.empty()) return;
    const TreeRay ray(r.origin, unit);
    const PovRay box_ray(r.origin, unit);
    const auto& nodes = tree.nodes();
    const auto& order = tree.order();
    struct Best {
        Real t = kInfinity, entry = kInfinity;
        uint32_t face = ~0u;
    } best;
    const Real lo = std::max(r.want_lo, r.restart), hi = r.want_hi;
    struct Pending {
        uint32_t node;
        Real entry;
    };
    Pending stack[64];  // the tree's depth stays under 64 (core/box_tree.cpp)
    int size = 0;
    Real entry;
    if (ray.meets(nodes[0], entry)) stack[size++] = {0, entry};
    while (size > 0) {
        const Pending p = stack[--size];
        if (p.entry > best.t) continue;
        const BoxTree::Node& n = nodes[p.node];
        if (n.count == 0) {
            Real e1, e2;
            const bool m1 = ray.meets(nodes[p.node + 1], e1),
                       m2 = ray.meets(nodes[n.first], e2);
            // The nearer child on top.
            if (m1 && m2 && e1 < e2) {
                stack[size++] = {n.first, e2};
                stack[size++] = {p.node + 1, e1};
            } else {
                if (m1) stack[size++] = {p.node + 1, e1};
                if (m2) stack[size++] = {n.first, e2};
            }
            continue;
        }
        for (uint32_t i = n.first; i < n.first + n.count; ++i) {
            const uint32_t fi = order[i];
            Point3 pts[3];
            Real t;
            if (!face_crossing(m, fi, r.origin, unit, pts, t)) continue;
            const Real world_t = t / r.length;
            if (!(world_t > r.restart) || world_t < lo || world_t >= hi || t > best.t)
                continue;
            Bounds3 box;
            for (const Point3& q : pts) box.extend(q);
            Real box_entry = 0;
            if (!slab_tree_entry(pov_bbox(box), box_ray, box_entry)) continue;
            if (t == best.t &&
                (box_entry > best.entry || (box_entry == best.entry && fi > best.face)))
                continue;
            best = {t, box_entry, fi};
            if (r.any_crossing) {
                size = 0;
                break;
            }
        }
    }
    if (best.face != ~0u)
        out.push_back({best.t / r.length, r.origin + unit * best.t, int(best.face)});
}
}  // namespace

bool mesh_as_triangles(const Object& o) {
    const Mesh* m = std::get_if<Mesh>(&o.shape);
    return m && !m->instanced() && !o.inverse && o.clipped_by.empty();
}

bool mesh_stops_at_nearest(const Mesh& m) { return m.hierarchy && !has_inside(m); }

void shape_hits(const Mesh& m, const LocalRay& r, const ShapeClip* clip, ShapeHits& out) {
    // Divided (not multiplied by the reciprocal) as meshes in CSG always were.
    const Vector3 dn = r.direction / r.length;
    if (mesh_stops_at_nearest(m)) {
        if (r.nearest_only && !clip) return nearest_crossing(m, r, dn, out);
        return nearest_walk_hits(m, r, dn, clip, out);
    }
    const BoxTree& tree = m->tree();
    if (tree.empty()) return;
    // Every crossing, in face order.
    thread_local std::vector<std::pair<uint32_t, Real>> crossed;
    crossed.clear();
    walk_faces(tree, TreeRay(r.origin, dn), [&](uint32_t fi) {
        Point3 p[3];
        Real t;
        if (face_crossing(m, fi, r.origin, dn, p, t) &&
            (!clip || clip->keeps(clip->context, t / r.length)))
            crossed.push_back({fi, t});
    });
    std::sort(crossed.begin(), crossed.end());
    for (const auto& [fi, t] : crossed)
        out.push_back({t / r.length, r.origin + dn * t, int(fi)});
}

void shape_hits(const Mesh& m, const LocalRay& r, ShapeHits& out) {
    shape_hits(m, r, nullptr, out);
}

Vector3 shape_normal(const Mesh& m, const ShapeHit& h) {
    const Mesh::Face& f = m->faces[size_t(h.face)];
    Point3 p[3];
    mesh_face_corners(m, f, p);
    if (f.n[0] < 0 || f.n[1] < 0 || f.n[2] < 0) return pov_triangle_normal(p);
    // A smooth face (in CSG or clipped, as outside them): its unit vertex normals
    // interpolated at the hit, in the mesh's own space as POV-Ray's.
    Vector3 n[3];
    for (int k = 0; k < 3; ++k) n[k] = normalize(m->normals[size_t(f.n[k])]);
    return normalize(smooth_triangle_normal(p, n, h.p));
}

// POV-Ray's Mesh::Inside answers false for a mesh without inside_vector before it looks
// at the inverted flag: such a mesh holds nothing, inverted or not.
bool shape_inside_inverted(const Mesh& m, const Point3& q) {
    return has_inside(m) && !shape_inside(m, q);
}

bool shape_has_no_inside(const Mesh& m) { return !has_inside(m); }

bool shape_inside(const Mesh& m, const Point3& q) {
    if (!has_inside(m)) return false;
    const Vector3 dir = normalize(*m->inside_vector);
    const BoxTree& tree = m->tree();
    if (tree.empty()) return false;
    int crossed = 0;
    walk_faces(tree, TreeRay(q, dir), [&](uint32_t fi) {
        Point3 p[3];
        Real t;
        crossed += face_crossing(m, fi, q, dir, p, t);
    });
    return crossed % 2 == 1;
}

Bounds3 shape_bounds(const Mesh& m) {
    Bounds3 b;
    for (const auto& p : m->vertices) b.extend(p);
    return b;
}

PovBBox shape_pov_bbox(const Mesh& m, const CompactTransform& xf) {
    // Vertices are single precision; the box of the mesh's own space goes through the
    // transform.
    Bounds3 b;
    for (const Point3& p : m->vertices) b.extend(single_precision(p));
    if (b.empty()) return pov_infinite_bbox();
    return pov_transformed_bbox(b, xf);
}

bool shape_oracle_first(const Mesh& m, const OracleRay& r, OracleBest& best) {
    for (const auto& f : m->faces) {
        Point3 p[3];
        mesh_face_corners(m, f, p);
        V3 q[3] = {V3(p[0]), V3(p[1]), V3(p[2])};
        oracle_triangle(q, r, best);
    }
    return true;
}

}  // namespace povwall::trace
