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

}  // namespace povwall
