#include "trace/pov_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trace/pov_order.h"
#include "trace/pov_slab_test.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {

PovBBox pov_bbox(const Bounds3& b) {
    PovBBox r;
    for (int a = 0; a < 3; ++a) {
        r.lo[a] = float(b.lo[a]);
        r.len[a] = float(b.hi[a] - b.lo[a]);
    }
    return r;
}

Bounds3 pov_bbox_bounds(const PovBBox& b) {
    Bounds3 r;
    for (int a = 0; a < 3; ++a) {
        r.lo[a] = Real(b.lo[a]);
        r.hi[a] = Real(b.lo[a]) + Real(b.len[a]);
    }
    return r;
}

bool pov_bbox_finite(const PovBBox& b) {
    const Real volume = Real(b.len[0]) * Real(b.len[1]) * Real(b.len[2]);
    return volume <= kBoundHuge;
}

PovRay::PovRay(const Ray& ray) {
    const Real len = length(ray.direction);
    *this = PovRay(ray.origin, len == 1 ? ray.direction : ray.direction / len);
}

PovRay::PovRay(const Point3& o, const Vector3& d) {
    for (int a = 0; a < 3; ++a) {
        origin[a] = float(o[a]);
        nonzero[a] = d[a] != 0;
        inv[a] = float(1.0 / d[a]);  // +-inf along a zero component, as POV-Ray's invdir
    }
}

bool slab_tree_entry(const PovBBox& box, const PovRay& ray, Real& entry) {
    return slab_test(box, ray, entry);
}

bool slab_tree_accepts(const PovBBox& box, const PovRay& ray) {
    Real entry;
    return slab_tree_entry(box, ray, entry);
}

bool own_bbox_accepts(const PovBBox& box, const PovRay& ray, float mind, float maxd) {
    float lo = 0, hi = 0;
    for (int a = 0; a < 3; ++a) {
        const float lower = box.lo[a], upper = box.lo[a] + box.len[a];
        const bool back = ray.inv[a] < 0;
        const float enter = ((back ? upper : lower) - ray.origin[a]) * ray.inv[a];
        const float leave = ((back ? lower : upper) - ray.origin[a]) * ray.inv[a];
        if (a == 0) {
            lo = enter;
            hi = leave;
            continue;
        }
        if (lo > leave || enter > hi) return false;
        if (enter > lo) lo = enter;
        if (leave < hi) hi = leave;
    }
    return lo < maxd && hi > mind;
}

bool is_similarity(const Transform& t, Real& scale) {
    const auto& m = t.forward().m;
    Vector3 c0{m[0][0], m[1][0], m[2][0]}, c1{m[0][1], m[1][1], m[2][1]},
        c2{m[0][2], m[1][2], m[2][2]};
    Real s0 = dot(c0, c0), s1 = dot(c1, c1), s2 = dot(c2, c2);
    Real tol = 1e-12 * std::max({s0, s1, s2});
    if (std::fabs(s0 - s1) > tol || std::fabs(s0 - s2) > tol) return false;
    if (std::fabs(dot(c0, c1)) > tol || std::fabs(dot(c0, c2)) > tol ||
        std::fabs(dot(c1, c2)) > tol)
        return false;
    scale = std::sqrt(s0);
    return true;
}

// POV-Ray's canonical frame for a cylinder, cone or disc along `up` (unit): the images of
// x and y under the rotation about (-up.y, up.x, 0) by acos(up.z) that takes z to `up`
// (Compute_Coordinate_Transform, 3.7:source/backend/math/matrices.cpp:1027).
void pov_canonical_frame(Vector3 up, Vector3& ex, Vector3& ey) {
    Vector3 k;
    if (std::fabs(up.z) > 1.0 - kPovEpsilon) {
        k = {1, 0, 0};
        up.z = up.z < 0 ? -1.0 : 1.0;
    } else {
        k = normalize(Vector3{-up.y, up.x, 0});
    }
    const Real angle = std::acos(std::clamp(up.z, -1.0, 1.0));
    const Real c = std::cos(angle), s = std::sin(angle);
    auto rotate = [&](const Vector3& v) {  // Rodrigues
        return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
    };
    ex = rotate({1, 0, 0});
    ey = rotate({0, 1, 0});
}

Bounds3 pov_corners_bounds(const Bounds3& canonical,
                           const std::function<Point3(const Point3&)>& place) {
    Bounds3 r;
    for (int i = 0; i < 8; ++i) {
        const Point3 p{(i & 1) ? canonical.hi.x : canonical.lo.x,
                       (i & 2) ? canonical.hi.y : canonical.lo.y,
                       (i & 4) ? canonical.hi.z : canonical.lo.z};
        r.extend(place(p));
    }
    for (int a = 0; a < 3; ++a) {  // clipped at the largest box POV-Ray allows
        r.lo[a] = std::max(r.lo[a], -kBoundHuge / 2);
        r.hi[a] = std::min(r.hi[a], kBoundHuge / 2);
    }
    return r;
}

