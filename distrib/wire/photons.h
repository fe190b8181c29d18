// The photon map as the TCP coordinator sends it to its workers (trace/photon_map.h): a
// worker holds a part of the scene and cannot shoot the map, so the coordinator, which
// parsed the whole scene, shoots it once and every worker gathers from that same map.
//
// Once per frame, after every worker is ready and before the first wave's samples:
// Photons frames (wire/frame.h) of kPhotonRecordSize-byte records, the surface map's
// photons then the media map's, each map in its kd-tree order; then a Control "photons"
// message with both maps' counts, radii (as bit patterns: the gather divides by them)
// and the gather settings, or {"map": false} for a frame without photons.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "distrib/wire/control.h"
#include "trace/photon_map.h"

namespace povwall::distrib {

// position 3 x f32, RGBE 4 x u8, theta i8, phi i8, kd-tree axis u8
constexpr size_t kPhotonRecordSize = 19;
// Records per Photons frame (2.5 MB): larger maps go out in several frames.
constexpr size_t kPhotonsPerFrame = size_t(1) << 17;

// The frames and the closing message that carry `map` (null: none).
std::vector<Buffer> photon_map_frames(const trace::PhotonMap* map);

// Appends the `count` records of `body` to `out`, after checking them all: false (and
// `out` unchanged) unless the body is exactly `count` records of finite positions and
// axes 0 to 2.
bool read_photons(std::span<const uint8_t> body, uint32_t count,
                  std::vector<trace::Photon>& out);

// The map a closing "photons" `message` describes, made of the `photons` its frames
// brought (taken). False when the message is malformed or its counts are not those of
// `photons`; `map` becomes null for a frame without photons.
bool photon_map_from_message(const nlohmann::json& message,
                             std::vector<trace::Photon>&& photons,
                             std::shared_ptr<const trace::PhotonMap>& map);

}  // namespace povwall::distrib
