// The coordinator of black boxes over TCP: starts or connects to the workers, sends them
// the job, emits the camera rays, watches their status (heartbeats, flow control,
// termination waves), gathers the pixel sums, and recovers from a lost worker by giving
// its boxes to the others.
#include <fcntl.h>
#include <malloc.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>
#include <unordered_map>

#include "core/memory.h"
#include "distrib/box_host.h"
#include "distrib/child_process.h"
#include "distrib/connection.h"
#include "distrib/distribution_plan.h"
#include "distrib/object_boxes.h"
#include "distrib/shared_pixel_sums.h"
#include "distrib/stats_json.h"
#include "distrib/tcp.h"
#include "distrib/wire/control.h"
#include "distrib/wire/items.h"
#include "distrib/wire/job.h"
#include "distrib/wire/messages.h"
#include "distrib/wire/photons.h"
#include "distrib/wire/pixels.h"
#include "distrib/wire/samples.h"
#include "distrib/worker_processes.h"
#include "parser/parser.h"
#include "trace/pattern.h"
#include "trace/sample_waves.h"

namespace povwall::distrib {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

}  // namespace

// The coordinator of one set of workers: starts or connects to them on the first frame,
// then renders frames on them until a frame fails.
class TcpCoordinator {
  public:
    TcpCoordinator(const TcpOptions& tcp_options, FixedJob fixed)
        : tcp_(tcp_options), fixed_(std::move(fixed)), timer_(io_) {}

    ~TcpCoordinator() {
        // Failed: take the job down (before closing, so no worker reports the close).
        if (failed_ || in_frame_) {
            for (const LocalWorker& l : local_) kill(l.pid, SIGKILL);
        }
        for (auto& w : workers_) {
            if (w.conn) w.conn->close();  // workers between frames exit on their own
        }
        for (const LocalWorker& l : local_) wait_child(l.pid, 10.0);
    }

    const FixedJob& fixed() const { return fixed_; }
    bool failed() const { return failed_; }
    // Workers between frames exit when their connection closes; the destructor reaps
    // them.
    void release_workers() {
        for (auto& w : workers_) {
            if (w.conn) w.conn->close();
        }
        released_ = true;
    }
    bool released() const { return released_; }
    int frames() const { return frames_; }
    int processes_started() const { return int(local_.size()); }
    bool forked() const { return forked_; }

    Image render(const Scene& scene, const SceneSource& source,
                 const trace::RenderSettings& settings, const SpaceOptions& options,
                 SpaceStats* stats, const trace::RenderPlan* plan) {
        auto t0 = Clock::now();
        settings_ = &settings;
        options_ = &options;
        emitter_ = std::make_unique<BoxHost>(scene, settings, options, plan);
        numbers_ = std::make_unique<ObjectNumbers>(scene);
        scene_ = &scene;
        sampling_ = trace::sampler_settings(settings, scene);
        in_frame_ = true;
        workers_ready_ = false;
        if (workers_.empty()) {
            emitter_->place_walls();
            // Before forked workers share this process's pages: written after, every
            // page it touches is copied.
            emitter_->build_boxes({});
            start_workers(source);
        } else {
            emitter_->set_walls(emitter_walls_);
            for (WorkerState& w : workers_) {
                json frame = to_json(FrameJob{source.animation, emitter_->plan(),
                                              objects_per_worker(),
                                              walk_reaches(emitter_walls_, *scene_)});
                frame["type"] = "frame";
                w.conn->send(control_frame(frame));
            }
            emitter_->build_boxes({});
        }
        // While the workers prepare: the photon map, shot from the whole scene here
        // (a worker holds a part), goes to each once it is ready.
        emitter_->build_photon_map();
        const int boxes = emitter_->walls().box_count();
        empty_.assign(boxes, 1);
        created_ = 0;
        for (WorkerState& w : workers_) {
            w.ready = false;
            w.created = w.finished = 0;
            w.pixels_sent = w.pixels_done = 0;
            w.last_seen = Clock::now();
        }
        Image image;
        if (sampling_.method == 0 && !emitter_->focal_blur()) {
            run_pass(nullptr);
            image =
                image_from_sums(sums_, settings.width, settings.height, settings.alpha);
            trace::finish_pixels_without_camera_ray(image, scene.camera, settings);
        } else {
            // Anti-aliasing or focal blur: the samples (or their rays) go through the
            // boxes in waves, every block's decisions replayed here
            // (trace/sample_waves.h), as in one process.
            auto trace_wave = [&](const std::vector<trace::SamplePosition>& wave,
                                  std::vector<float>& rgbt) {
                run_pass(&wave);
                const size_t channels = settings.alpha ? 4 : 3;
                rgbt.assign(wave.size() * 4, 0.0f);
                for (size_t p = 0; p < wave.size(); ++p) {
                    double s[4] = {0, 0, 0, 0};
                    for (size_t c = 0; c < channels; ++c) s[c] = sums_[p * channels + c];
                    sample_colour(s, settings.alpha, emitter_->has_camera_ray(int(p)),
                                  &rgbt[p * 4]);
                }
            };
            trace::WaveStats waves;
            image = trace::render_in_waves(settings, sampling_, trace_wave, &waves,
                                           emitter_->focal_blur());
            if (stats) stats->wave_samples = waves.samples;
        }
        in_frame_ = false;
        ++frames_;
        if (stats) {
            stats->parent_tracking = emitter_->parent_tracking();
            stats->boxes = box_stats_;
            stats->worker_peak_resident.clear();
            stats->worker_objects_kept.clear();
            stats->worker_objects_left_out.clear();
            for (const WorkerState& w : workers_) {
                stats->worker_peak_resident.push_back(w.peak_resident);
                stats->worker_objects_kept.push_back(w.objects_kept);
                stats->worker_objects_left_out.push_back(w.objects_left_out);
            }
            stats->worker_cores = worker_cores_;
            stats->teams = teams_;
            stats->seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        }
        return image;
    }

