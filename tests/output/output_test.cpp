// output/: POV-Ray 3.7 output encoding, file formats, atomic writes, and the image diff.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "output/diff.h"
#include "output/html_report.h"
#include "output/image_io.h"
#include "tests/output/open_image_io_loaded.h"
#include "tests/scratch_folder.h"

namespace povwall::output {
namespace {

namespace fs = std::filesystem;

fs::path scratch() { return povwall_test::process_scratch("povwall-output-test"); }

Image flat(int w, int h, float r, float g, float b, float a = 1.0f) {
    Image img(w, h);
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        img.rgba[i] = r;
        img.rgba[i + 1] = g;
        img.rgba[i + 2] = b;
        img.rgba[i + 3] = a;
    }
    return img;
}

std::string head_bytes(const fs::path& p, size_t n) {
    std::ifstream in(p, std::ios::binary);
    std::string s(n, '\0');
    in.read(s.data(), std::streamsize(n));
    s.resize(size_t(in.gcount()));
    return s;
}

// Only the named files are left in `dir` (no temporaries).
std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

int quantise8(float v) { return int(std::floor(v * 255.0f + 0.5f)); }

TEST(EncodeChannel, LegacySceneWritesRawValuesClamped) {
    OutputEncoding legacy;
    legacy.gamma_handling = false;
    EXPECT_FLOAT_EQ(encode_channel(0.5f, legacy), 0.5f);
    EXPECT_EQ(quantise8(encode_channel(0.5f, legacy)), 128);  // verified with POV-Ray 3.7
    EXPECT_FLOAT_EQ(encode_channel(1.7f, legacy), 1.0f);
    EXPECT_FLOAT_EQ(encode_channel(-0.3f, legacy), 0.0f);
}

TEST(EncodeChannel, LinearWorkingSpaceIsSrgbEncoded) {
    OutputEncoding e;  // assumed_gamma 1, File_Gamma sRGB
    EXPECT_EQ(quantise8(encode_channel(0.5f, e)), 188);  // POV-Ray: rgb 0.5 -> 188
    EXPECT_NEAR(encode_channel(0.5f, e), 1.055 * std::pow(0.5, 1 / 2.4) - 0.055, 1e-6);
    // Below 0.0031308 the sRGB curve is linear with slope 12.92.
    EXPECT_NEAR(encode_channel(0.002f, e), 0.002 * 12.92, 1e-7);
    EXPECT_FLOAT_EQ(encode_channel(0.0f, e), 0.0f);
    EXPECT_FLOAT_EQ(encode_channel(1.0f, e), 1.0f);
    EXPECT_FLOAT_EQ(encode_channel(3.0f, e), 1.0f);
}

TEST(EncodeChannel, WorkingGammaIsUndoneBeforeFileEncoding) {
    OutputEncoding e;
    // #version 3.6; assumed_gamma 2.2: POV-Ray writes 128 for 0.5
    e.working_gamma = GammaCurve::power(2.2f);
    EXPECT_EQ(quantise8(encode_channel(0.5f, e)), 128);
    EXPECT_NEAR(encode_channel(0.5f, e),
                1.055 * std::pow(std::pow(0.5, 2.2), 1 / 2.4) - 0.055, 1e-6);
    OutputEncoding g;
    g.file_srgb = false;
    g.file_gamma = 2.2f;
    EXPECT_NEAR(encode_channel(0.5f, g), std::pow(0.5, 1 / 2.2), 1e-6);
}

// assumed_gamma srgb: an sRGB file gets the working value itself (POV-Ray's transcoding
// between equal curves is the identity); another file gamma, the value linearised with
// sRGB's curve first.
TEST(EncodeChannel, SrgbWorkingSpaceIsWrittenAsItIsToAnSrgbFile) {
    OutputEncoding e;
    e.working_gamma = GammaCurve::srgb();
    EXPECT_EQ(encode_channel(0.5f, e), 0.5f);
    EXPECT_EQ(encode_channel(0.01f, e), 0.01f);
    EXPECT_EQ(encode_channel(1.5f, e), 1.0f);
    e.file_srgb = false;
    e.file_gamma = 1.8f;
    EXPECT_NEAR(encode_channel(0.5f, e), std::pow(std::pow(0.555 / 1.055, 2.4), 1 / 1.8),
                1e-5);
    EXPECT_NEAR(encode_channel(0.02f, e), std::pow(0.02 / 12.92, 1 / 1.8), 1e-6);
}

TEST(WriteImage, Png8And16BitQuantiseAsPovRay) {
    fs::path p8 = scratch() / "q8.png", p16 = scratch() / "q16.png";
    Image img = flat(3, 2, 0.5f, 0.0f, 1.0f);
    OutputEncoding e;
    write_image(img, p8.string(), e);
    EXPECT_EQ(head_bytes(p8, 4), "\x89PNG");
    Image back = read_image(p8.string());
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    EXPECT_FLOAT_EQ(back.pixel(2, 1)[0] * 255.0f, 188.0f);
    EXPECT_FLOAT_EQ(back.pixel(2, 1)[1], 0.0f);
    EXPECT_FLOAT_EQ(back.pixel(2, 1)[2], 1.0f);
    e.bits = 16;
    write_image(img, p16.string(), e);
    back = read_image(p16.string());
    EXPECT_NEAR(back.pixel(0, 0)[0] * 65535.0f, 48192.0f, 1e-2);  // POV-Ray's PNG16 value
}

TEST(WriteImage, ColourDepthsAsPovRayStoresThem) {
    // 0.5 linear is 0.735358 in sRGB: at 5 bits 23, at 12 bits 3011 (floor(x max + 0.5)).
    Image img = flat(1, 1, 0.5f, 0.5f, 0.5f);
    OutputEncoding e;
    auto stored = [&](int bits, const std::string& name) {
        e.bits = bits;
        const fs::path p = scratch() / name;
        write_image(img, p.string(), e);
        return read_image(p.string()).pixel(0, 0)[0];
    };
    // PNG: 8- or 16-bit samples filled by left bit replication (23 << 3 | 23 >> 2 = 189,
    // 3011 << 4 | 3011 >> 8 = 48187), as POV-Ray's +FN5 and +FN12.
    EXPECT_FLOAT_EQ(stored(5, "d5.png") * 255.0f, 189.0f);
    EXPECT_NEAR(stored(12, "d12.png") * 65535.0f, 48187.0f, 1e-2);
    // Out of 5..16 as POV-Ray clamps it.
    EXPECT_FLOAT_EQ(stored(2, "d2.png") * 255.0f, 189.0f);
    // PPM: the depth's largest value is the maxval and the samples are stored as is.
    e.bits = 12;
    const fs::path ppm = scratch() / "d12.ppm";
    write_image(img, ppm.string(), e);
    EXPECT_EQ(head_bytes(ppm, 19),
              std::string("P6\n1 1\n4095\n\x0b\xc3\x0b\xc3\x0b\xc3", 18));
    e.bits = 8;
    e.alpha = true;  // PPM has no alpha channel (POV-Ray's +FP ignores +UA)
    const fs::path ppm8 = scratch() / "d8.ppm";
    write_image(img, ppm8.string(), e);
    EXPECT_EQ(head_bytes(ppm8, 15), std::string("P6\n1 1\n255\n\xbc\xbc\xbc", 14));
}

// The chunk types of a PNG file in order, with the gAMA value (gamma x 100000) if any.
std::vector<std::string> png_chunks(const fs::path& p, uint32_t* gama = nullptr) {
    std::ifstream in(p, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
    std::vector<std::string> types;
    auto be32 = [&](size_t at) {
        return uint32_t(uint8_t(data[at])) << 24 | uint32_t(uint8_t(data[at + 1])) << 16 |
               uint32_t(uint8_t(data[at + 2])) << 8 | uint32_t(uint8_t(data[at + 3]));
    };
    for (size_t at = 8; at + 8 <= data.size();) {
        const uint32_t length = be32(at);
        const std::string type = data.substr(at + 4, 4);
        if (type == "gAMA" && gama) *gama = be32(at + 8);
        if (types.empty() || types.back() != type) types.push_back(type);
        at += 12 + length;
    }
    return types;
}

TEST(WriteImage, PngDeclaresItsEncodingAsPovRayDoes) {
    Image img = flat(2, 2, 0.5f, 0.5f, 0.5f);
    fs::path srgb = scratch() / "srgb.png", g22 = scratch() / "g22.png",
             legacy = scratch() / "legacy.png";
    uint32_t gama = 0;
    write_image(img, srgb.string(), OutputEncoding{});
    EXPECT_EQ(png_chunks(srgb, &gama),
              (std::vector<std::string>{"IHDR", "gAMA", "sRGB", "cHRM", "IDAT", "IEND"}));
    EXPECT_EQ(gama, 45455u);  // the value the PNG specification pairs with sRGB
    OutputEncoding e;
    e.file_srgb = false;
    e.file_gamma = 2.2f;
    write_image(img, g22.string(), e);
    EXPECT_EQ(png_chunks(g22, &gama),
              (std::vector<std::string>{"IHDR", "gAMA", "IDAT", "IEND"}));
    EXPECT_EQ(gama, 45455u);  // 1/2.2
    EXPECT_NEAR(read_image(g22.string()).pixel(0, 0)[0] * 255.0f,
                std::floor(std::pow(0.5f, 1 / 2.2f) * 255.0f + 0.5f), 1e-3);
    e.gamma_handling = false;  // legacy scene: raw values, no declaration
    write_image(img, legacy.string(), e);
    EXPECT_EQ(png_chunks(legacy), (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
    EXPECT_FLOAT_EQ(read_image(legacy.string()).pixel(1, 1)[2] * 255.0f, 128.0f);
}

// PNG, the format nearly every render writes, must not load the OpenImageIO module (some
// 260 libraries, 0.2 s per process). In a fresh process: a death test re-executes the
// binary, so modules that other tests loaded do not count.
TEST(WriteImage, PngIsWrittenWithoutLoadingOpenImageIo) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    // The re-executed child has another pid, hence another scratch(): it inherits the
    // parent's folder through the environment.
    if (!std::getenv("POVWALL_OUTPUT_TEST_DIR"))
        setenv("POVWALL_OUTPUT_TEST_DIR", scratch().c_str(), 1);
    const fs::path dir = std::getenv("POVWALL_OUTPUT_TEST_DIR");
    const std::string path = (dir / "light.png").string();
    EXPECT_EXIT(
        {
            write_image(flat(4, 4, 0.25f, 0.5f, 1.0f), path, OutputEncoding{});
            std::_Exit(open_image_io_loaded() ? 1 : 0);
        },
        testing::ExitedWithCode(0), "");
    // And the file is a whole PNG (this process may load the module to read it).
    EXPECT_FLOAT_EQ(read_image(path).pixel(3, 3)[1] * 255.0f, 188.0f);
    // A .tga is written by OpenImageIO: the same check fails for it, so the test above
    // can fail.
    const std::string tga = (dir / "heavy.tga").string();
    EXPECT_EXIT(
        {
            write_image(flat(4, 4, 0.25f, 0.5f, 1.0f), tga, OutputEncoding{});
            std::_Exit(open_image_io_loaded() ? 1 : 0);
        },
        testing::ExitedWithCode(1), "");
}

TEST(WriteImage, AlphaIsWrittenStraightAsPovRayDoes) {
    fs::path p = scratch() / "alpha.png";
    OutputEncoding e;
    e.alpha = true;
    // Premultiplied 0.125 at alpha 0.25 is straight 0.5, which sRGB-encodes to 188.
    write_image(flat(2, 2, 0.125f, 0.125f, 0.125f, 0.25f), p.string(), e);
    Image back = read_image(p.string());
    EXPECT_FLOAT_EQ(back.pixel(1, 1)[0] * 255.0f, 188.0f);
    EXPECT_FLOAT_EQ(back.pixel(1, 1)[3] * 255.0f, 64.0f);  // floor(0.25*255 + 0.5)
    fs::path opaque = scratch() / "opaque.png";
    write_image(flat(2, 2, 0.5f, 0.5f, 0.5f, 0.25f), opaque.string(), OutputEncoding{});
    EXPECT_FLOAT_EQ(read_image(opaque.string()).pixel(0, 0)[3], 1.0f);  // RGB file
}

// A pixel brighter than its opacity (glass over a transparent background: little alpha,
// much light) takes its brightness (0.297 r + 0.589 g + 0.114 b) as its alpha before the
// division, as POV-Ray's GetEncodedRGBAValue does; without an alpha channel (PPM with
// +UA) the premultiplied colour is written.
TEST(WriteImage, BrightTransparentPixelsGetTheirBrightnessAsAlpha) {
    fs::path p = scratch() / "bright.png";
    OutputEncoding e;
    e.alpha = true;
    e.file_srgb = false;
    e.file_gamma = 1.0f;
    // bright = 0.297 * 0.6 + 0.589 * 0.6 + 0.114 * 0.4 = 0.5772 > alpha 0.25.
    write_image(flat(2, 2, 0.6f, 0.6f, 0.4f, 0.25f), p.string(), e);
    Image back = read_image(p.string());
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[3] * 255.0f, 147.0f);  // floor(0.5772 * 255 + 0.5)
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[0] * 255.0f, 255.0f);  // 0.6 / 0.5772, clipped
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[2] * 255.0f, 177.0f);  // 0.4 / 0.5772 = 0.693
    // No brighter than its alpha: unchanged.
    write_image(flat(2, 2, 0.1f, 0.1f, 0.1f, 0.25f), p.string(), e);
    back = read_image(p.string());
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[3] * 255.0f, 64.0f);
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[0] * 255.0f, 102.0f);  // 0.1 / 0.25 = 0.4
    fs::path ppm = scratch() / "bright.ppm";
    write_image(flat(2, 2, 0.6f, 0.6f, 0.4f, 0.25f), ppm.string(), e);
    back = read_image(ppm.string());
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[0] * 255.0f, 153.0f);  // 0.6, not divided
    EXPECT_FLOAT_EQ(back.pixel(0, 0)[2] * 255.0f, 102.0f);
}

