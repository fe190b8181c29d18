// The wire format between processes (distrib/wire/): frames, item records, pixel sums and
// the parts of control messages that carry numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <random>

#include "distrib/object_boxes.h"
#include "distrib/wire/control.h"
#include "distrib/wire/frame.h"
#include "distrib/wire/items.h"
#include "distrib/wire/job.h"
#include "distrib/wire/messages.h"
#include "distrib/wire/photons.h"
#include "distrib/wire/pixels.h"
#include "distrib/wire/samples.h"
#include "parser/parser.h"

namespace povwall::distrib {
namespace {

TEST(WireFrame, RoundTripsAndConcatenates) {
    const std::vector<uint8_t> body = {1, 2, 3, 250};
    std::vector<uint8_t> bytes;
    encode_frame(FrameType::Items, 7, body, bytes);
    encode_frame(FrameType::Control, 0, {}, bytes);
    ASSERT_EQ(bytes.size(), 2 * kHeaderSize + body.size());
    Frame f;
    ASSERT_EQ(decode_frame(bytes, f), DecodeStatus::Complete);
    EXPECT_EQ(f.type, FrameType::Items);
    EXPECT_EQ(f.count, 7u);
    EXPECT_EQ(std::vector<uint8_t>(f.body.begin(), f.body.end()), body);
    EXPECT_EQ(f.consumed, kHeaderSize + body.size());
    Frame g;
    ASSERT_EQ(decode_frame(std::span(bytes).subspan(f.consumed), g),
              DecodeStatus::Complete);
    EXPECT_EQ(g.type, FrameType::Control);
    EXPECT_TRUE(g.body.empty());
}

TEST(WireFrame, TruncatedNeedsMoreAndAWrongHeaderIsRefusedAtOnce) {
    std::vector<uint8_t> bytes;
    encode_frame(FrameType::Pixels, 1, std::vector<uint8_t>(12, 9), bytes);
    Frame f;
    for (size_t n = 0; n < bytes.size(); ++n)
        EXPECT_EQ(decode_frame(std::span(bytes).first(n), f), DecodeStatus::NeedMore)
            << n;
    auto refused = [&](size_t at, uint8_t value) {
        auto b = bytes;
        b[at] = value;
        return decode_frame(std::span(b).first(kHeaderSize), f) == DecodeStatus::Bad;
    };
    EXPECT_TRUE(refused(0, 0x00));                  // magic
    EXPECT_TRUE(refused(2, 1));                     // the retired fixed ray frame
    EXPECT_TRUE(refused(2, 8));                     // no such type
    EXPECT_TRUE(refused(3, kProtocolVersion - 1));  // an older peer
    EXPECT_TRUE(refused(7, 0x7f));  // body length over the limit, before it arrives
}

// Every single flipped bit of a frame, header or body, is refused: the CRC (or the header
// check) catches it, or a longer length waits for bytes that never come. Truncations
// wait. So corrupt bytes are never read as other records.
TEST(WireFrame, EveryBitFlipIsRefusedOrWaitsForMore) {
    std::vector<uint8_t> body(300);
    for (size_t i = 0; i < body.size(); ++i) body[i] = uint8_t(i * 37 + 11);
    for (FrameType type : {FrameType::Items, FrameType::Control, FrameType::Photons}) {
        std::vector<uint8_t> bytes;
        encode_frame(type, 5, body, bytes);
        Frame f;
        ASSERT_EQ(decode_frame(bytes, f), DecodeStatus::Complete);
        size_t refused = 0, waiting = 0;
        for (size_t bit = 0; bit < 8 * bytes.size(); ++bit) {
            std::vector<uint8_t> flipped = bytes;
            flipped[bit / 8] ^= uint8_t(1u << (bit % 8));
            const DecodeStatus st = decode_frame(flipped, f);
            ASSERT_NE(st, DecodeStatus::Complete) << "bit " << bit;
            (st == DecodeStatus::Bad ? refused : waiting) += 1;
            // The fuzzer's reading without the CRC takes body flips as a body.
            if (bit >= 8 * kHeaderSize) {
                ASSERT_EQ(decode_frame(flipped, f, CrcCheck::Off),
                          DecodeStatus::Complete);
                EXPECT_EQ(f.body[bit / 8 - kHeaderSize], flipped[bit / 8]);
            }
        }
        // Only raising the body length can leave the frame waiting (bits of bytes 4-7).
        EXPECT_LE(waiting, 32u);
        EXPECT_GT(refused, 8 * bytes.size() - 32);
    }
}

// A scene whose objects the items' interior stacks name: glass, a CSG of glass (children
// numbered too) and a light.
const Scene& codec_scene() {
    static const Scene scene = parser::parse_scene_text(
        "#version 3.7;\n"
        "camera { location <0,0,-5> look_at 0 }\n"
        "light_source { <5,5,-5>, 1 }\n"
        "light_source { <-5,5,-5>, 0.5 }\n"
        "sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 } }\n"
        "union { box { -1, 1 } sphere { 2, 1 } pigment { rgbf 0.9 } "
        "interior { ior 1.33 } }\n",
        "codec.pov", {});
    return scene;
}

constexpr ItemLimits kLimits{6, 2, 1000};

// Random items covering every optional part of a record, and values that bit-exactness
// must keep (negative zero, infinities, subnormals, NaN payloads).
class RandomItems {
  public:
    // stacks false: interior stacks stay empty.
    RandomItems(const ObjectNumbers& numbers, bool stacks)
        : numbers_(numbers), stacks_(stacks) {}
    Item next() {
        Item item;
        item.is_result = coin(0.3);
        if (item.is_result) {
            item.result.parent = rng_();
            item.result.slot = uint16_t(rng_());
            item.result.result.colour = {f(), f(), f()};
            item.result.result.transmit = f();
            return item;
        }
        RayItem& r = item.ray;
        r.shadow = coin(0.5);
        r.counted = coin(0.5);
        r.trace.ray.origin = {d(), d(), d()};
        r.trace.ray.direction = {d(), d(), d()};
        r.trace.depth = int(rng_() % 12);
        r.trace.weight = f();
        r.trace.use = trace::RayUse(rng_() % trace::kRayUses);
        r.trace.continued = rng_() % 2;
        if (coin(0.3)) {
            r.trace.band.count = uint16_t(2 + rng_() % 65534);
            r.trace.band.index = uint16_t(rng_() % r.trace.band.count);
        }
        stack(r.trace.interiors);
        r.t_from = d();
        if (coin(0.5)) {
            r.light_distance = d();
            r.shadow_state.filter = {f(), f(), f()};
            r.shadow_state.t_min = d();
            r.shadow_state.last_hit = d();
            r.shadow_state.blocked = coin(0.5);
            stack(r.shadow_state.inside);
            r.shadow_state.light = int(rng_() % 3) - 1;
            r.shadow_state.photon_caustics = coin(0.5);
            r.shadow_state.volume = coin(0.8);
        }
        if (coin(0.5)) {
            r.parent = rng_() | 1;
            r.parent_box = int32_t(rng_() % 7) - 1;
            r.slot = uint16_t(rng_());
        }
        r.pixel = int32_t(rng_() % 1000);
        r.contribution = {f(), f(), f()};
        const int t = int(rng_() % 3);
        r.transmit_contribution =
            t == 0   ? 0.0f
            : t == 1 ? 1.0f
                     : float(std::uniform_real_distribution<>(0.01, 0.99)(rng_));
        return item;
    }
    int box() { return int(rng_() % 6); }

