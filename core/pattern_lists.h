// The patterns whose value is the number of an entry of their list (POV-Ray's blend
// lists: checker, brick, hexagon, square, triangular, cubic, the object pattern), and how
// many entries the list has; 0 for every other pattern.
#pragma once

#include "core/scene.h"

namespace povwall {

inline int pattern_list_size(PatternKind k) {
    switch (k) {
        case PatternKind::Checker:
        case PatternKind::Brick:
        case PatternKind::ObjectInside:
            return 2;
        case PatternKind::Hexagon:
            return 3;
        case PatternKind::Square:
            return 4;
        case PatternKind::Triangular:
        case PatternKind::Cubic:
            return 6;
        default:
            return 0;
    }
}

// The frequency a new pattern starts with (POV-Ray's parser): 0 for the list patterns,
// quilted and image_pattern (their value is not wrapped unless a frequency is given), 1
// for the others.
inline Real initial_frequency(PatternKind k) {
    return pattern_list_size(k) != 0 || k == PatternKind::Quilted ||
                   k == PatternKind::ImagePattern
               ? 0
               : 1;
}

// How many tilings pavement has of tiles of `tiles` cells (1-6) with `sides` sides (3, 4
// or 6); 0 where it has none (hexagons of 6 cells, other side counts).
constexpr int pavement_patterns(int sides, int tiles) {
    constexpr int kTriangles[6] = {1, 1, 1, 3, 4, 12};
    constexpr int kSquares[6] = {1, 1, 2, 5, 12, 35};
    constexpr int kHexagons[5] = {1, 1, 3, 7, 22};
    if (tiles < 1) return 0;
    if (sides == 3 && tiles <= 6) return kTriangles[tiles - 1];
    if (sides == 4 && tiles <= 6) return kSquares[tiles - 1];
    if (sides == 6 && tiles <= 5) return kHexagons[tiles - 1];
    return 0;
}

}  // namespace povwall
