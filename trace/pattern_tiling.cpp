// POV-Ray 3.7's `tiling N` pattern in the x-z plane (pattern.cpp of 3.7-stable read for
// semantics; an independent implementation), for the tilings 1 to 24 (25 to 27, the
// Penrose tilings, are in pattern_penrose.cpp): each tile runs
// from 0 at its centre line to 1 at its edges, and a tiling of k kinds of tiles gives
// kind i the values [i/k, (i+1)/k]. The fixed offsets above 0.5, 2 or 5 (1e-7, 1e-12) are
// POV-Ray's, keeping a value inside its kind's range.
#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

constexpr Real kSqrt2 = 1.4142135623730950488;
constexpr Real kSqrt2Half = 0.70710678118654752440;

// v folded into [0, period).
Real wrap_to_period(Real v, Real period) { return v - period * std::floor(v / period); }

// 0 at the middle of a unit cell, 1 at its sides: 2 |frac(v) - 0.5|.
Real from_middle(Real v) { return 2 * std::fabs(v - 0.5); }

// 1: squares of side 1.
Real square_tiles(Real x, Real z) {
    x = std::fabs(x);
    z = std::fabs(z);
    return std::max(from_middle(x - std::floor(x)), from_middle(z - std::floor(z)));
}

// 2: hexagons of side 1 (centres 3 apart in x, sqrt 3 in z).
Real hexagon_tiles(Real x, Real z) {
    x = wrap_to_period(x + 0.5, 3.0);
    z = wrap_to_period(z, kSqrt3);
    // Mirror and shift into the quarter [0, 1.5] x [0, sqrt3/2], a hexagon's centre at
    // its top right; the bottom left corner belongs to the next hexagon.
    if (z > kSqrt3Half) z = kSqrt3 - z;
    if (x > 1.5) {
        x -= 1.5;
        z = kSqrt3Half - z;
    }
    if (kSqrt3 * x + z < kSqrt3Half) {
        x = 0.5 - x;
        z = kSqrt3Half - z;
    }
    if (x > 1.0) x = 2.0 - x;
    const Real to_top = 1.0 - z / kSqrt3Half;
    const Real to_slant = 1.0 - (kSqrt3 * x + z - kSqrt3Half) / kSqrt3;
    return std::clamp(std::max(to_top, to_slant), 0.0, 1.0);
}

// A point of the half triangle strip 0 <= x <= 0.5 folded into the triangle of side 1
// with its base on z = 0 (its apex over x = 0.5): above the rising edge it belongs to the
// triangle pointing down, whose kind `flipped` toggles (on x = 0 only when
// `flip_on_axis`, as POV-Ray's tilings 3 and 8 differ there). Returns POV-Ray's scaled
// distance max(1 - 2 sqrt3 z, 1 - sqrt3 (sqrt3 x - z)).
Real triangle_distance(Real x, Real z, int& flipped, bool flip_on_axis) {
    if (x != 0.0) {
        if (z / x > kSqrt3) {
            z = kSqrt3Half - z;
            x = 0.5 - x;
            flipped = 1 - flipped;
        }
    } else {
        z = kSqrt3Half - z;
        x = 0.5;
        if (flip_on_axis) flipped = 1 - flipped;
    }
    return std::max(1.0 - z * 2 * kSqrt3, 1.0 - (kSqrt3 * x - z) * kSqrt3);
}

// 3: equilateral triangles of side 1, pointing up (kind 0) and down (kind 1).
Real triangle_tiles(Real x, Real z) {
    x -= std::floor(x);
    z = wrap_to_period(z, kSqrt3);
    int flipped = 0;
    if (z > kSqrt3Half) {
        z = kSqrt3 - z;
        flipped = 1;
    }
    if (x > 0.5) x = 1.0 - x;
    const Real d = triangle_distance(x, z, flipped, false);
    return flipped / 2.0 + 0.5 * d;
}

// The lozenge (60 degree rhombus of side 1, long axis along x) distance once (x, z) is
// in the strip 0 <= z < sqrt3/2 of the lozenge lattice.
Real lozenge_distance(Real x, Real z) {
    if (2.0 * z > kSqrt3Half) {
        z = kSqrt3Half - z;
        x = 1.5 - x;
    }
    if (x > 0.75) x -= 1.0;
    if (x != 0.0 && z / x > kSqrt3) {
        z = kSqrt3Half - z;
        x = 0.5 - x;
    }
    return std::max(1.0 - z * 4.0 * kSqrt3 / 3.0,
                    1.0 - std::fabs(kSqrt3 * x - z) * kSqrt3 * 2.0 / 3.0);
}

