// Messages between black boxes: rays to trace and results returning to waiting parents.
//
// Pure data and a byte codec; no sockets here. A frame is a fixed 12-byte header
//   magic u16 | type u8 | version u8 | body length u32 | count u32
// followed by `count` fixed-size records, all little-endian. Rays are batched per
// destination.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/colour.h"
#include "core/math.h"

namespace povwall::distrib {

enum class RayKind : uint8_t { Camera, Reflected, Refracted, Shadow };

// Enough interior nesting for real scenes (glass in water in glass); deeper stacks are
// refused.
constexpr int kMaxInteriorDepth = 8;

struct RayMessage {
    uint64_t id = 0;         // unique per render: (origin box << 40) | sequence
    uint64_t parent_id = 0;  // 0 for camera rays
    int32_t parent_box = -1;
    int32_t pixel_x = 0, pixel_y = 0;
    int32_t light = -1;  // shadow rays: which light
    RayKind kind = RayKind::Camera;
    uint8_t depth = 0;       // trace level (1 for camera rays)
    uint8_t child_slot = 0;  // index among the parent's children
    uint8_t interior_depth = 0;
    int32_t interiors[kMaxInteriorDepth] = {};
    // Origin as first emitted: never re-based at a wall, so POV-Ray's minimum-distance
    // rules (distances measured from the true origin) still hold in the next box.
    Point3 origin;
    Vector3 direction;
    Real t_min = 0, t_max = kInfinity;  // accepted hit range along the ray
    float weight = 1;                   // POV-Ray's adc weight for bailout decisions
    Rgb contribution{1.0f};  // forward mode: factor from this ray's colour to the pixel
};

struct ResultMessage {
    uint64_t parent_id = 0;
    int32_t parent_box = -1;
    uint8_t child_slot = 0;
    Rgb colour;       // traced colour, or shadow transmittance
    float alpha = 1;  // camera rays: coverage for +UA output
    Real distance = kInfinity;
};

// Rays/Results: fixed records (RayMessage, ResultMessage). Pixels, Control (JSON text)
// and Items (black-box work items, distrib/tcp_render.cpp) carry an opaque body.
enum class FrameType : uint8_t {
    Rays = 1,
    Results = 2,
    Pixels = 3,
    Control = 4,
    Items = 5
};
constexpr uint16_t kFrameMagic = 0x5057;  // "PW"
constexpr uint8_t kProtocolVersion = 2;   // 2: ray records leave out defaults
constexpr size_t kHeaderSize = 12;
// Bounds memory per frame; senders split larger batches.
constexpr size_t kMaxBodySize = size_t(4) << 20;

void encode_rays(std::span<const RayMessage> rays, std::vector<uint8_t>& out);
void encode_results(std::span<const ResultMessage> results, std::vector<uint8_t>& out);
// A frame with an opaque body of at most kMaxBodySize bytes.
void encode_opaque(FrameType type, uint32_t count, std::span<const uint8_t> body,
                   std::vector<uint8_t>& out);

enum class DecodeStatus { Complete, NeedMore, Bad };
struct Frame {
    FrameType type = FrameType::Rays;
    std::vector<RayMessage> rays;
    std::vector<ResultMessage> results;
    uint32_t count = 0;
    // Pixels, Control, Items: the body within the decoded bytes (no copy; valid while
    // they are).
    std::span<const uint8_t> body;
    size_t consumed = 0;  // bytes of input used by this frame
};
// Decodes one frame from the start of `bytes`.
DecodeStatus decode_frame(std::span<const uint8_t> bytes, Frame& frame);

size_t encoded_ray_size();
size_t encoded_result_size();

}  // namespace povwall::distrib
