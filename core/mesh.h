// mesh and mesh2 geometry: triangles over shared vertices, held once however many
// objects copy the mesh (as POV-Ray shares a mesh's data between its copies), with a box
// tree over the faces for rays that meet the mesh whole (copies, CSG, clips) instead of
// its triangles one by one. The per-object part (face textures, which a copy's
// transform moves) is core/scene.h's Mesh.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/box_tree.h"
#include "core/heap_optional.h"
#include "core/math.h"

namespace povwall {

struct MeshFace {
    uint32_t v[3];
    int32_t n[3] = {-1, -1, -1};
    // Index into the object's face textures (Mesh::textures); -1: the mesh's texture;
    // -2 - k: the three textures of texture_triples[k] (rare, so kept out of every face).
    int32_t texture = -1;
};

// What the mesh's braces define. Made once by the parser and shared (const) by every
// object that copies the mesh.
struct MeshData {
    std::vector<Point3> vertices;
    std::vector<Vector3> normals;  // empty when flat
    std::vector<MeshFace> faces;
    // Texture coordinates (mesh2 uv_vectors, a mesh triangle's uv_vectors) and per face,
    // parallel to `faces`, the indices of its corners' coordinates; both empty when the
    // mesh has none (every corner then has (0, 0), as POV-Ray's).
    std::vector<std::array<Real, 2>> uvs;
    std::vector<std::array<uint32_t, 3>> uv_faces;
    // Faces with a texture per corner (mesh2 `<a, b, c>, t0, t1, t2`, a mesh triangle's
    // texture_list): POV-Ray blends them by the hit's barycentric weights.
    std::vector<std::array<int32_t, 3>> texture_triples;
    HeapOptional<Vector3> inside_vector;  // only a mesh with one is solid

    // The box tree over the faces (each face's box that of its corners in single
    // precision, as POV-Ray stores them), built on first use (by any thread; once).
    const BoxTree& tree() const;

  private:
    mutable std::once_flag tree_built_;
    mutable BoxTree tree_;
};

}  // namespace povwall