// 4: lozenges, all in one orientation.
Real lozenge_tiles(Real x, Real z) {
    x -= std::floor(x);
    z = wrap_to_period(z, kSqrt3);
    if (z > kSqrt3Half) {
        z -= kSqrt3Half;
        x += 0.5;
    }
    return lozenge_distance(x, z);
}

// 5: lozenges in three orientations (the cube-corner rhombille), one kind each.
Real rhombus_tiles(Real x, Real z) {
    x = wrap_to_period(x + 0.5, 3.0);
    z = wrap_to_period(z, kSqrt3);
    int kind = 0;
    if (z > kSqrt3Half) {
        z = kSqrt3 - z;
        kind = 2 - kind;
    }
    if (x > 1.5) {
        x -= 1.5;
        z = kSqrt3Half - z;
        kind = 2 - kind;
    }
    if (x < 0.5) {
        x = 1.0 - x;
        kind = 2 - kind;
    }
    x -= 0.5;
    // The upright lozenge turned by -60 degrees onto the horizontal one.
    if (x == 0.0 || z / x > kSqrt3) {
        const Real turned_x = x / 2.0 + z * kSqrt3Half;
        const Real turned_z = z / 2.0 - x * kSqrt3Half;
        x = turned_x;
        z = turned_z;
        kind = 1;
    }
    const Real value = lozenge_distance(x, z) / 3.0 + kind / 3.0;
    return std::clamp(value, 0.0, 1.0);
}

// 6: 2x1 rectangles in a pinwheel of period 4: for each unit cell of the 4x4 block, the
// offset to the cell where its rectangle's reference corner is and whether the rectangle
// lies along x (kind 0) or along z (kind 1).
struct RectangleCell {
    Real dx, dz;
    bool along_z;
};
constexpr RectangleCell kRectangleCells[16] = {
    {0, 1, true},  {2, 0, false}, {2, 0, false}, {3, 0, true},   // z row 0
    {0, 1, true},  {1, 2, true},  {3, 1, false}, {3, 1, false},  // z row 1
    {0, 2, false}, {1, 2, true},  {2, 3, true},  {4, 2, false},  // z row 2
    {1, 3, false}, {1, 3, false}, {2, 3, true},  {3, 4, true},   // z row 3
};
Real rectangle_tiles(Real x, Real z) {
    x = wrap_to_period(x, 4.0);
    z = wrap_to_period(z, 4.0);
    // (x or z can round up to 4 just below 0)
    const RectangleCell& c =
        kRectangleCells[std::min(int(x), 3) + std::min(int(z), 3) * 4];
    x -= c.dx;
    z -= c.dz;
    Real across, along;
    if (c.along_z) {
        across = from_middle(x);
        along = 2 * (std::max(std::fabs(z), 0.5) - 0.5);
    } else {
        along = 2 * (std::max(std::fabs(x), 0.5) - 0.5);
        across = from_middle(z);
    }
    const Real kind = c.along_z ? 1.0 : 0.0;
    return std::fabs(std::max(across, along) / 2.0 + kind / 2);
}

// 7: octagons with squares between them (period 1 + sqrt 2).
Real octagon_square_tiles(Real x, Real z) {
    constexpr Real period = kSqrt2 + 1.0;
    z = std::fabs(wrap_to_period(z, period) - (kSqrt2Half + 0.5));
    x = std::fabs(wrap_to_period(x, period) - (kSqrt2Half + 0.5));
    if (z > x) std::swap(x, z);
    if (x + z < kSqrt2Half) return (x + z) / kSqrt2;  // the square
    const Real to_side = 1.0 - z;
    const Real to_diagonal = (kSqrt2 + kSqrt2Half - (x + z)) / kSqrt2;
    return std::max(0.500000000001, std::max(to_side, to_diagonal));
}