  private:
    bool coin(double p) { return std::uniform_real_distribution<>(0, 1)(rng_) < p; }
    double d() {
        switch (rng_() % 8) {
            case 0:
                return -0.0;
            case 1:
                return std::numeric_limits<double>::infinity();
            case 2:
                return std::numeric_limits<double>::denorm_min() * double(rng_() % 100);
            case 3:
                return std::bit_cast<double>(uint64_t(0x7ff8000000000000) |
                                             (rng_() & 0xffff));
            default:
                return std::uniform_real_distribution<>(-1e6, 1e6)(rng_);
        }
    }
    float f() { return float(d()); }
    void stack(trace::InteriorStack& s) {
        // Up to 20 entries: past the 8 a ray holds itself.
        s = trace::InteriorStack{};
        const int size = stacks_ ? int(rng_() % 21) : 0;
        for (int i = 0; i < size; ++i) {
            const int32_t n = int32_t(rng_() % (numbers_.size() + 1)) - 1;
            s.push(numbers_.material(n));
        }
    }
    std::mt19937_64 rng_{20261204};
    const ObjectNumbers& numbers_;
    bool stacks_;
};

struct Body {
    std::vector<uint8_t> bytes;
    std::vector<size_t> record_end;
    std::vector<int> boxes;
    std::vector<Item> items;
};

Body random_body(const ObjectNumbers& numbers, int count, bool stacks = true) {
    RandomItems random(numbers, stacks);
    Body body;
    for (int i = 0; i < count; ++i) {
        body.items.push_back(random.next());
        body.boxes.push_back(random.box());
        write_item(body.bytes, body.boxes.back(), body.items.back(), numbers);
        body.record_end.push_back(body.bytes.size());
    }
    return body;
}

// Reads every record of `bytes`; re-encodes what it read into `again`. False when the
// reader refuses the body.
bool read_all(std::span<const uint8_t> bytes, uint32_t count,
              const ObjectNumbers& numbers, std::vector<uint8_t>& again,
              std::vector<Item>* items = nullptr) {
    ItemReader rd(bytes, count, kLimits, numbers);
    while (!rd.done()) {
        const int64_t peeked = rd.next_box();
        Item item;
        int box;
        size_t size = 0;
        if (!rd.read(box, item, size)) break;
        EXPECT_EQ(peeked, box);
        write_item(again, box, item, numbers);
        if (items) items->push_back(item);
    }
    return !rd.bad() && rd.done();
}

TEST(WireItems, RecordsRoundTripBitForBit) {
    const ObjectNumbers numbers(codec_scene());
    ASSERT_EQ(numbers.size(), 4u);  // sphere, union, its box and sphere
    const Body body = random_body(numbers, 3000);
    std::vector<uint8_t> again;
    std::vector<Item> read;
    ASSERT_TRUE(read_all(body.bytes, uint32_t(body.items.size()), numbers, again, &read));
    EXPECT_EQ(again, body.bytes);
    ASSERT_EQ(read.size(), body.items.size());
    for (size_t i = 0; i < read.size(); ++i) {
        const Item& a = body.items[i];
        const Item& b = read[i];
        ASSERT_EQ(a.is_result, b.is_result);
        if (a.is_result) {
            EXPECT_EQ(a.result.parent, b.result.parent);
            EXPECT_EQ(a.result.slot, b.result.slot);
            continue;
        }
        EXPECT_EQ(std::bit_cast<uint64_t>(a.ray.trace.ray.origin.x),
                  std::bit_cast<uint64_t>(b.ray.trace.ray.origin.x));
        EXPECT_EQ(a.ray.trace.use, b.ray.trace.use);
        EXPECT_EQ(a.ray.trace.continued, b.ray.trace.continued);
        EXPECT_EQ(a.ray.trace.band.index, b.ray.trace.band.index);
        EXPECT_EQ(a.ray.trace.band.count, b.ray.trace.band.count);
        EXPECT_EQ(a.ray.trace.depth, b.ray.trace.depth);
        EXPECT_EQ(a.ray.trace.interiors.size, b.ray.trace.interiors.size);
        for (int k = 0; k < a.ray.trace.interiors.size; ++k)
            EXPECT_EQ(a.ray.trace.interiors.at(k), b.ray.trace.interiors.at(k));
        EXPECT_EQ(a.ray.shadow_state.light, b.ray.shadow_state.light);
        EXPECT_EQ(a.ray.shadow_state.blocked, b.ray.shadow_state.blocked);
        EXPECT_EQ(a.ray.shadow_state.photon_caustics, b.ray.shadow_state.photon_caustics);
        EXPECT_EQ(a.ray.shadow_state.volume, b.ray.shadow_state.volume);
        EXPECT_EQ(a.ray.pixel, b.ray.pixel);
        EXPECT_EQ(a.ray.parent_box, b.ray.parent_box);
        EXPECT_EQ(std::bit_cast<uint32_t>(a.ray.transmit_contribution),
                  std::bit_cast<uint32_t>(b.ray.transmit_contribution));
    }
}

TEST(WireItems, EveryTruncationIsRefused) {
    const ObjectNumbers numbers(codec_scene());
    const Body body = random_body(numbers, 40);
    for (size_t n = 0; n < body.bytes.size(); ++n) {
        std::vector<uint8_t> again;
        EXPECT_FALSE(read_all(std::span(body.bytes).first(n), uint32_t(body.items.size()),
                              numbers, again))
            << n;
    }
    std::vector<uint8_t> again, longer = body.bytes;
    longer.push_back(0);  // garbage after the last record
    EXPECT_FALSE(read_all(longer, uint32_t(body.items.size()), numbers, again));
}

// A flipped bit is refused, or read as records that are within the limits and that write
// back to exactly the flipped bytes: a reader never takes corrupt bytes for other bytes.
// (Items here have empty interior stacks: a stack entry naming an object this process
// does not hold reads as no object, as a worker that parsed part of the scene needs; see
// the next test.) No flip crashes the reader (the sanitizer build runs this too).
TEST(WireItems, EveryBitFlipIsRefusedOrReadAsWritten) {
    const ObjectNumbers numbers(codec_scene());
    const Body body = random_body(numbers, 30, false);
    int refused = 0, read_back = 0;
    for (size_t bit = 0; bit < body.bytes.size() * 8; ++bit) {
        std::vector<uint8_t> flipped = body.bytes;
        flipped[bit / 8] ^= uint8_t(1u << (bit % 8));
        std::vector<uint8_t> again;
        std::vector<Item> items;
        if (!read_all(flipped, uint32_t(body.items.size()), numbers, again, &items)) {
            ++refused;
            continue;
        }
        for (const Item& item : items) {
            if (item.is_result) continue;
            ASSERT_LT(item.ray.pixel, kLimits.pixels);
            ASSERT_LT(item.ray.shadow_state.light, kLimits.lights);
            ASSERT_LT(item.ray.parent_box, kLimits.boxes);
        }
        ASSERT_EQ(again, flipped) << "bit " << bit;
        ++read_back;
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(read_back, 0);
}

TEST(WireItems, AnInteriorNumberNotHeldReadsAsNoObject) {
    const ObjectNumbers numbers(codec_scene());
    Item item;
    item.ray.trace.interiors.size = 2;
    item.ray.trace.interiors.items[0] = numbers.material(3);
    item.ray.trace.interiors.items[1] = numbers.material(1);
    std::vector<uint8_t> bytes, again;
    write_item(bytes, 0, item, numbers);
    std::vector<Item> read;
    ASSERT_TRUE(read_all(bytes, 1, numbers, again, &read));
    EXPECT_EQ(read[0].ray.trace.interiors.items[0], numbers.material(3));
    EXPECT_NE(read[0].ray.trace.interiors.items[0], nullptr);
    // The first entry's number (after box, flags, ray, depth, weight, use, stack size).
    const size_t entry = 4 + 1 + 48 + 4 + 4 + 1 + 2;
    int32_t n;
    std::memcpy(&n, bytes.data() + entry, 4);
    ASSERT_EQ(n, 3);
    n = 4;  // one past the objects of this scene
    std::memcpy(bytes.data() + entry, &n, 4);
    read.clear();
    ASSERT_TRUE(read_all(bytes, 1, numbers, again, &read));
    EXPECT_EQ(read[0].ray.trace.interiors.items[0], nullptr);
    EXPECT_EQ(read[0].ray.trace.interiors.items[1], numbers.material(1));
}

// A worker that left an object out of its parse reads its number as a stand-in with what
// an interior stack reads of the object in the whole scene (ior, media, hollow: kept by
// the parse, Scene::left_out_nodes), and writes it back as the same number.
TEST(WireItems, StandInsOfLeftOutObjectsKeepTheirInteriors) {
    const char* text =
        "#version 3.7;\n"
        "sphere { 0, 1 interior { ior 1.5 media { absorption 1 } } }\n"
        "union { box { -1, 1 } sphere { 2, 1 interior { ior 1.2 } } hollow }\n"
        "merge { box { -1, 1 } sphere { 2, 1 } interior { ior 1.7 } }\n"
        "sphere { <5, 0, 0>, 1 hollow }\n";
    parser::ParseOptions keep_last;
    keep_last.keep_object = [](const Object& o) {
        auto s = std::get_if<Sphere>(&o.shape);
        return s && s->centre.x > 0;
    };
    const Scene part = parser::parse_scene_text(text, "part.pov", keep_last);
    const Scene whole = parser::parse_scene_text(text, "whole.pov", {});
    ASSERT_EQ(part.objects.size(), 1u);
    const ObjectNumbers numbers(part), all(whole);
    auto hollow = [](const trace::Material& m) {
        return m.interior ? m.interior->hollow : m.object->hollow;
    };
    auto ior = [](const trace::Material& m) {
        return m.interior ? m.interior->ior : 1.0f;
    };
    auto media = [](const trace::Material& m) {
        return m.interior ? m.interior->media.size() : size_t(0);
    };
    // Nodes: sphere 0; union 1 (2, 3); merge 4 (5, 6); sphere 7 (kept).
    ASSERT_EQ(all.size(), 8u);
    for (int32_t n = 0; n < 8; ++n) {
        SCOPED_TRACE(n);
        const trace::Material* m = numbers.material(n);
        const trace::Material* w = all.material(n);
        ASSERT_TRUE(m && w);
        EXPECT_EQ(hollow(*m), hollow(*w));
        EXPECT_EQ(ior(*m), ior(*w));
        EXPECT_EQ(media(*m), media(*w));
        // (A default interior's stand-in has an id of its own: no object held here
        // shares it.)
        if (m->interior) {
            EXPECT_EQ(m->interior_id, w->interior_id);
        }
        EXPECT_EQ(numbers.number(m), n);
    }
    EXPECT_FLOAT_EQ(ior(*numbers.material(0)), 1.5f);
    EXPECT_EQ(media(*numbers.material(0)), 1u);
    EXPECT_FLOAT_EQ(ior(*numbers.material(3)), 1.2f);
    EXPECT_TRUE(hollow(*numbers.material(1)));
    EXPECT_EQ(numbers.material(8), nullptr);  // past the scene's numbers
}

TEST(WireItems, RecordsNamingWhatTheReceiverLacksAreRefused) {
    const ObjectNumbers numbers(codec_scene());
    auto refused = [&](int box, const Item& item) {
        std::vector<uint8_t> bytes, again;
        write_item(bytes, box, item, numbers);
        return !read_all(bytes, 1, numbers, again);
    };
    Item ok;
    ok.ray.pixel = 999;
    EXPECT_FALSE(refused(5, ok));
    EXPECT_TRUE(refused(6, ok));  // no such box
    Item pixel = ok;
    pixel.ray.pixel = 1000;
    EXPECT_TRUE(refused(0, pixel));
    Item light = ok;
    light.ray.shadow_state.light = 2;
    EXPECT_TRUE(refused(0, light));
    Item parent_box = ok;
    parent_box.ray.parent_box = 6;
    EXPECT_TRUE(refused(0, parent_box));
    Item depth = ok;
    depth.ray.trace.depth = -1;
    EXPECT_TRUE(refused(0, depth));
}

TEST(WirePixels, SumsRoundTripAndBadRecordsAddNothing) {
    std::vector<uint8_t> body;
    const double a[4] = {0.5, -0.0, 1e300, 0.25}, b[4] = {1, 2, 3, 4};
    write_pixel_sum(body, 3, a, 4);
    write_pixel_sum(body, 9, b, 4);
    ASSERT_EQ(body.size(), 2 * pixel_record_size(4));
    std::vector<double> sums(40, 0.0);
    auto add = [&](uint32_t p, const double* v) {
        for (int c = 0; c < 4; ++c) sums[p * 4 + size_t(c)] += v[c];
    };
    ASSERT_TRUE(read_pixel_sums(body, 2, 4, 10, add));
    EXPECT_EQ(sums[12], 0.5);
    EXPECT_EQ(sums[14], 1e300);
    EXPECT_EQ(sums[39], 4.0);
    const std::vector<double> before = sums;
    EXPECT_FALSE(read_pixel_sums(body, 2, 4, 9, add));  // pixel 9 of 9
    EXPECT_FALSE(read_pixel_sums(body, 3, 4, 10, add));
    EXPECT_FALSE(read_pixel_sums(std::span(body).first(body.size() - 1), 2, 4, 10, add));
    EXPECT_EQ(sums, before);
}

TEST(WireSamples, PositionsRoundTripAndBadRecordsAddNothing) {
    std::vector<uint8_t> body;
    write_sample_position(body, {0.1 + 0.2, -0.5});
    write_sample_position(body, {44.75, 32.999999999999993});
    ASSERT_EQ(body.size(), 2 * kSampleRecordSize);
    std::vector<trace::SamplePosition> out = {{1, 1}};
    ASSERT_TRUE(read_sample_positions(body, 2, 49, out));
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[1].x, 0.1 + 0.2);  // every bit: the slot's camera ray is the same ray
    EXPECT_EQ(out[1].y, -0.5);
    EXPECT_EQ(out[2].y, 32.999999999999993);
    EXPECT_FALSE(read_sample_positions(body, 2, 44, out));  // x beyond the image's reach
    EXPECT_FALSE(read_sample_positions(body, 3, 49, out));  // count and body disagree
    std::vector<uint8_t> nan = body;
    const double not_a_number = std::nan("");
    std::memcpy(nan.data() + 8, &not_a_number, 8);
    EXPECT_FALSE(read_sample_positions(nan, 2, 49, out));
    EXPECT_EQ(out.size(), 3u);
}

// The photon map goes to the workers whole: every photon's bits in kd-tree order, the
// radii's bits, the gather settings; a frame without photons says so.
TEST(WirePhotons, AMapRoundTripsBitForBitAndBadFramesAreRefused) {
    std::vector<trace::Photon> surface(3), media(2);
    for (size_t i = 0; i < surface.size(); ++i) {
        surface[i] = {
            {0.1f * float(i), -2.5f, 1e-7f}, {200, 17, 3, 248}, -5, 127, uint8_t(i % 3)};
    }
    media[0] = {{4, 5, 6}, {1, 2, 3, 251}, 0, -127, 2};
    media[1] = {{-4, -5, -6}, {9, 8, 7, 250}, 64, 3, 0};
    PhotonSettings s;
    s.gather_min = 7;
    s.gather_max = 42;
    s.expand_tolerance = 0.1f + 0.2f;
    s.expand_min = 11;
    auto media_map = trace::PhotonMap::assemble(s, media, 0.1 + 0.2, 0.7, nullptr);
    const auto map = trace::PhotonMap::assemble(s, surface, 1.0 / 3, 2.0 / 3, media_map);
    const std::vector<Buffer> frames = photon_map_frames(map.get());
    ASSERT_EQ(frames.size(), 3u);  // surface photons, media photons, the message
    std::vector<trace::Photon> got;
    std::optional<nlohmann::json> message;
    for (const Buffer& b : frames) {
        Frame f;
        ASSERT_EQ(decode_frame(*b, f), DecodeStatus::Complete);
        if (f.type == FrameType::Photons)
            ASSERT_TRUE(read_photons(f.body, f.count, got));
        else
            message = parse_control(f);
    }
    ASSERT_TRUE(message);
    EXPECT_EQ(control_type(*message), "photons");
    std::shared_ptr<const trace::PhotonMap> back;
    ASSERT_TRUE(photon_map_from_message(*message, std::vector<trace::Photon>(got), back));
    ASSERT_TRUE(back && back->media());
    auto same = [](const std::vector<trace::Photon>& a,
                   const std::vector<trace::Photon>& b) {
        if (a.size() != b.size()) return false;
        for (size_t i = 0; i < a.size(); ++i)
            if (std::memcmp(a[i].pos, b[i].pos, 12) != 0 ||
                std::memcmp(a[i].rgbe, b[i].rgbe, 4) != 0 || a[i].theta != b[i].theta ||
                a[i].phi != b[i].phi || a[i].axis != b[i].axis)
                return false;
        return true;
    };
    EXPECT_TRUE(same(back->photons(), surface));
    EXPECT_TRUE(same(back->media()->photons(), media));
    EXPECT_EQ(back->min_gather_radius(), 1.0 / 3);
    EXPECT_EQ(back->radius_step(), 2.0 / 3);
    EXPECT_EQ(back->media()->min_gather_radius(), 0.1 + 0.2);
    EXPECT_EQ(back->settings().gather_min, 7);
    EXPECT_EQ(back->settings().gather_max, 42);
    EXPECT_EQ(back->settings().expand_tolerance, 0.1f + 0.2f);
    EXPECT_EQ(back->settings().expand_min, 11);
    // A message with a field missing, of another type or out of range is not a map
    // (false, no exception: the fuzz target found the missing-field throw).
    for (const char* key :
         {"surface", "gather_min", "gather_max", "expand_tolerance", "expand_min"}) {
        nlohmann::json broken = *message;
        broken.erase(key);
        EXPECT_FALSE(
            photon_map_from_message(broken, std::vector<trace::Photon>(got), back))
            << key;
        broken[key] = "7";
        EXPECT_FALSE(
            photon_map_from_message(broken, std::vector<trace::Photon>(got), back))
            << key;
    }
    for (const auto& [key, value] : std::vector<std::pair<const char*, nlohmann::json>>{
             {"gather_min", 43},
             {"gather_max", 0},
             {"expand_min", -1},
             {"gather_max", uint64_t(1) << 40},
             {"expand_tolerance", uint64_t(1) << 33},
             {"expand_tolerance", std::bit_cast<uint32_t>(-1.0f)}}) {
        nlohmann::json broken = *message;
        broken[key] = value;
        EXPECT_FALSE(
            photon_map_from_message(broken, std::vector<trace::Photon>(got), back))
            << key << " " << value;
    }
    nlohmann::json no_count = *message;
    no_count["surface"].erase("count");
    EXPECT_FALSE(
        photon_map_from_message(no_count, std::vector<trace::Photon>(got), back));
    // Counts that disagree with the photons received.
    got.pop_back();
    EXPECT_FALSE(photon_map_from_message(*message, std::move(got), back));
    // A record with a NaN position or an axis beyond z adds nothing.
    Frame f;
    ASSERT_EQ(decode_frame(*frames[0], f), DecodeStatus::Complete);
    std::vector<uint8_t> bad(f.body.begin(), f.body.end());
    bad[kPhotonRecordSize + 18] = 3;
    std::vector<trace::Photon> none;
    EXPECT_FALSE(read_photons(bad, f.count, none));
    bad[kPhotonRecordSize + 18] = 0;
    const float nan = std::nanf("");
    std::memcpy(bad.data() + 4, &nan, 4);
    EXPECT_FALSE(read_photons(bad, f.count, none));
    EXPECT_TRUE(none.empty());
    // No photons this frame.
    const std::vector<Buffer> empty = photon_map_frames(nullptr);
    ASSERT_EQ(empty.size(), 1u);
    ASSERT_EQ(decode_frame(*empty[0], f), DecodeStatus::Complete);
    back = map;
    EXPECT_TRUE(photon_map_from_message(parse_control(f), {}, back));
    EXPECT_EQ(back, nullptr);
}

// Focal blur's rays travel as (position, ray index): the index within the camera's rays
// per sample, or -1 (a sample's one ray).
TEST(WireSamples, FocalBlurRayIndicesRoundTripWithinTheCamerasRays) {
    std::vector<uint8_t> body;
    write_sample_position(body, {3.25, 7.5, 36});
    write_sample_position(body, {3.25, 7.5, -1});
    std::vector<trace::SamplePosition> out;
    ASSERT_TRUE(read_sample_positions(body, 2, 49, out, 37));
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].ray, 36);
    EXPECT_EQ(out[1].ray, -1);
    EXPECT_FALSE(read_sample_positions(body, 2, 49, out, 36));  // ray 36 of 36
    EXPECT_FALSE(read_sample_positions(body, 2, 49, out));      // no focal blur
    std::vector<uint8_t> below = body;
    const int32_t minus_two = -2;
    std::memcpy(below.data() + kSampleRecordSize + 16, &minus_two, 4);
    EXPECT_FALSE(read_sample_positions(below, 2, 49, out, 37));
    EXPECT_EQ(out.size(), 2u);
}