PovBBox pov_transformed_bbox(const Bounds3& local, const CompactTransform& xf) {
    return pov_bbox(
        pov_corners_bounds(local, [&](const Point3& p) { return xf.point(p); }));
}

Bounds3 pov_axial_bounds(const CompactTransform& xf, const Point3& origin,
                         const Vector3& axis, Real radius, Real height, Real z0) {
    Vector3 ex, ey;
    pov_canonical_frame(axis, ex, ey);
    return pov_corners_bounds(Bounds3{{-1, -1, z0}, {1, 1, 1}}, [&](const Point3& p) {
        const Point3 local =
            origin + ex * (p.x * radius) + ey * (p.y * radius) + axis * (p.z * height);
        return xf.point(local);
    });
}

PovBBox pov_infinite_bbox() {
    PovBBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = float(-kBoundHuge / 2);
        b.len[a] = float(kBoundHuge);
    }
    return b;
}

namespace {

const PovBBox kInfiniteBox = pov_infinite_bbox();

PovBBox csg_bbox(const Csg& csg);

PovBBox shape_bbox(const Object& o) {
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) return csg_bbox(*csg);
    return leaf_pov_bbox(o);
}

// The half space of a plane whose normal lies along an axis, as a box (POV-Ray's
// Compute_Plane_Min_Max, which an intersection's box takes from its planes); every other
// plane bounds nothing. A plane keeps no matrix until a `matrix` or `transform` (the
// parser folds translate, rotate and scale into its normal and offset, as POV-Ray's
// Plane::Translate, Rotate, Scale): its own normal and offset. With one, it is read as
// POV-Ray reads it (its formula, not the plane's true half space): the normal through
// the transposed matrix, the offset less that normal taken as a point back through the
// inverse, plus one.
Bounds3 pov_plane_bounds(const Plane& plane, const CompactTransform& xf) {
    Vector3 n = plane.normal;
    Real d = plane.distance;
    if (!xf.is_identity()) {
        const Matrix34& m = xf.forward();
        const Vector3& o = plane.normal;
        n = {m.m[0][0] * o.x + m.m[1][0] * o.y + m.m[2][0] * o.z,
             m.m[0][1] * o.x + m.m[1][1] * o.y + m.m[2][1] * o.z,
             m.m[0][2] * o.x + m.m[1][2] * o.y + m.m[2][2] * o.z};
        const Point3 p = xf.inverse_point(Point3{n.x, n.y, n.z});
        d = plane.distance - (p.x * n.x + p.y * n.y + p.z * n.z) + 1.0;
    }
    Bounds3 b{{-kBoundHuge / 2, -kBoundHuge / 2, -kBoundHuge / 2},
              {kBoundHuge / 2, kBoundHuge / 2, kBoundHuge / 2}};
    constexpr Real kEpsilon = 1e-10;
    for (int a = 0; a < 3; ++a) {
        const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        if (std::abs(n[a1]) < kEpsilon && std::abs(n[a2]) < kEpsilon) {
            if (n[a] > 0)
                b.hi[a] = d;
            else
                b.lo[a] = -d;
        }
    }
    return b;
}

// An inverted CSG keeps the box it was closed with (POV-Ray's Invert_CSG_Object inverts
// the children and morphs the CSG into a copy that keeps its BBox).
PovBBox csg_bbox(const Csg& csg) {
    if (csg.pov_box) {  // the box it was closed with, moved
        PovBBox b;
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = csg.pov_box->lo[a];
            b.len[a] = csg.pov_box->len[a];
        }
        return b;
    }
    Bounds3 b;
    if (csg.kind == CsgKind::Intersection || csg.kind == CsgKind::Difference) {
        // The children's boxes intersected, inverted children (every child of a
        // difference but the first) and height fields left out.
        b = {{-kBoundHuge, -kBoundHuge, -kBoundHuge},
             {kBoundHuge, kBoundHuge, kBoundHuge}};
        for (size_t i = 0; i < csg.children.size(); ++i) {
            const Object& c = csg.children[i];
            // A difference inverts its children after the first (an inverse one comes
            // back).
            if (child_held_inverted(csg, i, c.inverse)) continue;
            // POV-Ray leaves height fields out too: their inside reaches below the box.
            if (std::holds_alternative<HeightField>(c.shape)) continue;
            if (const Plane* plane = std::get_if<Plane>(&c.shape)) {
                b = intersection(b, pov_plane_bounds(*plane, c.transform));
                continue;
            }
            b = intersection(b, pov_bbox_bounds(pov_object_bbox(c)));
        }
    } else {
        for (const Object& c : csg.children)
            b.extend(pov_bbox_bounds(pov_object_bbox(c)));
    }
    if (b.empty()) return kInfiniteBox;  // "degenerate CSG bounding box (not used)"
    const PovBBox r = pov_bbox(b);
    for (int a = 0; a < 3; ++a) {
        if (Real(r.len[a]) > kCriticalLength) return kInfiniteBox;
    }
    return r;
}

}  // namespace