// 8: rows of unit squares between rows of triangles (period 2 + sqrt 3 in z).
Real square_triangle_tiles(Real x, Real z) {
    x -= std::floor(x);
    z = wrap_to_period(z, 2.0 + kSqrt3);
    if (z > kSqrt3Half + 1.0) {  // the second half: shifted by half a tile
        z -= kSqrt3Half + 1.0;
        x += x > 0.5 ? -0.5 : 0.5;
    }
    if (x > 0.5) x = 1.0 - x;
    z -= 1.0;
    if (z > 0.0) {
        int flipped = 0;
        const Real d = triangle_distance(x, z, flipped, true);
        return (flipped + d) / 3.0;
    }
    if (z < -0.5) z = -1.0 - z;
    if (x > 0.5) x = 1.0 - x;
    const Real across_x = std::min(2 + 2 * kSqrt3 * std::fabs(x), 3.0);
    const Real across_z = std::min(2 + 2 * kSqrt3 * std::fabs(z), 3.0);
    return (5.0000001 - std::min(across_x, across_z)) / 3.0;
}

// 9: hexagons with two triangles each (trihexagonal), triangles the kinds 0 and 1.
Real hexagon_triangle_tiles(Real x, Real z) {
    x = wrap_to_period(x + 0.5, 2.0);
    z = wrap_to_period(z, 2.0 * kSqrt3);
    if (z > kSqrt3) {
        z -= kSqrt3;
        x += x < 1.0 ? 1.0 : -1.0;
    }
    int flipped = 0;
    if (z > kSqrt3Half) {
        z = kSqrt3 - z;
        flipped = 1;
    }
    if (x > 1.0) x = 2.0 - x;
    if (kSqrt3 * x + z < kSqrt3Half) {  // the triangle at the bottom left corner
        const Real to_base = 1.0 - z * 2 * kSqrt3;
        const Real to_slant = 1.0 + (kSqrt3 * x + z - kSqrt3Half) * kSqrt3;
        return (flipped + std::max(to_base, to_slant)) / 3.0;
    }
    const Real across_z = 2 + 2 * (z * kSqrt3);
    const Real across_slant = 2 + 2 * (kSqrt3 * x + z - kSqrt3Half) * kSqrt3Half;
    return std::max(5.0 - std::min(across_z, across_slant), 2.0000001) / 3.0;
}

// 10: unit squares, every other row shifted by half a square.
Real square_offset_tiles(Real x, Real z) {
    z = wrap_to_period(z, 2.0);
    if (z > 1.0) {
        x += 0.5;
        z -= 1.0;
    }
    x -= std::floor(x);
    return std::max(from_middle(x), from_middle(z));
}

// 11 and 12: a unit square ringed by four 2x1 rectangles turning around it (12: mirrored
// in each 3x3 quarter of a 6x6 block, so they turn both ways). For each unit cell of the
// 3x3 block: the offset to its tile's reference corner and its kind (0 the square, 1 a
// rectangle along x, 2 one along z). Cells 9 and up (a coordinate rounded up to 3) keep
// the point as it is, as kind 2 (POV-Ray's switch has no case for them).
struct PinwheelCell {
    Real dx, dz;
    int kind;
};
constexpr PinwheelCell kPinwheelCells[9] = {
    {0, 1, 2}, {2, 0, 1}, {2, 0, 1},  // z row 0
    {0, 1, 2}, {1, 1, 0}, {2, 2, 2},  // z row 1
    {1, 2, 1}, {1, 2, 1}, {2, 2, 2},  // z row 2
};
Real pinwheel_value(Real x, Real z) {
    const int cell = int(x) + int(z) * 3;
    PinwheelCell c{0, 0, 2};
    if (cell < 9) c = kPinwheelCells[cell];
    x -= c.dx;
    z -= c.dz;
    auto along = [](Real v) { return 2.0 * (std::max(std::fabs(v), 0.5) - 0.5); };
    auto across = [](Real v) { return 2.0 * std::fabs(v - 0.5); };
    Real dx = across(x), dz = across(z);
    if (c.kind == 1) dx = along(x);
    if (c.kind == 2) dz = along(z);
    return (std::max(dx, dz) + c.kind) / 3.0;
}
Real square_rectangle_tiles(Real x, Real z) {
    return pinwheel_value(wrap_to_period(x, 3.0), wrap_to_period(z, 3.0));
}
Real rectangle_square_tiles(Real x, Real z) {
    return pinwheel_value(std::fabs(wrap_to_period(x, 6.0) - 3.0),
                          std::fabs(wrap_to_period(z, 6.0) - 3.0));
}

