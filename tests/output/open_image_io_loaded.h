// Whether this process has mapped OpenImageIO's library (output/ loads it only when a
// format needs it).
#pragma once

#include <fstream>
#include <string>

namespace povwall::output {

inline bool open_image_io_loaded() {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line))
        if (line.find("libOpenImageIO") != std::string::npos) return true;
    return false;
}

}  // namespace povwall::output