TEST(WireControl, ReachKeepsEveryDoubleAndRefusesBadBoxes) {
    const std::vector<Bounds3> reach = {
        {{-kInfinity, -0.0, 1e-300}, {kInfinity, 2.5, 3}},
        {{0, 0, 0}, {1, 1, 1}},
    };
    const nlohmann::json j = reach_to_json(reach);
    std::vector<Bounds3> back;
    ASSERT_TRUE(reach_from_json(j, 2, back));
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].lo.x, -kInfinity);
    EXPECT_TRUE(std::signbit(back[0].lo.y));
    EXPECT_EQ(back[0].lo.z, 1e-300);
    std::vector<Bounds3> ignored;
    EXPECT_FALSE(reach_from_json(j, 3, ignored));
    nlohmann::json nan = j;
    nan[1][0] = std::bit_cast<uint64_t>(std::numeric_limits<double>::quiet_NaN());
    EXPECT_FALSE(reach_from_json(nan, 2, ignored));
    EXPECT_FALSE(reach_from_json(nlohmann::json("x"), 2, ignored));
}

TEST(WireControl, PlanRoundTripsAndAMissingFieldThrows) {
    trace::RenderPlan plan;
    plan.everything_on = false;
    plan.quality = trace::Quality::of(5);
    plan.reflection_rays = true;
    plan.lights.push_back({true, false, "blocked"});
    plan.flat_threshold = 7;
    plan.parent_reason = "why";
    plan.finite_primitives = 123456789012;
    const trace::RenderPlan back = plan_from_json(plan_to_json(plan));
    EXPECT_EQ(plan_to_json(back), plan_to_json(plan));
    EXPECT_EQ(back.finite_primitives, plan.finite_primitives);
    nlohmann::json partial = plan_to_json(plan);
    partial.erase("lights");
    EXPECT_THROW(plan_from_json(partial), nlohmann::json::exception);
}

