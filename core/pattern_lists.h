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

}  // namespace povwall
