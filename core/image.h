// A float RGBA image in working colour space, as the renderer produces it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/colour.h"
#include "core/gamma.h"

namespace povwall {

struct Image {
    int width = 0, height = 0;
    std::vector<float>
        rgba;  // row-major, top row first, 4 floats per pixel, alpha 1 = opaque

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 0.0f) {}
    float* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const float* pixel(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// How working-space values become file values (POV-Ray 3.7's gamma rules).
struct OutputEncoding {
    // false: legacy scene (#version < 3.7 and no assumed_gamma): values written raw.
    bool gamma_handling = true;
    GammaCurve working_gamma;  // assumed_gamma (a power of 1: linear)
    bool file_srgb = true;  // File_Gamma sRGB (POV-Ray's Unix default); else file_gamma
    float file_gamma = 2.2f;
    // Colour depth as +F gives it (POV-Ray takes 5..16): PNG stores it in 8 or 16 bits
    // by left bit replication, PPM as is; other formats 8 bits or floats.
    int bits = 8;
    bool alpha = false;  // +UA: write RGBA (non-premultiplied)
};

// An image file's pixels as stored (encoded values scaled to 0..1, not decoded) and what
// POV-Ray's input gamma rules need to know about the file.
struct StoredImage {
    Image pixels;  // RGBA; files without alpha have alpha 1
    bool has_alpha = false;
    std::string
        format;  // "png", "targa", "pnm", "jpeg", "gif", "bmp", "tiff", "openexr", "hdr"
    // Encoding gamma the file declares (PNG gAMA chunk), as a decoding exponent; 0: none
    // (PNG without gAMA: sRGB as POV-Ray assumes).
    float declared_gamma = 0;
    // A palette image (GIF, palette PNG, BMP of up to 8 bits, colour-mapped TGA): POV-Ray
    // keeps its indices, which some of its options read (bump_map use_index).
    bool colour_mapped = false;
    // A colour-mapped file's palette index of each pixel, when its palette could be read
    // and names each colour once (output/palette.h); else empty.
    std::vector<uint8_t> indices;
    int palette_size = 0;
    // How the file stores its samples (height_field takes its heights from them).
    int channels = 0;         // 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
    int bits = 0;             // bits per sample
    bool float_data = false;  // floating-point samples (EXR, HDR)
    int pnm_maxval = 0;       // a Netpbm file's maxval (0: not Netpbm, or a bitmap)
};

// Reads an image file; throws std::runtime_error with a message naming the problem. The
// parser gets one from its caller so that it does not depend on the image library.
using ImageReader = std::function<StoredImage(const std::string& path)>;

}  // namespace povwall