  private:
    // One run through the workers: every pixel's centre (`wave` null), or the camera
    // samples of an anti-aliasing wave, whose slot k is wave[k]. Returns when the pass's
    // sums are all in sums_; throws when a worker fails.
    void run_pass(const std::vector<trace::SamplePosition>* wave) {
        wave_ = wave;
        emitter_->set_samples(wave ? *wave : std::vector<trace::SamplePosition>{});
        slots_ = wave ? int(wave->size()) : settings_->width * settings_->height;
        const size_t sum_count = size_t(slots_) * (settings_->alpha ? 4 : 3);
        if (shared_sums_) {
            // Forked workers add into these (fresh zero pages for the first frame). A
            // kept worker may have this frame's message already, but adds nothing
            // before its first camera range, which io_.run() below sends.
            if (frames_ > 0) std::fill(sums_.begin(), sums_.end(), 0.0);
        } else {
            // On 2 MB pages (thousands of 4 KB faults otherwise).
            if (own_sums_.capacity() < sum_count) {
                own_sums_ = std::vector<double>();
                own_sums_.reserve(sum_count);
                advise_huge_pages(own_sums_.data(), sum_count * sizeof(double));
            }
            own_sums_.assign(sum_count, 0.0);
            sums_ = own_sums_;
        }
        // The workers' statistics count every run of the frame; their last reports are
        // the totals.
        box_stats_ = emitter_->box_stats();
        for (BoxStats& b : box_stats_) {
            const Bounds3 region = b.region;
            b = BoxStats{};
            b.region = region;
        }
        pixels_emitted_ = 0;
        next_range_ = 0;
        wave_pending_ = -1;
        last_wave_.clear();
        started_ = false;
        progress_reported_ = 0;
        if (settings_->progress) settings_->progress->start_pass(uint64_t(slots_));
        for (WorkerState& w : workers_) {
            w.done = false;
            w.samples_taken = false;
            w.wave_seq = -1;
            w.last_seen = Clock::now();
        }
        // A later pass: the workers are ready (the first waits for their "ready").
        if (workers_ready_) send_samples();
        watch();
        io_.restart();
        io_.run();
        if (failed_) {
            if (lost_) throw WorkerLost(error_, lost_worker_);
            throw DistribError(error_);
        }
    }

