// JPEG files read with libjpeg directly (see output/png_reader.h for why not through
// OpenImageIO's module): a 4096x2048 JPEG texture took 2.4 s and 424 MB.
#pragma once

#include <string>

#include "output/decoded_image.h"

namespace povwall::output {

// Reads a grey or colour (YCbCr/RGB) JPEG as OpenImageIO 2.4 reads it (NotMine: not a
// JPEG): libjpeg's default
// decoding (islow DCT, fancy upsampling), each sample float(v) * (1 / 255). CMYK and YCCK
// files are left to OpenImageIO (NotMine), which converts them to RGB its own way.
DirectRead read_jpeg(const std::string& path, DecodedImage& image, std::string& error);

}  // namespace povwall::output
