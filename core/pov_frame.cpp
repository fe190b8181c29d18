#include "core/pov_frame.h"

#include <cmath>

namespace povwall {

Transform pov_coordinate_transform(const Point3& origin, Vector3 up, Real radius,
                                   Real length) {
    Vector3 k;
    if (std::fabs(up.z) > 1.0 - 1e-10) {
        k = {1, 0, 0};
        up.z = up.z < 0 ? -1.0 : 1.0;
    } else {
        k = {-up.y, up.x, 0};
    }
    // Compute_Axis_Rotation_Transform: Rodrigues' matrix term by term, its inverse the
    // transpose.
    const Vector3 v = normalize(k);
    const Real angle = std::acos(up.z);
    const Real c = std::cos(angle), s = std::sin(angle);
    // p[r][c] with POV-Ray's row-vector convention (a point is p times the matrix).
    const Real p[3][3] = {
        {v.x * v.x + c * (1.0 - v.x * v.x), v.x * v.y * (1.0 - c) + v.z * s,
         v.x * v.z * (1.0 - c) - v.y * s},
        {v.x * v.y * (1.0 - c) - v.z * s, v.y * v.y + c * (1.0 - v.y * v.y),
         v.y * v.z * (1.0 - c) + v.x * s},
        {v.x * v.z * (1.0 - c) + v.y * s, v.y * v.z * (1.0 - c) - v.x * s,
         v.z * v.z + c * (1.0 - v.z * v.z)}};
    Matrix34 fwd, inv;
    for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) {
            fwd.m[col][r] = p[r][col];
            inv.m[r][col] = p[r][col];
        }
    return Transform::scale({radius, radius, length})
        .then(Transform::from_matrices(fwd, inv))
        .then(Transform::translate(origin));
}

}  // namespace povwall
