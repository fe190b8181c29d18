// The band of an ovus (scene.h), as POV-Ray's Parse_Ovus computes it.
#include <cmath>

#include "core/scene.h"

namespace povwall {

Ovus make_ovus(Real bottom, Real top) {
    // POV-Ray's formulas in its order, so that the band meets the spheres at the same
    // rounded heights.
    Ovus o;
    o.bottom_radius = bottom;
    o.top_radius = top;
    if (bottom > top) {
        o.band_radius = 2.0 * bottom;
        o.band_height = 2.0 * top - bottom - (top * top / (2.0 * bottom));
        o.band_offset = std::sqrt(bottom * bottom - o.band_height * o.band_height);
        o.band_bottom = -o.band_height;
        const Real distance = o.band_radius - top;
        o.band_top = ((bottom - o.band_height) * top / distance) + bottom;
    } else {
        o.band_radius = 2.0 * top;
        o.band_height = -2.0 * top + bottom + (1.5 * top * top / bottom);
        o.band_offset =
            std::sqrt(top * top - ((o.band_height - bottom) * (o.band_height - bottom)));
        o.band_top = 2.0 * bottom - o.band_height;
        const Real distance = o.band_radius - bottom;
        o.band_bottom = -o.band_height * bottom / distance;
    }
    return o;
}

}  // namespace povwall
