// A Transform that takes 8 bytes when it is the identity.
//
// Every object and every pattern (each object's pigment has one) carries a Transform of
// 200 bytes, and most of them are the identity: a sphere placed by its centre, a solid
// colour. Kept inline, those identities were a third of a parsed sphere's memory, all
// of it copied and paged in once per object. CompactTransform stores a Transform only
// when it is not the identity and otherwise reads as Transform's own identity.
#pragma once

#include "core/heap_optional.h"
#include "core/math.h"

namespace povwall {

class CompactTransform {
  public:
    CompactTransform() = default;
    CompactTransform(const Transform& t) { *this = t; }
    CompactTransform& operator=(const Transform& t) {
        // Transform's identity flag is only ever set on exact identity matrices.
        if (t.is_identity())
            stored_.reset();
        else
            stored_ = t;
        return *this;
    }

    const Transform& get() const { return stored_ ? *stored_ : identity(); }
    operator const Transform&() const { return get(); }

    bool is_identity() const { return !stored_; }
    Transform then(const Transform& next) const { return get().then(next); }
    Transform inverse() const { return get().inverse(); }
    Point3 point(const Point3& p) const { return get().point(p); }
    Vector3 vector(const Vector3& v) const { return get().vector(v); }
    Point3 inverse_point(const Point3& p) const { return get().inverse_point(p); }
    Vector3 inverse_vector(const Vector3& v) const { return get().inverse_vector(v); }
    Vector3 normal(const Vector3& n) const { return get().normal(n); }
    Ray inverse_ray(const Ray& r) const { return get().inverse_ray(r); }
    Bounds3 bounds(const Bounds3& b) const { return get().bounds(b); }
    const Matrix34& forward() const { return get().forward(); }
    const Matrix34& inverse_matrix() const { return get().inverse_matrix(); }

  private:
    static const Transform& identity() {
        static const Transform kIdentity;
        return kIdentity;
    }
    HeapOptional<Transform> stored_;
};

}  // namespace povwall
