#include "distrib/space_render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <new>
#include <thread>

#include "core/memory.h"
#include "distrib/box_host.h"
#include "distrib/object_boxes.h"
#include "distrib/shared_pixel_sums.h"
#include "distrib/stats_json.h"
#include "trace/camera.h"
#include "trace/forward_sum.h"
#include "trace/sample_waves.h"
#include "trace/shading.h"

namespace povwall::distrib {

using Clock = std::chrono::steady_clock;
using trace::TraceResult;

namespace {
// The worker thread running on this OS thread: its index (for its pixel sums and box
// lanes), how many direct hand-overs deep it is, and the rays it traced since it last
// added them to the progress line.
struct WorkerThread {
    int index = 0;
    int depth = 0;
    uint64_t rays = 0;
};
thread_local WorkerThread tl_worker;
// Each level is one item traced inside another's processing (a child in its parent's
// box; with parent tracking also a ray crossing into a free box): enough for a ray tree
// of POV-Ray's default depth; deeper items go through the queues.
constexpr int kMaxHandoffDepth = 24;

// The calling worker thread's lane of `box`.
Box::Lane& lane(Box& box) { return box.lanes[size_t(tl_worker.index)]; }

// An item passed from box `from` to box `to` in this process, in both boxes' counters.
void count_message(Box& from, Box& to) {
    BoxStats& out = lane(from).stats;
    ++out.messages_sent, out.bytes_sent += sizeof(Item);
    BoxStats& in = lane(to).stats;
    ++in.messages_received, in.bytes_received += sizeof(Item);
}
}  // namespace

BoxHost::BoxHost(const Scene& scene, const trace::RenderSettings& settings,
                 const SpaceOptions& options, const trace::RenderPlan* plan)
    : scene_(scene),
      settings_(settings),
      options_(options),
      plan_(plan ? *plan
                 : trace::make_render_plan(scene, settings.plan_everything_on,
                                           settings.quality)),
      camera_interiors_(scene) {
    parents_ =
        options.results == SpaceOptions::Results::Parents ||
        (options.results == SpaceOptions::Results::Auto && plan_.parent_tracking) ||
        plan_.parents_required;
    shared_boxes_ = !parents_ && options.direct_handoff;
    total_pixels_ = settings.width * settings.height;
    sum_channels_ = settings.alpha ? 4 : 3;
    if (trace::FocalBlur::enabled(scene.camera)) {
        trace::PatternEnv env;  // as trace::PreparedScene makes it (for a bokeh pigment)
        env.noise_generator = scene.settings.noise_generator;
        env.number_of_waves = scene.settings.number_of_waves;
        env.quick_colours = plan_.quality.quick_colours();
        blur_ = std::make_unique<trace::FocalBlur>(scene.camera, env);
    }
}

void BoxHost::sleep_until_work() {
    std::unique_lock<std::mutex> lock(idle_mutex_);
    sleepers_.fetch_add(1);
    bool work = stop_.load();
    for (size_t b = 0; b < boxes_.size() && !work; ++b)
        work = boxes_[b]->pending.load() > 0;
    // The timeout only bounds a wake-up lost to a future change; none is expected.
    if (!work) idle_cv_.wait_for(lock, std::chrono::milliseconds(20));
    sleepers_.fetch_sub(1);
}

void BoxHost::push(Box* current, int dest, Item&& item) {
    Box& d = *boxes_[dest];
    // `created_` counts the items that go through a queue, an inbox or another process
    // (and `finished_` those processed from a queue): an item traced at once is made
    // and finished in one call, and one shared counter for every item kept the two
    // threads' caches busy passing its line back and forth.
    if (!d.scene) {  // hosted by another process
        created_.fetch_add(1, std::memory_order_relaxed);
        const size_t bytes = remote(dest, std::move(item));
        if (current) {
            BoxStats& st = lane(*current).stats;
            ++st.messages_sent, st.bytes_sent += bytes;
        }
        return;
    }
    const bool stays = current == &d;
    const bool nest = options_.direct_handoff && tl_worker.depth < kMaxHandoffDepth;
    // Trace the item now, depth first, in this thread: no trip through a queue (most
    // children stay in the box that made them), no inbox lock, no copies of the item.
    auto trace_here = [&] {
        if (current && !stays) {
            count_message(*current, d);
        } else if (!current) {  // a camera ray from the emitter
            BoxStats& st = lane(d).stats;
            ++st.messages_received, st.bytes_received += sizeof(Item);
        }
        ++tl_worker.depth;
        process(d, item, tl_worker.index);
        --tl_worker.depth;
        if (on_processed) on_processed();
    };
    if (shared_boxes_) {
        // Nothing waits in a box: any thread traces in any box, each in its own lane.
        if (nest) return trace_here();
    } else if (stays || d.holder.load(std::memory_order_relaxed) == tl_worker.index) {
        // This thread holds the box (the current one, or one that an item further up
        // this thread's stack is traced in; a ray that crosses back comes home).
        if (nest) return trace_here();
        if (current && !stays) count_message(*current, d);
        created_.fetch_add(1, std::memory_order_relaxed);
        const bool is_result = item.is_result;
        const int depth = is_result ? 255 : item.ray.trace.depth;
        d.queue.push(std::move(item), is_result, depth);
        d.stats.peak_queue = std::max(d.stats.peak_queue, d.queue.size());
        d.pending.fetch_add(1, std::memory_order_release);
        return;
    } else if (nest && !d.busy.exchange(true, std::memory_order_acquire)) {
        // Nobody holds the destination: hold it while the item is traced.
        d.holder.store(tl_worker.index, std::memory_order_relaxed);
        trace_here();
        d.holder.store(-1, std::memory_order_relaxed);
        d.busy.store(false, std::memory_order_release);
        return;
    }
    if (current) {  // received when the box drains its inbox
        BoxStats& st = lane(*current).stats;
        ++st.messages_sent, st.bytes_sent += sizeof(Item);
    }
    created_.fetch_add(1, std::memory_order_relaxed);
    {
        std::lock_guard<std::mutex> lock(d.inbox_mutex);
        d.inbox.push_back(std::move(item));
        d.inbox_bytes += sizeof(Item);
    }
    d.pending.fetch_add(1);
    wake_idle();
}

// The box a ray leaving `current` for `dest` goes on in at once, in this thread, with the
// crossing counted as a message: with forward contributions any thread traces in any box
// it hosts. Null when the ray must go through push() (parent tracking, another process).
Box* BoxHost::go_on_in(Box& current, int dest) {
    if (!shared_boxes_) return nullptr;
    Box& d = *boxes_[size_t(dest)];
    if (!d.scene) return nullptr;
    count_message(current, d);  // a crossing: never into the box it leaves
    ++lane(d).stats.rays_received;
    ++tl_worker.rays;
    if (on_processed) on_processed();
    return &d;
}

void BoxHost::deliver(Box& box, const RayItem& ray, const TraceResult& result,
                      int thread) {
    if (!parents_) {
        // Forward contributions: the result lands on the pixel with the factor it
        // carries.
        add_pixel(thread, ray.pixel, ray.contribution * result.colour,
                  ray.shadow ? 0.0f : ray.transmit_contribution * result.transmit);
        return;
    }
    if (ray.parent ==
        0) {  // a camera ray's colour: the pixel (set once, so the sum is it)
        add_pixel(thread, ray.pixel, result.colour, result.transmit);
        return;
    }
    Item item;
    item.is_result = true;
    item.result = {ray.parent, ray.slot, result};
    push(&box, ray.parent_box, std::move(item));
}

void BoxHost::process_ray(Box& entry, Item& item, int thread) {
    RayItem& ray = item.ray;
    const GlobalSettings& g = scene_.settings;
    // A ray that leaves a box goes on as this same item (no copy of its 300-odd bytes):
    // into a box this thread may trace in at once by going round this loop again (no
    // recursion: a ray crossing many boxes does not deepen the stack), else by push().
    Box* in = &entry;
    auto leave = [&](int dest) {
        if (Box* d = go_on_in(*in, dest)) {
            in = d;
            return true;
        }
        push(in, dest, std::move(item));
        return false;
    };
    for (;;) {
        Box& box = *in;
        // The walk along the walls goes on from where the box that sent the ray left it;
        // a ray without one (new over TCP) walks from t_from.
        VirtualWalls::Segment seg;
        int next;
        VirtualWalls::WalkState& at = ray.route_walk;
        if (ray.route_box == box.index) {
            route(ray.trace.ray, at, seg, next);
        } else {
            first_box(ray.trace.ray, ray.t_from, seg, next, at);
        }
        // `at` is at the next box's segment now: the ray goes there with it.
        ray.route_box = next;
        if (seg.box != box.index) {  // a tie on a wall sent it here: pass it on unchanged
            ray.route_box = -1;
            if (leave(seg.box)) continue;
            return;
        }
        if (ray.shadow) {
            bool blocked = trace::shadow_segment(*box.scene, ray.trace.ray, seg.t_exit,
                                                 ray.light_distance, ray.shadow_state,
                                                 lane(box).ctx);
            if (blocked || next < 0 || seg.t_exit >= ray.light_distance - 1e-3) {
                if (!blocked)
                    trace::shadow_last_leg(*box.scene, ray.trace.ray, ray.light_distance,
                                           ray.shadow_state);
                deliver(box, ray, {ray.shadow_state.filter, 0}, thread);
                return;
            }
            ray.t_from = seg.t_exit;
            if (leave(next)) continue;
            return;
        }
        Box::Lane& here = lane(box);
        // A refused ray is black and opaque (max_trace_level, adc_bailout).
        if (trace::refuse_ray(ray.trace, g, here.stats.rays)) {
            deliver(box, ray, {}, thread);
            return;
        }
        if (!ray.counted) {
            ray.counted = true;
            trace::count_ray(ray.trace, here.stats.rays);
        }
        trace::Hit hit;
        // One record per nesting level: a child traced at once reuses the box. Sized
        // once, before any level holds a reference into it.
        if (here.records.empty()) here.records.resize(kMaxHandoffDepth + 1);
        trace::ShadingRecord& rec = here.records[size_t(tl_worker.depth)];
        if (!box.scene->closest_hit(ray.trace.ray, ray.t_from, seg.t_exit, ray.trace.use,
                                    hit, here.ctx, false, next >= 0 ? kInfinity : -1)) {
            if (next >= 0) {
                ray.t_from = seg.t_exit;
                if (leave(next)) continue;
                return;
            }
            // A scattering atmosphere lights the missed ray's media samples with shadow
            // rays: a parent like a hit's.
            if (!parents_ || !trace::spawn_miss(*box.scene, ray.trace, rec)) {
                deliver(box, ray, trace::miss_colour(*box.scene, ray.trace), thread);
                return;
            }
        } else {
            trace::spawn_children(*box.scene, ray.trace, hit, rec);
        }
        const size_t n = rec.children.size();
        uint64_t id = 0;
        // Result slots: an area-light shadow child takes one per grid sample, after the
        // children's own slots. (Children may be traced at once, in this thread, and
        // come back here: nothing of this hit is kept in thread-wide scratch.)
        auto area_child = [&](const trace::ChildRay& c) {
            return parents_ && c.kind == trace::ChildRay::Kind::Shadow && c.area &&
                   !c.unoccluded;
        };
        std::vector<uint32_t> first_slot;
        uint32_t slots = uint32_t(n);
        int pending = int(n);  // results to wait for (an area child's own slot gets none)
        if (parents_) {
            for (size_t i = 0; i < n; ++i) {
                if (!area_child(rec.children[i])) continue;
                if (first_slot.empty()) {
                    for (uint32_t k = 0; k < n; ++k) first_slot.push_back(k);
                }
                first_slot[i] = slots;
                const auto samples =
                    uint32_t(trace::AreaGrid(scene_, rec.children[i]).samples());
                slots += samples;
                pending += int(samples) - 1;
            }
            if (slots > 65535)
                throw std::runtime_error(
                    "a point's area-light grids and media shadow rays are more than "
                    "65,535");
        }
        if (parents_) {
            if (n == 0) {
                deliver(box, ray, trace::combine_children(rec, nullptr), thread);
                return;
            }
            id = ++box.next_id;
            WaitingParent w;
            w.record = rec;
            w.results.resize(slots);
            w.first_slot = std::move(first_slot);
            w.origin = ray;
            box.parents.park(id, std::move(w), pending);
            box.stats.peak_parents = std::max(box.stats.peak_parents, box.parents.size());
        } else {
            // Fog along this ray is affine (add + mul x colour): its added part goes to
            // the pixel now, its factor into every child's contribution.
            const trace::FogEffect& fog = rec.fog;
            add_pixel(thread, ray.pixel,
                      ray.contribution * (fog.add + fog.mul * rec.local),
                      ray.transmit_contribution * fog.add_transmit);
        }
        uint32_t next_area_slot = uint32_t(n);
        for (size_t i = 0; i < n; ++i) {
            const trace::ChildRay& c = rec.children[i];
            Item child_item;
            RayItem& child = child_item.ray;
            child.trace = c.trace;
            child.shadow = c.kind == trace::ChildRay::Kind::Shadow;
            child.light_distance = c.t_max;
            if (child.shadow) {
                // As point_shadow() starts it in the single-process tracer.
                child.shadow_state.inside = c.trace.interiors;
                child.shadow_state.light = c.light;
                child.shadow_state.photon_caustics = c.photon_caustics;
                child.shadow_state.volume =
                    trace::sees_volume(box.scene->scene(), c.trace);
            }
            child.pixel = ray.pixel;
            if (parents_) {
                child.parent = id;
                child.parent_box = box.index;
                child.slot = uint16_t(i);
            } else {
                child.contribution = ray.contribution * rec.fog.mul * c.coeff;
                child.transmit_contribution =
                    c.kind == trace::ChildRay::Kind::Transmission
                        ? ray.transmit_contribution * rec.fog.mul_transmit *
                              c.transmit_factor
                        : 0.0f;
            }
            if (c.unoccluded) {  // the plan proved nothing can block it: no message
                deliver(box, child, {Rgb(1.0f), 0}, thread);
                continue;
            }
            if (area_child(c)) {
                // An area light: a shadow ray to each sample of its grid.
                const trace::AreaGrid grid(scene_, c);
                uint32_t slot = next_area_slot;
                next_area_slot += uint32_t(grid.samples());
                for (int u = 0; u < grid.n1; ++u) {
                    for (int v = 0; v < grid.n2; ++v, ++slot) {
                        Item sample_item = child_item;
                        RayItem& sample = sample_item.ray;
                        sample.slot = uint16_t(slot);
                        Real d = 0;
                        if (!grid.sample_ray(u, v, sample.trace.ray, d)) {
                            deliver(box, sample, {Rgb(1.0f), 0}, thread);
                            continue;
                        }
                        sample.light_distance = d;
                        ++here.stats.rays.shadow;
                        const int dest = enter(sample.trace.ray, 0, sample.route_walk);
                        sample.route_box = dest;
                        push(&box, std::max(dest, 0), std::move(sample_item));
                    }
                }
                continue;
            }
            if (child.shadow) ++here.stats.rays.shadow;
            const int dest = enter(child.trace.ray, 0, child.route_walk);
            child.route_box = dest;
            push(&box, std::max(dest, 0), std::move(child_item));
        }
        return;
    }
}

void WaitingParent::gather(const Scene& scene,
                           std::vector<trace::TraceResult>& out) const {
    const size_t n = record.children.size();
    if (first_slot.empty()) {
        out.assign(results.begin(), results.begin() + ptrdiff_t(n));
        return;
    }
    out.resize(n);
    thread_local std::vector<Rgb> samples;
    for (size_t i = 0; i < n; ++i) {
        if (first_slot[i] == i) {
            out[i] = results[i];
            continue;
        }
        const trace::AreaGrid grid(scene, record.children[i]);
        samples.resize(grid.samples());
        for (size_t k = 0; k < samples.size(); ++k)
            samples[k] = results[first_slot[i] + k].colour;
        out[i] = {grid.average(samples.data()), 0};
    }
}

void BoxHost::process(Box& box, Item& item, int thread) {
    if (!item.is_result) {
        ++lane(box).stats.rays_received;
        ++tl_worker.rays;
        process_ray(box, item, thread);
        return;
    }
    ++lane(box).stats.results_received;
    const ResultItem& r = item.result;
    auto done = box.parents.deliver(r.parent, [&](WaitingParent& w) {
        if (r.slot < w.results.size())
            w.results[r.slot] = r.result;
        else
            bad_result_ = true;
    });
    if (done) {
        thread_local std::vector<TraceResult> results;
        done->gather(scene_, results);
        trace::replay_media(*box.scene, done->origin.trace, done->record, results.data());
        deliver(box, done->origin, trace::combine_children(done->record, results.data()),
                thread);
    }
}

int BoxHost::pixels_sent() const {
    int sent = 0;
    for (const PixelBand& b : bands_)
        sent += std::min(b.next.load(std::memory_order_relaxed), b.end) - b.begin;
    return sent;
}

void BoxHost::emit_camera_rays() {
    constexpr int kBatch = 256;
    while (created() - finished() < options_.max_rays_in_flight) {
        // The thread's own band first, then whatever is left of the others.
        int start = -1, end = 0;
        for (size_t k = 0; k < bands_.size() && start < 0; ++k) {
            PixelBand& band = bands_[(size_t(tl_worker.index) + k) % bands_.size()];
            if (band.next.load(std::memory_order_relaxed) >= band.end) continue;
            const int s = band.next.fetch_add(kBatch);
            if (s < band.end) start = s, end = std::min(band.end, s + kBatch);
        }
        if (start < 0) return;
        for (int p = start; p < end; ++p) {
            Item item;
            int box = camera_item(p, item);
            if (box >= 0) push(nullptr, box, std::move(item));
        }
        report_progress();
    }
}

bool BoxHost::work_on_a_box(int thread, bool emit_camera, size_t& start, bool send) {
    const size_t n = boxes_.size();
    for (size_t k = 0; k < n; ++k) {
        Box& box = *boxes_[(start + k) % n];
        if (box.pending.load(std::memory_order_acquire) == 0) continue;
        if (box.busy.exchange(true, std::memory_order_acquire)) continue;
        box.holder.store(thread, std::memory_order_relaxed);
        auto t0 = Clock::now();
        uint64_t done = 0;
        {
            // Swapped with a spare that keeps its capacity: no allocation per batch.
            std::vector<Item>& incoming = box.inbox_spare;
            {
                std::lock_guard<std::mutex> lock(box.inbox_mutex);
                incoming.swap(box.inbox);
                box.stats.bytes_received += box.inbox_bytes;
                box.inbox_bytes = 0;
            }
            box.stats.messages_received += incoming.size();
            if (shared_boxes_) {
                // Nothing waits in a box, so the order does not matter: traced
                // straight from the inbox, not copied through the queue.
                box.stats.peak_queue = std::max(box.stats.peak_queue, incoming.size());
                for (Item& it : incoming) {
                    process(box, it, thread);
                    ++done;
                    if (on_processed) on_processed();
                }
            } else {
                for (Item& it : incoming) {
                    const bool is_result = it.is_result;
                    const int depth = is_result ? 255 : it.ray.trace.depth;
                    box.queue.push(std::move(it), is_result, depth);
                }
                box.stats.peak_queue = std::max(box.stats.peak_queue, box.queue.size());
            }
            incoming.clear();
        }
        for (int budget = 0; budget < 4096 && !box.queue.empty(); ++budget) {
            Item it = box.queue.pop();
            process(box, it, thread);
            ++done;
            if (on_processed) on_processed();
        }
        // Counted once per batch: one atomic add per item on counters every thread
        // shares cost more than the queue. Late counts are safe: `finished` only
        // lags `created` (termination waits, flow control holds back a little more).
        box.pending.fetch_sub(done, std::memory_order_release);
        finished_.fetch_add(done, std::memory_order_acq_rel);
        report_progress();
        box.stats.busy_seconds +=
            std::chrono::duration<double>(Clock::now() - t0).count();
        box.holder.store(-1, std::memory_order_relaxed);
        box.busy.store(false, std::memory_order_release);
        if (send && flush) flush();
        start = (start + k + 1) % n;
        return true;
    }
    return false;
}

void BoxHost::worker(int thread, bool emit_camera) {
    tl_worker = {thread, 0, 0};
    size_t start = size_t(thread) * 7919 % std::max<size_t>(1, boxes_.size());
    for (;;) {
        if (emit_camera) emit_camera_rays();
        if (work_on_a_box(thread, emit_camera, start, !emit_camera)) continue;
        if (emit_camera) {
            if (pixels_sent() >= total_pixels_ && created() == finished()) return;
            std::this_thread::yield();
        } else {
            if (flush) flush();
            if (stop_.load()) return;
            sleep_until_work();
        }
    }
}

void BoxHost::drain() {
    tl_worker = {0, 0, 0};
    size_t start = 0;
    while (work_on_a_box(0, false, start, false)) {
    }
    if (flush) flush();
}

void BoxHost::report_progress() {
    if (!settings_.progress) return;
    settings_.progress->rays += tl_worker.rays;
    tl_worker.rays = 0;
    const uint64_t done =
        pixels_done_estimate(uint64_t(std::clamp(pixels_sent(), 0, total_pixels_)),
                             created_.load(), finished_.load());
    uint64_t before = progress_reported_.load();
    while (done > before && !progress_reported_.compare_exchange_weak(before, done)) {
    }
    if (done > before) settings_.progress->pixels_done += done - before;
}

int BoxHost::begin_run(int threads) {
    // Runs after the first (anti-aliasing waves) add to the first's statistics.
    if (run_start_ == Clock::time_point{}) run_start_ = Clock::now();
    progress_reported_ = 0;
    stop_.store(false);  // a worker's next wave: the last run was stopped
    // With parent tracking a box is worked on by one thread at a time: threads beyond
    // the boxes that hold something only fill inboxes and spin (one box on two threads
    // took twice as long).
    int busy_boxes = 0;
    for (size_t b = 0; b < boxes_.size(); ++b)
        busy_boxes += boxes_[b]->scene && !reach_[b].empty();
    if (!shared_boxes_) threads = std::clamp(threads, 1, std::max(1, busy_boxes));
    threads = std::max(threads, 1);
    for (auto& b : boxes_) {
        if (!b->scene) continue;
        for (const Box::Lane& l : b->lanes) add_lane_counts(b->stats, l.stats);
        b->lanes = std::vector<Box::Lane>(size_t(threads));
        for (Box::Lane& l : b->lanes) b->scene->init_context(l.ctx);
    }
    accum_.clear();
    if (!shared_sums_) accum_.resize(size_t(threads));
    if (shared_sums_) {
        sum_logs_.assign(size_t(threads) * SharedPixelSums::kStripes, {});
        stripe_pixels_ =
            std::max<size_t>(1, (size_t(total_pixels_) + SharedPixelSums::kStripes - 1) /
                                    SharedPixelSums::kStripes);
    }
    for (PixelSums& sums : accum_) {
        const size_t n = size_t(total_pixels_) * size_t(sum_channels_);
        sums.values.reset(
            static_cast<double*>(std::calloc(std::max<size_t>(n, 1), sizeof(double))));
        if (!sums.values) throw std::bad_alloc();
        // Pixels anywhere in the image get light (reflections): 2 MB pages, not
        // thousands of 4 KB faults.
        advise_huge_pages(sums.values.get(), n * sizeof(double));
        sums.written.assign((size_t(total_pixels_) >> kSumRunShift) + 1, 0);
    }
    // One band of the image per thread: threads tracing neighbouring pixels need the
    // same boxes and wait on each other (two threads on one band of 600x600 took longer
    // than one thread).
    bands_ = std::vector<PixelBand>(size_t(threads));
    for (int b = 0; b < threads; ++b) {
        bands_[b].begin = int(int64_t(total_pixels_) * b / threads);
        bands_[b].end = int(int64_t(total_pixels_) * (b + 1) / threads);
        bands_[b].next.store(bands_[b].begin);
    }
    return threads;
}

void BoxHost::end_run() {
    for (size_t log = 0; log < sum_logs_.size(); ++log) {
        if (!sum_logs_[log].empty()) add_sum_log(log, true);
    }
    const double wall = std::chrono::duration<double>(Clock::now() - run_start_).count();
    for (auto& b : boxes_) {
        if (b->scene) b->stats.idle_seconds = std::max(0.0, wall - b->stats.busy_seconds);
    }
}

void BoxHost::run(int threads, bool emit_camera) {
    threads = begin_run(threads);
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i)
        pool.emplace_back(&BoxHost::worker, this, i, emit_camera);
    worker(0, emit_camera);
    for (auto& t : pool) t.join();
    if (emit_camera) report_progress();
    end_run();
}

