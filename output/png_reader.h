// PNG files read with libpng directly. Image maps are mostly PNG and JPEG, and loading
// OpenImageIO's module costs about 0.5 s and 130 MB a process (its ~280 libraries): a
// scene with one PNG texture took 0.52 s against 0.01 s without.
#pragma once

#include <string>

#include "output/decoded_image.h"

namespace povwall::output {

// Reads a PNG (NotMine: the file does not start with PNG's signature) as OpenImageIO 2.4
// reads it, sample for sample (tests/output compare the
// two): bit depths below 8 and palettes expanded to 8 bits, tRNS to an alpha channel,
// 16-bit samples kept, each sample float(v) * (1 / max); an sRGB chunk or none declares
// no gamma, a gAMA chunk alone its decoding exponent rounded to hundredths.
DirectRead read_png(const std::string& path, DecodedImage& image, std::string& error);

}  // namespace povwall::output