    // Every worker ready for the pass: its samples (anti-aliasing), then "start".
    void send_samples() {
        if (!wave_) return start_pass();
        for (WorkerState& w : workers_) {
            const size_t n = wave_->size();
            for (size_t first = 0; first < n; first += kSamplesPerFrame) {
                const size_t count = std::min(kSamplesPerFrame, n - first);
                std::vector<uint8_t> body;
                body.reserve(count * kSampleRecordSize);
                for (size_t k = first; k < first + count; ++k)
                    write_sample_position(body, (*wave_)[k]);
                auto buf = std::make_shared<std::vector<uint8_t>>();
                encode_frame(FrameType::Samples, uint32_t(count), body, *buf);
                w.conn->send(buf);
            }
            w.conn->send(message_frame(SamplesSentMessage{uint64_t(n)}));
        }
    }

    // The workers hold the pass's samples: the run starts, and the camera rays go out.
    void start_pass() {
        started_ = true;
        measure_for_cores();
        const Buffer start = message_frame(StartMessage{reach_to_json(reach_)});
        // For the tests: POVWALL_FAULT_LATE_START="I,MS" sends worker I its start MS
        // milliseconds after the others, so that its peers' items come first.
        int late = -1, late_ms = 0;
        if (const char* spec = std::getenv("POVWALL_FAULT_LATE_START"))
            if (std::sscanf(spec, "%d,%d", &late, &late_ms) != 2) late = -1;
        for (size_t k = 0; k < workers_.size(); ++k) {
            if (int(k) != late) {
                workers_[k].conn->send(start);
                continue;
            }
            auto timer = std::make_shared<asio::steady_timer>(
                io_, std::chrono::milliseconds(late_ms));
            timer->async_wait(
                [this, timer, k, frame = start](boost::system::error_code ec) {
                    if (!ec && in_frame_) workers_[k].conn->send(frame);
                });
        }
        emit();
    }

    // Each worker's objects: the indices of those in its boxes (boxes_of_object),
    // ascending.
    std::vector<std::vector<uint32_t>> objects_of_workers() const {
        const VirtualWalls& walls = emitter_walls_;
        const size_t workers = size_t(team_size_);
        std::vector<std::vector<uint32_t>> objects(workers);
        const std::vector<WalkReach> walk = walk_reaches(walls, *scene_);
        for (size_t i = 0; i < scene_->objects.size(); ++i) {
            for (int b : boxes_holding(walls, scene_->objects[i], walk)) {
                const auto w = size_t(owner_[size_t(b)]);
                if (w < objects.size() &&
                    (objects[w].empty() || objects[w].back() != uint32_t(i)))
                    objects[w].push_back(uint32_t(i));
            }
        }
        // Worker t * team_size_ + k hosts the boxes of the team's k.
        for (int t = 1; t < teams_; ++t)
            for (size_t k = 0; k < workers; ++k) objects.push_back(objects[k]);
        return objects;
    }
    // The owner table team `t`'s workers route by (worker indices among all).
    std::vector<int> owners_of_team(int t) const {
        std::vector<int> owners = owner_;
        for (int& o : owners) o += t * team_size_;
        return owners;
    }
    // How many of the scene's objects each worker will keep, so it can reserve its
    // object list.
    std::vector<size_t> objects_per_worker() const {
        std::vector<size_t> count;
        for (const auto& o : objects_of_workers()) count.push_back(o.size());
        return count;
    }

    struct WorkerState {
        std::string address;
        std::shared_ptr<Connection> conn;
        Clock::time_point last_seen;
        bool ready = false, done = false;
        bool samples_taken = false;          // this pass's (anti-aliasing)
        uint64_t created = 0, finished = 0;  // latest status
        // Pixels of the ranges sent to this worker, and handled by it (latest status).
        uint64_t pixels_sent = 0, pixels_done = 0;
        uint64_t peak_resident = 0;  // the process's VmHWM at its last "done"
        size_t objects_kept = 0, objects_left_out = 0;  // by its parse (ready)
        long wave_seq = -1;                             // latest probe answered
        uint64_t wave_created = 0, wave_finished = 0;
        std::vector<uint64_t> sent;  // items sent to each worker (latest status)
    };

