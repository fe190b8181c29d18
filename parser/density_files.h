// The df3 voxel files of `density_file df3 "name"` (density_files.cpp).
#pragma once

#include <string_view>

#include "core/scene.h"

namespace povwall::parser {

// A df3 file's bytes decoded as POV-Ray 3.7 reads them (the voxel width from the file's
// length); throws std::runtime_error with POV-Ray's message for a short or mis-sized
// file.
DensityFile decode_df3(std::string_view bytes);

}  // namespace povwall::parser