// 13 and 14: squares of side sqrt2/2 (in a sqrt2-scaled 4x4 block folded into its
// quarter [0, 2]^2) with diagonal-cut pieces around them: kinds by the unit cell of the
// quarter (cell 0 the square). 14 also tells the four quarters' pieces apart (five
// kinds).
Real square_internal_tiles(Real x, Real z, bool five_kinds) {
    x = wrap_to_period(x * kSqrt2, 4.0) - 2.0;
    z = wrap_to_period(z * kSqrt2, 4.0) - 2.0;
    const int mirror_x = x < 0 ? 1 : 0, mirror_z = z < 0 ? 2 : 3;
    x = std::fabs(x);
    z = std::fabs(z);
    // The pieces' value ramps: across the piece from the far side and from the cut.
    auto from_side = [](Real v) { return std::fabs(1.5 - v) * 2.0; };
    auto from_cut = [](Real a, Real b) { return kSqrt2 * std::fabs(a - b); };
    const Real kind_x = mirror_x, kind_z = mirror_z;
    switch (int(x) + int(z) * 2) {
        case 0: {
            const Real d =
                std::max(std::max(x - 0.5, 0.0) * 2.0, std::max(z - 0.5, 0.0) * 2.0);
            return five_kinds ? (4.000001 + d) / 5.0 : d / 3.0;
        }
        case 1: {
            if (!five_kinds) {
                Real v = (2.0 + from_side(x)) / 3.0;
                if (z > 0.5) v = std::max(v, (3.0 - from_cut(x, z)) / 3.0);
                return v;
            }
            Real v = from_side(x);
            if (z > 0.5) v = std::max(v, 1.0 - from_cut(x, z));
            return (v + kind_x) / 5.0;
        }
        case 2: {
            if (!five_kinds) {
                Real v = (1.0 + from_side(z)) / 3.0;
                if (x > 0.5) v = std::max(v, (2.0 - from_cut(x, z)) / 3.0);
                return v;
            }
            Real v = from_side(z);
            if (x > 0.5) v = std::max(v, 1.0 - from_cut(x, z));
            return (v + kind_z) / 5.0;
        }
        case 3:
            if (!five_kinds) {
                if (x > z)
                    return std::max((2.0 + from_side(x)) / 3.0,
                                    (3.0 - from_cut(z, x)) / 3.0);
                return std::max((1.0 + from_side(z)) / 3.0, (2.0 - from_cut(x, z)) / 3.0);
            }
            if (x > z)
                return (std::max(from_side(x), 1.0 - from_cut(z, x)) + kind_x) / 5.0;
            return (std::max(from_side(z), 1.0 - from_cut(x, z)) + kind_z) / 5.0;
        default:  // a coordinate rounded up to 2: no case in POV-Ray's switch
            return 0;
    }
}

// 15: unit squares (kind 0) and 2x2 squares (kind 1) in a 5x5 block: per unit cell the
// offset to its square's reference point and whether it is a big one. Cells 25 and up (a
// coordinate rounded up to 5) keep the point, as a big square (POV-Ray's switch).
struct DoubleSquareCell {
    Real dx, dz;
    bool big;
};
constexpr DoubleSquareCell kDoubleSquareCells[25] = {
    {0, 0, false}, {2, 0, true},  {2, 0, true},  {4, 1, true},  {4, 1, true},
    {1, 2, true},  {1, 2, true},  {2, 1, false}, {4, 1, true},  {4, 1, true},
    {1, 2, true},  {1, 2, true},  {3, 3, true},  {3, 3, true},  {4, 2, false},
    {0, 4, true},  {1, 3, false}, {3, 3, true},  {3, 3, true},  {5, 4, true},
    {0, 4, true},  {2, 5, true},  {2, 5, true},  {3, 4, false}, {5, 4, true},
};
Real square_double_tiles(Real x, Real z) {
    x = wrap_to_period(x, 5.0);
    z = wrap_to_period(z, 5.0);
    const int cell = int(x) + int(z) * 5;
    DoubleSquareCell c{0, 0, true};
    if (cell < 25) c = kDoubleSquareCells[cell];
    x -= c.dx;
    z -= c.dz;
    if (c.big) {
        x = 2 * (std::max(std::fabs(x), 0.5) - 0.5);
        z = 2 * (std::max(std::fabs(z), 0.5) - 0.5);
    } else {
        x = from_middle(x);
        z = from_middle(z);
    }
    const Real kind = c.big ? 0.50000001 : 0.0;
    return std::fabs(std::max(x, z) / 2.0 + kind);
}

