#include "trace/shapes/bicubic_patch.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"
#include "trace/shapes/sort_hits.h"

namespace povwall::trace {
namespace {

constexpr Real kBezierEpsilon = 1e-10;  // BEZIER_EPSILON
constexpr Real kTolerance = 1e-5;       // BEZIER_TOLERANCE: nearer hits are dropped

// POV-Ray's sphere test of a piece: the origin inside, or the ray's line passing within
// the radius (in front of the origin or not).
bool meets_sphere(const BicubicPatchData::Node& n, const Point3& o, const Vector3& d) {
    const Vector3 v = n.centre - o;
    const Real l = dot(v, v);
    if (l < n.radius2) return true;
    const Real along = dot(v, d);
    const Real s = along * along;
    return s > 0 && l - s <= n.radius2 + kBezierEpsilon;
}

// Visits the tree in POV-Ray's order (preorder, children in order).
template <class Leaf>
void walk(const BicubicPatchData& d, uint32_t index, const Point3& o, const Vector3& dir,
          Leaf&& leaf) {
    const BicubicPatchData::Node& n = d.nodes[index];
    if (!meets_sphere(n, o, dir)) return;
    if (n.leaf >= 0) {
        leaf(uint32_t(n.leaf));
        return;
    }
    for (int k = 0; k < n.child_count; ++k) walk(d, n.child[k], o, dir, leaf);
}

}  // namespace

void shape_hits(const BicubicPatch& p, const LocalRay& r, ShapeHits& out) {
    const BicubicPatchData& d = *p.data;
    if (d.nodes.empty()) return;
    const size_t first = out.size();
    const Point3& o = r.origin;
    const Vector3& dir = r.unit;
    walk(d, 0, o, dir, [&](uint32_t leaf) {
        for (int k = 0; k < 2; ++k) {
            const BicubicPatchData::Triangle& t = d.leaves[leaf][size_t(k)];
            if (!t.valid) continue;
            const Real den = dot(dir, t.e2);
            if (std::fabs(den) < kBezierEpsilon) continue;
            const Real dist = dot(t.v0 - o, t.e2) / den;
            if (dist < kTolerance) continue;
            const Point3 hit = o + dir * dist;
            const Vector3 q = hit - t.v0;
            const Real a = dot(q, t.e0), b = dot(q, t.e1);
            if (a < 0 || b < 0 || a + b > 1) continue;
            out.push_back({dist / r.length, hit, int(2 * leaf) + k, a, b});
        }
    });
    stable_sort_by_depth(out, first);
}

Vector3 shape_normal(const BicubicPatch& p, const ShapeHit& h) {
    const BicubicPatchData::Triangle& t =
        p.data->leaves[size_t(h.face / 2)][size_t(h.face % 2)];
    const Real r = 1 - h.param - h.param2;
    const Vector3 n = t.normal[0] * r + t.normal[1] * h.param + t.normal[2] * h.param2;
    if (dot(n, n) <= kBezierEpsilon) return {1, 0, 0};
    return n / length(n);
}

bool shape_inside(const BicubicPatch&, const Point3&) { return false; }

Bounds3 shape_bounds(const BicubicPatch& p) {
    Bounds3 b;
    for (const Point3& q : p.data->control) b.extend(q);
    return b;
}

PovBBox shape_pov_bbox(const BicubicPatch& p, const CompactTransform& xf) {
    return pov_transformed_bbox(shape_bounds(p), xf);
}

bool shape_oracle_first(const BicubicPatch& p, const OracleRay& r, OracleBest& best) {
    // The same flat pieces (they are the surface POV-Ray renders), met in 50 digits.
    const BicubicPatchData& d = *p.data;
    for (const auto& leaf : d.leaves) {
        for (const auto& t : leaf) {
            if (!t.valid) continue;
            const V3 e2(t.e2);
            const HP den = dot(r.d, e2);
            if (den == 0) continue;
            const HP dist = dot(V3(t.v0) - r.o, e2) / den;
            const V3 q = r.o + r.d * dist - V3(t.v0);
            const HP a = dot(q, V3(t.e0)), b = dot(q, V3(t.e1));
            if (a < 0 || b < 0 || a + b > 1) continue;
            best.offer(dist, kTolerance);
        }
    }
    return true;
}

}  // namespace povwall::trace
