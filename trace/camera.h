// Primary rays: POV-Ray 3.7's pixel-to-ray mapping for each camera type (pixel centres,
// row 0 at the top, no automatic aspect correction).
#pragma once

#include <cmath>
#include <optional>

#include "core/scene.h"

namespace povwall::trace {

// The primary ray through image position (px, py), in pixels from the top-left corner
// (pixel centres are at +0.5), with a unit direction; none where the camera sees nothing
// (outside the fisheye circle), which POV-Ray renders black and fully transparent.
// POV-Ray's own form: its pixel position (x, y) (pixel i's centre at i), which it moves
// to (x + 0.5, y - 0.5) before scaling; `shifted` is that moved position.
inline std::optional<Ray> camera_ray_shifted(const Camera& cam, Real shifted_x,
                                             Real shifted_y, int width, int height);

inline std::optional<Ray> camera_ray(const Camera& cam, Real px, Real py, int width,
                                     int height) {
    return camera_ray_shifted(cam, px, py - 1.0, width, height);
}

// The ray of POV-Ray's pixel position (x, y) (pixel (i, j)'s centre at (i, j)), rounded
// as POV-Ray rounds it, for anti-aliasing's sub-pixel samples.
inline std::optional<Ray> camera_ray_pov(const Camera& cam, Real x, Real y, int width,
                                         int height) {
    return camera_ray_shifted(cam, x + 0.5, y - 0.5, width, height);
}

inline std::optional<Ray> camera_ray_shifted(const Camera& cam, Real shifted_x,
                                             Real shifted_y, int width, int height) {
    using Kind = Camera::Kind;
    // Image position from -0.5 to 0.5, right and up, rounded as POV-Ray computes it
    // (y from the bottom row). The last bits decide which side of a surface lying on a
    // pattern's edge (an onion's r = 1 on a unit sphere) a hit falls.
    const Real x0 = shifted_x / width - 0.5;
    const Real y0 = ((height - 1) - shifted_y) / height - 0.5;
    switch (cam.kind) {
        case Kind::Perspective:
            break;
        case Kind::Orthographic:
            return Ray{cam.location + cam.right * x0 + cam.up * y0,
                       normalize(cam.direction)};
        default: {
            // The other projections use the unit camera axes; the lengths of right and up
            // only set the aspect ratio (as POV-Ray's camera set-up does).
            const Real right_len = length(cam.right), up_len = length(cam.up);
            const Vector3 r = cam.right / right_len, u = cam.up / up_len;
            const Vector3 d = normalize(cam.direction);
            const Real angle = cam.angle * kPi / 180;
            Point3 origin = cam.location;
            Vector3 dir;
            switch (cam.kind) {
                case Kind::Fisheye: {
                    // Polar coordinates of the image point in the unit circle: the radius
                    // is the angle from the view axis (1 = half the viewing angle).
                    const Real fx = 2 * x0 * right_len, fy = 2 * y0 * up_len;
                    const Real rad = std::sqrt(fx * fx + fy * fy);
                    if (rad > 1) return std::nullopt;
                    Real phi = 0;
                    if (rad != 0)
                        phi = fx < 0 ? kPi - std::asin(fy / rad) : std::asin(fy / rad);
                    const Real theta = rad * angle / 2;
                    dir = r * (std::cos(phi) * std::sin(theta)) +
                          u * (std::sin(phi) * std::sin(theta)) + d * std::cos(theta);
                    break;
                }
                case Kind::UltraWideAngle: {
                    const Real ax = x0 * angle, ay = y0 * angle * (up_len / right_len);
                    dir = r * std::sin(ax) + u * std::sin(ay) +
                          d * (std::cos(ax) * std::cos(ay));
                    break;
                }
                case Kind::Panoramic: {
                    // 180 degrees across, latitude from -90 to 90 degrees mapped by tan.
                    const Real lon = (1 - (x0 + 0.5)) * kPi, lat = kPi / 2 * (2 * y0);
                    constexpr Real kHuge = 2e10;  // POV-Ray's BOUND_HUGE at the poles
                    Real ty = std::fabs(kPi / 2 - std::fabs(lat)) < 1e-10
                                  ? (lat > 0 ? kHuge : -kHuge)
                                  : std::tan(lat);
                    // POV-Ray does not normalise the camera vectors for this one.
                    dir = cam.right * std::cos(lon) + cam.up * ty +
                          cam.direction * std::sin(lon);
                    break;
                }
                case Kind::Cylinder1:  // vertical axis, perspective up/down
                    dir = r * std::sin(x0 * angle) + u * (y0 * up_len) +
                          d * std::cos(x0 * angle);
                    break;
                case Kind::Cylinder2:  // horizontal axis, perspective left/right
                    dir = r * (x0 * right_len) + u * std::sin(y0 * angle) +
                          d * std::cos(y0 * angle);
                    break;
                case Kind::Cylinder3:  // vertical axis, orthographic up/down
                    dir = r * std::sin(x0 * angle) + d * std::cos(x0 * angle);
                    origin = cam.location + u * (y0 * up_len);
                    break;
                case Kind::Cylinder4:  // horizontal axis, orthographic left/right
                    dir = u * std::sin(y0 * angle) + d * std::cos(y0 * angle);
                    origin = cam.location + r * (x0 * right_len);
                    break;
                default:
                    break;
            }
            return Ray{origin, normalize(dir)};
        }
    }
    const Vector3 dir = cam.direction + cam.right * x0 + cam.up * y0;
    return Ray{cam.location, dir * (1.0 / length(dir))};  // POV-Ray's VNormalize
}

}  // namespace povwall::trace
