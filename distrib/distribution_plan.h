// How a render is spread over workers, decided once per scene from its size and the
// memory a worker may use (issue: "leave out what a given scene does not need"):
//
//   single: one process; its threads take image rows as they finish (screen subdivision
//           inside one process: every thread shares the one copy of the scene);
//   screen: worker processes each hold the whole scene and take image tiles as they
//   finish
//           (distrib/screen_render.h);
//   space:  virtual walls cut the scene into black boxes, each holding only its objects.
//
// auto picks screen subdivision when the whole prepared scene fits the worker memory
// budget (in this process's threads, or over --procs worker processes), else the fewest
// balanced boxes whose largest local scene fits it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.h"
#include "distrib/space_render.h"

namespace povwall::distrib {

enum class RenderMode { Auto, Single, Screen, Space };
// Its names (--mode), found by distrib/wire/job_fields.h's NamedEnum.
std::array<std::pair<RenderMode, const char*>, 4> enum_names(RenderMode);

struct DistributionRequest {
    RenderMode mode = RenderMode::Auto;
    std::string boxes;         // --boxes as given (empty: not given)
    size_t worker_memory = 0;  // bytes; 0: half of this machine's memory
    int threads = 0;           // 0: all cores
    int procs = 0;             // worker processes, screen or space (0: not asked for)
    int workers = 0;           // running workers given (--workers): their count
    int cores = 0;             // this machine's cores (0: those this process may use)
    // Local processes that outnumber the cores: each kept on one (SpaceOptions::
    // keep_on_cores).
    bool keep_on_cores = true;
    // Teams of workers that each host every box (SpaceOptions::teams); 0: auto, the most
    // teams of at least 2 workers whose largest worker fits the budget (local workers:
    // all of them within half of this machine's memory). More than 1 needs --boxes and
    // workers.
    int teams = 1;
    size_t pixels = 0;          // image width x height (worker accumulators)
    int width = 0, height = 0;  // the image (the pilot of --boxes auto over workers)
};

struct DistributionPlan {
    RenderMode mode = RenderMode::Single;
    SpaceOptions space;  // mode == Space
    // Estimated memory of the whole scene in one process: the parsed model plus its
    // prepared form (primitives, materials, octree).
    size_t scene_bytes = 0;
    size_t prepared_bytes = 0;     // the prepared part alone
    size_t largest_box_bytes = 0;  // estimated, mode == Space
    // mode == Space over worker processes: the largest worker's estimated memory (the
    // process itself, the objects of its boxes, their prepared scenes).
    size_t largest_worker_bytes = 0;
    size_t worker_memory = 0;
    int threads = 1;
    // Worker processes: mode == Screen, or mode == Space over TCP (0: boxes in this
    // process).
    int procs = 0;
    std::vector<std::string> reasons;  // plain words, for --explain
};

struct DistributionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// The scene has a feature the chosen mode cannot render (a located `unsupported:`
// diagnostic, printed as a parse error is).
struct UnsupportedInMode : DistributionError {
    using DistributionError::DistributionError;
};

// Parses "4x4x4" (equal slabs), "N" (balanced N x N x N) or "auto". Throws
// DistributionError on a bad value.
SpaceOptions parse_boxes(const std::string& spec);

// Parses a memory size: "512M", "2G", "300000K", "1.5G", plain bytes.
size_t parse_memory_size(const std::string& text);

DistributionPlan plan_distribution(const Scene& scene,
                                   const DistributionRequest& request);

// "12.3 MB"
std::string format_bytes(size_t bytes);

// Which of `workers` processes hosts each box of a grid of `slabs` boxes (box_index
// order). The grid is cut in two again and again, the workers shared in proportion, into
// compact blocks: few walls lie between processes, so few crossings go over the network.
// The longest side is cut first; among equal sides, the one most across the `view`
// direction, so each process gets a part of the picture (cutting along the view puts
// the front boxes, which most rays reach, on one process). More workers than boxes:
// some host none (teams, SpaceOptions::teams, put such workers to use).
// With `grid` (px x py x pz = workers, each at most the slabs on its axis) the blocks are
// that grid's instead: blocks chosen by the pilot's ray traffic (SpaceOptions::
// process_grid). Any other `grid` is ignored.
std::vector<int> box_owners(std::array<int, 3> slabs, int workers, const Vector3& view,
                            std::array<int, 3> grid = {0, 0, 0});

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

// A worker process's own memory before any scene (binary, libraries, stacks): measured
// 7.7 MB resident for a worker holding one sphere.
constexpr size_t kWorkerProcessBytes = size_t(8) << 20;
// Auto mode starts at most this many local worker processes for a memory budget.
constexpr int kMaxAutoWorkers = 64;

// Memory per ray in flight, as the worker where rays pile up holds it (the queued item,
// its encoded copy in receive buffers, inbox and queue rings that double as they grow):
// the worker receiving the camera rays grew by up to 2.5 KB per ray of the in-flight
// bound while tracing (100,000 spheres, 80x60 to 320x240, bounds 13,000 and 65,536).
constexpr size_t kRayInFlightBytes = 2560;
constexpr size_t kMinRaysInFlight = 1024;

// --boxes auto over several workers chooses its cuts with a pilot of about this many
// camera rays (distrib/traffic_estimate.h), for scenes of at most this many objects
// (the pilot prepares the whole scene in the coordinator).
constexpr int kTrafficPilotRays = 1024;
constexpr size_t kTrafficPilotMaxObjects = 200000;

// Per pixel of the image, a worker holds r, g, b, transmit in double per render thread,
// their sum when the frame ends, and that sum encoded for the coordinator.
constexpr size_t kPixelBytesPerThread = 32, kPixelBytesAtEnd = 96;

}  // namespace povwall::distrib
