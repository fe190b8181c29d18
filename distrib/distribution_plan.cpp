#include "distrib/distribution_plan.h"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <thread>

#include "distrib/traffic_estimate.h"
#include "trace/prepared_scene.h"
#include "trace/render_plan.h"

namespace povwall::distrib {

std::array<std::pair<RenderMode, const char*>, 4> enum_names(RenderMode) {
    return {{{RenderMode::Auto, "auto"},
             {RenderMode::Single, "single"},
             {RenderMode::Screen, "screen"},
             {RenderMode::Space, "space"}}};
}

SpaceOptions parse_boxes(const std::string& spec) {
    SpaceOptions space;
    if (spec == "auto") {
        // About 4 boxes per core, walls on object quantiles.
        int n = int(std::max(1u, std::thread::hardware_concurrency()));
        int per_axis = n >= 4 ? 3 : 2;
        space.boxes = {per_axis, per_axis, per_axis};
        space.balanced = true;
        return space;
    }
    int a = 0, b = 0, c = 0;
    char extra;
    if (std::sscanf(spec.c_str(), "%dx%dx%d%c", &a, &b, &c, &extra) == 3 && a > 0 &&
        b > 0 && c > 0) {
        space.boxes = {a, b, c};
        return space;
    }
    if (std::sscanf(spec.c_str(), "%d%c", &a, &extra) == 1 && a > 0) {
        space.boxes = {a, a, a};
        space.balanced = true;
        return space;
    }
    throw DistributionError("bad --boxes value '" + spec +
                            "' (expected NxNxN, N or auto)");
}

size_t parse_memory_size(const std::string& text) {
    double value = 0;
    char unit = 0, extra = 0;
    int n = std::sscanf(text.c_str(), "%lf%c%c", &value, &unit, &extra);
    double scale = 1;
    if (n >= 2) {
        switch (unit) {
            case 'k':
            case 'K':
                scale = 1024.0;
                break;
            case 'm':
            case 'M':
                scale = 1024.0 * 1024;
                break;
            case 'g':
            case 'G':
                scale = 1024.0 * 1024 * 1024;
                break;
            default:
                n = 0;
        }
        // An optional trailing 'B' ("512MB").
        if (n == 3 && extra != 'B' && extra != 'b') n = 0;
    }
    if (n < 1 || !(value > 0) || !std::isfinite(value))
        throw DistributionError("bad memory size '" + text +
                                "' (expected e.g. 512M or 2G)");
    return size_t(value * scale);
}

std::string format_bytes(size_t bytes) {
    char buf[32];
    if (bytes >= (size_t(1) << 30)) {
        std::snprintf(buf, sizeof buf, "%.1f GB", double(bytes) / (1 << 30));
    } else if (bytes >= (size_t(1) << 20)) {
        std::snprintf(buf, sizeof buf, "%.1f MB", double(bytes) / (1 << 20));
    } else {
        std::snprintf(buf, sizeof buf, "%.1f KB", double(bytes) / 1024);
    }
    return buf;
}

namespace {

VirtualWalls walls_for(const std::vector<Bounds3>& bounds, const SpaceOptions& space) {
    Bounds3 world;
    std::vector<Bounds3> finite;
    for (const Bounds3& b : bounds) {
        if (b.infinite()) continue;
        world.extend(b.lo);
        world.extend(b.hi);
        finite.push_back(b);
    }
    const auto& n = space.boxes;
    return space.balanced ? VirtualWalls::balanced(finite, n[0], n[1], n[2])
                          : VirtualWalls::uniform(world, n[0], n[1], n[2]);
}

// Each box also keeps its own prepared-scene header and octree root.
constexpr size_t kBoxBytes = sizeof(trace::PreparedScene) + 256;

// Measured: workers reach 1.03-1.06x their estimate after parsing and building their
// boxes (allocator rounding, the parse's own lists) and up to 1.01x at the end of the
// trace. Since the scene model shrank (Object 200 B, Texture 80 B), what the estimate
// leaves out weighs more: 42,000 spheres over 4 workers peaked at up to 1.25x. Estimates
// of worker memory get 30 % on top.
size_t with_margin(size_t bytes) { return bytes * 130 / 100; }

// "file:line:col: " of a scene location, for a message (empty when it has none).
std::string located(const Scene& scene, const SourceLoc& loc) {
    if (!loc.valid() || size_t(loc.file) >= scene.files.size()) return {};
    return scene.files[size_t(loc.file)] + ":" + std::to_string(loc.line) + ":" +
           std::to_string(loc.column) + ": ";
}

struct ObjectSizes {
    std::vector<Bounds3> bounds;
    std::vector<size_t> model, prepared;
};

// The boxes each object overlaps under one set of walls (flat lists: the planner tries
// several box and worker counts over 100,000s of objects).
struct Overlaps {
    int boxes = 0;
    std::array<int, 3> slabs{1, 1, 1};
    Vector3 view{0, 0, 1};        // the camera's direction (box_owners)
    std::array<int, 3> grid{};    // SpaceOptions::process_grid (box_owners)
    std::vector<uint32_t> start;  // object i's boxes: box[start[i] .. start[i + 1])
    std::vector<int> box;
};

Overlaps overlaps_of(const ObjectSizes& o, const VirtualWalls& walls,
                     const Vector3& view) {
    Overlaps ov;
    ov.boxes = walls.box_count();
    ov.slabs = walls.slabs();
    ov.view = view;
    ov.start.reserve(o.bounds.size() + 1);
    for (const Bounds3& b : o.bounds) {
        ov.start.push_back(uint32_t(ov.box.size()));
        for (int x : walls.boxes_overlapping(b)) ov.box.push_back(x);
    }
    ov.start.push_back(uint32_t(ov.box.size()));
    return ov;
}

// Largest estimated local scene (objects and their prepared form) over the boxes.
size_t largest_box(const ObjectSizes& o, const Overlaps& ov) {
    std::vector<size_t> per_box(size_t(ov.boxes), kBoxBytes);
    for (size_t i = 0; i < o.bounds.size(); ++i) {
        for (uint32_t k = ov.start[i]; k < ov.start[i + 1]; ++k)
            per_box[size_t(ov.box[k])] += o.model[i] + o.prepared[i];
    }
    return *std::max_element(per_box.begin(), per_box.end());
}

// Largest estimated worker over `workers` processes hosting the boxes as the coordinator
// shares them out (box_owners): the process, each object overlapping any of its boxes
// once (a worker keeps only those while it parses), and a prepared copy per box it
// overlaps.
size_t largest_worker(const ObjectSizes& o, const Overlaps& ov, int workers,
                      size_t pixels, int threads_asked) {
    const int boxes = ov.boxes;
    // The process, the fewest rays in flight the flow control allows, the image sums.
    // Render threads per worker: --threads, else the cores shared out (as
    // TcpCoordinator starts them).
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int per_worker_threads =
        threads_asked > 0 ? threads_asked : std::max(1, cores / workers);
    std::vector<size_t> per_worker(
        size_t(workers), kWorkerProcessBytes + kMinRaysInFlight * kRayInFlightBytes +
                             pixels * (kPixelBytesPerThread * size_t(per_worker_threads) +
                                       kPixelBytesAtEnd));
    const std::vector<int> owner = box_owners(ov.slabs, workers, ov.view, ov.grid);
    for (int b = 0; b < boxes; ++b) per_worker[size_t(owner[size_t(b)])] += kBoxBytes;
    std::vector<size_t> seen(size_t(workers), SIZE_MAX);
    for (size_t i = 0; i < o.bounds.size(); ++i) {
        for (uint32_t k = ov.start[i]; k < ov.start[i + 1]; ++k) {
            const auto w = size_t(owner[size_t(ov.box[k])]);
            per_worker[w] += o.prepared[i];
            if (seen[w] != i) per_worker[w] += o.model[i];
            seen[w] = i;
        }
    }
    return with_margin(*std::max_element(per_worker.begin(), per_worker.end()));
}

}  // namespace

std::vector<int> box_owners(std::array<int, 3> slabs, int workers, const Vector3& view,
                            std::array<int, 3> grid) {
    const size_t boxes = size_t(slabs[0]) * size_t(slabs[1]) * size_t(slabs[2]);
    if (grid[0] * grid[1] * grid[2] == workers && workers > 0 && grid[0] >= 1 &&
        grid[1] >= 1 && grid[2] >= 1 && grid[0] <= slabs[0] && grid[1] <= slabs[1] &&
        grid[2] <= slabs[2]) {
        std::vector<int> owner(boxes, 0);
        for (int z = 0; z < slabs[2]; ++z)
            for (int y = 0; y < slabs[1]; ++y)
                for (int x = 0; x < slabs[0]; ++x) {
                    const int bx = x * grid[0] / slabs[0], by = y * grid[1] / slabs[1],
                              bz = z * grid[2] / slabs[2];
                    owner[size_t((z * slabs[1] + y) * slabs[0] + x)] =
                        (bz * grid[1] + by) * grid[0] + bx;
                }
        return owner;
    }
    struct Block {
        std::array<int, 3> lo, hi;  // boxes [lo, hi) per axis
        int first, count;           // workers [first, first + count)
    };
    std::vector<int> owner(boxes, 0);
    std::vector<Block> todo{{{0, 0, 0}, slabs, 0, std::max(1, workers)}};
    while (!todo.empty()) {
        const Block b = todo.back();
        todo.pop_back();
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            const int side = b.hi[a] - b.lo[a];
            if (side < 2) continue;
            const int best = axis < 0 ? 0 : b.hi[axis] - b.lo[axis];
            if (side > best ||
                (side == best && std::fabs(view[a]) < std::fabs(view[axis])))
                axis = a;
        }
        if (b.count == 1 || axis < 0) {
            for (int z = b.lo[2]; z < b.hi[2]; ++z)
                for (int y = b.lo[1]; y < b.hi[1]; ++y)
                    for (int x = b.lo[0]; x < b.hi[0]; ++x)
                        owner[size_t((z * slabs[1] + y) * slabs[0] + x)] = b.first;
            continue;
        }
        const int left = b.count / 2, side = b.hi[axis] - b.lo[axis];
        const int cut =
            b.lo[axis] +
            std::clamp(int(std::lround(double(side) * left / b.count)), 1, side - 1);
        Block low = b, high = b;
        low.hi[axis] = cut, low.count = left;
        high.lo[axis] = cut, high.first = b.first + left, high.count = b.count - left;
        todo.push_back(low);
        todo.push_back(high);
    }
    return owner;
}

