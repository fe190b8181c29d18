#include "core/height_field.h"

#include <algorithm>
#include <cmath>

#include "core/math_constants.h"

namespace povwall {
namespace {

constexpr Real kOffset = 0.001;  // HFIELD_OFFSET: the box's margin above and below
constexpr Real kBoundHuge = 2e10;

// POV-Ray's HField::normalize (times the reciprocal, as its VInverseScale): a vector
// shorter than EPSILON becomes +y.
Vector3 normalized_or_up(const Vector3& v) {
    const Real len = length(v);
    return len > kPovEpsilon ? v * (1.0 / len) : Vector3{0, 1, 0};
}

// The unit normal (upwards) of the triangle of vertex (x0, z0) and its neighbours 1 and
// 2, added to `sum`; false when a neighbour is off the grid.
bool add_triangle_normal(const HeightFieldData& d, int x0, int z0, int x1, int z1, int x2,
                         int z2, Vector3& sum) {
    const int xs = d.width - 1, zs = d.depth - 1;
    for (int v : {x0, x1, x2})
        if (v < 0 || v > xs) return false;
    for (int v : {z0, z1, z2})
        if (v < 0 || v > zs) return false;
    const Vector3 v0{Real(x0), d.at(x0, z0), Real(z0)};
    const Vector3 v1{Real(x1), d.at(x1, z1), Real(z1)};
    const Vector3 v2{Real(x2), d.at(x2, z2), Real(z2)};
    Vector3 n = normalized_or_up(cross(v2 - v0, v1 - v0));
    if (n.y < 0) n = -n;
    sum = sum + n;
    return true;
}

void build_blocks(HeightFieldData& d, bool hierarchy) {
    int nx = std::max(1, int(std::sqrt(Real(d.max_x))));
    int nz = std::max(1, int(std::sqrt(Real(d.max_z))));
    const int wx = int(std::ceil(Real(d.max_x + 2) / Real(nx)));
    const int wz = int(std::ceil(Real(d.max_z + 2) / Real(nz)));
    if (nx * wx < d.max_x + 2) ++nx;
    if (nz * wz < d.max_z + 2) ++nz;
    d.blocks.clear();
    if (!hierarchy || (nx == 1 && nz == 1)) {
        d.blocks_x = d.blocks_z = 1;
        d.block_width_x = d.max_x + 2;
        d.block_width_z = d.max_z + 2;
        d.blocks.push_back({0, d.max_x, 0, d.max_z, d.floor_y, d.top_y});
        return;
    }
    d.blocks_x = nx;
    d.blocks_z = nz;
    d.block_width_x = wx;
    d.block_width_z = wz;
    // POV-Ray takes the water level from the box's floor here, already lowered by the
    // margin once.
    const Real water = d.floor_y;
    for (int bz = 0; bz < nz; ++bz) {
        for (int bx = 0; bx < nx; ++bx) {
            HeightFieldBlock b;
            b.xmin = bx * wx;
            b.zmin = bz * wz;
            b.xmax = std::min((bx + 1) * wx - 1, d.max_x);
            b.zmax = std::min((bz + 1) * wz - 1, d.max_z);
            Real lo = kBoundHuge, hi = -kBoundHuge;
            for (int x = b.xmin; x <= b.xmax + 1; ++x) {
                for (int z = b.zmin; z <= b.zmax + 1; ++z) {
                    lo = std::min(lo, d.at(x, z));
                    hi = std::max(hi, d.at(x, z));
                }
            }
            b.ymin = std::max(lo, water) - kOffset;
            b.ymax = hi + kOffset;
            d.blocks.push_back(b);
        }
    }
}

}  // namespace

HeightFieldData make_height_field(int width, int depth, std::vector<uint16_t> heights,
                                  Real water, bool smooth, bool hierarchy) {
    HeightFieldData d;
    d.width = width;
    d.depth = depth;
    d.heights = std::move(heights);
    const auto [lo, hi] = std::minmax_element(d.heights.begin(), d.heights.end());
    d.min_height = *lo;
    d.max_height = *hi;
    d.floor_y = std::max(Real(d.min_height), water) - kOffset;
    d.top_y = Real(d.max_height) + kOffset;
    if (smooth) {
        d.normals.resize(d.heights.size());
        for (int z = 0; z < depth; ++z) {
            for (int x = 0; x < width; ++x) {
                Vector3 sum{0, 0, 0};
                add_triangle_normal(d, x, z, x + 1, z, x, z + 1, sum);
                add_triangle_normal(d, x, z, x, z + 1, x - 1, z, sum);
                add_triangle_normal(d, x, z, x - 1, z, x, z - 1, sum);
                add_triangle_normal(d, x, z, x, z - 1, x + 1, z, sum);
                const Vector3 n = normalized_or_up(sum);
                d.normals[size_t(z) * size_t(width) + size_t(x)] = {
                    int16_t(32767 * n.x), int16_t(32767 * n.y), int16_t(32767 * n.z)};
            }
        }
    }
    d.max_x = width - 2;
    d.max_z = depth - 2;
    build_blocks(d, hierarchy);
    return d;
}

}  // namespace povwall
