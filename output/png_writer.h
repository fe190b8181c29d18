// PNG files written with libpng directly. PNG is what nearly every render writes
// (POV-Ray's default +FN), and libpng is one small library where OpenImageIO's module
// pulls in some 260 (0.2 s of relocation per process, a fifth of a 600x600 render on two
// cores). Every other format goes through OpenImageIO (output/image_backend.h); reads of
// PNG and JPEG through output/png_reader.h and output/jpeg_reader.h.
#pragma once

#include <cstdint>
#include <string>

namespace povwall::output {

// How the file declares its encoding: an sRGB chunk (with the gAMA and cHRM values the
// PNG specification gives for it), a gAMA chunk of 1/`gamma`, or nothing (legacy scenes
// whose values are written raw, as POV-Ray does for them).
struct PngEncoding {
    enum class Kind { None, Srgb, Gamma } kind = Kind::Srgb;
    float gamma = 2.2f;  // the encoding's display gamma, for Kind::Gamma
};

// Writes `pixels` (row-major, `channels` of 3 (RGB) or 4 (RGBA, straight alpha) per
// pixel, 8 or 16 bits per channel, 16-bit values in host order) to `path`. Returns an
// empty string on success, else the error (the file may then be incomplete: the caller
// writes to a temporary name).
std::string write_png(const std::string& path, int width, int height, int channels,
                      int bits, const void* pixels, const PngEncoding& encoding);

}  // namespace povwall::output