TEST(WriteImage, FormatFromExtensionOrExplicit) {
    Image img = flat(4, 3, 0.5f, 0.25f, 0.125f);
    OutputEncoding e;
    fs::path tga = scratch() / "f.tga", ppm = scratch() / "f.ppm",
             exr = scratch() / "f.exr";
    write_image(img, tga.string(), e);
    write_image(img, ppm.string(), e);
    write_image(img, exr.string(), e);
    EXPECT_EQ(head_bytes(ppm, 2), "P6");
    EXPECT_EQ(head_bytes(exr, 4), std::string("\x76\x2f\x31\x01", 4));
    EXPECT_FLOAT_EQ(read_image(tga.string()).pixel(0, 0)[0] * 255.0f, 188.0f);
    EXPECT_FLOAT_EQ(read_image(ppm.string()).pixel(3, 2)[0] * 255.0f, 188.0f);
    EXPECT_FLOAT_EQ(read_image(exr.string()).pixel(0, 0)[1], 0.25f);  // EXR stays linear
    // POV-Ray's +FP with a .png name: the format wins over the extension.
    fs::path forced = scratch() / "forced.png";
    write_image(img, forced.string(), e, "ppm");
    EXPECT_EQ(head_bytes(forced, 2), "P6");
}

TEST(WriteImage, FailuresLeaveNoFileBehind) {
    fs::path dir = scratch() / "atomic";
    fs::remove_all(dir);
    fs::create_directories(dir);
    Image img = flat(2, 2, 1, 1, 1);
    EXPECT_THROW(write_image(img, (dir / "x.unknownformat").string(), OutputEncoding{}),
                 ImageIoError);
    EXPECT_THROW(write_image(img, (dir / "missing" / "x.png").string(), OutputEncoding{}),
                 ImageIoError);
    EXPECT_TRUE(listing(dir).empty());
    // Overwriting replaces the old file whole and leaves no temporary.
    std::ofstream(dir / "old.png") << "not an image";
    write_image(img, (dir / "old.png").string(), OutputEncoding{});
    EXPECT_EQ(listing(dir), std::vector<std::string>{"old.png"});
    EXPECT_EQ(read_image((dir / "old.png").string()).width, 2);
}

