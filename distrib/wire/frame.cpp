#include "distrib/wire/frame.h"

#include <zlib.h>

namespace povwall::distrib {
namespace {

void put_le(std::vector<uint8_t>& out, uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

uint64_t get_le(const uint8_t* p, int bytes) {
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= uint64_t(p[i]) << (8 * i);
    return v;
}

bool known_type(uint8_t type) {
    switch (FrameType(type)) {
        case FrameType::Pixels:
        case FrameType::Control:
        case FrameType::Items:
        case FrameType::Samples:
        case FrameType::Photons:
            return true;
    }
    return false;
}

uint32_t frame_crc(const uint8_t* header, std::span<const uint8_t> body) {
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32(crc, header, 12);
    // zlib takes lengths as uInt; bodies are at most kMaxBodySize.
    if (!body.empty()) crc = crc32(crc, body.data(), uInt(body.size()));
    return uint32_t(crc);
}

}  // namespace

void encode_frame(FrameType type, uint32_t count, std::span<const uint8_t> body,
                  std::vector<uint8_t>& out) {
    put_le(out, kFrameMagic, 2);
    put_le(out, uint8_t(type), 1);
    put_le(out, kProtocolVersion, 1);
    put_le(out, uint32_t(body.size()), 4);
    put_le(out, count, 4);
    const size_t at = out.size() - 12;
    put_le(out, frame_crc(out.data() + at, body), 4);
    out.insert(out.end(), body.begin(), body.end());
}

DecodeStatus decode_frame(std::span<const uint8_t> bytes, Frame& frame, CrcCheck crc) {
    if (bytes.size() < kHeaderSize) return DecodeStatus::NeedMore;
    const uint8_t* p = bytes.data();
    if (get_le(p, 2) != kFrameMagic || !known_type(p[2]) || p[3] != kProtocolVersion)
        return DecodeStatus::Bad;
    const uint64_t body = get_le(p + 4, 4);
    if (body > kMaxBodySize) return DecodeStatus::Bad;
    if (bytes.size() < kHeaderSize + body) return DecodeStatus::NeedMore;
    if (crc == CrcCheck::On &&
        get_le(p + 12, 4) != frame_crc(p, bytes.subspan(kHeaderSize, size_t(body))))
        return DecodeStatus::Bad;
    frame.type = FrameType(p[2]);
    frame.count = uint32_t(get_le(p + 8, 4));
    frame.body = bytes.subspan(kHeaderSize, size_t(body));
    frame.consumed = kHeaderSize + size_t(body);
    return DecodeStatus::Complete;
}

}  // namespace povwall::distrib
