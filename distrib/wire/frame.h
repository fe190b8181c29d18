// Frames: the unit every byte between povwall processes travels in. No sockets here.
//
// A frame is a 16-byte header, all little-endian,
//   magic u16 | type u8 | protocol version u8 | body length u32 | record count u32 |
//   CRC-32 u32 (zlib's, of the header's first 12 bytes and the body)
// followed by the body: JSON text (Control), item records (Items, wire/items.h), pixel
// sum records (Pixels, wire/pixels.h), camera sample positions (Samples,
// wire/samples.h) or photons (Photons, wire/photons.h). The header is checked before the
// body is awaited: a wrong magic, type or version, or a body over kMaxBodySize, is
// refused at once; a frame whose CRC does not match once it is whole is refused too, so
// a flipped bit or a truncated frame is never read as other records.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace povwall::distrib {

enum class FrameType : uint8_t {
    Pixels = 3,
    Control = 4,
    Items = 5,
    Samples = 6,
    Photons = 7
};
constexpr uint16_t kFrameMagic = 0x5057;  // "PW"
// 2: ray records leave out defaults; 3: the fixed ray/result frames (1, 2) are gone;
// 4: anti-aliasing samples (Samples frames, "samples" and later "start" messages);
// 5: sample records carry a focal-blur ray index (20 bytes); 8: the photon map (Photons
// frames, "photons" message), shadow states carry photon_caustics; 9: ray records carry a
// dispersion band (flag 128); 10: shadow states carry "no media or fog" (bit 2); 12:
// typed control messages (11), and every frame carries a CRC-32; 13: a job's walk
// reaches as {box, lo, hi} records.
constexpr uint8_t kProtocolVersion = 13;
constexpr size_t kHeaderSize = 16;
// Bounds memory per frame; senders split larger batches.
constexpr size_t kMaxBodySize = size_t(4) << 20;

// Appends a frame of `body` (at most kMaxBodySize bytes) to `out`.
void encode_frame(FrameType type, uint32_t count, std::span<const uint8_t> body,
                  std::vector<uint8_t>& out);

enum class DecodeStatus { Complete, NeedMore, Bad };
struct Frame {
    FrameType type = FrameType::Control;
    uint32_t count = 0;
    // The body within the decoded bytes (no copy; valid while they are).
    std::span<const uint8_t> body;
    size_t consumed = 0;  // bytes of input this frame took
};
// Whether decode_frame compares the CRC. Only a fuzzer turns it off, to reach the body
// readers with bytes no sender wrote (a peer can send garbage under a valid CRC).
enum class CrcCheck { On, Off };
// Decodes one frame from the start of `bytes`.
DecodeStatus decode_frame(std::span<const uint8_t> bytes, Frame& frame,
                          CrcCheck crc = CrcCheck::On);

}  // namespace povwall::distrib
