// The black boxes one process hosts: all of them (in-process render) or a subset (a TCP
// worker). Items for boxes hosted elsewhere go to `remote`; items arriving from elsewhere
// come in through inject_many(). Internal to distrib/.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "distrib/item.h"
#include "distrib/parent_table.h"
#include "distrib/space_render.h"
#include "distrib/wire/items.h"
#include "trace/camera_interiors.h"
#include "trace/focal_blur.h"
#include "trace/photon_map.h"
#include "trace/prepared_scene.h"
#include "trace/render_plan.h"
#include "trace/shading.h"

namespace povwall::distrib {

struct WaitingParent {
    trace::ShadingRecord record;
    // Result slots: one per child, except that an area-light shadow child has one per
    // sample of its grid; child i's first slot is first_slot[i] (empty: slot i).
    std::vector<trace::TraceResult> results;
    std::vector<uint32_t> first_slot;
    RayItem origin;
    // The children's results in record order, area grids averaged.
    void gather(const Scene& scene, std::vector<trace::TraceResult>& out) const;
};

struct Box {
    explicit Box(QueuePolicy policy) : queue(policy) {}
    int index = 0;
    std::unique_ptr<trace::PreparedScene> scene;
    // What tracing in the box changes, one lane per worker thread: when rays return
    // colours forward (no parent waits in the box) threads trace in the same box at
    // once, each in its lane; with parent tracking one thread holds the box at a time.
    struct alignas(64) Lane {
        trace::RayContext ctx;
        // Scratch for spawn_children, one per nesting level of direct hand-overs (a
        // child traced at once in the same box must not overwrite its parent's record).
        std::vector<trace::ShadingRecord> records;
        BoxStats stats;  // counters; summed into the box's by box_stats()
    };
    std::vector<Lane> lanes;
    std::mutex inbox_mutex;
    std::vector<Item> inbox;
    uint64_t inbox_bytes = 0;       // with inbox_mutex: arrived since the last drain
    std::vector<Item> inbox_spare;  // the box's thread only (while busy)
    std::atomic<size_t> pending{0};
    std::atomic<bool> busy{false};
    // The worker thread that set `busy` (-1: none). Only that thread writes its own
    // index, so a thread that reads its own index holds the box.
    std::atomic<int> holder{-1};
    WorkQueue<Item> queue;
    ParentTable<WaitingParent> parents;
    uint64_t next_id = 0;
    BoxStats stats;  // what the thread holding the box counts (queue, busy time)
};

// Progress of a black-box render: a pixel is done when every ray it led to is, which
// nobody tracks, so the pixels whose camera rays were sent count in the proportion of
// items finished to items created (exact once the two meet).
inline uint64_t pixels_done_estimate(uint64_t sent, uint64_t created, uint64_t finished) {
    if (created == 0) return 0;
    return uint64_t(double(sent) * std::min(1.0, double(finished) / double(created)));
}

class BoxHost {
  public:
    // `plan`: the coordinator's, for a worker whose scene holds only its part (a plan
    // made from a part could leave out shadow rays that another part's objects block);
    // null: made from `scene`.
    BoxHost(const Scene& scene, const trace::RenderSettings& settings,
            const SpaceOptions& options, const trace::RenderPlan* plan = nullptr);
    const trace::RenderPlan& plan() const { return plan_; }

    // Walls from the options (in-process render, coordinator).
    void place_walls();
    void set_walls(VirtualWalls walls) { walls_ = std::move(walls); }
    // A worker's scene holds only its boxes' objects: the whole scene's object list,
    // recorded as it parsed, gives its boxes POV-Ray's ties and slab-tree tests.
    void set_whole_scene(std::shared_ptr<const trace::PovWholeScene> whole) {
        whole_scene_ = std::move(whole);
    }
    const VirtualWalls& walls() const { return walls_; }
    // Prepares the local scenes of the `hosted` boxes; the others stay unprepared here
    // and are reached through `remote`.
    void build_boxes(const std::vector<int>& hosted);
    bool hosts(int box) const { return boxes_[box]->scene != nullptr; }
    size_t primitive_count(int box) const {
        return boxes_[box]->scene->primitive_count();
    }
    // Per box, the bounds of what it holds within its region, padded (its reach): a ray
    // goes to a box only if its segment there meets the box's reach, and a box holding
    // no primitive has an empty reach. All processes route with the same table.
    // build_boxes() computes it from this host's scene (the whole scene in-process and on
    // the coordinator, which sends it to the workers).
    const std::vector<Bounds3>& box_reach() const { return reach_; }
    void set_box_reach(std::vector<Bounds3> reach) {
        reach_ = std::move(reach);
        classify_boxes();
    }
    bool parent_tracking() const { return parents_; }

