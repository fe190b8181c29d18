#include "core/math.h"

#include "core/pov_matrix_inverse.h"

namespace povwall {
namespace {

// a after b, summed in POV-Ray's order (its MTimesA/MTimesB on row-vector matrices): the
// three products first, then a's translation. Adding the translation first rounds
// differently, and one bit of a transformed ray is enough to change which round-off
// roots a sor or lathe met edge-on reports.
Matrix34 multiply(const Matrix34& a, const Matrix34& b) {
    Matrix34 r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            Real s =
                a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
            if (j == 3) s += a.m[i][3];
            r.m[i][j] = s;
        }
    }
    return r;
}

Matrix34 invert(const Matrix34& a) {
    const auto& m = a.m;
    Real c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    Real c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    Real c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    Real det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    Matrix34 r;
    if (det == 0) {
        // Singular (e.g. scale 0): keep it finite; POV-Ray warns and clamps scale to
        // 1e-10.
        det = 1e-300;
    }
    Real id = 1 / det;
    r.m[0][0] = c00 * id;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
    r.m[1][0] = c01 * id;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
    r.m[2][0] = c02 * id;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
    for (int i = 0; i < 3; ++i) {
        r.m[i][3] = -(r.m[i][0] * m[0][3] + r.m[i][1] * m[1][3] + r.m[i][2] * m[2][3]);
    }
    return r;
}

}  // namespace

Transform Transform::from_matrix(const Matrix34& fwd) {
    Transform t;
    t.fwd_ = fwd;
    t.inv_ = invert(fwd);
    t.identity_ = false;
    return t;
}

Transform Transform::translate(const Vector3& v) {
    Matrix34 f;
    f.m[0][3] = v.x;
    f.m[1][3] = v.y;
    f.m[2][3] = v.z;
    Transform t;
    t.fwd_ = f;
    t.inv_ = f;
    t.inv_.m[0][3] = -v.x;
    t.inv_.m[1][3] = -v.y;
    t.inv_.m[2][3] = -v.z;
    t.identity_ = false;
    return t;
}

Transform Transform::scale(const Vector3& s) {
    Matrix34 f;
    f.m[0][0] = s.x;
    f.m[1][1] = s.y;
    f.m[2][2] = s.z;
    if (s.x == 0 || s.y == 0 || s.z == 0) return from_matrix(f);  // kept finite there
    // The inverse holds 1/s as POV-Ray's Compute_Scaling_Transform does: the general
    // inversion gives s*s/(s*s*s), an ulp off for most s, and that ulp flips decisions
    // in chaotic shapes (julia_fractal's dust).
    Transform t;
    t.fwd_ = f;
    t.inv_.m[0][0] = 1 / s.x;
    t.inv_.m[1][1] = 1 / s.y;
    t.inv_.m[2][2] = 1 / s.z;
    t.identity_ = false;
    return t;
}

Transform Transform::rotate(const Vector3& deg) {
    Transform t;
    const Real k = kPi / 180;
    for (int axis = 0; axis < 3; ++axis) {
        Real a = deg[axis] * k;
        if (a == 0) continue;
        Real c = std::cos(a), s = std::sin(a);
        Matrix34 f;
        int i = (axis + 1) % 3, j = (axis + 2) % 3;
        f.m[i][i] = c;
        f.m[j][j] = c;
        f.m[j][i] = s;
        f.m[i][j] = -s;
        Transform r;
        r.fwd_ = f;
        // A rotation's inverse is its transpose.
        Matrix34 inv = f;
        inv.m[i][j] = s;
        inv.m[j][i] = -s;
        r.inv_ = inv;
        r.identity_ = false;
        t = t.then(r);
    }
    return t;
}

Transform Transform::from_pov_matrix(const Real v[12]) {
    Matrix34 f;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) f.m[row][col] = v[col * 3 + row];
        f.m[row][3] = v[9 + row];
    }
    // The inverse as POV-Ray's MInvers computes it from its 4x4 (rows: the images of x,
    // y, z, then the translation; last column 0, 0, 0, 1), element for element: a
    // general inverse differs in the last bits, which change the round-off roots of a
    // sor met edge-on for most rays.
    const Real pov[4][4] = {{v[0], v[1], v[2], 0},
                            {v[3], v[4], v[5], 0},
                            {v[6], v[7], v[8], 0},
                            {v[9], v[10], v[11], 1}};
    Real pov_inverse[4][4];
    if (!pov_invert_4x4(pov, pov_inverse)) return from_matrix(f);  // kept finite
    Matrix34 inv;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) inv.m[row][col] = pov_inverse[col][row];
        inv.m[row][3] = pov_inverse[3][row];
    }
    return from_matrices(f, inv);
}

Transform Transform::then(const Transform& next) const {
    if (identity_) return next;
    if (next.identity_) return *this;
    Transform t;
    t.fwd_ = multiply(next.fwd_, fwd_);
    t.inv_ = multiply(inv_, next.inv_);
    t.identity_ = false;
    return t;
}

Bounds3 Transform::bounds(const Bounds3& b) const {
    if (identity_ || b.empty()) return b;
    if (b.infinite()) return Bounds3::everything();
    Bounds3 r;
    for (int i = 0; i < 8; ++i) {
        Point3 p{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                 (i & 4) ? b.hi.z : b.lo.z};
        r.extend(point(p));
    }
    return r;
}

}  // namespace povwall