TEST(ReadImage, UnreadableFilesThrow) {
    EXPECT_THROW(read_image((scratch() / "nonexistent.png").string()), ImageIoError);
    fs::path text = scratch() / "text.png";
    std::ofstream(text) << "hello";
    EXPECT_THROW(read_image(text.string()), ImageIoError);
}

TEST(Diff, ExactMetricsAndLocationOfTheLargestError) {
    Image a = flat(10, 10, 0.5f, 0.5f, 0.5f);
    Image b = a;
    b.pixel(7, 2)[2] = 0.8f;   // 0.3: bad
    b.pixel(1, 1)[0] = 0.45f;  // 0.05: not bad
    DiffResult r = diff_images(a, b);
    const double sum = 0.3f * 0.3f + 0.05f * 0.05f;  // float inputs as stored
    EXPECT_NEAR(r.rmse, std::sqrt(sum / 300.0), 1e-7);
    EXPECT_NEAR(r.psnr, 20 * std::log10(1 / std::sqrt(sum / 300.0)), 1e-5);
    EXPECT_NEAR(r.max_abs, 0.3, 1e-6);
    EXPECT_EQ(r.max_x, 7);
    EXPECT_EQ(r.max_y, 2);
    EXPECT_EQ(r.max_channel, 2);
    EXPECT_FLOAT_EQ(float(r.max_value_a), 0.5f);
    EXPECT_FLOAT_EQ(float(r.max_value_b), 0.8f);
    EXPECT_EQ(r.bad_pixels, 1);
    EXPECT_DOUBLE_EQ(r.bad_pixel_fraction, 0.01);
    EXPECT_EQ(r.status, DiffResult::Status::Fail);  // 0.01 > 0.002 and rmse 0.0176 > 0.01
    // Alpha is not compared.
    Image c = a;
    c.pixel(0, 0)[3] = 0.0f;
    DiffResult same = diff_images(a, c);
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_EQ(same.psnr, std::numeric_limits<double>::infinity());
    EXPECT_EQ(same.status, DiffResult::Status::Pass);
}

