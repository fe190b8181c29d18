// Control frames: JSON messages between the coordinator and its workers, and the parts of
// the job that travel inside them.
//
// clang-format off
// Protocol (all frames: distrib/wire/frame.h header, version checked, body <= kMaxBodySize):
//   peer -> worker    Control hello {token, from: index or -1}: first frame, else closed
//   coord -> worker   Control job (scene source, walls, box owners, worker addresses)
//   worker -> coord   Control busy every second while parsing and building its boxes
//   worker -> coord   Control ready (primitive count per hosted box)
//   coord -> worker   photons only, once per frame: Photons (the map's photons), then
//                     Control photons {counts, radii, gather settings} (wire/photons.h)
//   coord -> worker   anti-aliasing only: Samples (the wave's positions), then Control
//                     samples {count}; worker -> coord Control samples (taken)
//   coord -> worker   Control start (each box's reach), then Control pixels {begin, end}
//                     (slot ranges whose camera rays the worker makes)
//   worker -> worker  Items (rays and results for the receiver's boxes)
//   worker -> coord   Control status (items created/finished) every 10 ms: heartbeat, flow
//                     control, and the answer to probes (termination waves)
//   coord -> worker   Control finish; worker -> coord Pixels (sums), then Control done;
//                     anti-aliasing: the next wave from "Samples", until the image is whole
//   coord -> worker   Control frame (new animation values): the next frame, from "busy"
// clang-format on
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "distrib/wire/frame.h"
#include "trace/render_plan.h"

namespace povwall::distrib {

using Buffer = std::shared_ptr<std::vector<uint8_t>>;

// A Control frame holding `message`.
Buffer control_frame(const nlohmann::json& message);
// The message of a Control frame; a discarded value (is_discarded()) when it is not JSON.
nlohmann::json parse_control(const Frame& frame);

// A message's "type", or "" when it has none (or one that is not a string).
std::string control_type(const nlohmann::json& message);

// The first frame on every connection to a worker: the job's token, and who calls (-1 the
// coordinator, else the calling worker's index).
struct Hello {
    std::string token;
    int from = -1;
};
Buffer hello_frame(const Hello& hello);
// The hello of `message`; nothing unless it is a well-formed one.
std::optional<Hello> hello_from_json(const nlohmann::json& message);

// The coordinator's render plan, sent with every frame: a worker that parsed only its
// part of the scene must not decide from that part which rays the scene needs.
nlohmann::json plan_to_json(const trace::RenderPlan& plan);
// Throws nlohmann::json::exception when a field is missing or of the wrong type.
trace::RenderPlan plan_from_json(const nlohmann::json& j);

// The boxes' reach: six bit patterns per box, so that every process routes with exactly
// the same doubles (infinities included, which JSON lacks).
nlohmann::json reach_to_json(const std::vector<Bounds3>& reach);
// False unless `j` holds `boxes` boxes of six non-NaN doubles.
bool reach_from_json(const nlohmann::json& j, int boxes, std::vector<Bounds3>& reach);

}  // namespace povwall::distrib