TEST(WireControl, ControlFramesCarryJsonAndGarbageIsDiscarded) {
    const Buffer buf = control_frame({{"type", "status"}, {"seq", 4}});
    Frame f;
    ASSERT_EQ(decode_frame(*buf, f), DecodeStatus::Complete);
    EXPECT_EQ(parse_control(f).at("seq"), 4);
    const std::vector<uint8_t> junk = {'{', 'x'};
    std::vector<uint8_t> bytes;
    encode_frame(FrameType::Control, 0, junk, bytes);
    ASSERT_EQ(decode_frame(bytes, f), DecodeStatus::Complete);
    EXPECT_TRUE(parse_control(f).is_discarded());
}

TEST(WireControl, HellosAreReadOnlyWhenWellFormed) {
    Frame f;
    const Buffer buf = hello_frame({"t0k", 3});
    ASSERT_EQ(decode_frame(*buf, f), DecodeStatus::Complete);
    const std::optional<Hello> h = hello_from_json(parse_control(f));
    ASSERT_TRUE(h);
    EXPECT_EQ(h->token, "t0k");
    EXPECT_EQ(h->from, 3);
    using nlohmann::json;
    for (const json& bad :
         {json::parse(R"({"type":"hello","token":5,"from":-1})"),
          json::parse(R"({"type":5,"token":"t","from":-1})"),
          json::parse(R"({"type":"hello","token":"t","from":"x"})"),
          json::parse(R"({"type":"hello","token":"t","from":-2})"),
          json::parse(R"({"type":"hello","token":"t"})"), json::parse(R"([1,2])")}) {
        EXPECT_FALSE(hello_from_json(bad)) << bad.dump();
        EXPECT_NO_THROW(control_type(bad));
    }
}

