// An image file's samples as stored, and what the read learnt about the file: what every
// reader gives (output/png_reader.h, output/jpeg_reader.h, the OpenImageIO module).
#pragma once

#include <string>
#include <vector>

#include "output/image_backend.h"

namespace povwall::output {

struct DecodedImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> samples;  // `channels` a pixel, row-major, scaled to 0..1
    ImageFileInfo info;
};

// A direct reader's answer: the file read, a broken file, or a file it leaves to
// OpenImageIO (not its format, or a variant it does not decode).
enum class DirectRead { Done, Failed, NotMine };

}  // namespace povwall::output