PovBBox pov_object_bbox(const Object& o) {
    // An inverted shape keeps its box (only its inside flips).
    PovBBox box = shape_bbox(o);
    // bounded_by, then clipped_by (Parse_Object_Mods): the objects' boxes intersected,
    // kept when smaller. A bound shrinks the box even where it is later removed.
    auto shrink = [&](const std::vector<Object>& list) {
        if (list.empty()) return;
        Bounds3 all = {{-kBoundHuge, -kBoundHuge, -kBoundHuge},
                       {kBoundHuge, kBoundHuge, kBoundHuge}};
        for (const Object& c : list) {
            if (c.inverse) continue;
            all = intersection(all, pov_bbox_bounds(pov_object_bbox(c)));
        }
        const PovBBox smaller = pov_bbox(all);
        auto volume = [](const PovBBox& b) {
            return Real(b.len[0]) * Real(b.len[1]) * Real(b.len[2]);
        };
        if (volume(smaller) < volume(box)) box = smaller;
    };
    shrink(*o.bounded_by);
    shrink(*o.clipped_by);
    return box;
}

PovBBox pov_sphere_bbox(const Point3& centre, Real radius) {
    PovBBox r;
    for (int a = 0; a < 3; ++a) {
        r.lo[a] = float(centre[a] - radius);
        r.len[a] = float(2.0 * radius);
    }
    return r;
}

PovBBox pov_mesh_triangle_bbox(const Point3 (&p)[3]) {
    Bounds3 b;
    for (const Point3& q : p) b.extend(single_precision(q));
    return pov_bbox(b);
}

bool pov_tests_own_bbox(const Object& o) {
    return std::holds_alternative<Csg>(o.shape) || leaf_pov_tests_own_bbox(o);
}

size_t pov_frame_object_count(const Object& o) {
    if (pov_splits_union(o)) {
        size_t n = 0;
        for (const Object& c : std::get<Csg>(o.shape).children)
            n += pov_frame_object_count(c);
        return n;
    }
    return 1;
}

bool pov_slab_root(const Scene& scene, PovBBox& root, const PovWholeScene* whole) {
    if (whole) {
        Bounds3 b;
        for (const PovBBox& box : whole->boxes()) {
            if (!pov_bbox_finite(box)) return false;
            b.extend(pov_bbox_bounds(box));
        }
        for (const Light& l : scene.lights) {
            if (l.looks_like.empty()) continue;
            const PovBBox box = pov_object_bbox(l.looks_like.front());
            if (!pov_bbox_finite(box)) return false;
            b.extend(pov_bbox_bounds(box));
        }
        if (b.empty()) return false;
        root = pov_bbox(b);
        return true;
    }
    if (scene.objects_filtered()) return false;
    // Most scenes have a plane: their root is infinite, known without the other boxes.
    bool plane = false;
    for (const Object& o : scene.objects) {
        pov_for_frame_objects(o, [&](const Object& f) {
            plane = plane || std::holds_alternative<Plane>(f.shape);
        });
        if (plane) return false;
    }
    Bounds3 b;
    bool finite = true;
    auto add = [&](const Object& o) {
        if (!finite) return;
        const PovBBox box = pov_object_bbox(o);
        if (!pov_bbox_finite(box)) finite = false;
        b.extend(pov_bbox_bounds(box));
    };
    for (const Object& o : scene.objects) pov_for_frame_objects(o, add);
    for (const Light& l : scene.lights) {
        if (!l.looks_like.empty()) add(l.looks_like.front());
    }
    if (!finite || b.empty()) return false;
    root = pov_bbox(b);
    return true;
}

size_t pov_frame_objects(const Scene& scene, const PovWholeScene* whole) {
    if (whole) return scene.lights.size() + whole->boxes().size();
    size_t n = scene.lights.size() + scene.objects_left_out;
    for (const Object& o : scene.objects) n += pov_frame_object_count(o);
    return n;
}

}  // namespace povwall::trace
