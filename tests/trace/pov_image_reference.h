// Renders hand-written .pov text with the real POV-Ray (16-bit PPM) so tests can compare
// povwall's renderer against it on a core::Scene built directly in C++ (no parser
// involved).
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/image.h"
#include "tests/scratch_folder.h"

namespace povwall::test {

inline bool povray_available() {
    return std::system("command -v povray > /dev/null 2>&1") == 0;
}

// Linear values decoded from POV-Ray's sRGB-encoded output (scene uses assumed_gamma 1).
struct PovImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // file values in 0..1 (sRGB encoded)
};

inline PovImage render_with_povray(const std::string& name, const std::string& pov, int w,
                                   int h, const std::string& extra = "-A") {
    namespace fs = std::filesystem;
    // Per process: concurrent test runs must not overwrite each other's references.
    const fs::path dir = povwall_test::process_scratch("povwall_trace_tests");
    fs::path in = dir / (name + ".pov"), out = dir / (name + ".ppm");
    std::ofstream(in) << pov;
    std::string cmd = "povray +I" + in.string() + " +O" + out.string() + " +FP16 +W" +
                      std::to_string(w) + " +H" + std::to_string(h) + " -D +WT1 " +
                      extra + " -GA > /dev/null 2>&1";
    PovImage img;
    if (std::system(cmd.c_str()) != 0) return img;
    std::ifstream f(out, std::ios::binary);
    // Header fields, skipping POV-Ray's "# Software" comment lines.
    auto field = [&f]() {
        std::string tok;
        while (f >> tok) {
            if (tok[0] != '#') return tok;
            std::getline(f, tok);
        }
        return std::string("0");
    };
    std::string magic = field();
    img.width = std::stoi(field());
    img.height = std::stoi(field());
    int maxval = std::stoi(field());
    f.get();
    img.rgb.resize(size_t(img.width) * img.height * 3);
    for (float& v : img.rgb) {
        if (maxval > 255) {
            int hi = f.get(), lo = f.get();
            v = float(hi * 256 + lo) / float(maxval);
        } else {
            v = float(f.get()) / float(maxval);
        }
    }
    return img;
}

inline float srgb_encode(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1 / 2.4f) - 0.055f;
}

// Debug aid: with POVWALL_DUMP set, tests write their own render next to POV-Ray's.
inline void dump_ppm(const Image& img, const std::string& name) {
    if (!std::getenv("POVWALL_DUMP")) return;
    std::ofstream f(std::filesystem::temp_directory_path() / "povwall_trace_tests" /
                        (name + "-ours.ppm"),
                    std::ios::binary);
    f << "P6\n" << img.width << " " << img.height << "\n255\n";
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c)
            f.put(char(int(srgb_encode(img.rgba[i + c]) * 255 + 0.5f)));
    }
}

struct Diff {
    double rmse = 1, bad_fraction = 1, max_abs = 1;
};

// Compared as POV-Ray writes them: sRGB-encoded values on 0..1.
inline Diff compare(const Image& ours, const PovImage& pov) {
    Diff d;
    if (ours.width != pov.width || ours.height != pov.height) return d;
    double sum = 0, mx = 0;
    size_t bad = 0, n = size_t(ours.width) * ours.height;
    for (size_t i = 0; i < n; ++i) {
        bool is_bad = false;
        for (int c = 0; c < 3; ++c) {
            double e = srgb_encode(ours.rgba[i * 4 + c]) - pov.rgb[i * 3 + c];
            sum += e * e;
            mx = std::max(mx, std::fabs(e));
            if (std::fabs(e) > 0.1) is_bad = true;
        }
        bad += is_bad;
    }
    d.rmse = std::sqrt(sum / double(n * 3));
    d.bad_fraction = double(bad) / double(n);
    d.max_abs = mx;
    return d;
}

}  // namespace povwall::test
