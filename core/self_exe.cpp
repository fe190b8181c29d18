#include "core/self_exe.h"

#include <unistd.h>

namespace povwall {

std::string self_exe() {
    char path[4096];
    const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0) return "";
    return std::string(path, size_t(n));
}

}  // namespace povwall