TEST(WireJob, AWorkerJobRoundTripsByName) {
    WorkerJob job;
    job.fixed.scene = "sphere { 0, 1 }";
    job.fixed.name = "a.pov";
    job.fixed.library_paths = {"/inc"};
    job.fixed.declares = {{"X", 2.5}};
    job.fixed.language_version = 370;
    job.fixed.output_file_type = 'P';
    job.fixed.max_loop_iterations = 99;
    job.fixed.adc_bailout = 0.25;
    job.fixed.width = 64, job.fixed.height = 48;
    job.fixed.alpha = true;
    job.fixed.results = SpaceOptions::Results::Parents;
    job.fixed.queue = QueuePolicy::Fifo;
    job.fixed.threads = 3;
    job.fixed.boxes = {2, 1, 3};
    job.frame.animation = {0.5, 0.1, 0, 1, 6, 1, 11};
    job.frame.plan.flat_threshold = 4;
    job.frame.expected_objects = {10, 20};
    job.frame.walk_reaches = {{3, Bounds3{{-1, -2, -3}, {1, 2, 3.5}}},
                              {0, Bounds3{{-kInfinity, 0, 0}, {kInfinity, 1, 1}}}};
    job.walls = {std::vector<Real>{-1.5, 2}, {}, {0.25}};
    job.workers = {"127.0.0.1:1", "127.0.0.1:2"};
    job.inherited = true;
    job.index = 1;
    job.owner = {0, 1, 1, -1};
    const nlohmann::json j = to_json(job);
    EXPECT_EQ(j.at("type"), "job");
    EXPECT_EQ(j.at("queue"), "fifo");
    const WorkerJob back = worker_job_from_json(j);
    EXPECT_EQ(back.fixed, job.fixed);
    EXPECT_EQ(back.frame.animation, job.frame.animation);
    EXPECT_EQ(plan_to_json(back.frame.plan), plan_to_json(job.frame.plan));
    EXPECT_EQ(back.frame.expected_objects, job.frame.expected_objects);
    // An unbounded hull side comes back as the largest finite number (JSON has no
    // infinity): the same boxes overlap it.
    ASSERT_EQ(back.frame.walk_reaches.size(), 2u);
    constexpr Real kMax = std::numeric_limits<Real>::max();
    EXPECT_EQ(back.frame.walk_reaches[0].box, 3);
    EXPECT_EQ(back.frame.walk_reaches[0].hull.lo, Point3(-1, -2, -3));
    EXPECT_EQ(back.frame.walk_reaches[0].hull.hi, Point3(1, 2, 3.5));
    EXPECT_EQ(back.frame.walk_reaches[1].box, 0);
    EXPECT_EQ(back.frame.walk_reaches[1].hull.lo, Point3(-kMax, 0, 0));
    EXPECT_EQ(back.frame.walk_reaches[1].hull.hi, Point3(kMax, 1, 1));
    EXPECT_EQ(back.walls, job.walls);
    EXPECT_EQ(back.workers, job.workers);
    EXPECT_EQ(back.inherited, true);
    EXPECT_EQ(back.index, 1);
    EXPECT_EQ(back.owner, job.owner);
    EXPECT_EQ(to_json(back), j);
}

