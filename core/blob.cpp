// POV-Ray 3.7's Make_Blob (notes: shape-blob.md section 1): the stored element list.
#include "core/scene.h"

namespace povwall {
namespace {

// The box of the sphere of radius r about c (element space) through the element's matrix:
// per axis the centre moved, r times the length of the matrix's row.
Bounds3 moved_sphere_box(const Transform& t, const Point3& c, Real r) {
    const Matrix34& m = t.forward();
    const Point3 centre = t.point(c);
    Bounds3 b;
    for (int a = 0; a < 3; ++a) {
        const Real half = r * std::sqrt(m.m[a][0] * m.m[a][0] + m.m[a][1] * m.m[a][1] +
                                        m.m[a][2] * m.m[a][2]);
        b.lo[a] = centre[a] - half;
        b.hi[a] = centre[a] + half;
    }
    return b;
}

}  // namespace

Bounds3 blob_element_box(const BlobElement& e) {
    const Real r = std::sqrt(e.rad2);
    Bounds3 b;
    switch (e.kind) {
        case BlobElementKind::Sphere:
            b = {e.origin - Vector3(r), e.origin + Vector3(r)};
            break;
        case BlobElementKind::Ellipsoid:
            b = moved_sphere_box(e.transform, e.origin, r);
            break;
        case BlobElementKind::BaseHemisphere:
            b = moved_sphere_box(e.transform, {0, 0, 0}, r);
            break;
        case BlobElementKind::ApexHemisphere:
            b = moved_sphere_box(e.transform, {0, 0, e.len}, r);
            break;
        case BlobElementKind::Cylinder:
            b = moved_sphere_box(e.transform, {0, 0, 0}, r);
            b.extend(moved_sphere_box(e.transform, {0, 0, e.len}, r));
            break;
    }
    // The elements' own tests round (the interval's discriminant, the inverse matrix):
    // a margin relative to the box's size and place keeps what they accept inside.
    Real size = 0;
    for (int a = 0; a < 3; ++a)
        size =
            std::max({size, b.hi[a] - b.lo[a], std::fabs(b.lo[a]), std::fabs(b.hi[a])});
    const Real margin = 1e-6 * size + 1e-12;
    b.lo = b.lo - Vector3(margin);
    b.hi = b.hi + Vector3(margin);
    // A matrix that is not finite: the element may be anywhere.
    for (int a = 0; a < 3; ++a)
        if (!(b.lo[a] <= b.hi[a])) return Bounds3::everything();
    return b;
}

BlobData make_blob(Real threshold, const std::vector<BlobElement>& components) {
    BlobData d;
    d.threshold = threshold;
    // POV-Ray prepends each component to its list as it parses: the last one comes first.
    for (auto it = components.rbegin(); it != components.rend(); ++it) {
        BlobElement e = *it;
        const Real rad2 = e.rad2, s = e.c[2];
        e.c[0] = s / (rad2 * rad2);
        e.c[1] = -(2.0 * s) / rad2;
        e.c[2] = s;
        d.elements.push_back(e);
        if (e.kind == BlobElementKind::Cylinder) {
            e.kind = BlobElementKind::BaseHemisphere;
            d.elements.push_back(e);
            e.kind = BlobElementKind::ApexHemisphere;
            d.elements.push_back(e);
        }
    }
    std::vector<Bounds3> boxes;
    boxes.reserve(d.elements.size());
    for (const BlobElement& e : d.elements) boxes.push_back(blob_element_box(e));
    d.tree = BoxTree(boxes);
    return d;
}

}  // namespace povwall
