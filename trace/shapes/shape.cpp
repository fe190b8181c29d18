#include "trace/shapes/shape.h"

#include <cstdlib>
#include <variant>

namespace povwall::trace {
namespace {

// Calls f(shape) for a leaf; CSG has no leaf operations.
template <class R, class F>
R visit_leaf(const Object& leaf, F&& f) {
    return std::visit(
        [&](const auto& s) -> R {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, Csg>) {
                std::abort();  // a programming error: callers open CSG themselves
            } else {
                return f(s);
            }
        },
        leaf.shape);
}

}  // namespace

LocalRay leaf_ray(const Object& leaf, const Ray& ray) {
    const Ray local =
        leaf.transform.is_identity() ? ray : leaf.transform.inverse_ray(ray);
    const Real len = length(local.direction);
    return {local.origin, local.direction, local.direction * (1.0 / len), len,
            !leaf.transform.is_identity()};
}

void leaf_hits(const Object& leaf, const LocalRay& r, ShapeHits& out) {
    visit_leaf<void>(leaf, [&](const auto& s) { shape_hits(s, r, out); });
}

Vector3 leaf_normal(const Object& leaf, const ShapeHit& h) {
    return visit_leaf<Vector3>(leaf, [&](const auto& s) { return shape_normal(s, h); });
}

Vector3 leaf_world_normal(const Object& leaf, const ShapeHit& h, const Point3& world) {
    // POV-Ray finds a cylinder's or cone's normal at the world hit point turned back into
    // its frame (Cone::Normal), not at the point in the frame the ray reached.
    if (!h.own_point && !leaf.transform.is_identity() &&
        (std::holds_alternative<Cylinder>(leaf.shape) ||
         std::holds_alternative<Cone>(leaf.shape))) {
        ShapeHit at = h;
        at.p = leaf.transform.inverse_point(world);
        return leaf_world_normal(leaf, at);
    }
    // So do Sor::Normal and Lathe::Normal, with or without a transform (the world point
    // is origin + (k / length) * direction, the frame's point origin + k * unit: their
    // last bits differ, and a normal's last bits bend a refracted ray onto another of
    // the round-off roots a sor or lathe met edge-on has).
    if (!h.own_point && (std::holds_alternative<Sor>(leaf.shape) ||
                         std::holds_alternative<Lathe>(leaf.shape))) {
        ShapeHit at = h;
        at.p = leaf.transform.is_identity() ? world : leaf.transform.inverse_point(world);
        return leaf_world_normal(leaf, at);
    }
    return leaf_world_normal(leaf, h);
}

Vector3 leaf_world_normal(const Object& leaf, const ShapeHit& h) {
    if (const HeightField* hf = std::get_if<HeightField>(&leaf.shape))
        return height_field_world_normal(*hf, h, leaf.transform);
    const Vector3 n = leaf_normal(leaf, h);
    return normalize(leaf.transform.is_identity() ? n : leaf.transform.normal(n));
}

bool leaf_inside(const Object& leaf, const Point3& p) {
    return visit_leaf<bool>(leaf, [&](const auto& s) { return shape_inside(s, p); });
}

bool leaf_inside_inverted(const Object& leaf, const Point3& p) {
    return visit_leaf<bool>(leaf, [&](const auto& s) {
        if constexpr (requires { shape_inside_inverted(s, p); })
            return shape_inside_inverted(s, p);
        else
            return !shape_inside(s, p);
    });
}

Bounds3 leaf_bounds(const Object& leaf) {
    return visit_leaf<Bounds3>(leaf, [&](const auto& s) { return shape_bounds(s); });
}

PovBBox leaf_pov_bbox(const Object& leaf) {
    return visit_leaf<PovBBox>(
        leaf, [&](const auto& s) { return shape_pov_bbox(s, leaf.transform); });
}

bool leaf_pov_tests_own_bbox(const Object& leaf) {
    return visit_leaf<bool>(leaf,
                            [&](const auto& s) { return shape_pov_tests_own_bbox(s); });
}

bool leaf_convex(const Object& leaf) {
    return visit_leaf<bool>(leaf, [&](const auto& s) { return shape_convex(s); });
}

bool leaf_invertible(const Object& leaf) {
    return visit_leaf<bool>(leaf, [&](const auto& s) { return shape_invertible(s); });
}

bool leaf_never_inside(const Object& leaf) {
    return visit_leaf<bool>(leaf, [&](const auto& s) {
        if constexpr (requires { shape_has_no_inside(s); })
            return shape_has_no_inside(s);
        else
            return false;
    });
}

bool leaf_oracle_first(const Object& leaf, const OracleRay& r, OracleBest& best) {
    return visit_leaf<bool>(
        leaf, [&](const auto& s) { return shape_oracle_first(s, r, best); });
}

}  // namespace povwall::trace
