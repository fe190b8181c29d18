// Expected ray traffic between black boxes, for choosing walls (issue 7: adaptive walls
// balance "object count and expected ray traffic"). A pilot traces a sparse grid of the
// image's camera rays through the whole scene, with one shadow ray per light and, where
// the scene reflects or refracts, one bounce from each hit; each candidate set of walls
// is then scored by the crossings those ray segments would make between boxes.
#pragma once

#include <array>
#include <vector>

#include "core/math.h"
#include "core/scene.h"
#include "distrib/virtual_walls.h"

namespace povwall::distrib {

// A piece of a ray between where it starts and where it ends (a hit, a light, or the
// scene's bounds when it leaves); `camera`: a camera ray's, which the coordinator hands
// to the first box that can stop it rather than sending it across walls.
struct PilotSegment {
    Point3 from, to;
    bool camera = false;
};

// The pilot: about `samples` camera rays on a regular grid of a width x height image.
// `threads`: for preparing the scene (0: every core).
std::vector<PilotSegment> pilot_segments(const Scene& scene, int width, int height,
                                         int samples, int threads = 0);

// An object's world bounds (the boxes it is in) and the bounds of where a ray can hit
// it (what it adds to their reach), computed once for all the walls scored.
struct ObjectExtent {
    Bounds3 world, hit;
};
std::vector<ObjectExtent> object_extents(const Scene& scene);

// Crossings between boxes the segments make under `walls`: for each segment, the boxes
// after the first that its path meets where they hold something (a box whose objects'
// bounds the segment misses is skipped without a message, as BoxHost routes).
uint64_t estimated_crossings(const std::vector<PilotSegment>& segments,
                             const VirtualWalls& walls,
                             const std::vector<ObjectExtent>& objects);

// Every way to cut `boxes` boxes into nx x ny x nz slabs.
std::vector<std::array<int, 3>> box_grids(int boxes);

}  // namespace povwall::distrib