TEST(Diff, ThresholdsDecidePassWarnFail) {
    Image a = flat(100, 10, 0.5f, 0.5f, 0.5f);
    Image b = a;
    b.pixel(0, 0)[0] = 0.7f;  // one bad pixel of 1000, rmse 0.2/sqrt(3000) = 0.00365
    DiffThresholds t;
    EXPECT_EQ(diff_images(a, b, t).status, DiffResult::Status::Warn);  // 0.001 <= 0.002
    t.warn_percent = 0.1;
    EXPECT_EQ(diff_images(a, b, t).status, DiffResult::Status::Pass);  // 0.1 % allowed
    t.max_bad_fraction = 0.0;
    EXPECT_EQ(diff_images(a, b, t).status, DiffResult::Status::Fail);
    t = {};
    t.max_rmse = 0.003;
    EXPECT_EQ(diff_images(a, b, t).status, DiffResult::Status::Fail);
    t = {};
    t.fail = t.warn = 0.25;  // the pixel is no longer over either threshold
    DiffResult r = diff_images(a, b, t);
    EXPECT_EQ(r.bad_pixels, 0);
    EXPECT_EQ(r.status, DiffResult::Status::Pass);
}

TEST(Diff, SizeMismatchUnreadableAndDifferenceImage) {
    DiffResult r = diff_images(flat(4, 4, 0, 0, 0), flat(4, 5, 0, 0, 0));
    EXPECT_EQ(r.status, DiffResult::Status::SizeMismatch);
    EXPECT_EQ(r.error, "image sizes differ: 4x4 vs 4x5");
    r = diff_files((scratch() / "nope.png").string(), (scratch() / "nope2.png").string());
    EXPECT_EQ(r.status, DiffResult::Status::Unreadable);
    Image d =
        difference_image(flat(2, 1, 0.5f, 0.2f, 1.0f), flat(2, 1, 0.25f, 0.7f, 1.0f));
    EXPECT_FLOAT_EQ(d.pixel(1, 0)[0], 0.25f);
    EXPECT_FLOAT_EQ(d.pixel(1, 0)[1], 0.5f);
    EXPECT_FLOAT_EQ(d.pixel(1, 0)[2], 0.0f);
    EXPECT_FLOAT_EQ(d.pixel(1, 0)[3], 1.0f);
}

