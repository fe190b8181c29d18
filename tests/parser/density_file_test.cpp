// density_file df3 "name" [interpolate N]: the file found as POV-Ray finds it, its voxels
// decoded with the width its length implies, one read shared by every pattern naming
// it, and POV-Ray's errors, located and naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "parser/density_files.h"
#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::parse;

const std::string kGolden = std::string(POVWALL_SOURCE_DIR) + "/scenes/golden/";

const PatternSpec& density_of(const Scene& s, size_t object) {
    return *s.objects.at(object).texture.at(0).pigment.pattern;
}

TEST(DensityFile, DecodesEachWidthBigEndian) {
    // 2 x 1 x 1 voxels: 8-bit (2 bytes), 16-bit (4 bytes), 32-bit (8 bytes) of data.
    const std::string header("\x00\x02\x00\x01\x00\x01", 6);
    DensityFile f8 = decode_df3(header + std::string("\x10\xff", 2));
    EXPECT_EQ(f8.bytes_per_voxel, 1);
    EXPECT_EQ(f8.voxels, (std::vector<uint32_t>{0x10, 0xff}));
    DensityFile f16 = decode_df3(header + std::string("\x12\x34\xff\x00", 4));
    EXPECT_EQ(f16.bytes_per_voxel, 2);
    EXPECT_EQ(f16.voxels, (std::vector<uint32_t>{0x1234, 0xff00}));
    DensityFile f32 =
        decode_df3(header + std::string("\x01\x02\x03\x04\xff\xff\xff\xff", 8));
    EXPECT_EQ(f32.bytes_per_voxel, 4);
    EXPECT_EQ(f32.voxels, (std::vector<uint32_t>{0x01020304, 0xffffffff}));
    EXPECT_EQ(f32.size_x, 2u);
    EXPECT_EQ(f32.size_y, 1u);
    EXPECT_EQ(f32.size_z, 1u);
    EXPECT_THROW(decode_df3(header + "abc"), std::runtime_error);
    EXPECT_THROW(decode_df3(std::string("\x00\x02\x00", 3)), std::runtime_error);
}

TEST(DensityFile, FoundLikeImagesAndShared) {
    const std::string name = kGolden + "density_cloud";
    Scene s = parse("#declare P = pigment { density_file df3 \"" + name +
                    "\" interpolate 2 }\n"
                    "plane { y, 0 pigment { P } }\n"
                    "plane { y, 1 pigment { density_file df3 \"" +
                    name + ".df3\" interpolate 11 } }");
    const PatternSpec& a = density_of(s, 0);
    const PatternSpec& b = density_of(s, 1);
    EXPECT_EQ(a.kind, PatternKind::DensityFile);
    EXPECT_EQ(a.density_interpolation, 2);
    EXPECT_EQ(b.density_interpolation, 11);
    ASSERT_TRUE(a.density_file);
    EXPECT_EQ(a.density_file.get(), b.density_file.get());  // read once
    EXPECT_EQ(a.density_file->size_x, 12u);
    EXPECT_EQ(a.density_file->size_y, 10u);
    EXPECT_EQ(a.density_file->size_z, 7u);
    EXPECT_EQ(a.density_file->voxels.size(), 12u * 10u * 7u);
    EXPECT_EQ(a.density_file->path, name + ".df3");
}

TEST(DensityFile, Errors) {
    EXPECT_EQ(error_of("plane { y, 0 pigment { density_file df3 \"nope.df3\" } }"),
              "test.pov:1:41: error: Cannot read media density file \"nope.df3\" (not "
              "found)");
    EXPECT_EQ(error_of("plane { y, 0 pigment { density_file \"a.df3\" } }"),
              "test.pov:1:37: error: expected df3 but found string \"a.df3\"");
    EXPECT_EQ(error_of("plane { y, 0 pigment { bozo interpolate 1 } }"),
              "test.pov:1:29: error: keyword 'interpolate' cannot be used with "
              "non-density_file");
    const std::string bad =
        (std::filesystem::temp_directory_path() / "povwall_bad.df3").string();
    {
        std::ofstream out(bad, std::ios::binary);
        out << std::string("\x00\x02\x00\x02\x00\x02", 6) << "12345";
    }
    EXPECT_EQ(error_of("plane { y, 0 pigment { density_file df3 \"" + bad + "\" } }"),
              "test.pov:1:41: error: Invalid density file size \"" + bad + "\"");
    std::filesystem::remove(bad);
}

}  // namespace
}  // namespace povwall::parser