    void start_workers(const SceneSource& source) {
        std::string token = tcp_.token;
        std::vector<std::string> addresses = tcp_.workers;
        const int n = int(addresses.size()) + std::max(0, tcp_.procs);
        if (n == 0) throw DistribError("no workers");
        // Walls stay for the whole sequence: the outer boxes are unbounded, so any
        // frame's objects fall in some box; only the balance may drift.
        emitter_walls_ = emitter_->walls();
        // Teams that divide the workers (after a lost worker, fewer may).
        teams_ = std::clamp(options_->teams, 1, n);
        while (n % teams_ != 0) --teams_;
        team_size_ = n / teams_;
        owner_ = box_owners(emitter_walls_.slabs(), team_size_, scene_->camera.direction,
                            options_->process_grid);
        // Before any fork: forked workers take their objects from these lists.
        worker_objects_ = objects_of_workers();
        std::vector<size_t> expected;
        for (const auto& o : worker_objects_) expected.push_back(o.size());
        if (tcp_.procs > 0) {
            if (token.empty()) {
                std::random_device rd;
                char hex[33];
                std::snprintf(hex, sizeof hex, "%08x%08x%08x%08x", rd(), rd(), rd(),
                              rd());
                token = hex;
            }
            unsigned cores = std::max(1u, std::thread::hardware_concurrency());
            int threads = settings_->threads > 0
                              ? settings_->threads
                              : int(std::max(1u, cores / unsigned(tcp_.procs)));
            const size_t before = local_.size();
            forked_ = tcp_.fork_workers && single_threaded();
            // Anti-aliasing and focal-blur waves vary in size: their sums come back as
            // records.
            if (forked_ && sampling_.method == 0 &&
                !trace::FocalBlur::enabled(scene_->camera)) {
                // The sums exist before the fork, so every worker maps them; the frame's
                // size is fixed for this coordinator (FixedJob).
                shared_sums_ =
                    SharedPixelSums(size_t(settings_->width) * size_t(settings_->height) *
                                    (settings_->alpha ? 4 : 3));
                sums_ = shared_sums_.values();
                // The child's copy of the scene is its own to take objects from.
                fork_workers(token, threads, tcp_.image_reader,
                             const_cast<Scene*>(scene_), worker_objects_, shared_sums_,
                             tcp_.procs, local_);
            } else {
                spawn_workers(tcp_.worker_binary, token, threads, tcp_.procs, local_);
            }
            for (size_t i = before; i < local_.size(); ++i)
                addresses.push_back(local_[i].address);
            std::vector<pid_t> pids;
            for (const LocalWorker& l : local_) pids.push_back(l.pid);
            maybe_inject_worker_fault(pids);
        }
        WorkerJob job;
        job.fixed = fixed_;
        job.frame = {source.animation, emitter_->plan(), expected,
                     walk_reaches(emitter_walls_, *scene_)};
        job.walls = {emitter_walls_.walls(0), emitter_walls_.walls(1),
                     emitter_walls_.walls(2)};
        job.workers = addresses;
        job.inherited = forked_;  // this frame's scene is in the workers already
        workers_.resize(n);
        for (int i = 0; i < n; ++i) {
            WorkerState& w = workers_[i];
            w.address = addresses[i];
            tcp::socket socket(io_);
            boost::system::error_code ec;
            socket.connect(resolve(io_, w.address), ec);
            // Hello and job written at once, not queued for the io loop: the workers
            // prepare while this process sets up the rest of the frame (zeroing the
            // image sums took 10 ms before the first job left).
            if (!ec) {
                job.index = i;
                job.owner = owners_of_team(i / team_size_);
                const Buffer hello = hello_frame({token, -1});
                const Buffer work = control_frame(to_json(job));
                asio::write(socket, std::array{asio::buffer(*hello), asio::buffer(*work)},
                            ec);
            }
            if (ec) {
                failed_ = true;
                throw WorkerLost("cannot connect to worker " + std::to_string(i) + " (" +
                                     w.address + "): " + ec.message(),
                                 i);
            }
            w.conn = std::make_shared<Connection>(std::move(socket), w.address);
            w.conn->on_frame = [this, i](Frame& f) {
                try {
                    from_worker(i, f);
                } catch (const json::exception& e) {
                    fail(i, std::string("malformed message: ") + e.what());
                }
            };
            w.conn->on_error = [this, i](const std::string& why) { fail(i, why); };
            w.conn->start();
        }
    }