    // The frame's photon map (trace/photon_map.h), which every hosted box gathers from.
    // build_photon_map() shoots it from this host's scene, which must be whole (one
    // process; the coordinator, which sends it to the workers), preparing the whole scene
    // for the pass as one process does, before the boxes trace; a worker, whose scene is
    // a part, takes the coordinator's with set_photon_map(). Call after build_boxes().
    void build_photon_map();
    void set_photon_map(std::shared_ptr<const trace::PhotonMap> map);
    const trace::PhotonMap* photon_map() const { return photons_.get(); }

    // The camera samples the next runs trace, one slot each in place of the pixels
    // (anti-aliasing waves): POV-Ray pixel positions (pixel (i, j)'s centre at (i, j)).
    // Empty: every pixel's centre, slot = pixel.
    void set_samples(std::vector<trace::SamplePosition> samples);
    // After a run of samples, summed here (in-process): each slot's rgbt as
    // trace::CameraSamples gives it (sample_colour()).
    void sample_colours(std::vector<float>& rgbt) const;
    // Camera ray of slot p (a pixel, or a sample of set_samples()) and the box it starts
    // in; -1 where the camera sees nothing.
    int camera_item(int pixel, Item& item) const;
    bool has_camera_ray(int slot) const;
    // The camera's focal blur (null without): samples of set_samples() may name its rays.
    const trace::FocalBlur* focal_blur() const { return blur_.get(); }
    // Items that arrived from another process for hosted box `box`, at once (one lock,
    // one wake-up): `fill(item)` decodes
    // the next item into place and returns its encoded size, or 0 when there is no
    // further item for this box (that slot is dropped). Returns the items added.
    template <class Fill>
    size_t inject_many(int box, Fill&& fill);

    // Worker process, on its receiving thread: the camera rays of pixels [begin, end)
    // go to their first boxes (queued here, or sent to the process hosting them). The
    // range counts as one finished item: the coordinator counted it as created.
    void emit_pixels(int begin, int end);
    // Pixels of the ranges emit_pixels() has handled (the coordinator's flow control).
    uint64_t pixels_emitted() const { return pixels_emitted_.load(); }

    // Runs `threads` worker threads until all camera rays are traced (in-process), or
    // until stop() (worker process: emit_camera false).
    void run(int threads, bool emit_camera);
    // A worker process with one render thread traces on the thread that receives the
    // items instead, between its network events (no second thread to wake, no
    // hand-over): begin_run(1) once, drain() whenever items arrived (traces until no
    // hosted box has any, then sends what goes elsewhere), end_run() at the end.
    int begin_run(int threads);
    void drain();
    void end_run();
    void stop() {
        stop_.store(true);
        wake_idle();
    }

    // Items for boxes hosted elsewhere; returns the bytes it sent (for --stats).
    std::function<size_t(int box, Item&& item)> remote;
    std::function<void()> flush;         // called when a thread runs dry
    std::function<void()> on_processed;  // test hook, after each item

    // Items created here (pushed to any box) and finished here (processed): summed over
    // all processes at one instant, equal totals mean no ray or result is left anywhere.
    uint64_t created() const { return created_.load(); }
    uint64_t finished() const { return finished_.load(); }

