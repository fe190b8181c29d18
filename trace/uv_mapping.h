// uv_mapping: the surface coordinates of a hit, as POV-Ray 3.7's UVCoord of each shape
// defines them (spheres, ovus: longitude and latitude; box: a cube-map layout; torus:
// the angles round the axis and round the tube; lathe and sor: the angle round y and the
// segment; bicubic_patch: its parameters through its uv_vectors; mesh: its corners'
// uv_vectors blended; any other shape: the world point's x and y).
#pragma once

#include "trace/prepared_scene.h"

namespace povwall::trace {

// (u, v, 0): where a pattern under uv_mapping is evaluated at `hit`.
Point3 surface_uv(const Hit& hit);

}  // namespace povwall::trace
