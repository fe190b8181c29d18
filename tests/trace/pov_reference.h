// Renders tiny scenes with the real POV-Ray and reads the pixels back, so pattern tests
// compare against POV-Ray itself. Renders are cached under the build tree by scene hash.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/math.h"

namespace povwall::test {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<double> rgb;  // 0..1, row-major, 3 per pixel
    double at(int x, int y, int c) const { return rgb[size_t((y * width + x) * 3 + c)]; }
};

// 16-bit binary PPM as POV-Ray writes it (+FP16), comments allowed in the header.
inline RgbImage read_ppm16(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    auto token = [&]() {
        std::string t;
        char c;
        while (in.get(c)) {
            if (c == '#') {
                std::string line;
                std::getline(in, line);
            } else if (!isspace(static_cast<unsigned char>(c))) {
                t += c;
                break;
            }
        }
        while (in.get(c) && !isspace(static_cast<unsigned char>(c))) t += c;
        return t;
    };
    if (token() != "P6") throw std::runtime_error("not a P6 file: " + path);
    RgbImage img;
    img.width = std::stoi(token());
    img.height = std::stoi(token());
    int maxval = std::stoi(token());
    size_t n = size_t(img.width) * size_t(img.height) * 3;
    img.rgb.resize(n);
    for (size_t i = 0; i < n; ++i) {
        unsigned v;
        if (maxval > 255) {
            unsigned char b[2];
            in.read(reinterpret_cast<char*>(b), 2);
            v = (unsigned(b[0]) << 8) | b[1];
        } else {
            unsigned char b;
            in.read(reinterpret_cast<char*>(&b), 1);
            v = b;
        }
        img.rgb[i] = double(v) / maxval;
    }
    if (!in) throw std::runtime_error("short read: " + path);
    return img;
}

// Renders `scene` (full .pov text) at size x size with linear 16-bit output; cached.
inline RgbImage render_with_povray(const std::string& scene, int size) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(POVWALL_TEST_CACHE_DIR) / "pov_refs";
    fs::create_directories(dir);
    std::string key =
        std::to_string(std::hash<std::string>{}(scene + std::to_string(size)));
    // Per-process scratch names: test processes may run in parallel.
    std::string scratch = key + "." + std::to_string(getpid());
    fs::path pov = dir / (scratch + ".pov"), ppm = dir / (key + ".ppm");
    if (!fs::exists(ppm)) {
        std::ofstream(pov) << scene;
        std::ostringstream cmd;
        cmd << "povray +W" << size << " +H" << size
            << " -D -A +FP16 File_Gamma=1.0 -GA +I" << pov.string() << " +O"
            << dir.string() << "/" << scratch << ".tmp.ppm >/dev/null 2>&1";
        if (std::system(cmd.str().c_str()) != 0) {
            throw std::runtime_error("povray failed on " + pov.string());
        }
        fs::rename(dir / (scratch + ".tmp.ppm"), ppm);
        fs::remove(pov);
    }
    return read_ppm16(ppm.string());
}

// Scene with an orthographic camera looking down -y at the plane y = `height`: pixel (x,
// y) sees the world point ((x+0.5)/n - 0.5) * extent + centre.x, height, (0.5 -
// (y+0.5)/n) * extent + centre.z.
struct TopView {
    double extent = 4, height = 0.37;
    Vector3 centre{0, 0, 0};
    std::string camera() const {
        std::ostringstream s;
        s.precision(17);
        s << "camera { orthographic location <" << centre.x << ",10," << centre.z
          << "> direction <0,-1,0> right <" << extent << ",0,0> up <0,0," << extent
          << "> }\n";
        return s.str();
    }
    Point3 point(int x, int y, int n) const {
        return {((x + 0.5) / n - 0.5) * extent + centre.x, height,
                (0.5 - (y + 0.5) / n) * extent + centre.z};
    }
};

}  // namespace povwall::test
