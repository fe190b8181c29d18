#include "output/ppm_writer.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace povwall::output {

std::string write_ppm(const std::string& path, int width, int height, int bits,
                      const void* samples) {
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return std::strerror(errno);
    const size_t count = size_t(width) * size_t(height) * 3;
    bool ok = std::fprintf(file, "P6\n%d %d\n%d\n", width, height, (1 << bits) - 1) > 0;
    if (bits <= 8) {
        ok = ok && std::fwrite(samples, 1, count, file) == count;
    } else {
        const auto* words = static_cast<const uint16_t*>(samples);
        std::vector<uint8_t> bytes(count * 2);
        for (size_t i = 0; i < count; ++i) {
            bytes[2 * i] = uint8_t(words[i] >> 8);
            bytes[2 * i + 1] = uint8_t(words[i] & 0xff);
        }
        ok = ok && std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    }
    const int saved = errno;
    if (std::fclose(file) != 0 || !ok) return std::strerror(ok ? errno : saved);
    return {};
}

}  // namespace povwall::output