    // "worker 1 (host:port, boxes 1, 3, 5-7)": its boxes, runs of neighbours joined.
    std::string describe(int i) const {
        std::string list;
        int count = 0;
        const int k = i % team_size_;  // its boxes: those of its place in its team
        for (size_t b = 0; b < owner_.size(); ++b) {
            if (owner_[b] != k || (b > 0 && owner_[b - 1] == k)) continue;
            size_t last = b;
            while (last + 1 < owner_.size() && owner_[last + 1] == k) ++last;
            if (!list.empty()) list += ", ";
            list += std::to_string(b);
            if (last > b) list += "-" + std::to_string(last);
            count += int(last - b) + 1;
        }
        return "worker " + std::to_string(i) + " (" + workers_[i].address + ", " +
               (count == 1 ? "box " : "boxes ") + list + ")";
    }

    // `lost`: the worker is gone (a job it refused is not a loss another try could mend).
    // A worker that dies between frames shows here at the next frame.
    void fail(int i, const std::string& why, bool lost = true) {
        if (failed_) return;
        failed_ = true;
        lost_ = lost;
        lost_worker_ = i;
        error_ = describe(i) + ": " + why;
        io_.stop();
    }

    void watch() {  // heartbeat: a worker silent for the timeout is taken as dead
        timer_.expires_after(std::chrono::milliseconds(250));
        timer_.async_wait([this](boost::system::error_code ec) {
            if (ec || !in_frame_) return;
            for (size_t i = 0; i < workers_.size(); ++i) {
                double silent =
                    std::chrono::duration<double>(Clock::now() - workers_[i].last_seen)
                        .count();
                // Status every 10 ms while tracing, "busy" every second while preparing.
                // A worker that has answered (ready, or holding the wave's samples)
                // has nothing to say until the slowest one has too (under load that
                // can take longer than the timeout); if it dies meanwhile, its
                // connection closes.
                const bool waiting = (workers_[i].ready && !workers_ready_) ||
                                     (workers_[i].samples_taken && !started_);
                if (!workers_[i].done && !waiting && silent > tcp_.heartbeat_timeout) {
                    return fail(int(i),
                                "no message for " + std::to_string(int(silent)) + " s");
                }
            }
            watch();
        });
    }

    void from_worker(int i, Frame& f) {
        WorkerState& w = workers_[i];
        w.last_seen = Clock::now();
        if (f.type == FrameType::Pixels) {
            const int channels = settings_->alpha ? 4 : 3;
            const bool ok = read_pixel_sums(
                f.body, f.count, channels, sums_.size() / size_t(channels),
                [&](uint32_t p, const double* v) {
                    for (int c = 0; c < channels; ++c)
                        sums_[size_t(p) * size_t(channels) + size_t(c)] += v[c];
                });
            if (!ok) return fail(i, "bad pixel frame");
            return;
        }
        if (f.type != FrameType::Control) return fail(i, "unexpected frame");
        json j = parse_control(f);
        const std::string type = control_type(j);
        if (type == ErrorMessage::kType) {
            // A worker it names as the cause (a peer it cannot reach: a worker killed
            // while the others connect to it shows here first; or one that sent it a
            // malformed item frame) is taken as lost, so recovery can leave it out.
            const auto e = read_message<ErrorMessage>(j);
            if (e.culprit >= 0 && e.culprit < int64_t(workers_.size()) && e.culprit != i)
                return fail(int(e.culprit), e.message);
            return fail(i, e.message, false);
        } else if (type == ReadyMessage::kType) {
            const auto ready = read_message<ReadyMessage>(j);
            w.objects_kept = ready.objects_kept;
            w.objects_left_out = ready.objects_left_out;
            for (size_t k = 0; k < ready.boxes.size(); ++k) {
                const int b = ready.boxes[k];
                if (size_t(b) >= owner_.size() || owner_[size_t(b)] != i % team_size_)
                    return fail(i, "reported box " + std::to_string(b) + " as its own");
                empty_[size_t(b)] = ready.primitives[k] == 0;
            }
            w.ready = true;
            for (const WorkerState& o : workers_) {
                if (!o.ready) return;
            }
            reach_ = emitter_->box_reach();
            for (size_t b = 0; b < reach_.size(); ++b) {
                if (empty_[b]) reach_[b] = Bounds3{};
            }
            emitter_->set_box_reach(reach_);
            workers_ready_ = true;
            for (WorkerState& o : workers_) o.last_seen = Clock::now();  // see watch()
            const std::vector<Buffer> photons = photon_map_frames(emitter_->photon_map());
            for (WorkerState& o : workers_)
                for (const Buffer& b : photons) o.conn->send(b);
            send_samples();
        } else if (type == SamplesTakenMessage::kType) {  // it holds the wave's samples
            w.samples_taken = true;
            for (const WorkerState& o : workers_) {
                if (!o.samples_taken) return;
            }
            for (WorkerState& o : workers_) o.last_seen = Clock::now();  // see watch()
            start_pass();
        } else if (type == StatusMessage::kType) {
            const auto status = read_message<StatusMessage>(j);
            w.created = status.created;
            // Progress: items (rays and results) the workers have finished.
            if (settings_->progress && status.finished > w.finished)
                settings_->progress->rays += status.finished - w.finished;
            w.finished = status.finished;
            w.pixels_done = status.pixels;
            if (status.sent.size() == workers_.size()) w.sent = status.sent;
            report_progress();
            if (status.seq >= 0) {
                w.wave_seq = long(status.seq);
                w.wave_created = w.created;
                w.wave_finished = w.finished;
                check_wave();
            }
            emit();
        } else if (type == DoneMessage::kType) {
            const auto done = read_message<DoneMessage>(j);
            for (const BoxReport& r : done.boxes) {
                if (size_t(r.box) >= owner_.size() ||
                    owner_[size_t(r.box)] != i % team_size_)
                    return fail(i, "reported statistics of box " + std::to_string(r.box) +
                                       ", not its own");
                // Every team hosts the box: its copies' reports add up.
                add_box_stats(box_stats_[size_t(r.box)], r.stats);
            }
            w.peak_resident = done.peak_resident;
            w.done = true;
            for (const WorkerState& o : workers_) {
                if (!o.done) return;
            }
            // The pass is whole; the workers wait for the next one, the next frame, or
            // the close.
            if (settings_->progress) {
                settings_->progress->pixels_done += uint64_t(slots_) - progress_reported_;
                progress_reported_ = uint64_t(slots_);
            }
            timer_.cancel();
            io_.stop();
        }
    }

