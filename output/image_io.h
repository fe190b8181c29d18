// Writing rendered images (gamma-encoded as POV-Ray 3.7 does) and reading images back.
#pragma once

#include <stdexcept>
#include <string>

#include "core/image.h"
#include "output/decoded_image.h"

namespace povwall::output {

struct ImageIoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Working-space value -> file value in [0,1], before quantisation.
float encode_channel(float v, const OutputEncoding& enc);

// Writes `image` (working space) to `path`, format from the extension (png, tga, ppm,
// exr), through a temporary file in the same folder and a rename, so no partial file is
// ever left behind. With enc.alpha the image's colours are taken as premultiplied (as the
// renderer makes them); integer formats get straight alpha and EXR premultiplied, as
// POV-Ray writes them.
void write_image(const Image& image, const std::string& path, const OutputEncoding& enc);
// Same, in the given format whatever the extension ("png", "tga", "ppm", "exr"; POV-Ray's
// +F).
void write_image(const Image& image, const std::string& path, const OutputEncoding& enc,
                 const std::string& format);

// For a SIGINT/SIGTERM handler (async-signal-safe): removes the temporary file of a
// write_image() in progress, so an interrupted write leaves nothing behind. Returns true
// when there was one.
bool remove_partial_output() noexcept;

// An image file's samples as stored: PNG and JPEG read directly (output/png_reader.h,
// output/jpeg_reader.h), every other format by OpenImageIO's module; throws ImageIoError.
DecodedImage decode_image_file(const std::string& path);
// The same through OpenImageIO whatever the format (what the direct readers must equal).
DecodedImage decode_with_open_image_io(const std::string& path);

// Reads an image as stored (encoded values scaled to 0..1), RGBA; throws ImageIoError.
Image read_image(const std::string& path);

// Reads an image file a scene names, as stored plus its format and declared gamma (for
// image_map, bump_map and height_field, decoded by the parser with POV-Ray's input gamma
// rules); values as POV-Ray's readers give them where they differ from OpenImageIO's
// (RGBE mantissas plus a half step, EXR in half precision); throws ImageIoError.
StoredImage read_stored_image(const std::string& path);

}  // namespace povwall::output
