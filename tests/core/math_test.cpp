#include "core/math.h"

#include <gtest/gtest.h>

namespace povwall {
namespace {

void expect_near(const Vector3& a, const Vector3& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Transform, RotateFollowsPovRayLeftHandedConvention) {
    // POV-Ray: rotate 90*y turns +x into -z (left-handed, clockwise looking down +y).
    Transform r = Transform::rotate({0, 90, 0});
    expect_near(r.vector({1, 0, 0}), {0, 0, -1});
    // rotate 90*z turns +x into +y; rotate 90*x turns +y into +z.
    expect_near(Transform::rotate({0, 0, 90}).vector({1, 0, 0}), {0, 1, 0});
    expect_near(Transform::rotate({90, 0, 0}).vector({0, 1, 0}), {0, 0, 1});
}

TEST(Transform, ThenAppliesInSourceOrderAndInverts) {
    Transform t = Transform::scale({2, 3, 4}).then(Transform::translate({1, 1, 1}));
    expect_near(t.point({1, 1, 1}), {3, 4, 5});
    expect_near(t.inverse_point({3, 4, 5}), {1, 1, 1});
    Transform u = t.then(Transform::rotate({10, 20, 30}));
    expect_near(u.inverse_point(u.point({0.3, -2, 7})), {0.3, -2, 7}, 1e-12);
}

TEST(Transform, NormalsUseInverseTranspose) {
    Transform t = Transform::scale({1, 4, 1});
    Vector3 n = normalize(t.normal({1, 1, 0}));
    // Surface x + y = 1 scaled by 4 in y becomes x + y/4 = 1: normal (1, 1/4, 0).
    expect_near(n, normalize(Vector3{1, 0.25, 0}));
}

TEST(Transform, PovMatrixRowsAreAxisImages) {
    Real m[12] = {1, 0, 0, 1, 1, 0, 0, 0, 1, 5, 6, 7};  // shear: y axis maps to (1,1,0)
    Transform t = Transform::from_pov_matrix(m);
    expect_near(t.point({0, 1, 0}), {6, 7, 7});
    expect_near(t.inverse_point({6, 7, 7}), {0, 1, 0});
}

TEST(Bounds3, TransformedBoundsEncloseCorners) {
    Bounds3 b{{-1, -1, -1}, {1, 1, 1}};
    Bounds3 r = Transform::rotate({0, 45, 0}).bounds(b);
    EXPECT_NEAR(r.hi.x, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(r.lo.z, -std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(r.hi.y, 1.0, 1e-12);
}

}  // namespace
}  // namespace povwall
