// Primary rays: POV-Ray 3.7's pixel-to-ray mapping (pixel centres, row 0 at the top, no
// automatic aspect correction).
#pragma once

#include "core/scene.h"

namespace povwall::trace {

// The primary ray through image position (px, py), in pixels from the top-left corner (pixel
// centres are at +0.5). Direction is unit length.
inline Ray camera_ray(const Camera& cam, Real px, Real py, int width, int height) {
    const Real x0 = px / width - 0.5;
    const Real y0 = 0.5 - py / height;
    if (cam.kind == Camera::Kind::Orthographic) {
        return {cam.location + cam.right * x0 + cam.up * y0, normalize(cam.direction)};
    }
    return {cam.location, normalize(cam.direction + cam.right * x0 + cam.up * y0)};
}

}  // namespace povwall::trace
