// mesh_camera { rays_per_pixel distribution [max_distance] mesh { } ... [smooth] }
// (POV-Ray 3.7, parse.cpp Parse_Mesh_Camera): every camera ray starts on a face of the
// given meshes and leaves it along the face's normal. The distribution picks the face
// from the pixel (trace/mesh_camera.h); the camera's location.z moves the start along
// the normal and a negative direction.z turns the ray around.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/scene.h"

namespace povwall {

struct MeshCamera {
    int rays_per_pixel = 1;
    // 0: ray k of a pixel from mesh k, a face per pixel; 1: the meshes' faces one after
    // the other, a face per pixel; 2: the meshes side by side across the image; 3: the
    // first mesh's point whose uv coordinates are the pixel's (`smooth`: the normal
    // there interpolated from its vertex normals).
    int distribution = 0;
    bool smooth = false;
    // In POV-Ray's corner order (Compute_Mesh_Triangle may swap the first two).
    struct Face {
        Point3 p[3];     // corners in mesh space, single precision as POV-Ray keeps them
        Vector3 normal;  // unit (p2 - p0) x (p1 - p0), single precision
        Vector3 n[3];    // unit vertex normals, single precision (smooth faces)
        Real u[3] = {0, 0, 0}, v[3] = {0, 0, 0};  // texture coordinates
        // POV-Ray's Smooth_Mesh_Normal: its Perp (single precision) and vAxis.
        Vector3 perp{0, 0, 0};
        int v_axis = 0;
        bool smooth = false;
    };
    struct Part {
        std::vector<Face> faces;
        CompactTransform transform;  // mesh space -> world
    };
    std::vector<Part> meshes;
    std::vector<uint32_t> face_ends;  // running face counts (POV-Ray's Mesh_Index)
    // Distribution 3: per tenth of u (and of v), bit sets of the first mesh's faces whose
    // coordinates reach into it (POV-Ray's U_Xref and V_Xref).
    std::array<std::vector<uint32_t>, 10> u_faces, v_faces;
};

}  // namespace povwall
