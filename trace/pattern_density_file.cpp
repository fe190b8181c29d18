// The density_file pattern: a df3 voxel grid over the unit cube, POV-Ray 3.7's
// density_pattern. Its value is 0 outside [0,1)^3; `interpolate` modulo 10 picks the
// nearest voxel (0), trilinear (1) or, for any other value, tricubic interpolation (in
// single precision, as POV-Ray's intp3). Both interpolations wrap around the grid's far
// faces to the near ones, as POV-Ray's index arithmetic does.
#include <cmath>
#include <cstdint>

#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

// POV-Ray's intp3: the cubic through fb (t = 0) and fc (t = 1) with slopes from the
// neighbours fa and fd, in float.
float cubic(float t, float fa, float fb, float fc, float fd) {
    const float b = (fc - fa) * 0.5;
    const float d = (fd - fb) * 0.5;
    const float e = 2.0 * (fb - fc) + b + d;
    const float f = -3.0 * (fb - fc) - 2.0 * b - d;
    return ((e * t + f) * t + b) * t + fb;
}

}  // namespace

Real density_file_value(const DensityFile& file, int interpolation, const Point3& p) {
    const uint64_t sx = file.size_x, sy = file.size_y, sz = file.size_z;
    if (sx == 0 || sy == 0 || sz == 0) return 0;
    if (!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 && p.z >= 0.0 && p.z < 1.0))
        return 0;
    const double full = file.bytes_per_voxel == 4   ? 4294967295.0
                        : file.bytes_per_voxel == 2 ? 65535.0
                                                    : 255.0;
    // Indices stay below the sizes: a coordinate just under 1 can round up to the size.
    auto at = [&](uint64_t x, uint64_t y, uint64_t z) {
        return double(file.voxels[(std::min(z, sz - 1) * sy + std::min(y, sy - 1)) * sx +
                                  std::min(x, sx - 1)]) /
               full;
    };
    Real density = 0;
    switch (interpolation % 10) {
        case 0: {
            const uint64_t x = uint64_t(p.x * double(sx));
            const uint64_t y = uint64_t(p.y * double(sy));
            const uint64_t z = uint64_t(p.z * double(sz));
            density = x >= sx || y >= sy || z >= sz ? 0.0 : at(x, y, z);
            break;
        }
        case 1: {
            double xx = p.x * double(sx), yy = p.y * double(sy), zz = p.z * double(sz);
            const uint64_t x1 = uint64_t(xx), y1 = uint64_t(yy), z1 = uint64_t(zz);
            const uint64_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
            xx -= std::floor(xx);
            yy -= std::floor(yy);
            zz -= std::floor(zz);
            const double xi = 1.0 - xx, yi = 1.0 - yy;
            density = ((at(x1, y1, z1) * xi + at(x2, y1, z1) * xx) * yi +
                       (at(x1, y2, z1) * xi + at(x2, y2, z1) * xx) * yy) *
                          (1.0 - zz) +
                      ((at(x1, y1, z2) * xi + at(x2, y1, z2) * xx) * yi +
                       (at(x1, y2, z2) * xi + at(x2, y2, z2) * xx) * yy) *
                          zz;
            break;
        }
        default: {
            double xx = p.x * double(sx), yy = p.y * double(sy), zz = p.z * double(sz);
            const uint64_t x1 = uint64_t(xx), y1 = uint64_t(yy), z1 = uint64_t(zz);
            xx -= std::floor(xx);
            yy -= std::floor(yy);
            zz -= std::floor(zz);
            // Neighbour i of index c along an axis of size n: c - 1 + i in unsigned
            // arithmetic, so that -1 wraps to 2^64 - 1 before the modulo (POV-Ray's).
            auto wrap = [](uint64_t c, uint64_t i, uint64_t n) {
                return (c + i - 1) % n;
            };
            float across[4][4];
            for (uint64_t i = 0; i < 4; ++i) {
                const uint64_t xi = wrap(x1, i, sx);
                for (uint64_t j = 0; j < 4; ++j) {
                    const uint64_t yj = wrap(y1, j, sy);
                    across[i][j] = cubic(float(zz), float(at(xi, yj, wrap(z1, 0, sz))),
                                         float(at(xi, yj, wrap(z1, 1, sz))),
                                         float(at(xi, yj, wrap(z1, 2, sz))),
                                         float(at(xi, yj, wrap(z1, 3, sz))));
                }
            }
            float along_y[4];
            for (int i = 0; i < 4; ++i)
                along_y[i] = cubic(float(yy), across[i][0], across[i][1], across[i][2],
                                   across[i][3]);
            density = cubic(float(xx), along_y[0], along_y[1], along_y[2], along_y[3]);
            break;
        }
    }
    return density < 0.0 ? 0.0 : density;
}

}  // namespace povwall::trace::detail
