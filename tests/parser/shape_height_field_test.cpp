// height_field { image | function W, H { } [water_level | smooth]* modifiers }: the
// image read (real files), the unit-square transform, water_level, smooth, hierarchy
// after the modifiers, and POV-Ray's errors and povwall's refusals, located.
#include <gtest/gtest.h>

#include "output/image_io.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;

const std::string kImages = std::string(POVWALL_SOURCE_DIR) + "/scenes/golden/images/";

Scene parse_with_images(const std::string& text) {
    ParseOptions o;
    o.image_reader = output::read_stored_image;
    return parse_scene_text(text, "test.pov", o);
}

// The first line of the error parsing `text` with images gives ("(no error)" if none).
std::string image_error(const std::string& text) {
    try {
        parse_with_images(text);
    } catch (const ParseError& e) {
        const std::string what = e.what();
        return what.substr(0, what.find('\n'));
    }
    return "(no error)";
}

TEST(ShapeHeightField, ImageGridTransformAndOptions) {
    Scene s = parse_with_images("height_field { png \"" + kImages +
                                "hf_grey16.png\" water_level 0.25 smooth "
                                "water_level 0.2 hierarchy off translate x }");
    const Object& o = s.objects.at(0);
    const HeightField& hf = std::get<HeightField>(o.shape);
    const HeightFieldData& d = *hf.data;
    EXPECT_EQ(d.width, 40);
    EXPECT_EQ(d.depth, 40);
    EXPECT_TRUE(hf.smooth);
    EXPECT_EQ(d.normals.size(), 1600u);
    EXPECT_FALSE(hf.hierarchy);
    EXPECT_EQ(d.blocks.size(), 1u);  // hierarchy off, given after the image's options
    // The last water_level counts: 0.2 * 65536 (above the lowest height here).
    EXPECT_DOUBLE_EQ(d.floor_y, std::max(0.2 * 65536, Real(d.min_height)) - 0.001);
    EXPECT_DOUBLE_EQ(d.top_y, d.max_height + 0.001);
    // The grid's far corner (39, 65536, 39) goes to (1, 1, 1), then translate x.
    const Point3 p = o.transform.point({39, 65536, 39});
    EXPECT_NEAR(p.x, 2, 1e-15);
    EXPECT_NEAR(p.y, 1, 1e-15);
    EXPECT_NEAR(p.z, 1, 1e-15);
    // A palette image: every height a multiple of 256.
    s = parse_with_images("height_field { \"" + kImages + "hf_palette.png\" }");
    const HeightFieldData& pal = *std::get<HeightField>(s.objects.at(0).shape).data;
    EXPECT_EQ(pal.width, 24);
    EXPECT_EQ(pal.depth, 30);
    for (uint16_t h : pal.heights) EXPECT_EQ(h % 256, 0);
    EXPECT_GT(pal.max_height, 0);
    // A copy keeps the grid (and its blocks: a later hierarchy changes nothing).
    s = parse_with_images("#declare H = height_field { png \"" + kImages +
                          "hf_grey16.png\" } object { H hierarchy off }");
    const HeightField& copy = std::get<HeightField>(s.objects.at(0).shape);
    EXPECT_FALSE(copy.hierarchy);
    EXPECT_EQ(copy.data->blocks.size(), 36u);
}

TEST(ShapeHeightField, Errors) {
    EXPECT_EQ(error_of("height_field { iff \"a.iff\" }"),
              "test.pov:1:16: error: File type not supported here.");
    EXPECT_EQ(error_of("height_field { \"a.xyz\" }"),
              "test.pov:1:16: error: Could not determine valid image file type from "
              "extension.");
    EXPECT_EQ(error_of("height_field { png \"nope.png\" }"),
              "test.pov:1:20: error: cannot find image file \"nope.png\"");
    EXPECT_EQ(error_of("height_field { function 4, 4 x }"),
              "test.pov:1:30: error: expected '{' after the function image's size but "
              "found 'x'");
    EXPECT_EQ(error_of("height_field { function 4, 4 { spline { 0, 1 1, 2 } } }"),
              "test.pov:1:30: error: Unsupported function type in function image.");
    EXPECT_EQ(error_of("height_field { function 4, 4 { 0.5 } texture { } smooth }"),
              "test.pov:1:50: error: expected an object modifier or '}' but found "
              "'smooth'");
    // The type from the extension, without case; `pot` only by its keyword.
    EXPECT_EQ(error_of("height_field { \"a.pot\" }"),
              "test.pov:1:16: error: Could not determine valid image file type from "
              "extension.");
    EXPECT_EQ(error_of("height_field { \"a.PNG\" }"),
              "test.pov:1:16: error: cannot find image file \"a.PNG\"");
    EXPECT_EQ(error_of("height_field { pot \"a\" }"),
              "test.pov:1:20: error: cannot find image file \"a\"");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { image_map { pot \"a.gif\" } } }"),
              "test.pov:1:37: error: File type not supported here.");
    EXPECT_EQ(error_of("sphere { 0, 1 hierarchy }"),
              "test.pov:1:15: error: 'hierarchy' cannot be used with this object");
}

