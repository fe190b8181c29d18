// The rays of a mesh camera (core/mesh_camera.h), as POV-Ray 3.7's CreateCameraRay
// makes them for its MESH_CAMERA.
#pragma once

#include <optional>

#include "core/mesh_camera.h"

namespace povwall::trace {

// Ray `ray` (0 to rays_per_pixel - 1) at POV-Ray's shifted pixel position (x, y) (pixel
// i's centre at (i + 0.5, j - 0.5), see camera.h) of an image width x height; none where
// the pixel has no face (POV-Ray then leaves the ray out of the pixel's average). The
// direction is not yet unit (the caller normalises it, after a camera normal).
std::optional<Ray> mesh_camera_ray(const MeshCamera& mc, const Camera& camera,
                                   Real shifted_x, Real shifted_y, int width, int height,
                                   int ray);

}  // namespace povwall::trace