// 16 and 17: hexagons, squares and triangles (rhombitrihexagonal); 16 has three kinds
// (square, triangle, hexagon), 17 six (the three square and two triangle orientations
// apart). The point is folded into the quarter cell [0, 1 + sqrt3/2]^2, the hexagon's
// centre at its top right, with the folds counted for 17.
Real hexagon_square_triangle_tiles(Real x, Real z, bool six_kinds) {
    x = wrap_to_period(x + 0.5, 3.0 + kSqrt3);
    z = wrap_to_period(z, 2.0 * (1.0 + kSqrt3));
    int mirror_x = 0, mirror_z = 0, turned = 0;
    if (x > kSqrt3Half + 1.5) {
        x -= kSqrt3Half + 1.5;
        z += z < kSqrt3 + 1.0 ? kSqrt3Half + 0.5 : -1 * (kSqrt3Half + 0.5);
    }
    if (z > kSqrt3 + 1.0) z -= kSqrt3 + 1.0;
    if (z > 0.5 + kSqrt3Half) {
        z = kSqrt3 + 1.0 - z;
        mirror_z = 1 - mirror_z;
    }
    if (x > 1.0 + kSqrt3Half) {
        x = kSqrt3 + 2.0 - x;
        mirror_x = 1 - mirror_x;
    }
    if (kSqrt3 * x + z < kSqrt3Half + 2.0 && x < 0.5 + kSqrt3Half) {
        // Turned by 60 degrees about the quarter's corner into the lower part.
        z -= 0.5 + kSqrt3Half;
        x -= 1.0 + kSqrt3Half;
        const Real turned_x = x / 2.0 - z * kSqrt3Half;
        const Real turned_z = z / 2.0 + x * kSqrt3Half;
        z = turned_z + (0.5 + kSqrt3Half);
        x = turned_x + (1.0 + kSqrt3Half);
        turned = 1 - turned;
        if (z < 0) z *= -1;
        if (x > 1.0 + kSqrt3Half) {
            x = kSqrt3 + 2.0 - x;
            mirror_x = 1 - mirror_x;
            mirror_z = 1 - mirror_z;
        }
    }
    if (!(kSqrt3 * x + z < kSqrt3Half + 2.0) && !(z < 0.5)) {  // the hexagon
        z = std::fabs(z - 0.5);
        x = std::fabs(x - kSqrt3Half);
        const Real to_side = 2 * z * kSqrt3;
        const Real to_slant = (kSqrt3 * x + z) * kSqrt3 - 1.5;
        if (six_kinds) return std::max(6.0 - std::min(to_side, to_slant), 5.000001) / 6.0;
        return std::max(3.0 - std::min(to_side, to_slant), 2.0000001) / 3.0;
    }
    if (!(z < 0.5)) return 0;
    if (x > kSqrt3Half + 0.5) {  // a square
        x -= kSqrt3Half + 0.5;
        z -= 0.5;
        const Real d = std::max(std::max(1.0 + z * 2 * kSqrt3, 0.0),
                                std::max(1.0 - x * 2 * kSqrt3, 0.0));
        if (!six_kinds) return d / 3.0;
        return (d + turned * (1.000001 + ((mirror_x + mirror_z) % 2))) / 6.0;
    }
    x = std::fabs(x - (kSqrt3Half + 0.5));  // a triangle
    const Real d = std::max(2.0 - x * 2.0 * kSqrt3, (kSqrt3 * z + x) * kSqrt3 + 0.5);
    if (!six_kinds) return d / 3.0;
    return (((turned + mirror_x) % 2 ? 2.0 : 3.0) + d) / 6.0;
}

// 18: pairs of 2x1 rectangles, the pairs alternating along x (kind 0) and along z
// (kind 1) in a 4x4 block; as 6, per unit cell.
constexpr RectangleCell kRectanglePairCells[16] = {
    {0, 1, true},  {1, 1, true},  {3, 0, false}, {3, 0, false},  // z row 0
    {0, 1, true},  {1, 1, true},  {3, 1, false}, {3, 1, false},  // z row 1
    {1, 2, false}, {1, 2, false}, {2, 3, true},  {3, 3, true},   // z row 2
    {1, 3, false}, {1, 3, false}, {2, 3, true},  {3, 3, true},   // z row 3
};
Real rectangle_pair_tiles(Real x, Real z) {
    x = wrap_to_period(x, 4.0);
    z = wrap_to_period(z, 4.0);
    const RectangleCell& c =
        kRectanglePairCells[std::min(int(x), 3) + std::min(int(z), 3) * 4];
    x -= c.dx;
    z -= c.dz;
    Real across, along;
    if (c.along_z) {
        across = from_middle(x);
        along = 2 * (std::max(std::fabs(z), 0.5) - 0.5);
    } else {
        along = 2 * (std::max(std::fabs(x), 0.5) - 0.5);
        across = from_middle(z);
    }
    const Real kind = c.along_z ? 1.0 : 0.0;
    return std::fabs((std::max(across, along) + kind) / 2.0);
}

