#include "output/radiance_rgbe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

namespace povwall::output {
namespace {

struct Bytes {
    std::vector<unsigned char> data;
    size_t at = 0;
    bool next(unsigned char& b) {
        if (at >= data.size()) return false;
        b = data[at++];
        return true;
    }
};

// A scanline without the run-length header: 4 bytes a pixel, where (1, 1, 1, n) repeats
// the previous pixel n times (n shifted by 8 more for each directly following run).
bool read_flat_line(Bytes& in, unsigned char* line, int count,
                    const unsigned char* start) {
    int shift = 0;
    while (count > 0) {
        unsigned char p[4];
        for (unsigned char& b : p) {
            if (!in.next(b)) return false;
        }
        if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
            if (line == start) return false;  // nothing to repeat
            for (long n = long(p[3]) << shift; n > 0 && count > 0; --n, --count) {
                std::memcpy(line, line - 4, 4);
                line += 4;
            }
            shift += 8;
        } else {
            std::memcpy(line, p, 4);
            line += 4;
            --count;
            shift = 0;
        }
    }
    return true;
}

}  // namespace

std::string read_rgbe_as_povray(const std::string& path, int& width, int& height,
                                std::vector<float>& rgb) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return "cannot open the file";
    Bytes in;
    in.data.assign(std::istreambuf_iterator<char>(file),
                   std::istreambuf_iterator<char>());
    // Header lines up to the resolution line, the first to start with '-' or '+'.
    std::string line;
    for (;;) {
        const size_t end = std::find(in.data.begin() + long(in.at), in.data.end(), '\n') -
                           in.data.begin();
        if (in.at >= in.data.size()) return "Bad HDR file header";
        line.assign(in.data.begin() + long(in.at), in.data.begin() + long(end));
        in.at = std::min(end + 1, in.data.size());
        if (!line.empty() && (line[0] == '-' || line[0] == '+')) break;
    }
    char axis1[3], axis2[3];
    unsigned rows = 0, columns = 0;
    if (std::sscanf(line.c_str(), "%2[+-XY] %u %2[+-XY] %u", axis1, &rows, axis2,
                    &columns) != 4 ||
        rows == 0 || columns == 0 || rows > 1u << 20 || columns > 1u << 20)
        return "Bad HDR file header";
    width = int(columns);
    height = int(rows);
    rgb.assign(size_t(width) * size_t(height) * 3, 0.0f);
    std::vector<unsigned char> scan(size_t(width) * 4);
    for (int row = 0; row < height; ++row) {
        bool ok = true;
        unsigned char b;
        if (width < 8 || width > 0x7fff || in.at >= in.data.size() ||
            in.data[in.at] != 2) {
            ok = read_flat_line(in, scan.data(), width, scan.data());
        } else {
            in.at++;
            unsigned char h[3];
            for (unsigned char& c : h) ok = ok && in.next(c);
            if (!ok) return "Incomplete HDR file";
            if (h[0] != 2 || (h[1] & 128) != 0) {
                // Not run-length encoded: the 4 bytes were the first pixel.
                const unsigned char first[4] = {2, h[0], h[1], h[2]};
                std::memcpy(scan.data(), first, 4);
                ok = read_flat_line(in, scan.data() + 4, width - 1, scan.data());
            } else {
                if ((int(h[1]) << 8 | h[2]) != width)
                    return "Invalid HDR file (length mismatch)";
                // Each component's run-length encoded bytes in turn.
                for (int c = 0; c < 4 && ok; ++c) {
                    for (int x = 0; x < width && ok;) {
                        ok = in.next(b);
                        if (!ok) break;
                        if (b > 128) {
                            unsigned char v = 0;
                            ok = in.next(v);
                            for (int n = b & 127; ok && n > 0 && x < width; --n)
                                scan[size_t(x++) * 4 + size_t(c)] = v;
                        } else {
                            for (int n = b; ok && n > 0 && x < width; --n) {
                                unsigned char v = 0;
                                ok = in.next(v);
                                scan[size_t(x++) * 4 + size_t(c)] = v;
                            }
                        }
                    }
                }
            }
        }
        if (!ok) return "Invalid HDR file (unexpected EOF)";
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = &scan[size_t(x) * 4];
            const double scale = std::ldexp(1.0, int(p[3]) - (128 + 8));
            float* out = &rgb[(size_t(row) * size_t(width) + size_t(x)) * 3];
            for (int c = 0; c < 3; ++c) out[c] = float((double(p[c]) + 0.5) * scale);
        }
    }
    return {};
}

}  // namespace povwall::output
