// A function image's samples (parser/function_image.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/scene.h"

namespace povwall::parser {

struct FunctionImage {
    int width = 0, height = 0;
    int channels = 1;               // 1: grey (a float function), 4: RGBA (a pigment one)
    std::vector<uint16_t> samples;  // rows top first, channels interleaved
};

// A float as POV-Ray 3.7.0 stores it in a 16-bit channel (float(v) * 65535 through a
// 32-bit int, wrapping). False when that int overflows.
bool stored_16(double value, uint16_t& out);

// The image's pixels as an image_map, bump_map, image_pattern or material_map reads them.
std::shared_ptr<ImagePixels> function_image_pixels(const FunctionImage& image);

}  // namespace povwall::parser