// z / sqrt3/2 truncated to an int (saturating far out, where POV-Ray's conversion is
// undefined).
int half_rows(Real z) { return int(std::clamp(z / kSqrt3Half, -2.0e9, 2.0e9)); }

// 19 and 20: hexagons among triangles (snub hexagonal), right- and left-handed. Rows of
// three half-heights shift by half a unit; within the 7 x 3sqrt3/2 block three moves
// bring the point next to the hexagon at the block's origin.
Real hexagon_triangle_snub_tiles(Real x, Real z, bool right_handed) {
    int rows = half_rows(z) / 3;
    if (z < 0) rows -= 1;
    x += right_handed ? rows / 2.0 : -(rows / 2.0);
    z = wrap_to_period(z, 3 * kSqrt3Half);
    x = wrap_to_period(x + 7.0, 7.0);
    if (right_handed) {
        if (x > 4.5 && z > kSqrt3) {
            x -= 4.5;
            z -= kSqrt3Half;
        }
        if (x > 5.0 && z < kSqrt3Half) {
            x -= 5;
            z += kSqrt3;
        }
        if (x > 2.5 && z < kSqrt3) {
            x -= 2.5;
            z += kSqrt3Half;
        }
    } else {
        if (x > 2.0 && z < kSqrt3Half) {
            x -= 2.0;
            z += kSqrt3;
        }
        if (x > 4.5 && z < kSqrt3) {
            x -= 4.5;
            z += kSqrt3Half;
        }
        if (x > 2.5 && z > kSqrt3) {
            x -= 2.5;
            z -= kSqrt3Half;
        }
    }
    int flipped = 0;
    int row = half_rows(z);
    if (row == 2) {
        row = 1;
        z = 2 * kSqrt3 - z;
        flipped = 1;
    }
    if (row == 0 || x > 2.0 || z + kSqrt3 * x < kSqrt3 || kSqrt3 * x - z > kSqrt3) {
        x -= std::floor(x);
        z = wrap_to_period(z, kSqrt3);
        if (z > kSqrt3Half) {
            z = kSqrt3 - z;
            flipped = 1 - flipped;
        }
        if (x > 0.5) x = 1.0 - x;
        const Real d = triangle_distance(x, z, flipped, true);
        return (flipped + d) / 3.0;
    }
    z -= kSqrt3Half;  // the hexagon
    if (x > 1.0) x = 2.0 - x;
    const Real across_z = 2 + 2 * (z * kSqrt3);
    const Real across_slant = 2 + 2 * (kSqrt3 * x + z - kSqrt3Half) * kSqrt3Half;
    return std::max(5.0 - std::min(across_z, across_slant), 2.000001) / 3.0;
}