TEST(WireJob, AMalformedJobThrowsNamingTheField) {
    WorkerJob job;
    job.fixed.width = job.fixed.height = 8;
    job.workers = {"a:1"};
    job.frame.expected_objects = {1};
    const nlohmann::json good = to_json(job);
    auto message = [&](const std::function<void(nlohmann::json&)>& edit) -> std::string {
        nlohmann::json j = good;
        edit(j);
        try {
            worker_job_from_json(j);
        } catch (const nlohmann::json::exception& e) {
            return e.what();
        }
        return "accepted";
    };
    EXPECT_EQ(message([](nlohmann::json&) {}), "accepted");
    EXPECT_NE(message([](nlohmann::json& j) { j["queue"] = "lifo"; }).find("bad queue"),
              std::string::npos);
    EXPECT_NE(message([](nlohmann::json& j) { j["index"] = 1; }).find("bad index"),
              std::string::npos);
    EXPECT_NE(message([](nlohmann::json& j) { j["owner"] = {3}; }).find("bad owner"),
              std::string::npos);
    EXPECT_NE(message([](nlohmann::json& j) { j["width"] = 0; }).find("bad image size"),
              std::string::npos);
    EXPECT_NE(message([](nlohmann::json& j) { j.erase("scene"); }).find("scene"),
              std::string::npos);
    EXPECT_NE(message([](nlohmann::json& j) {
                  j["output_file_type"] = "";
              }).find("output_file_type"),
              std::string::npos);
}

