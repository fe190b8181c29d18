// bicubic_patch: a Bezier patch of 16 control points, cut into flat pieces as POV-Ray
// 3.7 cuts it (bezier.cpp): subdivided in u and v up to u_steps / v_steps levels or
// until a piece is flatter than `flatness`; each leaf is two triangles. Transforms move
// the control points (POV-Ray keeps no matrix for a patch), so the pieces are rebuilt
// after each one. The intersection lives in trace/shapes/bicubic_patch.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace povwall {

struct BicubicPatchData {
    // control[4 * i + j]: i along u (the rows as written), j along v.
    std::array<Point3, 16> control;
    int type = 1;
    int u_steps = 0, v_steps = 0;
    Real flatness = 0;
    // `uv_vectors`: the texture coordinates of the patch's corners (u, v) = (0, 0),
    // (1, 0), (1, 1), (0, 1), which uv_mapping interpolates bilinearly.
    std::array<std::array<Real, 2>, 4> uv_vectors{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

    // A leaf's triangle with what POV-Ray's test derives from its corners: the dual basis
    // of its edges and unit normal (zero `e2` when POV-Ray drops it as degenerate), and
    // the patch's exact unit normals at its corners' parameters.
    struct Triangle {
        Point3 v0;
        Vector3 e0, e1, e2;
        Vector3 normal[3];
        Real u[3], v[3];
        bool valid = false;
    };
    // Preorder tree of pieces; every node has the bounding sphere of its control points.
    struct Node {
        Point3 centre;
        Real radius2 = 0;
        int32_t leaf = -1;  // index into `leaves`, or -1 for an inner node
        uint8_t child_count = 0;
        uint32_t child[4] = {0, 0, 0, 0};
    };
    std::vector<Node> nodes;
    std::vector<std::array<Triangle, 2>> leaves;
};

// The pieces of `d` from its control points and steps (replaces d.nodes and d.leaves).
void build_patch_pieces(BicubicPatchData& d);
// The patch's unit normal at (u, v): dP/du x dP/dv, or (1, 0, 0) where that vanishes.
Vector3 patch_normal(const BicubicPatchData& d, Real u, Real v);

}  // namespace povwall
