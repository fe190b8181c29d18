#include "distrib/distribution_plan.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include "trace/prepared_scene.h"
#include "trace/render_plan.h"

namespace povwall::distrib {

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

// Largest estimated local scene over the boxes of `space`'s walls.
size_t largest_box(const Scene& scene, const std::vector<Bounds3>& bounds,
                   const std::vector<size_t>& bytes, const SpaceOptions& space) {
    Bounds3 world;
    std::vector<Bounds3> finite;
    for (const Bounds3& b : bounds) {
        if (b.infinite()) continue;
        world.extend(b.lo);
        world.extend(b.hi);
        finite.push_back(b);
    }
    (void)scene;
    const auto& n = space.boxes;
    VirtualWalls walls = space.balanced ? VirtualWalls::balanced(finite, n[0], n[1], n[2])
                                        : VirtualWalls::uniform(world, n[0], n[1], n[2]);
    // Each box also keeps its own prepared-scene header and octree root.
    std::vector<size_t> per_box(walls.box_count(), sizeof(trace::PreparedScene) + 256);
    for (size_t i = 0; i < bounds.size(); ++i) {
        for (int b : walls.boxes_overlapping(bounds[i])) per_box[b] += bytes[i];
    }
    return *std::max_element(per_box.begin(), per_box.end());
}

}  // namespace

DistributionPlan plan_distribution(const Scene& scene,
                                   const DistributionRequest& request) {
    DistributionPlan plan;
    plan.threads = request.threads > 0
                       ? request.threads
                       : int(std::max(1u, std::thread::hardware_concurrency()));
    plan.worker_memory = request.worker_memory;
    if (plan.worker_memory == 0) {
        long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
        plan.worker_memory =
            pages > 0 && page > 0 ? size_t(pages) * size_t(page) / 2 : size_t(1) << 31;
    }
    std::vector<Bounds3> bounds;
    std::vector<size_t> bytes;
    for (const Object& o : scene.objects) {
        bounds.push_back(trace::object_world_bounds(o));
        bytes.push_back(trace::estimate_prepared_bytes(o));
        plan.scene_bytes += bytes.back();
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
            " take image rows as they finish (screen subdivision, one shared scene)");
        return plan;
    }
    plan.mode = RenderMode::Space;
    if (!request.boxes.empty()) {
        plan.space = parse_boxes(request.boxes);
        plan.largest_box_bytes = largest_box(scene, bounds, bytes, plan.space);
        const auto& b = plan.space.boxes;
        plan.reasons.push_back(
            "--boxes " + request.boxes + ": space subdivision, " + std::to_string(b[0]) +
            "x" + std::to_string(b[1]) + "x" + std::to_string(b[2]) +
            (plan.space.balanced ? " balanced" : "") + " boxes, largest local scene " +
            format_bytes(plan.largest_box_bytes));
        return plan;
    }
    // The fewest balanced boxes whose largest local scene fits the budget.
    for (int n = 1; n <= 16; ++n) {
        SpaceOptions s;
        s.boxes = {n, n, n};
        s.balanced = true;
        plan.space = s;
        plan.largest_box_bytes = largest_box(scene, bounds, bytes, s);
        if (plan.largest_box_bytes <= plan.worker_memory) break;
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
                                : " (still over budget: objects larger than a box)"));
    return plan;
}

}  // namespace povwall::distrib
