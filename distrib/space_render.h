// Space subdivision: virtual walls cut the scene into black boxes; each box holds only
// the objects that overlap it, traces the rays crossing its region, and forwards rays
// that leave it to the neighbouring box. Shading is trace/shading.h's
// spawn_children/combine_children.
//
// Two ways to return colours, chosen per scene (see RenderPlan):
//  - forward contributions: each ray carries the factor from its colour to the pixel, so
//  a
//    hit adds its local colour straight to the pixel and no parent waits (linear
//    shading);
//  - parent tracking: a hit parks its shading record in the box's ParentTable until the
//    children's results come back (needed for reflection exponents).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "distrib/virtual_walls.h"
#include "distrib/work_queue.h"
#include "trace/render.h"
#include "trace/render_plan.h"
#include "trace/tracer.h"

namespace povwall::distrib {

struct SpaceOptions {
    std::array<int, 3> boxes{1, 1, 1};
    bool balanced = false;  // walls at object quantiles instead of equal slabs
    enum class Results { Auto, Forward, Parents } results = Results::Auto;
    QueuePolicy queue = QueuePolicy::Priority;
    // Flow control: camera rays wait while this many queued items are in flight. 8,192
    // rather than 65,536: over TCP with 8 local workers the longer queues cost 30 % of
    // the render (7.3-8.2 s against 5.0-5.6 s, walls.pov 600x600 --boxes 4x4x4 --procs
    // 8).
    size_t max_rays_in_flight = 1 << 13;
    // A ray or result for a box of this process that no thread is working on is
    // processed at once by the thread that made it, instead of through the box's inbox
    // and queue (up to 8 boxes deep). Off (no command-line switch yet): every item goes
    // through the queues, so that the queue order (`--queue`) decides all of the work.
    bool direct_handoff = true;
    // How worker processes share the boxes: blocks of this grid of processes (x, y, z),
    // chosen for the least ray traffic between processes (plan_distribution); zeros:
    // box_owners' own cuts.
    std::array<int, 3> process_grid{0, 0, 0};
    // Local worker processes that outnumber these cores (2 or more): once a quarter of
    // the image is out, the coordinator keeps each on one of them by the work and the
    // traffic it has measured (core_groups). 0: the system places them.
    int keep_on_cores = 0;
    // Worker processes in this many teams, each team hosting every box (its workers
    // share them out as box_owners says), camera ranges handed to the teams in turn: a
    // ray then crosses only the walls between the processes of one team. Each worker
    // holds more of the scene, and rays between processes fall (--teams).
    int teams = 1;
};

struct BoxStats {
    Bounds3 region;
    size_t objects = 0;
    size_t resident_bytes = 0;  // estimate of the local scene
    trace::TraceCounters rays;
    uint64_t rays_received = 0, results_received = 0, messages_sent = 0;
    // Messages are items between boxes (in this process or over TCP); bytes are
    // sizeof(Item) in process and the encoded record over TCP.
    uint64_t messages_received = 0, bytes_sent = 0, bytes_received = 0;
    size_t peak_queue = 0, peak_parents = 0;
    // Busy: the box's queued items being processed (an item handed over directly counts
    // toward the box whose thread handed it over); idle: the rest of the wall time.
    double busy_seconds = 0, idle_seconds = 0;

    // How two reports of a box combine: counts add up (a box's lanes, and its copies in
    // each team), times add up over copies, peaks are the largest, sizes any copy's.
    enum class Combine { Count, Time, Peak, Size };
    // Every field but the region and the rays (TraceCounters, named on their own), by its
    // name in --stats and in the workers' "done" message, the same field of `a` and `b`
    // at a time: the JSON and the additions (distrib/stats_json.h) all read this list.
    template <class A, class B, class Visit>
    static void visit_pairs(A& a, B& b, Visit&& v) {
        v("objects", a.objects, b.objects, Combine::Size);
        v("resident_bytes", a.resident_bytes, b.resident_bytes, Combine::Size);
        v("rays_received", a.rays_received, b.rays_received, Combine::Count);
        v("results_received", a.results_received, b.results_received, Combine::Count);
        v("messages_sent", a.messages_sent, b.messages_sent, Combine::Count);
        v("messages_received", a.messages_received, b.messages_received, Combine::Count);
        v("bytes_sent", a.bytes_sent, b.bytes_sent, Combine::Count);
        v("bytes_received", a.bytes_received, b.bytes_received, Combine::Count);
        v("peak_queue", a.peak_queue, b.peak_queue, Combine::Peak);
        v("peak_waiting_parents", a.peak_parents, b.peak_parents, Combine::Peak);
        v("busy_seconds", a.busy_seconds, b.busy_seconds, Combine::Time);
        v("idle_seconds", a.idle_seconds, b.idle_seconds, Combine::Time);
    }
};

struct SpaceStats {
    bool parent_tracking = false;
    std::vector<BoxStats> boxes;
    double seconds = 0;
    // Over TCP: each worker process's peak resident memory in bytes (its parse
    // included), and how many of the scene's objects it kept (those overlapping its
    // boxes) and left out while parsing.
    std::vector<uint64_t> worker_peak_resident;
    std::vector<size_t> worker_objects_kept, worker_objects_left_out;
    // Local workers kept on cores (SpaceOptions::keep_on_cores): each one's core
    // group; empty when the system placed them.
    std::vector<int> worker_cores;
    int teams = 1;  // SpaceOptions::teams as used (fewer after a lost worker)
    // Anti-aliasing: the camera samples traced in each wave (trace/sample_waves.h).
    std::vector<size_t> wave_samples;
};

using trace::shading_is_linear;  // trace/render_plan.h

// The image from per-pixel sums of r, g, b, and with `alpha` (+UA) background transmit,
// from which alpha comes: 3 or 4 values per pixel.
Image image_from_sums(std::span<const double> sums, int width, int height, bool alpha);
// A camera sample's rgbt from its sums (3 or 4 values, as image_from_sums), as
// trace::CameraSamples gives it: transmit clamped with `alpha`, else 0; (0, 0, 0, 1)
// without a camera ray.
void sample_colour(const double* sums, bool alpha, bool camera_ray, float* rgbt);

// `plan`: the scene's render plan when the caller made it already (else made here).
Image render_space(const Scene& scene, const trace::RenderSettings& settings,
                   const SpaceOptions& options, SpaceStats* stats = nullptr,
                   const trace::RenderPlan* plan = nullptr);

}  // namespace povwall::distrib