// 21: squares and triangles (snub square), six kinds: four triangle orientations, then
// the two square orientations. Folded into the quarter cell [0, (1 + sqrt3)/2]^2 and
// turned or mirrored onto one triangle and one square.
Real square_triangle_snub_tiles(Real x, Real z) {
    constexpr Real period = 1.0 + kSqrt3;
    x = wrap_to_period(x, period);
    z = wrap_to_period(z, period);
    int mirrored = 0, kind = 0, mirrored_x = 0;
    if (z > 0.5 + kSqrt3Half) {
        z = 1.0 + kSqrt3 - z;
        mirrored = 1 - mirrored;
    }
    if (x > 0.5 + kSqrt3Half) {
        x = 1.0 + kSqrt3 - x;
        mirrored = 1 - mirrored;
        mirrored_x = 1;
    }
    const int past_x =
        2.0 * x + (kSqrt3 - 1.0) * 2.0 * z / (kSqrt3 + 1.0) > kSqrt3 ? 1 : 0;
    const int past_z =
        2.0 * z * kSqrt3 + (kSqrt3 - 3.0) * 2.0 * x / (kSqrt3 + 1.0) > kSqrt3 ? 1 : 0;
    const Real half = kSqrt3Half + 0.5;
    switch (past_x + 2 * past_z) {
        case 0:
            kind = 2 * mirrored_x;
            break;
        case 1: {  // turned clockwise
            kind = mirrored_x ? 1 + 2 * mirrored : 3 - 2 * mirrored;
            const Real old_x = x;
            x = z;
            z = half - old_x;
            break;
        }
        case 2: {  // turned counter-clockwise
            kind = mirrored_x ? 3 - 2 * mirrored : 1 + 2 * mirrored;
            const Real old_z = z;
            z = x;
            x = half - old_z;
            break;
        }
        default:  // point mirrored
            kind = mirrored_x ? 0 : 2;
            x = half - x;
            z = half - z;
            break;
    }
    if (x == 0.0) z = 0.0;
    const Real edge = (z * 2 * kSqrt3) - kSqrt3 + x * 2;
    if (edge < 0) {  // the triangle
        const Real d = std::min(-1.5 / kSqrt3 * edge, 2.0 * x * kSqrt3);
        return (kind + 1.0 - d) / 6.0;
    }
    const Real d = std::min(edge * (1.5 / kSqrt3), 1.0);  // the square
    if (mirrored) return std::min(std::max((-d + 6.0) / 6.0, 5.000001 / 6.0), 1.0);
    return std::max(std::min((-d + 5.0) / 6.0, 5.0 / 6.0), 4.000001 / 6.0);
}

// 22: dodecagons with triangles between them (truncated hexagonal): the triangles are the
// kinds 0 and 1, the dodecagons 2.
Real dodecagon_triangle_tiles(Real x, Real z) {
    x = wrap_to_period(x, 2.0 + kSqrt3);
    z = wrap_to_period(z, 3.0 + 2.0 * kSqrt3);
    int toggled = 0;
    if (z > kSqrt3 + 1.5) {
        z -= kSqrt3 + 1.5;
        x += (x < 1.0 + kSqrt3Half ? 1.0 : -1.0) * (1.0 + kSqrt3Half);
    }
    if (x > 1.0 + kSqrt3Half) x = 2.0 + kSqrt3 - x;
    if (z > 1.0 + kSqrt3Half) {
        z = 2.0 + kSqrt3 - z;
        toggled = 1;
    }
    Real to_slant = x - kSqrt3Half - 0.5 + z * kSqrt3;
    if (to_slant < 0.0) {  // mirrored across that slant
        const Real old_x = x, old_z = z;
        x = (1.0 + kSqrt3) / 4.0 + 0.5 * old_x - kSqrt3Half * old_z;
        z = (3.0 + kSqrt3) / 4.0 - kSqrt3Half * old_x - 0.5 * old_z;
        to_slant *= -1.0;
    }
    const Real to_bottom = z * 3.0;
    const Real to_triangle = (z - kSqrt3Half - 0.5 + x * kSqrt3) * kSqrt3;
    to_slant *= kSqrt3;
    const Real to_left = x * 3.0;
    if (to_triangle < 0.0) return (std::max(to_triangle, -1.0) + (1 + toggled)) / 3.0;
    const Real d = std::min(
        std::min(std::min(std::min(to_bottom, to_slant), to_triangle), to_left), 1.0);
    return (3.0000001 - d) / 3.0;
}