    // r, g, b, transmit per pixel summed over threads (before alpha conversion), for
    // the pixels in the runs some thread wrote, in pixel order: visit(pixel, sums[4]);
    // transmit is 0 unless the output has alpha (sum_channels() 4).
    // No image-sized array: a worker holding a few boxes touched a few runs.
    template <class Visit>
    void for_each_pixel_sum(Visit&& visit) const;
    // The image of this process's sums (in-process render: the whole image).
    Image image(int width, int height, bool alpha) const;
    // Values summed per pixel: r, g, b, and transmit when the output has alpha.
    int sum_channels() const { return sum_channels_; }
    // Contributions go into `sums` (total pixels x sum_channels(), shared with other
    // processes) instead of this process's own per-thread sums; for_each_pixel_sum()
    // then visits nothing. A thread logs them per stripe of the image and adds a stripe's
    // log under that stripe's lock in `stripe_locks` (SharedPixelSums' layout), at the
    // latest in end_run(). Call before begin_run() or run().
    void use_shared_sums(double* sums, uint32_t* stripe_locks) {
        shared_sums_ = sums;
        stripe_locks_ = stripe_locks;
    }
    std::vector<BoxStats> box_stats() const;
    int box_count() const { return int(boxes_.size()); }
    // What an item received from another process may name (wire/items.h).
    ItemLimits item_limits() const {
        return {box_count(), int(scene_.lights.size()), total_pixels_};
    }
    // A result came for a slot its waiting parent does not have: a peer sent a malformed
    // item (it is dropped; the render must not be trusted).
    bool received_bad_result() const { return bad_result_.load(); }

  private:
    enum class BoxVisit : uint8_t { Never, Always, IfReached };
    void worker(int thread, bool emit_camera);
    // One batch of one box that has items, on this thread, then `send` what goes to
    // other processes; false when no box had any.
    bool work_on_a_box(int thread, bool emit_camera, size_t& start, bool send);
    std::chrono::steady_clock::time_point run_start_;
    void emit_camera_rays();
    void process(Box& box, Item& item, int thread);
    void process_ray(Box& entry, Item& item, int thread);
    Box* go_on_in(Box& current, int dest);
    void deliver(Box& box, const RayItem& ray, const trace::TraceResult& result,
                 int thread);
    void push(Box* current, int dest, Item&& item);
    int enter(const Ray& ray, Real t_from, VirtualWalls::WalkState& at) const;
    void route(const Ray& ray, VirtualWalls::WalkState& at, VirtualWalls::Segment& seg,
               int& next) const;
    int first_box(const Ray& ray, Real t_from, VirtualWalls::Segment& seg, int& next,
                  VirtualWalls::WalkState& at) const;
    // Whether a ray goes to box s.box for its segment there. A box holding nothing is
    // skipped; a box hosted elsewhere is skipped when the segment cannot meet its reach
    // (that saves a message); a hosted box is entered anyway, as a search there costs
    // about what the test would. The walk asks for every box it passes: inline, with
    // the reach test out of line.
    bool visits(const Ray& ray, const VirtualWalls::Segment& s) const {
        const BoxVisit v = visit_[size_t(s.box)];
        if (v != BoxVisit::IfReached) [[likely]]
            return v == BoxVisit::Always;
        return reaches(ray, s);
    }
    [[gnu::noinline]] bool reaches(const Ray& ray, const VirtualWalls::Segment& s) const;
    void add_pixel(int thread, int pixel, const Rgb& c, float transmit);

