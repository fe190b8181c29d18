// Radiance RGBE (.hdr) pixels as POV-Ray 3.7 decodes them (base/image/hdr.cpp): each
// mantissa m with exponent e becomes (m + 0.5) * 2^(e - 136) (OpenImageIO leaves out the
// half), rows in file order whatever the resolution line's orientation says.
#pragma once

#include <string>
#include <vector>

namespace povwall::output {

// Fills `rgb` (3 floats per pixel, top row first); returns an empty string, else why the
// file cannot be read.
std::string read_rgbe_as_povray(const std::string& path, int& width, int& height,
                                std::vector<float>& rgb);

}  // namespace povwall::output