// 23 and 24: dodecagons, hexagons and squares (truncated trihexagonal), in a block of
// 3 + sqrt3 by 3 + 3 sqrt3 folded into its quarter and across the slant of its corner
// square. 23: hexagons the kind 0, squares 1, dodecagons 2. 24 (five kinds): hexagons 0,
// the squares between a hexagon and a dodecagon above them 1, the slanted squares 2 or 3
// by the parity of the quarter's mirrorings, dodecagons 4 (POV-Ray's squares above the
// hexagons keep no upper bound of 1 on their distance).
Real dodecagon_hexagon_tiles(Real x, Real z, bool five_kinds) {
    x = wrap_to_period(x, 3.0 + kSqrt3);
    z = wrap_to_period(z, 3.0 + 3.0 * kSqrt3);
    int mirrorings = 0;
    if (z > 1.5 * kSqrt3 + 1.5) {
        z -= 1.5 * kSqrt3 + 1.5;
        x += (x < 1.5 + kSqrt3Half ? 1.0 : -1.0) * (1.5 + kSqrt3Half);
    }
    if (x > 1.5 + kSqrt3Half) {
        x = 3.0 + kSqrt3 - x;
        ++mirrorings;
    }
    if (z > 1.0 + kSqrt3) {
        z = 2.0 + 2.0 * kSqrt3 - z;
        ++mirrorings;
    }
    if (x - kSqrt3Half - 1.5 + z * kSqrt3 < 0.0) {  // mirrored across that slant
        const Real old_x = x, old_z = z;
        x = (3.0 + kSqrt3) / 4.0 + 0.5 * old_x - kSqrt3Half * old_z;
        z = (3.0 + 3.0 * kSqrt3) / 4.0 - kSqrt3Half * old_x - 0.5 * old_z;
    }
    const Real kinds = five_kinds ? 5.0 : 3.0;
    const Real to_slant = x - kSqrt3Half - 2.5 + z * kSqrt3;
    const Real to_bottom = (z * 2.0) - kSqrt3;
    const Real to_right_slant = z - 1.5 * kSqrt3 - 0.5 + x * kSqrt3;
    const Real to_left = ((x - 0.5) * 2.0);
    if (to_slant >= 0.0 && to_bottom >= 0.0 && to_right_slant >= 0.0 && to_left >= 0.0) {
        const Real d = std::min(
            std::min(std::min(std::min(to_bottom, to_slant), to_right_slant), to_left),
            1.0);
        return ((five_kinds ? 5.000001 : 3.000001) - d) / kinds;
    }
    const Real to_top = 2 * z - 2 * kSqrt3 - 1.0;
    if (to_top >= 0) return (2.0 - std::min(to_top, -to_left)) / kinds;
    const Real to_hexagon_edge = kSqrt3 * x - z - kSqrt3Half + 0.5;
    const Real to_far_edge = to_hexagon_edge - 2.0;
    if (to_hexagon_edge < 0.0 && to_far_edge < 0.0) {  // the hexagon on the left
        const Real d =
            std::min(std::min(std::min(-to_hexagon_edge, -to_right_slant), -to_top), 1.0);
        return (1.0 - d) / kinds;
    }
    if (to_far_edge >= 0.0 && to_hexagon_edge >= 0.0) {  // the hexagon below
        const Real d = std::min(std::min(to_far_edge, -to_bottom), 1.0);
        return (1.0 - d) / kinds;
    }
    // The slanted square (also where the two hexagon tests disagree, as POV-Ray).
    const Real d = std::min(std::min(to_hexagon_edge, -to_slant), -to_far_edge);
    const Real base = five_kinds ? Real(mirrorings % 2) + 3.0 : 2.0;
    return (base - d) / kinds;
}

}  // namespace

Real tiling_value(int n, const Point3& p) {
    const Real x = p.x, z = p.z;
    switch (n) {
        case 2:
            return hexagon_tiles(x, z);
        case 3:
            return triangle_tiles(x, z);
        case 4:
            return lozenge_tiles(x, z);
        case 5:
            return rhombus_tiles(x, z);
        case 6:
            return rectangle_tiles(x, z);
        case 7:
            return octagon_square_tiles(x, z);
        case 8:
            return square_triangle_tiles(x, z);
        case 9:
            return hexagon_triangle_tiles(x, z);
        case 10:
            return square_offset_tiles(x, z);
        case 11:
            return square_rectangle_tiles(x, z);
        case 12:
            return rectangle_square_tiles(x, z);
        case 13:
            return square_internal_tiles(x, z, false);
        case 14:
            return square_internal_tiles(x, z, true);
        case 15:
            return square_double_tiles(x, z);
        case 16:
            return hexagon_square_triangle_tiles(x, z, false);
        case 17:
            return hexagon_square_triangle_tiles(x, z, true);
        case 18:
            return rectangle_pair_tiles(x, z);
        case 19:
            return hexagon_triangle_snub_tiles(x, z, true);
        case 20:
            return hexagon_triangle_snub_tiles(x, z, false);
        case 21:
            return square_triangle_snub_tiles(x, z);
        case 22:
            return dodecagon_triangle_tiles(x, z);
        case 23:
            return dodecagon_hexagon_tiles(x, z, false);
        case 24:
            return dodecagon_hexagon_tiles(x, z, true);
        case 25:
            return penrose_tiles(x, z, PenroseKind::Pentagons);
        case 26:
            return penrose_tiles(x, z, PenroseKind::KitesAndDarts);
        case 27:
            return penrose_tiles(x, z, PenroseKind::Rhombs);
        default:
            return square_tiles(x, z);
    }
}

}  // namespace povwall::trace::detail
