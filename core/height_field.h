// height_field: a grid of 16-bit heights, two triangles per cell, as POV-Ray 3.7's HField
// (3.7:source/backend/shape/hfield.cpp). Object space is POV-Ray's "pixel units": vertex
// (x, z) of the grid is at (x, height, z), heights 0..65535; the parser adds the scale
// that maps the grid to the unit square. The intersection lives in
// trace/shapes/height_field.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace povwall {

// A rectangle of cells with the height range of its vertices (the block walk's bounds).
struct HeightFieldBlock {
    int xmin = 0, xmax = 0, zmin = 0, zmax = 0;  // cells, inclusive
    Real ymin = 0, ymax = 0;
};

struct HeightFieldData {
    int width = 0, depth = 0;       // vertices along x and z (the image's columns, rows)
    std::vector<uint16_t> heights;  // [z * width + x]
    // With `smooth`: each vertex's normal as POV-Ray stores it (components * 32767,
    // truncated to int16); else empty.
    std::vector<std::array<int16_t, 3>> normals;
    uint16_t min_height = 0, max_height = 0;
    // The box: x in [0, width - 1], z in [0, depth - 1], y in [floor_y, top_y]
    // (the water level raised to the lowest height, less 0.001; the highest plus 0.001).
    Real floor_y = 0, top_y = 0;
    int max_x = 0, max_z = 0;  // the last cell's indices
    // The block grid (one block when the hierarchy is off or the grid is small).
    int blocks_x = 1, blocks_z = 1, block_width_x = 0, block_width_z = 0;
    std::vector<HeightFieldBlock> blocks;  // [bz * blocks_x + bx]

    Real at(int x, int z) const { return heights[size_t(z) * size_t(width) + size_t(x)]; }
    const HeightFieldBlock& block(int bx, int bz) const {
        return blocks[size_t(bz) * size_t(blocks_x) + size_t(bx)];
    }
};

// POV-Ray's Compute_HField: the heights (width * depth, row z = 0 first, at least 2 x
// 2), the water level in height units (65536 * water_level), the smooth normals and the
// blocks (hierarchy off: a single block).
HeightFieldData make_height_field(int width, int depth, std::vector<uint16_t> heights,
                                  Real water, bool smooth, bool hierarchy);

}  // namespace povwall