// Every control message reads back as written, through a real control frame, and says
// its type.
TEST(WireMessages, EveryMessageRoundTripsThroughItsFrame) {
    auto through_frame = [](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        const Buffer buf = message_frame(m);
        Frame f;
        EXPECT_EQ(decode_frame(*buf, f), DecodeStatus::Complete);
        const nlohmann::json j = parse_control(f);
        EXPECT_EQ(control_type(j), M::kType);
        return read_message<M>(j);
    };
    const ReadyMessage ready =
        through_frame(ReadyMessage{{1, 4, 7}, {10, 0, 3}, 120, 30});
    EXPECT_EQ(ready.boxes, (std::vector<int>{1, 4, 7}));
    EXPECT_EQ(ready.primitives, (std::vector<uint64_t>{10, 0, 3}));
    EXPECT_EQ(ready.objects_kept, 120u);
    EXPECT_EQ(ready.objects_left_out, 30u);
    EXPECT_EQ(through_frame(SamplesSentMessage{12345}).count, 12345u);
    const PixelRangeMessage range = through_frame(PixelRangeMessage{512, 1024});
    EXPECT_EQ(range.begin, 512);
    EXPECT_EQ(range.end, 1024);
    EXPECT_EQ(through_frame(ProbeMessage{17}).seq, 17);
    const StatusMessage status =
        through_frame(StatusMessage{-1, uint64_t(1) << 40, 99, 7, {1, 2, 3}});
    EXPECT_EQ(status.seq, -1);
    EXPECT_EQ(status.created, uint64_t(1) << 40);
    EXPECT_EQ(status.finished, 99u);
    EXPECT_EQ(status.pixels, 7u);
    EXPECT_EQ(status.sent, (std::vector<uint64_t>{1, 2, 3}));
    DoneMessage done;
    BoxStats b;
    b.objects = 5;
    b.rays.shadow = 11;
    b.rays.radiosity = 4;
    b.rays.max_level = 3;
    b.peak_queue = 9;
    b.busy_seconds = 0.25;
    done.boxes = {{2, b}, {6, BoxStats{}}};
    done.peak_resident = 1 << 20;
    const DoneMessage back = through_frame(done);
    ASSERT_EQ(back.boxes.size(), 2u);
    EXPECT_EQ(back.boxes[0].box, 2);
    EXPECT_EQ(back.boxes[0].stats.objects, 5u);
    EXPECT_EQ(back.boxes[0].stats.rays.shadow, 11u);
    EXPECT_EQ(back.boxes[0].stats.rays.radiosity, 4u);
    EXPECT_EQ(back.boxes[0].stats.rays.max_level, 3);
    EXPECT_EQ(back.boxes[0].stats.peak_queue, 9u);
    EXPECT_EQ(back.boxes[0].stats.busy_seconds, 0.25);
    EXPECT_EQ(back.boxes[1].box, 6);
    EXPECT_EQ(back.peak_resident, 1u << 20);
    const ErrorMessage error = through_frame(ErrorMessage{"worker 3 is gone", 3});
    EXPECT_EQ(error.message, "worker 3 is gone");
    EXPECT_EQ(error.culprit, 3);
    const RegisterMessage reg =
        through_frame(RegisterMessage{"tok", 2, 8, "10.0.0.1:4000"});
    EXPECT_EQ(reg.token, "tok");
    EXPECT_EQ(reg.rank, 2);
    EXPECT_EQ(reg.size, 8);
    EXPECT_EQ(reg.address, "10.0.0.1:4000");
    (void)through_frame(BusyMessage{});
    (void)through_frame(FinishMessage{});
    (void)through_frame(SamplesTakenMessage{});
    EXPECT_EQ(
        through_frame(StartMessage{reach_to_json({Bounds3::everything()})}).reach.size(),
        1u);
}