    const Scene& scene_;
    const trace::RenderSettings& settings_;
    const SpaceOptions& options_;
    trace::RenderPlan plan_;  // made once; every box's local scene follows it
    trace::CameraInteriors camera_interiors_;  // what camera rays start inside of
    bool parents_ = false;
    // Threads trace in a box at once (forward contributions, direct hand-over on).
    bool shared_boxes_ = false;
    VirtualWalls walls_;
    std::vector<std::unique_ptr<Box>> boxes_;
    std::vector<Bounds3> reach_;
    std::vector<BoxVisit> visit_;  // per box, how visits() decides
    void classify_boxes();
    // Written by every thread: a cache line of their own, away from the tables that
    // every ray's walk reads.
    alignas(64) std::atomic<uint64_t> created_{0}, finished_{0};
    std::atomic<uint64_t> pixels_emitted_{0};
    std::atomic<bool> stop_{false};
    // Worker processes: a thread with nothing to do sleeps here until inject_many() or
    // stop() wakes it (polling every 200 us was 176,000 wake-ups of 8 processes on 2
    // cores).
    alignas(64) std::mutex idle_mutex_;  // (ends the counters' line)
    std::condition_variable idle_cv_;
    std::atomic<int> sleepers_{0};
    void wake_idle() {
        // seq_cst on both sides (pending, then sleepers; sleepers, then pending): a
        // sleeper either sees the new item or is seen here.
        if (sleepers_.load() == 0) return;
        std::lock_guard<std::mutex> lock(idle_mutex_);
        idle_cv_.notify_all();
    }
    void sleep_until_work();
    // Camera rays still to send, per band of the image; a thread starts on its own band.
    struct alignas(64) PixelBand {
        std::atomic<int> next{0};
        int begin = 0, end = 0;
    };
    std::vector<PixelBand> bands_;
    int pixels_sent() const;
    std::atomic<bool> bad_result_{false};
    int total_pixels_ = 0;  // slots: the image's pixels, or samples_.size()
    std::vector<trace::SamplePosition> samples_;
    std::unique_ptr<trace::FocalBlur> blur_;
    std::shared_ptr<const trace::PhotonMap> photons_;
    std::shared_ptr<const trace::PovWholeScene> whole_scene_;
    // Progress (settings.progress): pixels sent, scaled by the share of items finished.
    std::atomic<uint64_t> progress_reported_{0};
    void report_progress();
    // Per thread: r, g, b (and transmit, only for alpha output: a quarter less fresh
    // memory to fault in otherwise) per pixel, in double so that the order in which
    // contributions arrive does not show in the image. Zeroed by calloc (fresh pages, not
    // written) with a flag per run of kSumRun pixels a thread wrote: a thread touches
    // only the pixels it traced, and the sum reads only those (two 11.5 MB arrays written
    // and copied at 600x600 were 11,000 page faults, a fifth of a one-box render).
    static constexpr int kSumRunShift = 7;  // 128 pixels: 3 or 4 KB of sums
    int sum_channels_ = 4;
    struct PixelSums {
        struct Free {
            void operator()(double* p) const { std::free(p); }
        };
        std::unique_ptr<double[], Free> values;
        std::vector<uint8_t> written;  // per run of 128 pixels
    };
    std::vector<PixelSums> accum_;
    double* shared_sums_ = nullptr;  // use_shared_sums()
    uint32_t* stripe_locks_ = nullptr;
    // Per thread and stripe (thread * kStripes + stripe): contributions not yet added to
    // the shared sums. A full log is added when its stripe's lock is free; one that grew
    // to kSumLogWait entries waits for the lock.
    struct PixelAdd {
        uint32_t pixel;
        double value[4];
    };
    static constexpr size_t kSumLogAdd = 256, kSumLogWait = 8192;
    std::vector<std::vector<PixelAdd>> sum_logs_;
    size_t stripe_pixels_ = 1;
    void add_sum_log(size_t log, bool wait);
};

template <class Visit>
void BoxHost::for_each_pixel_sum(Visit&& visit) const {
    if (accum_.empty()) return;
    const size_t runs = accum_[0].written.size();
    for (size_t run = 0; run < runs; ++run) {
        bool written = false;
        for (const PixelSums& a : accum_) written |= a.written[run] != 0;
        if (!written) continue;
        const size_t begin = run << kSumRunShift;
        const size_t end = std::min(size_t(total_pixels_), (run + 1) << kSumRunShift);
        for (size_t p = begin; p < end; ++p) {
            double sum[4] = {0, 0, 0, 0};
            for (const PixelSums& a : accum_) {
                if (!a.written[run]) continue;
                for (int c = 0; c < sum_channels_; ++c)
                    sum[c] += a.values[p * size_t(sum_channels_) + size_t(c)];
            }
            visit(p, static_cast<const double*>(sum));
        }
    }
}

template <class Fill>
size_t BoxHost::inject_many(int box, Fill&& fill) {
    Box& d = *boxes_[size_t(box)];
    size_t added = 0;
    {
        std::lock_guard<std::mutex> lock(d.inbox_mutex);
        for (;;) {
            Item& item = d.inbox.emplace_back();
            const size_t bytes = fill(item);
            if (bytes == 0) {
                d.inbox.pop_back();
                break;
            }
            d.inbox_bytes += bytes;
            ++added;
        }
    }
    if (added) {
        d.pending.fetch_add(added);
        wake_idle();
    }
    return added;
}

}  // namespace povwall::distrib
