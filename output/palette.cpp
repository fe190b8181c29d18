#include "output/palette.h"

#include <png.h>
#include <setjmp.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>

namespace povwall::output {
namespace {

std::vector<unsigned char> read_bytes(const std::string& path, size_t limit) {
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> out;
    char buf[4096];
    while (in && out.size() < limit) {
        in.read(buf, std::streamsize(std::min(sizeof buf, limit - out.size())));
        out.insert(out.end(), buf, buf + in.gcount());
    }
    return out;
}

uint32_t be32(const unsigned char* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

uint32_t le32(const unsigned char* p) {
    return uint32_t(p[3]) << 24 | uint32_t(p[2]) << 16 | uint32_t(p[1]) << 8 | p[0];
}

using Palette = std::vector<std::array<uint8_t, 3>>;

Palette png_palette(const std::string& path) {
    // The PLTE chunk comes before the image data, so the file's head holds it.
    const std::vector<unsigned char> d = read_bytes(path, 1 << 20);
    size_t at = 8;
    while (at + 12 <= d.size()) {
        const uint32_t len = be32(&d[at]);
        const std::string type(d.begin() + long(at + 4), d.begin() + long(at + 8));
        if (type == "PLTE") {
            if (len % 3 || at + 8 + len > d.size()) return {};
            Palette p(len / 3);
            for (size_t i = 0; i < p.size(); ++i)
                for (int c = 0; c < 3; ++c)
                    p[i][size_t(c)] = d[at + 8 + 3 * i + size_t(c)];
            return p;
        }
        if (type == "IDAT" || type == "IEND") return {};
        at += 12 + size_t(len);
    }
    return {};
}

Palette gif_palette(const std::string& path) {
    const std::vector<unsigned char> d = read_bytes(path, 1 << 20);
    auto table = [&](size_t at, int bits) -> Palette {
        const size_t n = size_t(1) << (bits + 1);
        if (at + 3 * n > d.size()) return {};
        Palette p(n);
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) p[i][size_t(c)] = d[at + 3 * i + size_t(c)];
        return p;
    };
    if (d.size() < 13) return {};
    if (d[10] & 0x80) return table(13, d[10] & 7);
    // No global table: the first image's local one (after any extension blocks).
    size_t at = 13;
    while (at < d.size()) {
        if (d[at] == 0x21) {  // extension: label, then data sub-blocks
            at += 2;
            while (at < d.size() && d[at] != 0) at += size_t(d[at]) + 1;
            ++at;
        } else if (d[at] == 0x2c) {  // image descriptor
            if (at + 10 > d.size() || !(d[at + 9] & 0x80)) return {};
            return table(at + 10, d[at + 9] & 7);
        } else {
            return {};
        }
    }
    return {};
}

Palette bmp_palette(const std::string& path) {
    const std::vector<unsigned char> d = read_bytes(path, 14 + 124 + 4 * 256);
    if (d.size() < 54) return {};
    const uint32_t header = le32(&d[14]);
    const int bits = d[28] | d[29] << 8;
    if (bits > 8 || header < 12) return {};
    uint32_t n = header >= 40 ? le32(&d[46]) : 0;  // colours used; 0: all
    if (n == 0 || n > (1u << bits)) n = 1u << bits;
    const size_t at = 14 + header, entry = header == 12 ? 3 : 4;  // BGR or BGRx
    if (at + entry * n > d.size()) return {};
    Palette p(n);
    for (size_t i = 0; i < n; ++i)
        p[i] = {d[at + entry * i + 2], d[at + entry * i + 1], d[at + entry * i]};
    return p;
}

void on_png_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_png_warning(png_structp, png_const_charp) {}

// A palette PNG's indices as stored (libpng, without expanding the palette): exact even
// when the palette repeats a colour. Empty on any error.
std::vector<uint8_t> png_indices(const std::string& path, int width, int height) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return {};
    // Locals changed after setjmp are indeterminate after a longjmp: the buffers live on
    // the heap behind pointers set before it.
    const auto out = std::make_unique<std::vector<uint8_t>>();
    const auto rows = std::make_unique<std::vector<png_bytep>>();
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, on_png_error,
                                             on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (png && info && !setjmp(png_jmpbuf(png))) {
        png_init_io(png, f);
        png_read_info(png, info);
        if (png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE &&
            int(png_get_image_width(png, info)) == width &&
            int(png_get_image_height(png, info)) == height) {
            png_set_packing(png);  // 1, 2 and 4-bit indices: one byte each
            png_set_interlace_handling(png);
            png_read_update_info(png, info);
            out->assign(size_t(width) * size_t(height), 0);
            rows->resize(size_t(height));
            for (int y = 0; y < height; ++y)
                (*rows)[size_t(y)] = &(*out)[size_t(y) * size_t(width)];
            png_read_image(png, rows->data());
        }
    } else {
        out->clear();
    }
    png_destroy_read_struct(png ? &png : nullptr, info ? &info : nullptr, nullptr);
    std::fclose(f);
    return std::move(*out);
}

}  // namespace

bool colour_mapped_file(const std::string& path, const std::string& format) {
    const std::vector<unsigned char> h = read_bytes(path, 32);
    const size_t n = h.size();
    if (format == "gif") return true;
    if (format == "png") return n >= 26 && h[25] == 3;  // IHDR colour type 3
    if (format == "bmp") return n >= 30 && (h[28] | h[29] << 8) <= 8;  // bits per pixel
    if (format == "targa") return n >= 3 && h[1] == 1 && (h[2] == 1 || h[2] == 9);
    return false;
}

std::vector<std::array<uint8_t, 3>> read_palette(const std::string& path,
                                                 const std::string& format) {
    if (format == "png") return png_palette(path);
    if (format == "gif") return gif_palette(path);
    if (format == "bmp") return bmp_palette(path);
    return {};
}

std::vector<uint8_t> palette_indices(const std::string& path, const std::string& format,
                                     const Image& pixels,
                                     const std::vector<std::array<uint8_t, 3>>& palette) {
    if (palette.empty() || palette.size() > 256) return {};
    if (format == "png") return png_indices(path, pixels.width, pixels.height);
    // A colour the palette repeats cannot name its index: refused only where a pixel has
    // it.
    std::map<std::array<uint8_t, 3>, int> index;
    for (size_t i = 0; i < palette.size(); ++i) {
        auto [it, fresh] = index.emplace(palette[i], int(i));
        if (!fresh) it->second = -1;
    }
    const size_t n = size_t(pixels.width) * size_t(pixels.height);
    std::vector<uint8_t> out(n);
    for (size_t i = 0; i < n; ++i) {
        std::array<uint8_t, 3> c;
        for (int k = 0; k < 3; ++k)
            c[size_t(k)] = uint8_t(std::lround(
                std::clamp(pixels.rgba[i * 4 + size_t(k)], 0.0f, 1.0f) * 255.0f));
        const auto it = index.find(c);
        if (it == index.end() || it->second < 0) return {};
        out[i] = uint8_t(it->second);
    }
    return out;
}

}  // namespace povwall::output