namespace {
// Splits `procs` between cores [first, first + count) of `group`: in two, the cores in
// halves, the processes in the proportion of their work; of the splits within 5 % of
// the best balance, the one the fewest crossings pass; then each half again.
void split_between_cores(const std::vector<double>& work,
                         const std::vector<std::vector<uint64_t>>& crossings,
                         const std::vector<int>& procs, int first, int count,
                         std::vector<int>& group) {
    if (count == 1) {
        for (int p : procs) group[size_t(p)] = first;
        return;
    }
    const int low_cores = count / 2, high_cores = count - low_cores;
    const size_t n = procs.size();
    auto makespan = [&](uint32_t mask) {  // bit set: the low half
        double low = 0, high = 0;
        for (size_t i = 0; i < n; ++i)
            (mask >> i & 1 ? low : high) += work[size_t(procs[i])];
        return std::max(low / low_cores, high / high_cores);
    };
    auto valid = [&](uint32_t mask) {
        const int in_low = std::popcount(mask);
        return in_low >= low_cores && int(n) - in_low >= high_cores;
    };
    double best = std::numeric_limits<double>::infinity();
    for (uint32_t mask = 1; mask + 1 < (1u << n); ++mask) {
        if (valid(mask)) best = std::min(best, makespan(mask));
    }
    uint32_t chosen = 0;
    uint64_t fewest = UINT64_MAX;
    for (uint32_t mask = 1; mask + 1 < (1u << n); ++mask) {
        if (!valid(mask) || makespan(mask) > best * 1.05) continue;
        uint64_t cut = 0;
        for (size_t i = 0; i < n; ++i) {
            for (size_t j = 0; j < n; ++j) {
                if ((mask >> i & 1) != (mask >> j & 1))
                    cut += crossings[size_t(procs[i])][size_t(procs[j])];
            }
        }
        if (cut < fewest) fewest = cut, chosen = mask;
    }
    std::vector<int> low, high;
    for (size_t i = 0; i < n; ++i) (chosen >> i & 1 ? low : high).push_back(procs[i]);
    split_between_cores(work, crossings, low, first, low_cores, group);
    split_between_cores(work, crossings, high, first + low_cores, high_cores, group);
}
}  // namespace