    // The workers' last reported counters (pixels_done_estimate); made exact when the
    // frame is whole.
    void report_progress() {
        if (!settings_->progress) return;
        uint64_t created = created_, finished = 0;
        for (const WorkerState& w : workers_) {
            created += w.created;
            finished += w.finished;
        }
        const uint64_t done =
            pixels_done_estimate(uint64_t(pixels_emitted_), created, finished);
        if (done > progress_reported_) {
            settings_->progress->pixels_done += done - progress_reported_;
            progress_reported_ = done;
        }
    }

    // Camera rays while the last reported traffic is below the in-flight bound. The
    // workers make them: each range of pixels goes to the worker hosting the box where
    // the range's middle camera ray starts (camera rays of one range mostly start in one
    // box), which queues those starting in its boxes and forwards the others. A range
    // counts as one created item until a worker finishes it, and as its pixels for the
    // flow control until the worker has handled it.
    void emit() {
        if (!started_ || !in_frame_) return;
        constexpr int kRange = 512;
        const int total = slots_;
        int64_t live = int64_t(created_);
        for (const WorkerState& w : workers_) {
            live += int64_t(w.created) - int64_t(w.finished);
            live += int64_t(w.pixels_sent) - int64_t(w.pixels_done);
        }
        const int ranges = (total + kRange - 1) / kRange;
        if (range_order_.size() != size_t(ranges)) range_order_ = spread_order(ranges);
        while (next_range_ < ranges && live < int64_t(options_->max_rays_in_flight)) {
            const int begin = range_order_[size_t(next_range_++)] * kRange;
            const int end = std::min(total, begin + kRange);
            Item item;
            const int box = emitter_->camera_item((begin + end) / 2, item);
            // The teams in turn: a team traces its rays' whole paths.
            const int team = next_range_ % teams_;
            WorkerState& w = workers_[size_t(team * team_size_ +
                                             (box >= 0 ? owner_[size_t(box)] : 0))];
            w.conn->send(message_frame(PixelRangeMessage{begin, end}));
            w.pixels_sent += uint64_t(end - begin);
            ++created_;
            live += 1 + (end - begin);
            pixels_emitted_ += end - begin;
        }
        if (!cpu_at_start_.empty() && pixels_emitted_ * 4 >= total) keep_on_cores();
        if (next_range_ >= ranges && live == 0 && wave_pending_ < 0) probe();
    }

