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
std::vector<PilotSegment> pilot_segments(const Scene& scene, int width, int height,
                                         int samples);

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

// Local processes that outnumber the cores take turns on them. Each one kept on one
// core, with the processes it trades most rays with, wakes them without an
// inter-processor interrupt (costly on a virtual machine) and keeps its caches. Which
// of `cores` groups each process runs in, given each one's `work` and the `crossings`
// between them ([from][to]): the cores halved again and again, the processes split in
// proportion to their work (within 5 % of the most even split) across the fewest
// crossings. Empty where each process has a core, or for more than
// kMaxProcessesOnCores processes (the splits are searched exhaustively).
constexpr int kMaxProcessesOnCores = 12;
std::vector<int> core_groups(const std::vector<double>& work,
                             const std::vector<std::vector<uint64_t>>& crossings,
                             int cores);

// Every way to cut `boxes` boxes into nx x ny x nz slabs.
std::vector<std::array<int, 3>> box_grids(int boxes);

}  // namespace povwall::distrib