TEST(Diff, HeatmapRampEndsRedAtTheBadPixelThreshold) {
    auto heat_of = [](float difference) {
        Image h = difference_heatmap(flat(1, 1, 0.5f, 0.5f, 0.5f),
                                     flat(1, 1, 0.5f, 0.5f - difference, 0.5f));
        return std::vector<float>(h.rgba.begin(), h.rgba.begin() + 3);
    };
    EXPECT_EQ(heat_of(0.0f), (std::vector<float>{0, 0, 0}));  // equal: black
    const std::vector<float> blue = heat_of(0.1f / 3), yellow = heat_of(0.2f / 3);
    EXPECT_NEAR(blue[0], 0, 1e-5);
    EXPECT_NEAR(blue[2], 1, 1e-5);
    EXPECT_NEAR(yellow[0], 1, 1e-5);
    EXPECT_NEAR(yellow[1], 1, 1e-5);
    EXPECT_NEAR(yellow[2], 0, 1e-5);
    const std::vector<float> threshold = heat_of(0.1f);  // bad from here on: red
    EXPECT_NEAR(threshold[0], 1, 1e-5);
    EXPECT_NEAR(threshold[1], 0, 1e-5);
    EXPECT_NEAR(threshold[2], 0, 1e-5);
    EXPECT_EQ(heat_of(0.4f), (std::vector<float>{1, 0, 0}));
    const std::vector<float> small = heat_of(0.01f);  // dark blue, growing with the error
    EXPECT_GT(small[2], 0.2f);
    EXPECT_LT(small[2], 0.4f);
    EXPECT_EQ(small[0], 0.0f);
    // The largest channel decides; sizes that differ give an all-black map.
    Image h = difference_heatmap(flat(1, 1, 0, 0, 0), flat(1, 1, 0.02f, 0.2f, 0.01f));
    EXPECT_FLOAT_EQ(h.pixel(0, 0)[0], 1.0f);
    EXPECT_FLOAT_EQ(difference_heatmap(flat(2, 2, 0, 0, 0), flat(1, 1, 1, 1, 1)).rgba[0],
                    0);
}

