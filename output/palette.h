// Palette images (GIF, palette PNG, BMP of up to 8 bits, colour-mapped TGA): OpenImageIO
// expands them to colours, but POV-Ray keeps each pixel's palette index, which
// `bump_map { use_index }` and an image_map's `filter N, V` / `transmit N, V` read. The
// palettes are read from the file headers here and each pixel's index recovered from its
// colour.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace povwall::output {

// Whether the file stores palette indices (OpenImageIO's format name: "gif", "png",
// "bmp", "targa").
bool colour_mapped_file(const std::string& path, const std::string& format);

// The palette of a GIF (its global table, else the first image's local table), a palette
// PNG (PLTE) or a BMP of up to 8 bits; empty when there is none or it cannot be read.
std::vector<std::array<uint8_t, 3>> read_palette(const std::string& path,
                                                 const std::string& format);

// Each pixel's palette index: a PNG's as stored; of other files, found from the pixel's
// 8-bit colour, and then empty when a pixel's colour is not in the palette or is one the
// palette repeats (the index would be a guess).
std::vector<uint8_t> palette_indices(const std::string& path, const std::string& format,
                                     const Image& pixels,
                                     const std::vector<std::array<uint8_t, 3>>& palette);

}  // namespace povwall::output