std::vector<int> core_groups(const std::vector<double>& work,
                             const std::vector<std::vector<uint64_t>>& crossings,
                             int cores) {
    const int processes = int(work.size());
    if (cores < 2 || processes <= cores || processes > kMaxProcessesOnCores ||
        crossings.size() != work.size())
        return {};
    for (const auto& row : crossings) {
        if (row.size() != work.size()) return {};
    }
    std::vector<int> procs(static_cast<size_t>(processes));
    for (int p = 0; p < processes; ++p) procs[size_t(p)] = p;
    std::vector<int> group(size_t(processes), 0);
    split_between_cores(work, crossings, procs, 0, cores, group);
    return group;
}

namespace {

// The pilot's segments and the objects' extents that score walls by ray traffic; none
// for scenes too big to trace a pilot through here, or an image size not given.
struct Pilot {
    std::vector<PilotSegment> segments;
    std::vector<ObjectExtent> extents;
};
std::optional<Pilot> traffic_pilot(const Scene& scene,
                                   const DistributionRequest& request) {
    if (request.width <= 0 || request.height <= 0 ||
        scene.objects.size() > kTrafficPilotMaxObjects)
        return std::nullopt;
    Pilot pilot;
    pilot.segments = pilot_segments(scene, request.width, request.height,
                                    kTrafficPilotRays, request.threads);
    if (pilot.segments.empty()) return std::nullopt;
    pilot.extents = object_extents(scene);
    return pilot;
}

// --boxes auto over `workers` processes: one balanced box per worker, cut along the axes
// whose walls the pilot's rays cross least (ray traffic between processes is what costs;
// BoxHost's in-process hand-over is cheap, so without workers the walls stay as they
// are). Sets `space` and returns the words for --explain; leaves `space` for scenes too
// big to trace a pilot through here, or an image size not given.
std::string walls_by_traffic(const Scene& scene, const std::vector<Bounds3>& bounds,
                             const DistributionRequest& request, int workers,
                             SpaceOptions& space) {
    const std::optional<Pilot> pilot = traffic_pilot(scene, request);
    if (!pilot) return "";
    const std::vector<PilotSegment>& segments = pilot->segments;
    const std::vector<ObjectExtent>& extents = pilot->extents;
    const std::array<std::vector<Real>, 3> centres = VirtualWalls::sorted_centres(bounds);
    uint64_t best = UINT64_MAX;
    std::optional<uint64_t> cube;  // the equal cuts' count, when the workers make a cube
    std::array<int, 3> chosen{};
    for (const std::array<int, 3>& grid : box_grids(workers)) {
        const uint64_t n = estimated_crossings(
            segments, VirtualWalls::balanced(centres, grid[0], grid[1], grid[2]),
            extents);
        if (grid[0] == grid[1] && grid[1] == grid[2]) cube = n;
        if (n < best) best = n, chosen = grid;
    }
    const bool cube_chosen = chosen[0] == chosen[1] && chosen[1] == chosen[2];
    space.boxes = chosen;
    space.balanced = true;
    std::string why =
        "; walls cut across the least ray traffic: " + std::to_string(best) +
        " crossings for " + std::to_string(segments.size()) + " pilot ray segments";
    if (cube && !cube_chosen) why += " (" + std::to_string(*cube) + " with equal cuts)";
    return why;
}

// --boxes NxMxK over `workers` processes: which blocks of boxes each process hosts. Of
// the grids of processes that fit the boxes, the one whose walls between processes the
// pilot's rays cross least (a crossing inside a process is a hand-over in memory; between
// processes, a message: 4x4x4 boxes over 8 processes in blocks of 2x1x4 took 0.98 s on
// the demo scene, in 2x2x2 blocks 1.10 s). Sets space.process_grid and returns the words
// for --explain; leaves it with a single candidate or where walls_by_traffic would not
// run the pilot.
std::string owners_by_traffic(const Scene& scene, const VirtualWalls& walls,
                              const DistributionRequest& request, int workers,
                              SpaceOptions& space) {
    const std::array<int, 3> slabs = walls.slabs();
    std::vector<std::array<int, 3>> grids;
    for (const std::array<int, 3>& g : box_grids(workers)) {
        if (g[0] <= slabs[0] && g[1] <= slabs[1] && g[2] <= slabs[2]) grids.push_back(g);
    }
    if (grids.size() < 2) return "";
    const std::optional<Pilot> pilot = traffic_pilot(scene, request);
    if (!pilot) return "";
    const std::vector<PilotSegment>& segments = pilot->segments;
    const std::vector<ObjectExtent>& extents = pilot->extents;
    // A process's block is boxes [ceil(i S / g), ceil((i + 1) S / g)) on an axis of S
    // slabs cut in g (box_owners): the walls between processes are those at the blocks'
    // first boxes.
    auto between_processes = [&](const std::array<int, 3>& g) {
        std::array<std::vector<Real>, 3> w;
        for (int a = 0; a < 3; ++a) {
            for (int i = 1; i < g[a]; ++i) {
                const int first = (i * slabs[a] + g[a] - 1) / g[a];
                w[size_t(a)].push_back(walls.walls(a)[size_t(first - 1)]);
            }
        }
        return VirtualWalls(std::move(w));
    };
    uint64_t best = UINT64_MAX;
    std::array<int, 3> chosen{};
    for (const std::array<int, 3>& g : grids) {
        const uint64_t n = estimated_crossings(segments, between_processes(g), extents);
        if (n < best) best = n, chosen = g;
    }
    space.process_grid = chosen;
    return "; processes hold blocks of " + std::to_string(slabs[0] / chosen[0]) + "x" +
           std::to_string(slabs[1] / chosen[1]) + "x" +
           std::to_string(slabs[2] / chosen[2]) + " boxes (" + std::to_string(chosen[0]) +
           "x" + std::to_string(chosen[1]) + "x" + std::to_string(chosen[2]) +
           " processes), cut across the least ray traffic: " + std::to_string(best) +
           " crossings between processes for " + std::to_string(segments.size()) +
           " pilot ray segments";
}

// The cores this process may run on.
int available_cores() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

DistributionPlan plan_distribution(const Scene& scene,
                                   const DistributionRequest& request) {
    DistributionPlan plan;
    plan.threads = request.threads > 0
                       ? request.threads
                       : int(std::max(1u, std::thread::hardware_concurrency()));
    if (request.teams > 1) {
        const int given = request.workers > 0 ? request.workers : request.procs;
        if (request.boxes.empty() || given <= 0 || request.mode == RenderMode::Single ||
            request.mode == RenderMode::Screen)
            throw DistributionError("--teams needs --boxes and --procs or --workers");
        if (request.teams > 1 && given % request.teams != 0)
            throw DistributionError("--teams " + std::to_string(request.teams) +
                                    " does not divide the " + std::to_string(given) +
                                    " workers into equal teams");
    }
    plan.worker_memory = request.worker_memory;
    size_t machine_half = size_t(1) << 31;
    if (long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
        pages > 0 && page > 0)
        machine_half = size_t(pages) * size_t(page) / 2;
    if (plan.worker_memory == 0) plan.worker_memory = machine_half;
    ObjectSizes sizes;
    for (const Object& o : scene.objects) {
        sizes.bounds.push_back(trace::object_world_bounds(o));
        sizes.prepared.push_back(trace::estimate_prepared_bytes(o));
        sizes.model.push_back(trace::estimate_model_bytes(o));
        plan.prepared_bytes += sizes.prepared.back();
        plan.scene_bytes += sizes.prepared.back() + sizes.model.back();
    }
    const std::string budget = format_bytes(plan.worker_memory);
    const std::string size = format_bytes(plan.scene_bytes);
    const std::string threads =
        std::to_string(plan.threads) + " thread" + (plan.threads == 1 ? "" : "s");

    const bool fits = plan.scene_bytes <= plan.worker_memory;
    if (request.mode == RenderMode::Screen ||
        (request.mode == RenderMode::Auto && request.boxes.empty() && fits &&
         request.procs > 0)) {
        plan.mode = RenderMode::Screen;
        plan.procs = request.procs > 0 ? request.procs : plan.threads;
        plan.reasons.push_back(
            (request.mode == RenderMode::Screen
                 ? std::string("--mode screen")
                 : "scene " + size + " fits the " + budget + " worker budget") +
            ": screen subdivision, " + std::to_string(plan.procs) +
            " worker processes each hold the whole scene and take tiles as they finish");
        return plan;
    }
    if (request.mode == RenderMode::Single ||
        (request.mode == RenderMode::Auto && request.boxes.empty() && fits)) {
        plan.mode = RenderMode::Single;
        plan.reasons.push_back(
            (request.mode == RenderMode::Single
                 ? "--mode single"
                 : "scene " + size + " fits the " + budget + " worker budget") +
            std::string(": one process, no walls; ") + threads +
            " take render blocks as they finish (screen subdivision, one shared scene)");
        return plan;
    }
    if (const auto& rad = scene.settings.radiosity) {
        // The irradiance cache is filled by rays through the whole scene and read
        // everywhere; black boxes hold parts of the scene.
        throw UnsupportedInMode(located(scene, rad->loc) +
                                "error: unsupported: radiosity with space subdivision "
                                "(black boxes hold parts of the scene; the irradiance "
                                "cache needs the whole): use --mode single or screen");
    }
    if (const auto& sss = scene.settings.subsurface) {
        // Its rays sample the object's whole surface from inside the shading.
        throw UnsupportedInMode(located(scene, sss->loc) +
                                "error: unsupported: subsurface with space subdivision "
                                "(black boxes hold parts of the scene; its samples need "
                                "the whole object): use --mode single or screen");
    }
    plan.mode = RenderMode::Space;
    // Worker processes: those asked for; in auto mode, as many as the budget needs (a
    // scene over the budget cannot be in one process, this one included).
    const int given = request.workers > 0 ? request.workers : request.procs;
    // A budget below an empty worker (process, fewest rays in flight, image sums) cannot
    // be met by more boxes: then the first box count whose boxes fit is taken.
    const size_t empty_worker =
        with_margin(kWorkerProcessBytes + kMinRaysInFlight * kRayInFlightBytes +
                    request.pixels * (kPixelBytesPerThread + kPixelBytesAtEnd));
    const bool workers_can_fit = plan.worker_memory > empty_worker;
    // Local worker processes for these boxes: `given`, else the fewest (at most one box
    // each, at most kMaxAutoWorkers) whose largest worker fits; false when none fits.
    // Teams (SpaceOptions::teams): each of `teams` groups of the workers hosts every box;
    // a team's `team_size` workers share the boxes out.
    int teams = 1;
    auto team_size = [&] { return given > 0 ? given / teams : 0; };
    auto fit_workers = [&](const Overlaps& ov) {
        // Below an empty worker no count fits: one per core then.
        int k = given > 0         ? team_size()
                : workers_can_fit ? 1
                                  : std::min(ov.boxes, plan.threads);
        plan.largest_worker_bytes =
            largest_worker(sizes, ov, k, request.pixels, request.threads);
        while (given == 0 && workers_can_fit &&
               plan.largest_worker_bytes > plan.worker_memory &&
               k < std::min(ov.boxes, kMaxAutoWorkers)) {
            plan.largest_worker_bytes =
                largest_worker(sizes, ov, ++k, request.pixels, request.threads);
        }
        plan.procs = request.workers > 0 ? 0 : given > 0 ? given : k;
        return plan.largest_worker_bytes <= plan.worker_memory;
    };
    auto over_processes = [&](const Overlaps& ov) {
        fit_workers(ov);
        // Rays in flight may pile up in one worker: as many as its room allows.
        const size_t room = plan.worker_memory > plan.largest_worker_bytes
                                ? plan.worker_memory - plan.largest_worker_bytes
                                : 0;
        plan.space.max_rays_in_flight =
            std::clamp(kMinRaysInFlight + room / kRayInFlightBytes, kMinRaysInFlight,
                       plan.space.max_rays_in_flight);
        const int k = request.workers > 0 ? request.workers : plan.procs;
        std::string text = " over " + std::to_string(k) +
                           (request.workers > 0 ? " running" : "") + " worker process" +
                           (k == 1 ? "" : "es");
        if (teams > 1)
            text += " in " + std::to_string(teams) + " teams of " +
                    std::to_string(team_size()) + " (each team hosts every box)";
        text += ", largest worker " + format_bytes(plan.largest_worker_bytes);
        if (!workers_can_fit)
            text +=
                " (over budget: a worker alone needs " + format_bytes(empty_worker) + ")";
        else if (plan.largest_worker_bytes > plan.worker_memory)
            text += given > 0 ? " (over budget: more workers would hold less each)"
                              : " (still over budget)";
        return text;
    };
    if (!request.boxes.empty()) {
        // Walls and owners for the current team size; for --teams auto, the most teams
        // (of at least 2 workers, so the scene stays cut between processes) whose
        // largest worker fits the budget.
        std::vector<int> candidates;
        if (request.teams == 0) {
            for (int t = given / 2; t >= 1; --t)
                if (given % t == 0) candidates.push_back(t);
            if (candidates.empty()) candidates.push_back(1);
        } else {
            candidates.push_back(std::max(1, request.teams));
        }
        std::string traffic;
        VirtualWalls walls;
        Overlaps ov;
        const int cores = request.cores > 0 ? request.cores : available_cores();
        const bool crowded = request.workers == 0 && given > cores;
        for (int t : candidates) {
            teams = t;
            plan.space = parse_boxes(request.boxes);
            plan.space.teams = teams;
            traffic.clear();
            if (request.boxes == "auto" && team_size() > 1)
                traffic = walls_by_traffic(scene, sizes.bounds, request, team_size(),
                                           plan.space);
            walls = walls_for(sizes.bounds, plan.space);
            // Only local processes that outnumber the cores: they take turns on them, so
            // what they do in all counts, not how it is shared out. Where each has a
            // core (or a host) of its own, the cuts across the view share the picture
            // out evenly; the least crossed cut may not (2x2x2 over 2 processes on 2
            // cores: 0.77 s cut across the view, 0.89 s cut along it, the least
            // crossed).
            if (request.boxes != "auto" && crowded)
                traffic =
                    owners_by_traffic(scene, walls, request, team_size(), plan.space);
            ov = overlaps_of(sizes, walls, scene.camera.direction);
            ov.grid = plan.space.process_grid;
            if (request.teams != 0 || t == candidates.back()) break;
            // Each worker within the budget, and local workers together within half of
            // this machine's memory (each team holds the whole scene).
            const size_t largest =
                largest_worker(sizes, ov, team_size(), request.pixels, request.threads);
            if (largest <= plan.worker_memory &&
                (request.workers > 0 || largest * size_t(given) <= machine_half))
                break;
        }
        if (crowded && request.keep_on_cores && cores > 1 &&
            given <= kMaxProcessesOnCores) {
            plan.space.keep_on_cores = cores;
            traffic +=
                "; once a quarter of the image is out, each process is kept on one "
                "of the " +
                std::to_string(cores) +
                " cores, its measured work balanced, with those it sends most rays";
        }
        plan.largest_box_bytes = largest_box(sizes, ov);
        const auto& b = plan.space.boxes;
        plan.reasons.push_back(
            "--boxes " + request.boxes + ": space subdivision, " + std::to_string(b[0]) +
            "x" + std::to_string(b[1]) + "x" + std::to_string(b[2]) +
            (plan.space.balanced ? " balanced" : "") + " boxes, largest local scene " +
            format_bytes(plan.largest_box_bytes) +
            (given > 0 ? over_processes(ov) : std::string()) + traffic);
        return plan;
    }
    // The fewest balanced boxes whose largest local scene fits the budget and, in auto
    // mode, whose boxes some number of workers can host within it.
    const bool with_workers = given > 0 || request.mode == RenderMode::Auto;
    Overlaps ov;
    for (int n = 1; n <= 16; ++n) {
        SpaceOptions s;
        s.boxes = {n, n, n};
        s.balanced = true;
        plan.space = s;
        ov = overlaps_of(sizes, walls_for(sizes.bounds, s), scene.camera.direction);
        plan.largest_box_bytes = largest_box(sizes, ov);
        if (plan.largest_box_bytes > plan.worker_memory) continue;
        if (!with_workers || given > 0 || !workers_can_fit || fit_workers(ov)) break;
    }
    const auto& b = plan.space.boxes;
    const std::string why =
        request.mode == RenderMode::Space
            ? std::string("--mode space")
            : "scene " + size + " exceeds the " + budget + " worker budget";
    plan.reasons.push_back(why + ": space subdivision, " + std::to_string(b[0]) + "x" +
                           std::to_string(b[1]) + "x" + std::to_string(b[2]) +
                           " balanced boxes, largest local scene " +
                           format_bytes(plan.largest_box_bytes) +
                           (plan.largest_box_bytes <= plan.worker_memory
                                ? ""
                                : " (still over budget: objects larger than a box)") +
                           (with_workers ? over_processes(ov) : std::string()));
    return plan;
}

}  // namespace povwall::distrib
