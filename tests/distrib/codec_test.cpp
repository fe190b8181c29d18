#include <gtest/gtest.h>

#include "distrib/message.h"

namespace povwall::distrib {
namespace {

RayMessage sample_ray(int i) {
    RayMessage r;
    r.id = (uint64_t(3) << 40) | uint64_t(i);
    r.parent_id = 77;
    r.parent_box = 5;
    r.pixel_x = 12;
    r.pixel_y = -1;
    r.light = 2;
    r.kind = RayKind::Refracted;
    r.depth = 4;
    r.child_slot = 3;
    r.interior_depth = 2;
    r.interiors[0] = 9;
    r.interiors[1] = 1000000;
    r.origin = {1.5, -2.25, 1e-300};
    r.direction = {0.1, 0.2, -0.97};
    r.t_min = 1e-4;
    r.t_max = kInfinity;
    r.weight = 0.125f;
    r.contribution = {0.5f, 0.25f, 1.0f};
    return r;
}

TEST(Codec, RaysRoundTripBitExact) {
    std::vector<RayMessage> rays{sample_ray(1), sample_ray(2)};
    std::vector<uint8_t> bytes;
    encode_rays(rays, bytes);
    EXPECT_EQ(bytes.size(), kHeaderSize + 2 * encoded_ray_size());
    Frame f;
    ASSERT_EQ(decode_frame(bytes, f), DecodeStatus::Complete);
    EXPECT_EQ(f.consumed, bytes.size());
    ASSERT_EQ(f.rays.size(), 2u);
    EXPECT_EQ(f.rays[1].id, rays[1].id);
    EXPECT_EQ(f.rays[1].kind, RayKind::Refracted);
    EXPECT_EQ(f.rays[1].interiors[1], 1000000);
    EXPECT_EQ(f.rays[1].origin, rays[1].origin);
    EXPECT_EQ(f.rays[1].t_max, kInfinity);
    EXPECT_EQ(f.rays[1].contribution, rays[1].contribution);
}

TEST(Codec, ResultsRoundTripAndFramesConcatenate) {
    std::vector<uint8_t> bytes;
    ResultMessage r{42, 7, 2, {0.1f, 0.2f, 0.3f}, 0.5f, 3.25};
    encode_results(std::span(&r, 1), bytes);
    encode_rays(std::vector<RayMessage>{sample_ray(5)}, bytes);
    Frame f;
    ASSERT_EQ(decode_frame(bytes, f), DecodeStatus::Complete);
    ASSERT_EQ(f.results.size(), 1u);
    EXPECT_EQ(f.results[0].parent_id, 42u);
    EXPECT_EQ(f.results[0].colour, (Rgb{0.1f, 0.2f, 0.3f}));
    EXPECT_EQ(f.results[0].distance, 3.25);
    Frame g;
    ASSERT_EQ(decode_frame(std::span(bytes).subspan(f.consumed), g),
              DecodeStatus::Complete);
    EXPECT_EQ(g.rays[0].id, sample_ray(5).id);
}

TEST(Codec, TruncatedInputNeedsMoreAndCorruptInputIsBad) {
    std::vector<uint8_t> bytes;
    encode_rays(std::vector<RayMessage>{sample_ray(1)}, bytes);
    Frame f;
    for (size_t n : {size_t(0), size_t(5), kHeaderSize, bytes.size() - 1}) {
        EXPECT_EQ(decode_frame(std::span(bytes).first(n), f), DecodeStatus::NeedMore)
            << n;
    }
    auto bad_magic = bytes;
    bad_magic[0] ^= 0xff;
    EXPECT_EQ(decode_frame(bad_magic, f), DecodeStatus::Bad);
    auto huge = bytes;
    huge[7] = 0x7f;  // body length far beyond the limit: refused before waiting for it
    EXPECT_EQ(decode_frame(huge, f), DecodeStatus::Bad);
    auto bad_kind = bytes;
    bad_kind[kHeaderSize + 8 + 8 + 4 * 4] = 9;  // ray kind byte
    EXPECT_EQ(decode_frame(bad_kind, f), DecodeStatus::Bad);
}

}  // namespace
}  // namespace povwall::distrib
