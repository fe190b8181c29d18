#include <cstring>

#include "distrib/message.h"

namespace povwall::distrib {
namespace {

// Explicit little-endian writes keep the wire format independent of the host.
struct Writer {
    std::vector<uint8_t>& out;
    void u8(uint8_t v) { out.push_back(v); }
    void u16(uint16_t v) {
        for (int i = 0; i < 2; ++i) out.push_back(uint8_t(v >> (8 * i)));
    }
    void u32(uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
    }
    void u64(uint64_t v) {
        for (int i = 0; i < 8; ++i) out.push_back(uint8_t(v >> (8 * i)));
    }
    void i32(int32_t v) { u32(uint32_t(v)); }
    void f32(float v) {
        uint32_t b;
        std::memcpy(&b, &v, 4);
        u32(b);
    }
    void f64(double v) {
        uint64_t b;
        std::memcpy(&b, &v, 8);
        u64(b);
    }
    void vec(const Vector3& v) {
        f64(v.x);
        f64(v.y);
        f64(v.z);
    }
    void rgb(const Rgb& c) {
        f32(c.r);
        f32(c.g);
        f32(c.b);
    }
};

struct Reader {
    const uint8_t* p;
    uint64_t le(int n) {
        uint64_t v = 0;
        for (int i = 0; i < n; ++i) v |= uint64_t(p[i]) << (8 * i);
        p += n;
        return v;
    }
    uint8_t u8() { return uint8_t(le(1)); }
    uint16_t u16() { return uint16_t(le(2)); }
    uint32_t u32() { return uint32_t(le(4)); }
    uint64_t u64() { return le(8); }
    int32_t i32() { return int32_t(u32()); }
    float f32() {
        uint32_t b = u32();
        float v;
        std::memcpy(&v, &b, 4);
        return v;
    }
    double f64() {
        uint64_t b = u64();
        double v;
        std::memcpy(&v, &b, 8);
        return v;
    }
    Vector3 vec() {
        Vector3 v;
        v.x = f64();
        v.y = f64();
        v.z = f64();
        return v;
    }
    Rgb rgb() {
        Rgb c;
        c.r = f32();
        c.g = f32();
        c.b = f32();
        return c;
    }
};

void write_ray(Writer& w, const RayMessage& r) {
    w.u64(r.id);
    w.u64(r.parent_id);
    w.i32(r.parent_box);
    w.i32(r.pixel_x);
    w.i32(r.pixel_y);
    w.i32(r.light);
    w.u8(uint8_t(r.kind));
    w.u8(r.depth);
    w.u8(r.child_slot);
    w.u8(r.interior_depth);
    for (int i = 0; i < kMaxInteriorDepth; ++i) w.i32(r.interiors[i]);
    w.vec(r.origin);
    w.vec(r.direction);
    w.f64(r.t_min);
    w.f64(r.t_max);
    w.f32(r.weight);
    w.rgb(r.contribution);
}

bool read_ray(Reader& rd, RayMessage& r) {
    r.id = rd.u64();
    r.parent_id = rd.u64();
    r.parent_box = rd.i32();
    r.pixel_x = rd.i32();
    r.pixel_y = rd.i32();
    r.light = rd.i32();
    uint8_t kind = rd.u8();
    r.kind = RayKind(kind);
    r.depth = rd.u8();
    r.child_slot = rd.u8();
    r.interior_depth = rd.u8();
    for (int i = 0; i < kMaxInteriorDepth; ++i) r.interiors[i] = rd.i32();
    r.origin = rd.vec();
    r.direction = rd.vec();
    r.t_min = rd.f64();
    r.t_max = rd.f64();
    r.weight = rd.f32();
    r.contribution = rd.rgb();
    return kind <= uint8_t(RayKind::Shadow) && r.interior_depth <= kMaxInteriorDepth;
}

void write_result(Writer& w, const ResultMessage& r) {
    w.u64(r.parent_id);
    w.i32(r.parent_box);
    w.u8(r.child_slot);
    w.rgb(r.colour);
    w.f32(r.alpha);
    w.f64(r.distance);
}

void read_result(Reader& rd, ResultMessage& r) {
    r.parent_id = rd.u64();
    r.parent_box = rd.i32();
    r.child_slot = rd.u8();
    r.colour = rd.rgb();
    r.alpha = rd.f32();
    r.distance = rd.f64();
}

template <class T, class WriteOne>
void encode(FrameType type, std::span<const T> items, std::vector<uint8_t>& out,
            WriteOne write_one) {
    Writer w{out};
    size_t start = out.size();
    w.u16(kFrameMagic);
    w.u8(uint8_t(type));
    w.u8(kProtocolVersion);
    w.u32(0);  // body length, patched below
    w.u32(uint32_t(items.size()));
    for (const T& item : items) write_one(w, item);
    uint32_t body = uint32_t(out.size() - start - kHeaderSize);
    for (int i = 0; i < 4; ++i) out[start + 4 + i] = uint8_t(body >> (8 * i));
}

}  // namespace

size_t encoded_ray_size() {
    std::vector<uint8_t> v;
    Writer w{v};
    write_ray(w, RayMessage{});
    return v.size();
}

size_t encoded_result_size() {
    std::vector<uint8_t> v;
    Writer w{v};
    write_result(w, ResultMessage{});
    return v.size();
}

void encode_rays(std::span<const RayMessage> rays, std::vector<uint8_t>& out) {
    encode(FrameType::Rays, rays, out, write_ray);
}

void encode_results(std::span<const ResultMessage> results, std::vector<uint8_t>& out) {
    encode(FrameType::Results, results, out, write_result);
}

void encode_opaque(FrameType type, uint32_t count, std::span<const uint8_t> body,
                   std::vector<uint8_t>& out) {
    Writer w{out};
    w.u16(kFrameMagic);
    w.u8(uint8_t(type));
    w.u8(kProtocolVersion);
    w.u32(uint32_t(body.size()));
    w.u32(count);
    out.insert(out.end(), body.begin(), body.end());
}

DecodeStatus decode_frame(std::span<const uint8_t> bytes, Frame& frame) {
    if (bytes.size() < kHeaderSize) return DecodeStatus::NeedMore;
    Reader rd{bytes.data()};
    if (rd.u16() != kFrameMagic) return DecodeStatus::Bad;
    uint8_t type = rd.u8();
    if (rd.u8() != kProtocolVersion) return DecodeStatus::Bad;
    uint32_t body = rd.u32();
    uint32_t count = rd.u32();
    if (body > kMaxBodySize) return DecodeStatus::Bad;
    if (type == uint8_t(FrameType::Pixels) || type == uint8_t(FrameType::Control) ||
        type == uint8_t(FrameType::Items)) {
        if (bytes.size() < kHeaderSize + body) return DecodeStatus::NeedMore;
        frame.type = FrameType(type);
        frame.count = count;
        frame.body = bytes.subspan(kHeaderSize, body);
        frame.consumed = kHeaderSize + body;
        return DecodeStatus::Complete;
    }
    size_t record = 0;
    if (type == uint8_t(FrameType::Rays)) {
        record = encoded_ray_size();
    } else if (type == uint8_t(FrameType::Results)) {
        record = encoded_result_size();
    } else {
        return DecodeStatus::Bad;
    }
    if (size_t(count) * record != body) return DecodeStatus::Bad;
    if (bytes.size() < kHeaderSize + body) return DecodeStatus::NeedMore;
    frame.type = FrameType(type);
    frame.rays.clear();
    frame.results.clear();
    if (frame.type == FrameType::Rays) {
        frame.rays.resize(count);
        for (auto& r : frame.rays) {
            if (!read_ray(rd, r)) return DecodeStatus::Bad;
        }
    } else {
        frame.results.resize(count);
        for (auto& r : frame.results) read_result(rd, r);
    }
    frame.consumed = kHeaderSize + body;
    return DecodeStatus::Complete;
}

}  // namespace povwall::distrib
