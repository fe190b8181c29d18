// height_field: exact heights from each image container (POV-Ray 3.7's image_height_at
// rules), exact crossings, normals, the inside test and the early exit outside CSG.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "parser/parser.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

namespace fs = std::filesystem;

// A reader that returns `image` for any file name (the file must exist).
struct Fake {
    StoredImage image;
    fs::path dir;
    explicit Fake(StoredImage s) : image(std::move(s)) {
        // One folder per test: ctest runs the tests of this file side by side.
        dir = fs::temp_directory_path() /
              ("povwall_height_field_test_" +
               std::string(
                   ::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir);
        for (const char* f : {"a.png", "a.pgm", "a.tga", "a.gif"})
            std::ofstream(dir / f) << "x";
    }
    Scene parse(const std::string& text) const {
        parser::ParseOptions o;
        StoredImage copy = image;
        o.image_reader = [copy](const std::string&) { return copy; };
        std::ofstream(dir / "s.pov") << text;
        return parser::parse_scene_file((dir / "s.pov").string(), o);
    }
};

// w x h pixels, `channels` as stored, every sample from `value(x, y, c)` (top row y = 0).
template <class F>
StoredImage image(int w, int h, const std::string& format, int channels, int bits,
                  F value) {
    StoredImage s;
    s.pixels = Image(w, h);
    s.format = format;
    s.channels = channels;
    s.bits = bits;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                s.pixels.pixel(x, y)[c] = c < 3 ? value(x, y, c) : 1;
    return s;
}

// A copy: the scene parsed is often a temporary.
HeightFieldData data_of(const Scene& s) {
    return *std::get<HeightField>(s.objects.at(0).shape).data;
}

TEST(HeightField, HeightsFromEachContainer) {
    // 8-bit grey PNG: through POV-Ray's grey palette, 3 -> 2 * 257, 4 -> 4 * 257.
    auto grey = [](int x, int y, int) { return float(x + 3 * y + 3) / 255.0f; };
    Fake png8(image(3, 2, "png", 1, 8, grey));
    const HeightFieldData a = data_of(png8.parse("height_field { png \"a.png\" }"));
    ASSERT_EQ(a.width, 3);
    ASSERT_EQ(a.depth, 2);
    // Grid z = 0 is the image's bottom row (y = 1): values 6, 7, 8; top row 3, 4, 5.
    EXPECT_EQ(a.at(0, 1), 2 * 257);  // 3, one lower
    EXPECT_EQ(a.at(1, 1), 4 * 257);
    EXPECT_EQ(a.at(2, 1), 4 * 257);  // 5, one lower
    EXPECT_EQ(a.at(0, 0), 5 * 257);  // 6, one lower
    EXPECT_EQ(a.at(1, 0), 7 * 257);
    // The same values from a PGM are exact: v * 257.
    StoredImage pgm = image(3, 2, "pnm", 1, 8, grey);
    pgm.pnm_maxval = 255;
    const HeightFieldData b = data_of(Fake(pgm).parse("height_field { pgm \"a.pgm\" }"));
    EXPECT_EQ(b.at(0, 1), 3 * 257);
    EXPECT_EQ(b.at(2, 1), 5 * 257);
    // 16-bit grey: exact.
    auto g16 = [](int x, int y, int) { return float(1001 + x + 1000 * y) / 65535.0f; };
    const HeightFieldData g =
        data_of(Fake(image(2, 2, "png", 1, 16, g16)).parse("height_field { \"a.png\" }"));
    EXPECT_EQ(g.at(0, 1), 1001);
    EXPECT_EQ(g.at(1, 0), 2002);
    // 16-bit RGB grey: the weights sum below 1, so 1001 -> 1000, 3 -> 2
    // and 2 -> 1 (about half of all values lose one).
    auto rgb16 = [](int x, int, int) {
        return float(x == 0 ? 1001 : x == 1 ? 3 : 2) / 65535.0f;
    };
    const HeightFieldData d = data_of(
        Fake(image(3, 2, "png", 3, 16, rgb16)).parse("height_field { png \"a.png\" }"));
    EXPECT_EQ(d.at(0, 0), 1000);
    EXPECT_EQ(d.at(1, 0), 2);
    EXPECT_EQ(d.at(2, 0), 1);
    // 8-bit colour: red * 256 + green, blue unused.
    auto rgb8 = [](int x, int, int c) {
        return float(c == 0 ? 12 + x : c == 1 ? 200 : 99) / 255.0f;
    };
    const HeightFieldData e = data_of(
        Fake(image(2, 2, "targa", 3, 8, rgb8)).parse("height_field { tga \"a.tga\" }"));
    EXPECT_EQ(e.at(0, 0), 12 * 256 + 200);
    EXPECT_EQ(e.at(1, 1), 13 * 256 + 200);
    // A palette image: index * 256.
    StoredImage pal = image(2, 2, "gif", 3, 8, [](int, int, int) { return 0.5f; });
    pal.colour_mapped = true;
    pal.indices = {7, 0, 255, 1};
    pal.palette_size = 256;
    const HeightFieldData f = data_of(Fake(pal).parse("height_field { gif \"a.gif\" }"));
    EXPECT_EQ(f.at(0, 1), 7 * 256);
    EXPECT_EQ(f.at(0, 0), 255 * 256);
    EXPECT_EQ(f.at(1, 0), 256);
    EXPECT_EQ(f.min_height, 0);
    EXPECT_EQ(f.max_height, 255 * 256);
}

TEST(HeightField, FunctionImages) {
    Fake none(StoredImage{});
    // function y: grid z = 0 is function y = 1.
    const HeightFieldData a =
        data_of(none.parse("height_field { function 11, 11 { y } }"));
    EXPECT_EQ(a.at(0, 0), 65535);
    EXPECT_EQ(a.at(3, 10), 0);
    EXPECT_EQ(a.at(0, 1), uint16_t(float(0.9) * 65535.0f));
    // 1.5 wraps: (uint16)(int)(1.5 * 65535) = 32766.
    EXPECT_EQ(data_of(none.parse("height_field { function 2, 2 { 1.5 } }")).at(1, 1),
              32766);
    EXPECT_EQ(data_of(none.parse("height_field { function 2, 2 { -0.5 } }")).at(0, 0),
              32769);
}

Scene flat_scene(const std::string& extra) {
    // 3 x 3 vertices, all at 0.5 * 65535 except vertex (1, 1) of the grid at 65535.
    auto v = [](int x, int y, int) { return x == 1 && y == 1 ? 1.0f : 0.5f; };
    return Fake(image(3, 3, "png", 1, 16, v))
        .parse("height_field { png \"a.png\" " + extra + " }");
}

ShapeHits hits_of(const Object& o, const Point3& origin, const Vector3& dir, bool csg) {
    ShapeHits hits;
    LocalRay r = leaf_ray(o, Ray{origin, normalize(dir)});
    r.csg_child = csg;
    leaf_hits(o, r, hits);
    return hits;
}

TEST(HeightField, CrossingsNormalsAndInside) {
    const Scene s = flat_scene("");
    const Object& o = s.objects.at(0);
    const Real h = 0.5;  // the flat part: 32768 (the sample 0.5 of 65535, rounded)
    // Straight down at (0.1, 0.1): cell (0, 0), its lower triangle; the vertical-ray
    // path.
    ShapeHits hits = hits_of(o, {0.1, 2, 0.1}, {0, -1, 0}, false);
    ASSERT_EQ(hits.size(), 1u);
    // Lower triangle of cell (0,0): vertices (0,0) and (1,0), (0,1) at the flat height.
    EXPECT_DOUBLE_EQ(hits[0].t, 2 - h);
    EXPECT_EQ(hits[0].face, kHeightFieldLower);
    const Vector3 n = leaf_world_normal(o, hits[0]);
    EXPECT_NEAR(n.y, 1, 1e-15);
    // A slanted ray across the peak: outside CSG the first cell that hits ends the walk.
    const Point3 from{-0.5, 0.8, 0.4};
    const Vector3 dir{1, -0.1, 0.001};
    const size_t first = hits_of(o, from, dir, false).size();
    const size_t all = hits_of(o, from, dir, true).size();
    EXPECT_EQ(first, 1u);
    EXPECT_EQ(all, 2u);
    // Inside: below the surface, even far below the box; outside above it and beside.
    EXPECT_TRUE(leaf_inside(o, o.transform.inverse_point({0.2, 0.3, 0.2})));
    EXPECT_TRUE(leaf_inside(o, o.transform.inverse_point({0.5, -100, 0.5})));
    EXPECT_FALSE(leaf_inside(o, o.transform.inverse_point({0.2, 0.6, 0.2})));
    EXPECT_FALSE(leaf_inside(o, o.transform.inverse_point({1.2, 0.3, 0.2})));
    EXPECT_TRUE(leaf_inside(o, o.transform.inverse_point({0.5, 0.9, 0.5})));  // the peak
}

TEST(HeightField, SmoothNormalsAndBlocks) {
    const Scene s = flat_scene("smooth");
    const HeightFieldData d = data_of(s);
    ASSERT_EQ(d.normals.size(), 9u);
    // A corner vertex on the flat part: one triangle normal, straight up.
    EXPECT_EQ(d.normals[0][0], 0);
    EXPECT_EQ(d.normals[0][1], 32767);
    // The peak's own normal: four symmetric triangles, straight up.
    EXPECT_EQ(d.normals[4][0], 0);
    EXPECT_EQ(d.normals[4][2], 0);
    // Its neighbour (1, 0) leans away from the peak (-z).
    EXPECT_LT(d.normals[1][2], 0);
    // Blocks: a 3 x 3 grid is one block; 40 x 40 has 6 x 6 of width 7 (hierarchy on).
    EXPECT_EQ(d.blocks.size(), 1u);
    Fake big(image(40, 40, "png", 1, 16,
                   [](int x, int y, int) { return float((x * y) % 7) / 7; }));
    const HeightFieldData on = data_of(big.parse("height_field { png \"a.png\" }"));
    EXPECT_EQ(on.blocks_x, 6);
    EXPECT_EQ(on.block_width_x, 7);
    const HeightFieldData off =
        data_of(big.parse("height_field { png \"a.png\" hierarchy off }"));
    EXPECT_EQ(off.blocks.size(), 1u);
}

}  // namespace
}  // namespace povwall::trace
