// output/png_reader.h and output/jpeg_reader.h: every kind of PNG and JPEG file reads
// sample for sample as OpenImageIO's module reads it (the reader it replaces), and
// reading them loads no OpenImageIO.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
// jpeglib.h needs size_t and FILE declared first.
#include <jpeglib.h>

#include "output/image_io.h"
#include "tests/output/open_image_io_loaded.h"
#include "tests/scratch_folder.h"

namespace povwall::output {
namespace {

namespace fs = std::filesystem;

fs::path readers_scratch() {
    return povwall_test::process_scratch("povwall-readers-test");
}

// One PNG to write: IHDR fields, optional palette/tRNS/gAMA/sRGB chunks, and rows of
// samples as PNG stores them (packed, big-endian).
struct PngSpec {
    std::string name;
    int width = 7, height = 5, depth = 8, colour = PNG_COLOR_TYPE_RGB;
    bool interlaced = false;
    int palette_size = 0;  // palette entries (colour type 3)
    int transparent = 0;   // tRNS entries for a palette, or 1 for a grey/RGB key
    double gamma = 0;      // gAMA chunk's file gamma (0: none)
    bool srgb = false;     // sRGB chunk
};

int channels_of(int colour) {
    switch (colour) {
        case PNG_COLOR_TYPE_GRAY:
            return 1;
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            return 2;
        case PNG_COLOR_TYPE_RGB:
            return 3;
        case PNG_COLOR_TYPE_RGB_ALPHA:
            return 4;
        default:
            return 1;  // palette indices
    }
}

void write_png_file(const fs::path& path, const PngSpec& s) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(s.width), png_uint_32(s.height), s.depth,
                 s.colour, s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    std::vector<png_color> palette;
    for (int i = 0; i < s.palette_size; ++i)
        palette.push_back({png_byte(i * 37), png_byte(255 - i * 11), png_byte(i * i)});
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), int(palette.size()));
    std::vector<png_byte> alphas;
    png_color_16 key{};
    if (s.transparent > 0 && s.colour == PNG_COLOR_TYPE_PALETTE) {
        for (int i = 0; i < s.transparent; ++i) alphas.push_back(png_byte(i * 50));
        png_set_tRNS(png, info, alphas.data(), int(alphas.size()), nullptr);
    } else if (s.transparent > 0) {
        key.gray = key.red = key.green = key.blue = 1;  // sample value 1 is transparent
        png_set_tRNS(png, info, nullptr, 0, &key);
    }
    if (s.gamma > 0) png_set_gAMA(png, info, s.gamma);
    if (s.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    // Every sample walks through its whole range (index values below the palette size).
    const int bits_per_pixel = s.depth * channels_of(s.colour);
    const size_t row_bytes = (size_t(s.width) * size_t(bits_per_pixel) + 7) / 8;
    const int top = s.colour == PNG_COLOR_TYPE_PALETTE ? s.palette_size : 1 << s.depth;
    std::vector<std::vector<png_byte>> rows(size_t(s.height),
                                            std::vector<png_byte>(row_bytes));
    unsigned counter = 0;
    for (auto& row : rows) {
        const int samples = s.width * channels_of(s.colour);
        for (int k = 0; k < samples; ++k) {
            const unsigned v = (counter++ * 2654435761u >> 7) % unsigned(top);
            if (s.depth == 16) {
                row[size_t(2 * k)] = png_byte(v >> 8);
                row[size_t(2 * k + 1)] = png_byte(v);
            } else {
                const int bit = k * s.depth;
                row[size_t(bit / 8)] |= png_byte(v << (8 - s.depth - bit % 8));
            }
        }
    }
    std::vector<png_bytep> pointers;
    for (auto& row : rows) pointers.push_back(row.data());
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

void write_jpeg_file(const fs::path& path, int components, bool progressive,
                     int h_sampling) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    jpeg_compress_struct c{};
    jpeg_error_mgr errors{};
    c.err = jpeg_std_error(&errors);
    jpeg_create_compress(&c);
    jpeg_stdio_dest(&c, f);
    c.image_width = 37;
    c.image_height = 23;
    c.input_components = components;
    c.in_color_space = components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 80, TRUE);
    if (components == 3) c.comp_info[0].h_samp_factor = h_sampling;
    if (progressive) jpeg_simple_progression(&c);
    jpeg_start_compress(&c, TRUE);
    std::vector<JSAMPLE> row(size_t(c.image_width) * size_t(components));
    while (c.next_scanline < c.image_height) {
        for (size_t i = 0; i < row.size(); ++i)
            row[i] = JSAMPLE((i * 13 + c.next_scanline * 29 + (i * i) % 17) & 0xFF);
        JSAMPROW p = row.data();
        jpeg_write_scanlines(&c, &p, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    std::fclose(f);
}

void expect_same_as_open_image_io(const fs::path& path) {
    SCOPED_TRACE(path.filename().string());
    const DecodedImage ours = decode_image_file(path.string());
    const DecodedImage oiio = decode_with_open_image_io(path.string());
    EXPECT_EQ(ours.width, oiio.width);
    EXPECT_EQ(ours.height, oiio.height);
    EXPECT_EQ(ours.channels, oiio.channels);
    ASSERT_EQ(ours.samples.size(), oiio.samples.size());
    size_t differing = 0;
    for (size_t i = 0; i < ours.samples.size(); ++i)
        differing += std::memcmp(&ours.samples[i], &oiio.samples[i], sizeof(float)) != 0;
    EXPECT_EQ(differing, 0u);
    EXPECT_EQ(ours.info.format, oiio.info.format);
    EXPECT_EQ(ours.info.declared_gamma, oiio.info.declared_gamma);
    EXPECT_EQ(ours.info.has_alpha, oiio.info.has_alpha);
    EXPECT_EQ(ours.info.channels, oiio.info.channels);
    EXPECT_EQ(ours.info.bits, oiio.info.bits);
    EXPECT_EQ(ours.info.float_data, oiio.info.float_data);
}

std::vector<PngSpec> every_png_kind() {
    std::vector<PngSpec> kinds;
    auto add = [&](std::string name, int colour, int depth) {
        PngSpec s;
        s.name = std::move(name);
        s.colour = colour;
        s.depth = depth;
        kinds.push_back(s);
        return &kinds.back();
    };
    for (int d : {1, 2, 4, 8, 16})
        add("grey" + std::to_string(d), PNG_COLOR_TYPE_GRAY, d);
    for (int d : {8, 16}) {
        add("greyalpha" + std::to_string(d), PNG_COLOR_TYPE_GRAY_ALPHA, d);
        add("rgb" + std::to_string(d), PNG_COLOR_TYPE_RGB, d);
        add("rgba" + std::to_string(d), PNG_COLOR_TYPE_RGB_ALPHA, d);
    }
    for (int d : {1, 2, 4, 8})
        add("palette" + std::to_string(d), PNG_COLOR_TYPE_PALETTE, d)->palette_size =
            1 << d;
    PngSpec* p = add("palette_trns", PNG_COLOR_TYPE_PALETTE, 4);
    p->palette_size = 12;
    p->transparent = 5;
    add("grey_key", PNG_COLOR_TYPE_GRAY, 8)->transparent = 1;
    add("grey4_key", PNG_COLOR_TYPE_GRAY, 4)->transparent = 1;
    add("rgb_key", PNG_COLOR_TYPE_RGB, 8)->transparent = 1;
    add("rgb16_key", PNG_COLOR_TYPE_RGB, 16)->transparent = 1;
    add("interlaced", PNG_COLOR_TYPE_RGB_ALPHA, 8)->interlaced = true;
    add("interlaced_grey2", PNG_COLOR_TYPE_GRAY, 2)->interlaced = true;
    for (double g : {1 / 2.2, 0.45, 1.0, 0.5, 0.4, 1 / 1.8, 0.123456})
        add("gamma" + std::to_string(g), PNG_COLOR_TYPE_RGB, 8)->gamma = g;
    p = add("srgb_and_gamma", PNG_COLOR_TYPE_RGB, 8);
    p->srgb = true;
    p->gamma = 1 / 2.2;
    add("srgb", PNG_COLOR_TYPE_GRAY_ALPHA, 8)->srgb = true;
    return kinds;
}

TEST(ImageReaders, EveryKindOfPngReadsAsOpenImageIoReadsIt) {
    const fs::path dir = readers_scratch();
    for (const PngSpec& spec : every_png_kind()) {
        const fs::path path = dir / (spec.name + ".png");
        write_png_file(path, spec);
        expect_same_as_open_image_io(path);
    }
    // The 8-bit and 16-bit scales, every value (one row of each).
    PngSpec ramp;
    ramp.name = "ramp16";
    ramp.colour = PNG_COLOR_TYPE_GRAY;
    ramp.depth = 16;
    ramp.width = 65536;
    ramp.height = 1;
    write_png_file(dir / "ramp16.png", ramp);
    expect_same_as_open_image_io(dir / "ramp16.png");
    // The gamma a gAMA chunk alone declares (rounded to hundredths) and none beside sRGB.
    EXPECT_FLOAT_EQ(
        decode_image_file((dir / "gamma0.454545.png").string()).info.declared_gamma,
        2.2f);
    EXPECT_EQ(
        decode_image_file((dir / "srgb_and_gamma.png").string()).info.declared_gamma, 0);
    EXPECT_EQ(decode_image_file((dir / "rgb8.png").string()).info.declared_gamma, 0);
    fs::remove_all(dir);
}

TEST(ImageReaders, GreyAndColourJpegsReadAsOpenImageIoReadsThem) {
    const fs::path dir = readers_scratch();
    write_jpeg_file(dir / "grey.jpg", 1, false, 1);
    write_jpeg_file(dir / "colour420.jpg", 3, false, 2);
    write_jpeg_file(dir / "colour444.jpg", 3, false, 1);
    write_jpeg_file(dir / "progressive.jpg", 3, true, 2);
    for (const char* name :
         {"grey.jpg", "colour420.jpg", "colour444.jpg", "progressive.jpg"})
        expect_same_as_open_image_io(dir / name);
    fs::remove_all(dir);
}

TEST(ImageReaders, BrokenFilesFailWithTheLibrarysReason) {
    const fs::path dir = readers_scratch();
    PngSpec spec;
    write_png_file(dir / "whole.png", spec);
    // Cut in the middle of its image data.
    std::string bytes;
    {
        std::ifstream in(dir / "whole.png", std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::ofstream(dir / "cut.png", std::ios::binary)
        << bytes.substr(0, bytes.size() - 30);
    write_jpeg_file(dir / "whole.jpg", 3, false, 2);
    {
        std::ifstream in(dir / "whole.jpg", std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::ofstream(dir / "cut.jpg", std::ios::binary) << bytes.substr(0, 40);
    for (const char* name : {"cut.png", "cut.jpg"}) {
        const std::string path = (dir / name).string();
        try {
            decode_image_file(path);
            ADD_FAILURE() << name << " was read";
        } catch (const ImageIoError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("cannot read '" + path + "': ", 0), 0u)
                << e.what();
        }
    }
    fs::remove_all(dir);
}

TEST(ImageReaders, PngAndJpegAreReadWithoutLoadingOpenImageIo) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    if (!std::getenv("POVWALL_READERS_TEST_DIR"))
        setenv("POVWALL_READERS_TEST_DIR", readers_scratch().c_str(), 1);
    const fs::path dir = std::getenv("POVWALL_READERS_TEST_DIR");
    PngSpec spec;
    write_png_file(dir / "light.png", spec);
    write_jpeg_file(dir / "light.jpg", 3, false, 2);
    EXPECT_EXIT(
        {
            read_stored_image((dir / "light.png").string());
            read_stored_image((dir / "light.jpg").string());
            std::_Exit(open_image_io_loaded() ? 1 : 0);
        },
        testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace povwall::output