    // Local workers that outnumber the cores: the CPU time each has used since the
    // start, with a quarter of the image handed out (in spread order, so from all over
    // it), is its share of the work, and the items each has sent each other its traffic;
    // each is then kept on a core with those it trades most with (core_groups). The
    // pilot's box visits had not told the work apart (4x4x4 over 8: one core got 57 %
    // of the samples).
    void measure_for_cores() {
        cpu_at_start_.clear();
        if (!worker_cores_.empty() || options_->keep_on_cores <= 1 ||
            local_.size() != workers_.size() ||
            int(local_.size()) <= options_->keep_on_cores)
            return;
        for (const LocalWorker& l : local_) {
            const uint64_t ns = cpu_nanoseconds(l.pid);
            if (ns == 0) return cpu_at_start_.clear();
            cpu_at_start_.push_back(ns);
        }
    }
    void keep_on_cores() {
        std::vector<double> work;
        for (size_t i = 0; i < local_.size(); ++i) {
            const uint64_t ns = cpu_nanoseconds(local_[i].pid);
            work.push_back(ns > cpu_at_start_[i] ? double(ns - cpu_at_start_[i]) : 0.0);
        }
        cpu_at_start_.clear();
        std::vector<std::vector<uint64_t>> traffic;
        for (const WorkerState& w : workers_) traffic.push_back(w.sent);
        worker_cores_ = core_groups(work, traffic, options_->keep_on_cores);
        for (size_t i = 0; i < worker_cores_.size(); ++i)
            keep_on_core(local_[i].pid, worker_cores_[i]);
    }

    // Termination: two consecutive probe waves with identical counters of every worker
    // mean the counters held at one instant between them; created == finished then means
    // no ray or result was queued, being traced, or on the wire anywhere.
    void probe() {
        wave_pending_ = ++wave_seq_;
        for (WorkerState& w : workers_) {
            w.conn->send(message_frame(ProbeMessage{wave_seq_}));
        }
    }

    void check_wave() {
        if (wave_pending_ < 0) return;
        uint64_t created = created_, finished = 0;
        std::vector<std::pair<uint64_t, uint64_t>> counts;
        for (const WorkerState& w : workers_) {
            if (w.wave_seq != wave_pending_) return;
            created += w.wave_created;
            finished += w.wave_finished;
            counts.emplace_back(w.wave_created, w.wave_finished);
        }
        wave_pending_ = -1;
        const bool same = counts == last_wave_;
        last_wave_ = counts;
        if (created != finished) return;  // traffic remains: later statuses probe again
        if (!same) return probe();
        for (WorkerState& w : workers_) w.conn->send(message_frame(FinishMessage{}));
    }

    const TcpOptions tcp_;
    const FixedJob fixed_;
    asio::io_context io_;
    asio::steady_timer timer_;
    // The current frame.
    const trace::RenderSettings* settings_ = nullptr;
    const SpaceOptions* options_ = nullptr;
    std::unique_ptr<BoxHost> emitter_;  // walls and camera rays; hosts no box
    const Scene* scene_ = nullptr;      // this frame's
    std::unique_ptr<ObjectNumbers> numbers_;
    std::vector<uint8_t> empty_;
    std::vector<BoxStats> box_stats_;
    // The image's sums: own_sums_, or shared_sums_ when the workers were forked.
    std::span<double> sums_;
    std::vector<double> own_sums_;
    SharedPixelSums shared_sums_;
    std::vector<std::pair<uint64_t, uint64_t>> last_wave_;
    uint64_t created_ = 0;
    int pixels_emitted_ = 0;  // pixels of the ranges sent so far (progress)
    int next_range_ = 0;      // into range_order_
    std::vector<int> range_order_;
    uint64_t progress_reported_ = 0;
    long wave_pending_ = -1;
    bool started_ = false, in_frame_ = false;
    trace::SamplerSettings sampling_;
    bool workers_ready_ = false;  // this frame's "ready" from all: passes may start
    std::vector<Bounds3> reach_;  // the boxes' reach, as the workers got it
    // The current pass: its samples (null: the pixels' centres) and their number.
    const std::vector<trace::SamplePosition>* wave_ = nullptr;
    int slots_ = 0;
    // The whole sequence.
    VirtualWalls emitter_walls_;
    std::vector<LocalWorker> local_;
    std::vector<WorkerState> workers_;
    // Which worker of a team hosts each box (an index within the team); worker
    // t * team_size_ + k is team t's k (SpaceOptions::teams).
    std::vector<int> owner_;
    int teams_ = 1, team_size_ = 1;
    long wave_seq_ = 0;
    int frames_ = 0;
    bool forked_ = false;  // the local workers were forked (else executed, or none)
    // Each worker's objects in the first frame (objects_of_workers); forked workers
    // read them from their copy of this process.
    std::vector<std::vector<uint32_t>> worker_objects_;
    bool failed_ = false, lost_ = false;
    bool released_ = false;  // release_workers(): no frame after it
    // Keeping local workers on cores: their CPU time at the start (until measured), then
    // each one's core group (kept for later frames).
    std::vector<uint64_t> cpu_at_start_;
    std::vector<int> worker_cores_;
    int lost_worker_ = -1;
    std::string error_;
};

