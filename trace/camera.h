// Primary rays: POV-Ray 3.7's pixel-to-ray mapping for each camera type (pixel centres,
// row 0 at the top, no automatic aspect correction).
#pragma once

#include <cmath>
#include <optional>

#include "core/pov_angles.h"
#include "core/scene.h"
#include "trace/mesh_camera.h"
#include "trace/pattern.h"

namespace povwall::trace {

// Focal blur's move of one ray (focal_blur.h): the ray starts at the camera location plus
// `deflection` (a point of the aperture) and aims at where the unmoved ray's direction,
// times `focal_scale`, ends (on the focal plane).
struct ApertureShift {
    Vector3 deflection;
    Real focal_scale = 1;
};

// The primary ray through image position (px, py), in pixels from the top-left corner
// (pixel centres are at +0.5), with a unit direction; none where the camera sees nothing
// (outside the fisheye circle), which POV-Ray renders black and fully transparent.
// POV-Ray's own form: its pixel position (x, y) (pixel i's centre at i), which it moves
// to (x + 0.5, y - 0.5) before scaling; `shifted` is that moved position.
// `mesh_ray`: which of a mesh camera's rays per pixel.
inline std::optional<Ray> camera_ray_shifted(const Camera& cam, Real shifted_x,
                                             Real shifted_y, int width, int height,
                                             const ApertureShift* shift = nullptr,
                                             int mesh_ray = 0);

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
                                             Real shifted_y, int width, int height,
                                             const ApertureShift* shift, int mesh_ray) {
    using Kind = Camera::Kind;
    // Image position from -0.5 to 0.5, right and up, rounded as POV-Ray computes it
    // (y from the bottom row). The last bits decide which side of a surface lying on a
    // pattern's edge (an onion's r = 1 on a unit sphere) a hit falls.
    const Real x0 = shifted_x / width - 0.5;
    const Real y0 = ((height - 1) - shifted_y) / height - 0.5;
    // Where a camera `normal` is evaluated: the kind's own image coordinates, as POV-Ray
    // leaves them after making the ray (its x0, y0: angles for the angular kinds).
    Real pattern_x = x0, pattern_y = y0;
    Ray ray;
    // The ray from `origin` along `dir` (not unit yet), moved by focal blur: POV-Ray then
    // starts every kind's rays at the location plus the aperture point (an orthographic
    // camera's too).
    auto make = [&](const Point3& origin, Vector3 dir) {
        if (!shift) return Ray{origin, normalize(dir)};  // as POV-Ray's VNormalize
        dir = dir * shift->focal_scale - shift->deflection;
        return Ray{cam.location + shift->deflection, normalize(dir)};
    };
    switch (cam.kind) {
        case Kind::Mesh: {
            // Its pattern position for a camera normal stays (0, 0), as POV-Ray's.
            pattern_x = pattern_y = 0;
            const std::optional<Ray> r = mesh_camera_ray(
                *cam.mesh, cam, shifted_x, shifted_y, width, height, mesh_ray);
            if (!r) return std::nullopt;
            ray = Ray{r->origin, normalize(r->direction)};
            break;
        }
        case Kind::Perspective:
            ray = make(cam.location, cam.direction + cam.right * x0 + cam.up * y0);
            break;
        case Kind::Orthographic:
            ray = make(cam.location + cam.right * x0 + cam.up * y0, cam.direction);
            break;
        case Kind::Spherical: {
            // Latitude: the direction turned about `right`; then longitude: about `up`.
            const Real lon = x0 * (cam.h_angle / 360 * 2 * kPi);
            const Real lat = y0 * (cam.v_angle / 360 * 2 * kPi);
            pattern_x = lon, pattern_y = lat;
            auto turn = [](const Vector3& v, const Vector3& axis, Real a) {
                const Vector3 k = normalize(axis);
                const Real c = std::cos(a), s = std::sin(a);
                return v * c + k * (dot(k, v) * (1 - c)) + cross(k, v) * s;
            };
            const Vector3 v = turn(cam.direction, cam.right, -lat);
            ray = make(cam.location, turn(v, cam.up, lon));
            break;
        }
        default: {
            // The other projections use the unit camera axes; the lengths of right and up
            // only set the aspect ratio (as POV-Ray's camera set-up does).
            const Real right_len = length(cam.right), up_len = length(cam.up);
            const Vector3 r = cam.right / right_len, u = cam.up / up_len;
            const Vector3 d = normalize(cam.direction);
            // Degrees to radians as POV-Ray rounds it (core/pov_angles.h).
            const Real angle = cam.angle * kPovRadiansPerDegree;
            Point3 origin = cam.location;
            Vector3 dir;
            // The unit circle's polar angle of image point (fx, fy), as POV-Ray takes it.
            auto polar = [](Real fx, Real fy, Real rad) {
                if (rad == 0) return Real(0);
                return fx < 0 ? kPi - std::asin(fy / rad) : std::asin(fy / rad);
            };
            switch (cam.kind) {
                case Kind::Fisheye: {
                    // Polar coordinates of the image point in the unit circle: the radius
                    // is the angle from the view axis (1 = half the viewing angle).
                    const Real fx = 2 * x0 * right_len, fy = 2 * y0 * up_len;
                    const Real rad = std::sqrt(fx * fx + fy * fy);
                    if (rad > 1) return std::nullopt;
                    const Real phi = polar(fx, fy, rad);
                    const Real theta = rad * cam.angle * kPovRadiansPerHalfDegree;
                    pattern_x = phi, pattern_y = theta;
                    dir = r * (std::cos(phi) * std::sin(theta)) +
                          u * (std::sin(phi) * std::sin(theta)) + d * std::cos(theta);
                    break;
                }
                case Kind::Omnimax: {
                    // A fisheye for a dome whose image circle sits low in the frame: the
                    // radius maps to the angle from the axis by an odd polynomial, and
                    // nothing more than 45 degrees below the axis is seen.
                    Real fx = 2.0 * shifted_x / width - 1.0;
                    Real fy = 2.0 * ((height - 1) - shifted_y) / height - 1.0;
                    const Real aspect = right_len / up_len;
                    constexpr Real kWide = 1.283458;
                    if (aspect > 1.0) {
                        if (aspect > kWide) {
                            fx *= aspect / kWide;
                            fy = (fy - 1.0) / kWide + 1.0;
                        } else {
                            fy = (fy - 1.0) / aspect + 1.0;
                        }
                    } else {
                        fy /= aspect;
                    }
                    const Real rad = std::sqrt(fx * fx + fy * fy);
                    if (rad > 1.0) return std::nullopt;
                    const Real phi = polar(fx, fy, rad);
                    const Real r3 = rad * rad * rad;
                    const Real theta =
                        1.411269 * rad - 0.09439 * r3 + 0.25674 * r3 * rad * rad;
                    const Real sx = std::sin(phi), sy = std::sin(theta),
                               cy = std::cos(theta);
                    if (sx * sy < std::tan(135.0 * kPovRadiansPerDegree) * cy)
                        return std::nullopt;
                    pattern_x = phi, pattern_y = theta;
                    dir = r * (std::cos(phi) * sy) + u * (sx * sy) + d * cy;
                    break;
                }
                case Kind::UltraWideAngle: {
                    const Real ax = x0 * angle,
                               ay = y0 * (cam.angle * (up_len / right_len) *
                                          kPovRadiansPerDegree);
                    pattern_x = ax, pattern_y = ay;
                    dir = r * std::sin(ax) + u * std::sin(ay) +
                          d * (std::cos(ax) * std::cos(ay));
                    break;
                }
                case Kind::Panoramic: {
                    // 180 degrees across, latitude from -90 to 90 degrees mapped by tan.
                    const Real lon = (1 - (x0 + 0.5)) * kPi, lat = kPi / 2 * (2 * y0);
                    pattern_x = lon, pattern_y = lat;
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
                    pattern_x = x0 * angle, pattern_y = y0 * up_len;
                    dir = r * std::sin(x0 * angle) + u * (y0 * up_len) +
                          d * std::cos(x0 * angle);
                    break;
                case Kind::Cylinder2:  // horizontal axis, perspective left/right
                    pattern_x = x0 * right_len, pattern_y = y0 * angle;
                    dir = r * (x0 * right_len) + u * std::sin(y0 * angle) +
                          d * std::cos(y0 * angle);
                    break;
                case Kind::Cylinder3:  // vertical axis, orthographic up/down
                    pattern_x = x0 * angle, pattern_y = y0 * up_len;
                    dir = r * std::sin(x0 * angle) + d * std::cos(x0 * angle);
                    origin = cam.location + u * (y0 * up_len);
                    break;
                case Kind::Cylinder4:  // horizontal axis, orthographic left/right
                    pattern_x = x0 * right_len, pattern_y = y0 * angle;
                    dir = u * std::sin(y0 * angle) + d * std::cos(y0 * angle);
                    origin = cam.location + r * (x0 * right_len);
                    break;
                default:
                    break;
            }
            ray = make(origin, dir);
            break;
        }
    }
    if (cam.normal) {
        // POV-Ray perturbs the unit direction like a surface normal, then normalises.
        PatternEnv env;
        env.noise_generator = cam.normal_noise_generator;
        env.number_of_waves = cam.normal_number_of_waves;
        ray.direction = normalize(perturb_normal(
            *cam.normal, Point3{pattern_x, pattern_y, 0}, ray.direction, env));
    }
    return ray;
}

}  // namespace povwall::trace