TEST(ShapeHeightField, Refusals) {
    EXPECT_EQ(
        error_of("height_field { function 1, 4 { x } }"),
        "test.pov:1:25: error: unsupported: height_field function smaller than 2 x 2");
    EXPECT_EQ(error_of("height_field { function 4, 4 { 70000 } }"),
              "test.pov:1:30: error: unsupported: height_field function value out of "
              "range");
    const std::string png = "\"" + kImages + "hf_grey8.png\"";
    auto refusal = [](const std::string& text) {
        try {
            parse_with_images(text);
        } catch (const ParseError& e) {
            const std::string what = e.what();
            return what.substr(0, what.find('\n'));
        }
        return std::string("(no error)");
    };
    const std::string at = "test.pov:1:" + std::to_string(21 + png.size()) + ": error: ";
    EXPECT_EQ(refusal("height_field { png " + png + " gamma 2 }"),
              at + "unsupported: height_field image gamma");
    // Only alpha is kept differently, and a PNG's (or Targa's, BMP's) heights ignore it
    // (golden shape_height_field_alpha); TIFF and OpenEXR alpha stay refused (libtiff
    // premultiplies in 8 bits).
    EXPECT_EQ(refusal("height_field { png " + png + " premultiplied on }"), "(no error)");
    EXPECT_EQ(
        refusal("height_field { png \"" + kImages + "card_alpha.png\" premultiplied 0 }"),
        "(no error)");
    EXPECT_EQ(refusal("height_field { png \"" + kImages + "card_alpha.png\" }"),
              "(no error)");
}

// Files named without extension (the type's extensions tried, or with no type keyword the
// output file type's), POT, TIFF and float images, and POV-Ray's errors for them.
TEST(ShapeHeightField, FileTypesAndNames) {
    auto grid = [](const std::string& spec, char output_type = 'N') {
        ParseOptions o;
        o.image_reader = output::read_stored_image;
        o.output_file_type = output_type;
        const Scene s = parse_scene_text("height_field { " + spec + " }", "test.pov", o);
        return *std::get<HeightField>(s.objects.at(0).shape).data;
    };
    const std::string dir = "\"" + kImages;
    EXPECT_EQ(grid(dir + "hf_grey8\"").width, 33);            // .png, the default +FN
    EXPECT_EQ(grid(dir + "hf_rgb8\"", 'T').width, 30);        // .tga for +FT
    EXPECT_EQ(grid("tiff " + dir + "hf_grey8\"").width, 33);  // .tif
    // POT: 16-bit heights, the grid half the GIF's width; each height's high byte left.
    const HeightFieldData pot = grid("pot " + dir + "hf_heights.pot\"");
    EXPECT_EQ(pot.width, 30);
    EXPECT_EQ(pot.depth, 26);
    bool low_bytes = false;
    for (uint16_t h : pot.heights) low_bytes = low_bytes || (h & 255) != 0;
    EXPECT_TRUE(low_bytes);
    // An 8-bit grey TIFF: v * 257 (red * 256 + green); a 16-bit one keeps its high byte.
    for (const char* name : {"hf_grey8.tif", "hf_grey16.tif"}) {
        for (uint16_t h : grid(dir + name + "\"").heights) EXPECT_EQ(h % 257, 0) << name;
    }
    // Float images: red * 256 + green, as if 8-bit.
    EXPECT_EQ(grid(dir + "hf_rgbe.hdr\"").width, 20);
    EXPECT_EQ(grid("exr " + dir + "hf_half\"").depth, 26);
    EXPECT_EQ(image_error("height_field { sys " + dir + "hf_grey8.png\" }"),
              "test.pov:1:16: error: This platform has not defined a SYS file type");
    // POV-Ray picks the reader by the type, not by the file's content.
    EXPECT_EQ(
        image_error("height_field { pot " + dir + "hf_grey8.png\" }"),
        "test.pov:1:20: error: Cannot read image: not a pot file (it reads as png)");
}

}  // namespace
}  // namespace povwall::parser