TEST(HtmlReport, EscapesTextShowsImagesAndCountsWhatLoaded) {
    EXPECT_EQ(html_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
    HtmlReport report;
    report.title = "T <1>";
    report.summary = {"1 & 2"};
    report.columns = {"scene", "image"};
    HtmlCell image;
    image.image = "images/a\"b.png";
    image.text = "alt";
    HtmlCell logged;
    logged.text = "failed <x>";
    logged.link = "logs/x.log";
    report.rows.push_back({"failed", {logged, image}});
    const std::string page = html_report_text(report);
    EXPECT_NE(page.find("<title>T &lt;1&gt;</title>"), std::string::npos);
    EXPECT_NE(page.find("<p>1 &amp; 2</p>"), std::string::npos);
    EXPECT_NE(
        page.find(
            "<tr class=\"failed\"><td><a href=\"logs/x.log\">failed &lt;x&gt;</a>"
            "</td><td><a href=\"images/a&quot;b.png\"><img src=\"images/a&quot;b.png\""),
        std::string::npos)
        << page;
    EXPECT_NE(page.find("document.body.dataset.imagesLoaded"), std::string::npos);
    EXPECT_NE(page.find("document.body.dataset.rows"), std::string::npos);
    EXPECT_EQ(page.find("http"), std::string::npos);  // nothing from the network
    const fs::path path = scratch() / "report.html";
    write_html_report(report, path.string());
    std::ifstream in(path);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), page);
    EXPECT_THROW(write_html_report(report, (scratch() / "no/such/dir/r.html").string()),
                 HtmlWriteError);
    EXPECT_FALSE(fs::exists(scratch() / "no"));
}

}  // namespace
}  // namespace povwall::output
