// The OpenImageIO calls of output/, in a module loaded on first use (dlopen). OpenImageIO
// pulls in some 260 shared libraries (codecs, OpenCV, GStreamer...) whose relocation
// costs about 0.2 s when a process starts: loaded when the first image is read in a
// format other than PNG or JPEG (output/png_reader.h, output/jpeg_reader.h) or written in
// a format other than PNG (output/png_writer.h), so a PNG render, a scene textured with
// PNG and JPEG files, a screen worker, `povwall parse` or a failing scene never pays it.
// (Preloading it on a thread while a render traces was measured: no gain on 2 busy
// cores.)
#pragma once

#include <string>
#include <vector>

namespace povwall::output {

enum class PixelType { UInt8, UInt16, Float };

// What a read learns about the file besides its pixels (for image_map's gamma rules).
struct ImageFileInfo {
    std::string format;        // OIIO's format name: "png", "targa", "pnm", "jpeg", ...
    float declared_gamma = 0;  // PNG gAMA chunk as a decoding exponent; 0: none
    bool has_alpha = false;
    int channels = 0;           // as stored in the file (1 grey, 2 grey+alpha, 3, 4)
    int bits = 0;               // bits per stored sample (oiio:BitsPerSample)
    bool float_data = false;    // samples are floating point (EXR, HDR)
    bool tiff_palette = false;  // a TIFF of palette indices (photometric "palette")
};

struct ImageBackend {
    // Writes `pixels` (`channels` per pixel, row-major) to `path`; the format comes from
    // `format` ("png", "targa", "pnm", "exr", "hdr") or, when empty, from the name.
    // Returns an empty string on success, else the error.
    std::string (*write)(const std::string& path, const std::string& format, int width,
                         int height, int channels, PixelType type, const void* pixels,
                         bool straight_alpha, bool srgb);
    // Reads an image as stored (values scaled to 0..1, no premultiplication) into
    // `pixels`, and fills `info`.
    std::string (*read)(const std::string& path, int& width, int& height, int& channels,
                        std::vector<float>& pixels, ImageFileInfo& info);
};

}  // namespace povwall::output

// The module's one entry point.
extern "C" const povwall::output::ImageBackend* povwall_image_backend();
