// The work items black boxes trade: rays to trace and results returning to waiting
// parents. In one process they move by value; between processes as records of
// distrib/wire/items.h (a new field goes here and there, nowhere else).
#pragma once

#include <cstdint>

#include "core/colour.h"
#include "core/math.h"
#include "distrib/virtual_walls.h"
#include "trace/shading.h"

namespace povwall::distrib {

// A ray travelling between boxes. Its origin is never re-based at a wall: searches resume
// at `t_from` along the original ray, so POV-Ray's absolute minimum distances still hold.
struct RayItem {
    trace::TraceRay trace;
    bool shadow = false;
    bool counted = false;
    Real t_from = 0;
    Real light_distance = kInfinity;
    trace::ShadowState shadow_state;
    // Where the result goes: a waiting parent (parent tracking) or the pixel (the
    // camera sample's slot when the run traces a list of samples: set_samples()).
    uint64_t parent = 0;
    int32_t parent_box = -1;
    uint16_t slot = 0;
    int32_t pixel = 0;
    // Forward contributions: factors from this ray's colour / transmit to the pixel.
    Rgb contribution{1.0f};
    float transmit_contribution = 1;
    // The walk along the walls, kept so that the box receiving the ray goes on with it
    // instead of starting again: valid for box `route_box` (-1: none; not sent over
    // TCP), standing at the start of that box's segment.
    int32_t route_box = -1;
    VirtualWalls::WalkState route_walk;
};

struct ResultItem {
    uint64_t parent = 0;
    uint16_t slot = 0;
    trace::TraceResult result;
};

struct Item {
    bool is_result = false;
    RayItem ray;
    ResultItem result;
};

}  // namespace povwall::distrib
