// Binary PPM (P6) files, written as POV-Ray 3.7's +FP writes them: its maxval is the
// colour depth's largest value (+FP12: 4095), samples of one byte up to 8 bits and two
// (most significant first) above; no alpha channel.
#pragma once

#include <string>

namespace povwall::output {

// Writes `samples` (row-major RGB, `bits` 5..16 per sample: uint8_t up to 8 bits,
// uint16_t above, each at most 2^bits - 1) to `path`. Returns an empty string on success,
// else the error (the file may then be incomplete: the caller writes to a temporary
// name).
std::string write_ppm(const std::string& path, int width, int height, int bits,
                      const void* samples);

}  // namespace povwall::output
