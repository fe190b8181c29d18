// Dispersion's spectral bands, as POV-Ray 3.7 splits a refracted ray: band i of n covers
// 1/n of 380-730 nm; its ray bends with an index of refraction scaled by the dispersion
// ratio to the power of its offset from the middle of that range, and its result is
// weighted by the band's hue.
#pragma once

#include <cstdint>

#include "core/colour.h"

namespace povwall::trace {

struct SpectralBand {
    // Band `index` of `count` (POV-Ray computes these in single precision).
    SpectralBand(int index, int count);
    float wavelength;  // nm, the band's middle
    float bandwidth;   // nm
    // The index of refraction `ior` becomes for this band when the two media's
    // dispersions have ratio `dispersion`.
    double ior(double ior, double dispersion) const;
    // The band's colour: the hue curve's mean over the band, so that the n hues of a
    // split sum to about n times white.
    Rgb hue() const;
};

// The band a ray carries once a dispersing surface split it (its descendants keep it and
// split no more): `count` 0 means the ray carries every wavelength.
struct RayBand {
    uint16_t index = 0, count = 0;
    bool monochromatic() const { return count != 0; }
};

}  // namespace povwall::trace