std::vector<BoxStats> BoxHost::box_stats() const {
    std::vector<BoxStats> out;
    for (const auto& b : boxes_) {
        BoxStats st = b->stats;
        for (const Box::Lane& l : b->lanes) add_lane_counts(st, l.stats);
        out.push_back(st);
    }
    return out;
}

Image render_space(const Scene& scene, const trace::RenderSettings& settings,
                   const SpaceOptions& options, SpaceStats* stats,
                   const trace::RenderPlan* plan) {
    auto t0 = Clock::now();
    BoxHost host(scene, settings, options, plan);
    host.place_walls();
    std::vector<int> all(host.walls().box_count());
    for (size_t b = 0; b < all.size(); ++b) all[b] = int(b);
    host.build_boxes(all);
    host.build_photon_map();
    int threads = settings.threads > 0
                      ? settings.threads
                      : int(std::max(1u, std::thread::hardware_concurrency()));
    const trace::SamplerSettings sampling = trace::sampler_settings(settings, scene);
    Image image;
    if (sampling.method != 0 || host.focal_blur()) {
        // Anti-aliasing or focal blur: the samples (or their rays) go through the boxes
        // in waves, every block's decisions replayed here (trace/sample_waves.h).
        auto trace_wave = [&](const std::vector<trace::SamplePosition>& wave,
                              std::vector<float>& rgbt) {
            if (settings.progress) settings.progress->start_pass(wave.size());
            host.set_samples(wave);
            host.run(threads, true);
            host.sample_colours(rgbt);
        };
        trace::WaveStats waves;
        image = trace::render_in_waves(settings, sampling, trace_wave, &waves,
                                       host.focal_blur());
        if (stats) stats->wave_samples = waves.samples;
    } else {
        if (settings.progress)
            settings.progress->start_pass(uint64_t(settings.width) * settings.height);
        host.run(threads, true);
        image = host.image(settings.width, settings.height, settings.alpha);
        trace::finish_pixels_without_camera_ray(image, scene.camera, settings);
    }
    if (stats) {
        stats->parent_tracking = host.parent_tracking();
        stats->boxes = host.box_stats();
        stats->seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    return image;
}

}  // namespace povwall::distrib