std::vector<int> spread_order(int count) {
    int bits = 0;
    while ((1 << bits) < count) ++bits;
    std::vector<int> order;
    order.reserve(size_t(count));
    for (int k = 0; k < (1 << bits); ++k) {
        int r = 0;
        for (int b = 0; b < bits; ++b) r |= ((k >> b) & 1) << (bits - 1 - b);
        if (r < count) order.push_back(r);
    }
    return order;
}

TcpSession::TcpSession(TcpOptions tcp) : tcp_(std::move(tcp)) {}
TcpSession::~TcpSession() = default;

int TcpSession::frames_on_these_workers() const {
    return coordinator_ ? coordinator_->frames() : 0;
}

bool TcpSession::workers_forked() const { return coordinator_ && coordinator_->forked(); }

int TcpSession::processes_started() const {
    return processes_started_before_ +
           (coordinator_ ? coordinator_->processes_started() : 0);
}

void TcpSession::release_workers() {
    if (coordinator_) coordinator_->release_workers();
}

Image TcpSession::render(const Scene& scene, const SceneSource& source,
                         const trace::RenderSettings& settings,
                         const SpaceOptions& options, SpaceStats* stats,
                         const trace::RenderPlan* plan) {
    FixedJob fixed = FixedJob::of(source.parse, settings, options);
    auto retire = [&] {
        if (!coordinator_) return;
        processes_started_before_ += coordinator_->processes_started();
        coordinator_.reset();
    };
    if (coordinator_ && (coordinator_->failed() || coordinator_->released() ||
                         coordinator_->fixed() != fixed))
        retire();
    for (;;) {
        if (!coordinator_) coordinator_ = std::make_unique<TcpCoordinator>(tcp_, fixed);
        try {
            return coordinator_->render(scene, source, settings, options, stats, plan);
        } catch (const WorkerLost& e) {
            retire();
            if (!tcp_.recover) throw;
            if (!tcp_.workers.empty()) {
                // Running workers are someone else's: the lost one is left out, the
                // others (back to waiting for a job) take its boxes.
                if (e.worker < 0 || size_t(e.worker) >= tcp_.workers.size() ||
                    tcp_.workers.size() <= 1)
                    throw;
                tcp_.workers.erase(tcp_.workers.begin() + e.worker);
                std::fprintf(
                    stderr,
                    "povwall: %s: its boxes went to the other workers; the frame "
                    "is traced again on %zu running worker%s\n",
                    e.what(), tcp_.workers.size(), tcp_.workers.size() == 1 ? "" : "s");
                continue;
            }
            if (tcp_.procs <= 1) throw;
            tcp_.procs -= 1;
            std::fprintf(stderr,
                         "povwall: %s: its boxes went to the other workers; the frame is "
                         "traced again on %d worker process%s\n",
                         e.what(), tcp_.procs, tcp_.procs == 1 ? "" : "es");
        } catch (const DistribError&) {
            retire();
            throw;
        } catch (const std::exception& e) {
            retire();
            throw DistribError(e.what());
        }
    }
}

}  // namespace povwall::distrib
