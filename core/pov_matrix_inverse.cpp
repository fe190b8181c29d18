// POV-Ray's 4x4 inverse (see core/pov_matrix_inverse.h).
#include "core/pov_matrix_inverse.h"

namespace povwall {

bool pov_invert_4x4(const Real m[4][4], Real r[4][4]) {
    const Real m00 = m[0][0], m01 = m[0][1], m02 = m[0][2], m03 = m[0][3];
    const Real m10 = m[1][0], m11 = m[1][1], m12 = m[1][2], m13 = m[1][3];
    const Real m20 = m[2][0], m21 = m[2][1], m22 = m[2][2], m23 = m[2][3];
    const Real m30 = m[3][0], m31 = m[3][1], m32 = m[3][2], m33 = m[3][3];
    // The 3x3 minors, each as six triple products (the rule of Sarrus).
    auto minor = [](Real a0, Real a1, Real a2, Real b0, Real b1, Real b2, Real c0,
                    Real c1, Real c2) {
        return a0 * b1 * c2 + a1 * b2 * c0 + a2 * b0 * c1 - c0 * b1 * a2 - c1 * b2 * a0 -
               c2 * b0 * a1;
    };
    const Real d00 = minor(m11, m12, m13, m21, m22, m23, m31, m32, m33);
    const Real d01 = minor(m10, m12, m13, m20, m22, m23, m30, m32, m33);
    const Real d02 = minor(m10, m11, m13, m20, m21, m23, m30, m31, m33);
    const Real d03 = minor(m10, m11, m12, m20, m21, m22, m30, m31, m32);
    const Real d10 = minor(m01, m02, m03, m21, m22, m23, m31, m32, m33);
    const Real d11 = minor(m00, m02, m03, m20, m22, m23, m30, m32, m33);
    const Real d12 = minor(m00, m01, m03, m20, m21, m23, m30, m31, m33);
    const Real d13 = minor(m00, m01, m02, m20, m21, m22, m30, m31, m32);
    const Real d20 = minor(m01, m02, m03, m11, m12, m13, m31, m32, m33);
    const Real d21 = minor(m00, m02, m03, m10, m12, m13, m30, m32, m33);
    const Real d22 = minor(m00, m01, m03, m10, m11, m13, m30, m31, m33);
    const Real d23 = minor(m00, m01, m02, m10, m11, m12, m30, m31, m32);
    const Real d30 = minor(m01, m02, m03, m11, m12, m13, m21, m22, m23);
    const Real d31 = minor(m00, m02, m03, m10, m12, m13, m20, m22, m23);
    const Real d32 = minor(m00, m01, m03, m10, m11, m13, m20, m21, m23);
    const Real d33 = minor(m00, m01, m02, m10, m11, m12, m20, m21, m22);
    const Real det = m00 * d00 - m01 * d01 + m02 * d02 - m03 * d03;
    if (det == 0) return false;
    const Real d[4][4] = {{d00, d01, d02, d03},
                          {d10, d11, d12, d13},
                          {d20, d21, d22, d23},
                          {d30, d31, d32, d33}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = ((i + j) % 2 ? -d[j][i] : d[j][i]) / det;
    return true;
}

}  // namespace povwall
