// Small value types shared by every layer: vectors, bounds, rays, affine transforms.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace povwall {

using Real = double;
constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
constexpr Real kPi = 3.14159265358979323846;

struct Vector3 {
    Real x = 0, y = 0, z = 0;

    constexpr Vector3() = default;
    constexpr Vector3(Real x_, Real y_, Real z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vector3(Real s) : x(s), y(s), z(s) {}

    constexpr Real operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Real& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vector3 operator+(const Vector3& o) const {
        return {x + o.x, y + o.y, z + o.z};
    }
    constexpr Vector3 operator-(const Vector3& o) const {
        return {x - o.x, y - o.y, z - o.z};
    }
    constexpr Vector3 operator-() const { return {-x, -y, -z}; }
    constexpr Vector3 operator*(Real s) const { return {x * s, y * s, z * s}; }
    constexpr Vector3 operator/(Real s) const { return {x / s, y / s, z / s}; }
    constexpr Vector3 operator*(const Vector3& o) const {
        return {x * o.x, y * o.y, z * o.z};
    }
    constexpr Vector3 operator/(const Vector3& o) const {
        return {x / o.x, y / o.y, z / o.z};
    }
    constexpr Vector3& operator+=(const Vector3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Vector3& operator-=(const Vector3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Vector3& operator*=(Real s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vector3& o) const = default;
};
// Points and vectors share one representation; the name documents intent.
using Point3 = Vector3;

constexpr Vector3 operator*(Real s, const Vector3& v) { return v * s; }
constexpr Real dot(const Vector3& a, const Vector3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vector3 cross(const Vector3& a, const Vector3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real length(const Vector3& v) { return std::sqrt(dot(v, v)); }
// As POV-Ray's VNormalize: times the reciprocal of the length (not divided by it), for
// the same last bits.
inline Vector3 normalize(const Vector3& v) {
    Real l = length(v);
    return l > 0 ? v * (1.0 / l) : v;
}
inline Vector3 min(const Vector3& a, const Vector3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vector3 max(const Vector3& a, const Vector3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

struct Bounds3 {
    Point3 lo{kInfinity, kInfinity, kInfinity};
    Point3 hi{-kInfinity, -kInfinity, -kInfinity};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool infinite() const {
        return std::isinf(lo.x) || std::isinf(lo.y) || std::isinf(lo.z) ||
               std::isinf(hi.x) || std::isinf(hi.y) || std::isinf(hi.z);
    }
    void extend(const Point3& p) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    void extend(const Bounds3& b) {
        lo = min(lo, b.lo);
        hi = max(hi, b.hi);
    }
    Point3 centre() const { return (lo + hi) * 0.5; }
    Vector3 diagonal() const { return hi - lo; }
    static Bounds3 everything() {
        return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
    }
};
inline Bounds3 intersection(const Bounds3& a, const Bounds3& b) {
    return {max(a.lo, b.lo), min(a.hi, b.hi)};
}

struct Ray {
    Point3 origin;
    Vector3 direction;  // not necessarily unit length after an inverse transform
    Point3 at(Real t) const { return origin + direction * t; }
};

// Affine transform as a 3x4 matrix with its inverse kept alongside, as POV-Ray keeps
// both.
struct Matrix34 {
    // m[row][col]; column 3 is the translation.
    Real m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
};

class Transform {
  public:
    Transform() = default;
    static Transform translate(const Vector3& t);
    static Transform scale(const Vector3& s);
    // Rotation in degrees about x, then y, then z, as POV-Ray's `rotate <x,y,z>`.
    static Transform rotate(const Vector3& degrees);
    // POV-Ray's `matrix <a,b,c, d,e,f, g,h,i, j,k,l>`: rows are images of x, y, z,
    // translation.
    static Transform from_pov_matrix(const Real v[12]);
    static Transform from_matrix(const Matrix34& fwd);
    // A matrix with the inverse POV-Ray keeps for it (a rotation's transpose, say), not
    // one computed by inversion.
    static Transform from_matrices(const Matrix34& fwd, const Matrix34& inv) {
        Transform t;
        t.fwd_ = fwd;
        t.inv_ = inv;
        t.identity_ = false;
        return t;
    }

    // `*this` followed by `next` (POV-Ray applies transforms in source order).
    Transform then(const Transform& next) const;
    Transform inverse() const {
        Transform t;
        t.fwd_ = inv_;
        t.inv_ = fwd_;
        t.identity_ = identity_;
        return t;
    }
    bool is_identity() const { return identity_; }

    Point3 point(const Point3& p) const { return apply(fwd_, p, 1); }
    Vector3 vector(const Vector3& v) const { return apply(fwd_, v, 0); }
    Point3 inverse_point(const Point3& p) const { return apply(inv_, p, 1); }
    Vector3 inverse_vector(const Vector3& v) const { return apply(inv_, v, 0); }
    // Normals transform by the inverse transpose.
    Vector3 normal(const Vector3& n) const {
        return {inv_.m[0][0] * n.x + inv_.m[1][0] * n.y + inv_.m[2][0] * n.z,
                inv_.m[0][1] * n.x + inv_.m[1][1] * n.y + inv_.m[2][1] * n.z,
                inv_.m[0][2] * n.x + inv_.m[1][2] * n.y + inv_.m[2][2] * n.z};
    }
    Ray inverse_ray(const Ray& r) const {
        return {inverse_point(r.origin), inverse_vector(r.direction)};
    }
    Bounds3 bounds(const Bounds3& b) const;  // world bounds of transformed box
    const Matrix34& forward() const { return fwd_; }
    const Matrix34& inverse_matrix() const { return inv_; }

  private:
    static Vector3 apply(const Matrix34& m, const Vector3& v, Real w) {
        return {m.m[0][0] * v.x + m.m[0][1] * v.y + m.m[0][2] * v.z + m.m[0][3] * w,
                m.m[1][0] * v.x + m.m[1][1] * v.y + m.m[1][2] * v.z + m.m[1][3] * w,
                m.m[2][0] * v.x + m.m[2][1] * v.y + m.m[2][2] * v.z + m.m[2][3] * w};
    }
    Matrix34 fwd_, inv_;
    bool identity_ = true;
};

}  // namespace povwall
