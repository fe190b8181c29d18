// Small helpers to build core::Scene values directly in tests (no parser involved).
#pragma once

#include "core/scene.h"

namespace povwall::test {

inline Texture solid(Rgb c, float filter = 0, float transmit = 0) {
    Texture t;
    t.pigment.colour = Colour(c, filter, transmit);
    return t;
}

inline Object object(ShapeData shape, Transform xf = {}, LayeredTexture tex = {}) {
    Object o;
    o.shape = std::move(shape);
    o.transform = xf;
    o.texture = std::move(tex);
    return o;
}

inline Light point_light(Point3 at, Rgb colour = Rgb(1.0f)) {
    Light l;
    l.location = at;
    l.colour = colour;
    return l;
}

// Camera at the origin looking down +z with POV-Ray's default vectors.
inline Camera default_camera() { return Camera{}; }

}  // namespace povwall::test