// What no writer makes is refused with a JSON error naming the field: a missing or
// mistyped field, a fraction or an out-of-range number where a count goes, counts that do
// not pair up, a reversed range, boxes out of order.
TEST(WireMessages, InconsistentMessagesAreRefusedNamingTheField) {
    auto refusal = [](const char* text, auto type_tag) -> std::string {
        using M = decltype(type_tag);
        try {
            (void)read_message<M>(nlohmann::json::parse(text));
        } catch (const nlohmann::json::exception& e) {
            return e.what();
        }
        return "accepted";
    };
    EXPECT_EQ(refusal(R"({"begin":0,"end":5})", PixelRangeMessage{}), "accepted");
    EXPECT_NE(refusal(R"({"begin":6,"end":5})", PixelRangeMessage{}).find("bad pixels"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"begin":1.5,"end":5})", PixelRangeMessage{}).find("bad begin"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"begin":0})", PixelRangeMessage{}).find("end"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"boxes":[1,2],"primitives":[5],"objects_kept":1,)"
                      R"("objects_left_out":0})",
                      ReadyMessage{})
                  .find("bad primitives"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"boxes":[1e300],"primitives":[5],"objects_kept":1,)"
                      R"("objects_left_out":0})",
                      ReadyMessage{})
                  .find("bad boxes"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"seq":-2,"created":0,"finished":0,"pixels":0,"sent":[]})",
                      StatusMessage{})
                  .find("bad seq"),
              std::string::npos);
    EXPECT_NE(
        refusal(R"({"message":"x","culprit":"two"})", ErrorMessage{}).find("culprit"),
        std::string::npos);
    EXPECT_NE(refusal(R"({"boxes":[{"box":3}],"peak_resident":0})", DoneMessage{})
                  .find("'rays'"),
              std::string::npos);
    DoneMessage unordered;
    unordered.boxes = {{6, BoxStats{}}, {2, BoxStats{}}};
    std::string said = "accepted";
    try {
        (void)read_message<DoneMessage>(message_json(unordered));
    } catch (const nlohmann::json::exception& e) {
        said = e.what();
    }
    EXPECT_NE(said.find("bad boxes"), std::string::npos) << said;
}

// The field lists are flattened into one JSON object (and one command line): two fields
// of one name would overwrite each other.
TEST(WireJob, EveryFieldOfAJobHasItsOwnName) {
    std::vector<std::string> names;
    WorkerJob job;
    visit_job_fields(job,
                     [&](const char* name, const auto&) { names.emplace_back(name); });
    EXPECT_EQ(names.size(), 34u);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
    EXPECT_EQ(std::count(names.begin(), names.end(), "type"), 0);
}

// The same field list writes a job as a command line: every field, lists one argument
// per entry, doubles to the last bit, enums by name.
TEST(WireJob, AFixedJobReadsBackFromItsCommandLine) {
    FixedJob job;
    job.scene = "sphere { 0, 1 } // --x=y";
    job.name = "dir with space/a=b.pov";
    job.library_paths = {"/inc", "x=y"};
    job.declares = {{"A", 0.1 + 0.2}, {"Tiny", 1e-300}};
    job.language_version = 362;
    job.output_file_type = 'E';
    job.max_loop_iterations = std::numeric_limits<uint64_t>::max();
    job.max_trace_level = 12;
    job.width = 641, job.height = 479;
    job.antialias = true;
    job.results = SpaceOptions::Results::Forward;
    job.queue = QueuePolicy::Fifo;
    job.boxes = {3, 1, 2};
    std::vector<std::string> args;
    job_to_argv(job, args);
    EXPECT_NE(std::find(args.begin(), args.end(), "--boxes=3,1,2"), args.end());
    EXPECT_NE(std::find(args.begin(), args.end(), "--queue=fifo"), args.end());
    EXPECT_EQ(
        std::count_if(args.begin(), args.end(),
                      [](const std::string& a) { return a.starts_with("--declare="); }),
        2);
    EXPECT_EQ(std::find(args.begin(), args.end(), "--adc_bailout="), args.end());
    FixedJob back;
    job_from_argv(args, 0, back);
    EXPECT_EQ(back, job);
    for (const char* bad :
         {"--boxes=3,1", "--boxes=3,1,2,4", "--queue=lifo", "--width=3x", "--alpha=2",
          "--declare=3", "--colour=3", "width=3"}) {
        FixedJob j;
        EXPECT_THROW(job_from_argv({bad}, 0, j), JobArgumentError) << bad;
    }
}

}  // namespace
}  // namespace povwall::distrib
