// The worker process of black boxes over TCP (`povwall worker`): it hosts some of the
// boxes, takes rays and results from its peers and the coordinator, sends on what leaves
// its boxes, and returns its pixel sums and statistics when the coordinator finishes the
// frame. One io_context on one thread; render threads hand finished frames to it with
// post().
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
#include "parser/parser.h"
#include "trace/object_queries.h"
#include "trace/pattern.h"

namespace povwall::distrib {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// Items for one destination process, batched; frames stay well below the body cap.
struct Outbox {
    static constexpr size_t kFlushBytes = 256 << 10;
    std::mutex mutex;
    std::vector<uint8_t> records;
    uint32_t count = 0;
    uint64_t sent = 0;  // items for this process so far (the status's "sent")
    Buffer take() {     // with mutex held
        auto buf = std::make_shared<std::vector<uint8_t>>();
        encode_frame(FrameType::Items, count, records, *buf);
        records.clear();
        count = 0;
        return buf;
    }
};

// The process's peak resident memory (VmHWM), in bytes; 0 when unknown.
uint64_t peak_resident_bytes() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    unsigned long long kb = 0;
    while (std::fgets(line, sizeof line, f)) {
        if (std::sscanf(line, "VmHWM: %llu kB", &kb) == 1) break;
    }
    std::fclose(f);
    return uint64_t(kb) * 1024;
}

class Worker {
  public:
    explicit Worker(const WorkerOptions& options)
        : options_(options),
          acceptor_(io_),
          status_timer_(io_),
          busy_timer_(io_),
          rendezvous_timer_(io_),
          retry_timer_(io_) {}

    int run() {
        tcp::endpoint ep = resolve(io_, options_.listen);
        acceptor_.open(ep.protocol());
        acceptor_.set_option(tcp::acceptor::reuse_address(true));
        acceptor_.bind(ep);
        acceptor_.listen();
        auto local = acceptor_.local_endpoint();
        std::printf("povwall worker: listening on %s:%u\n",
                    local.address().to_string().c_str(), unsigned(local.port()));
        std::fflush(stdout);
        accept();
        if (!options_.rendezvous.empty()) register_at_rendezvous(local);
        io_.run();
        if (preparing_.joinable()) preparing_.join();
        if (host_) host_->stop();
        if (render_.joinable()) render_.join();
        return exit_code_;
    }

  private:
    // Launcher mode: tell the coordinator's rendezvous this rank's address, retrying
    // while the coordinator is not up yet. A coordinator that never comes ends the
    // worker, so a launch step cannot hang.
    void register_at_rendezvous(tcp::endpoint listening) {
        listening_ = listening;
        rendezvous_timer_.expires_after(
            std::chrono::milliseconds(long(options_.rendezvous_timeout * 1000)));
        rendezvous_timer_.async_wait([this](boost::system::error_code ec) {
            if (ec || coordinator_) return;
            std::fprintf(
                stderr,
                "povwall worker: error: rank %d: no coordinator came through the "
                "rendezvous %s within %g s\n",
                options_.rank, options_.rendezvous.c_str(), options_.rendezvous_timeout);
            exit_code_ = 3;
            io_.stop();
        });
        try_register();
    }

    void try_register() {
        if (coordinator_) return;
        auto socket = std::make_shared<tcp::socket>(io_);
        socket->async_connect(
            resolve(io_, options_.rendezvous),
            [this, socket](boost::system::error_code ec) {
                if (ec) {
                    retry_timer_.expires_after(std::chrono::milliseconds(200));
                    retry_timer_.async_wait([this](boost::system::error_code e) {
                        if (!e) try_register();
                    });
                    return;
                }
                // Listening on every interface: the one that reaches the coordinator is
                // the address its peers can use.
                boost::system::error_code le;
                asio::ip::address host = listening_.address();
                if (host.is_unspecified()) host = socket->local_endpoint(le).address();
                const std::string address =
                    host.to_string() + ":" + std::to_string(listening_.port());
                registration_ =
                    std::make_shared<Connection>(std::move(*socket), options_.rendezvous);
                registration_->on_frame = [](Frame&) {};
                registration_->on_error = [](const std::string&) {};
                registration_->start();
                registration_->send(message_frame(RegisterMessage{
                    options_.token, options_.rank, options_.size, address}));
            });
    }

    void accept() {
        acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
            if (ec) return;
            std::string peer = "?";
            boost::system::error_code pe;
            auto rep = socket.remote_endpoint(pe);
            if (!pe) peer = rep.address().to_string() + ":" + std::to_string(rep.port());
            auto conn = std::make_shared<Connection>(std::move(socket), peer);
            std::weak_ptr<Connection> weak = conn;
            conn->on_frame = [this, weak](Frame& f) { hello(weak.lock(), f); };
            conn->on_error = [](const std::string&) {};
            conn->start();
            accept();
        });
    }

    void hello(std::shared_ptr<Connection> conn, Frame& f) {
        const std::optional<Hello> h = f.type == FrameType::Control
                                           ? hello_from_json(parse_control(f))
                                           : std::nullopt;
        if (!h || h->token != options_.token) {
            std::fprintf(
                stderr,
                "povwall worker: rejected a connection from %s: no valid job token\n",
                conn->name().c_str());
            conn->close();
            return;
        }
        const int from = h->from;
        if (from == -1 && !coordinator_) {
            coordinator_ = conn;
            if (registration_) registration_->close();
            conn->on_frame = [this](Frame& fr) { from_coordinator(fr); };
            conn->on_error = [this](const std::string& why) {
                if (!done_) {
                    std::fprintf(stderr, "povwall worker: coordinator lost: %s\n",
                                 why.c_str());
                }
                end_job(done_);
            };
        } else if (from >= 0) {
            incoming_.push_back(conn);
            std::weak_ptr<Connection> weak = conn;
            conn->on_frame = [this, from, weak](Frame& fr) { from_peer(from, weak, fr); };
            conn->on_error = [this, from, weak](const std::string& why) {
                // A peer that dies shows as a lost connection, which the coordinator
                // sees for itself; one whose bytes are no frame misbehaves.
                if (why.rfind("disconnected", 0) != 0) misbehaving_peer(from, weak, why);
            };
        } else {
            conn->close();
        }
    }

    void from_coordinator(Frame& f) {
        if (f.type == FrameType::Items) {
            if (!items(f)) fail_job("a malformed item frame from the coordinator");
            return;
        }
        if (f.type == FrameType::Samples) return sample_positions(f);
        if (f.type == FrameType::Photons) return photon_records(f);
        const json j = parse_control(f);
        try {
            control(j);
        } catch (const json::exception& e) {
            fail_job(std::string("malformed control message: ") + e.what());
        }
    }

    void control(const json& j) {
        const std::string type = control_type(j);
        if (type != "job" && type != "frame" && !host_) {
            if (!type.empty()) fail_job("'" + type + "' before a job");
            return;
        }
        if (type == "job") {
            job(j);
        } else if (type == "frame") {
            frame(j);
        } else if (type == SamplesSentMessage::kType) {
            // The next run's camera samples (anti-aliasing waves): slot k is the k-th
            // position of the Samples frames before this message.
            const auto sent = read_message<SamplesSentMessage>(j);
            if (running_ || sent.count != pending_samples_.size())
                return fail_job("bad sample list");
            host_->set_samples(std::move(pending_samples_));
            pending_samples_ = {};
            coordinator_->send(message_frame(SamplesTakenMessage{}));
        } else if (type == "photons") {
            // The frame's photon map, whose photons came before (wire/photons.h).
            std::shared_ptr<const trace::PhotonMap> map;
            if (running_ || !photon_map_from_message(j, std::move(pending_photons_), map))
                return fail_job("bad photon map");
            pending_photons_ = {};
            host_->set_photon_map(std::move(map));
        } else if (type == StartMessage::kType) {
            // A frame's first run, or (anti-aliasing) the next wave's.
            if (running_) return fail_job("'start' during a run");
            running_ = true;
            done_ = false;
            std::vector<Bounds3> reach;
            if (!reach_from_json(read_message<StartMessage>(j).reach, host_->box_count(),
                                 reach))
                return fail_job("bad box reach table");
            host_->set_box_reach(std::move(reach));
            // One render thread: the io thread traces itself, between network events.
            inline_ = threads_ == 1;
            if (inline_) {
                host_->begin_run(1);
                // Peers that started first may have sent items already (another
                // connection: no order with this message); they wait in the inboxes, and
                // this worker may get nothing else to wake it (a team without pixels).
                schedule_drain();
            } else {
                render_ = std::thread([this] { host_->run(threads_, false); });
            }
            send_status(-1);
        } else if (type == PixelRangeMessage::kType) {
            const auto range = read_message<PixelRangeMessage>(j);
            if (range.end > host_->item_limits().pixels)
                return fail_job("bad pixel range");
            host_->emit_pixels(int(range.begin), int(range.end));
            if (inline_) schedule_drain();
        } else if (type == ProbeMessage::kType) {
            const auto probe = read_message<ProbeMessage>(j);
            if (probe.seq < 0) return fail_job("bad probe");
            send_status(long(probe.seq));
        } else if (type == FinishMessage::kType) {
            finish();
        }
    }

    // The first frame: the whole job. Later frames arrive as "frame" with new animation
    // values only; processes, peer connections, walls and owners stay.
    void job(const json& j) {
        if (job_) return fail_job("a second job on one connection");
        job_ = worker_job_from_json(j);
        owner_ = job_->owner;
        self_ = job_->index;
        prepare_then([this] { connect_peers(); });
    }

    // After the first frame's preparation: connect to every other worker, then ready.
    void connect_peers() {
        const std::vector<std::string>& addresses = job_->workers;
        peers_.resize(addresses.size());
        for (size_t i = 0; i < addresses.size(); ++i)
            outboxes_.push_back(std::make_unique<Outbox>());
        // Only the workers of its team (those its owner table names) get its rays.
        std::vector<uint8_t> needed(addresses.size(), 0);
        for (int o : owner_)
            if (o >= 0 && size_t(o) < needed.size()) needed[size_t(o)] = 1;
        int to_connect = 0;
        for (size_t i = 0; i < addresses.size(); ++i)
            to_connect += int(i) != self_ && needed[i];
        auto remaining = std::make_shared<int>(to_connect);
        if (to_connect == 0) coordinator_->send(message_frame(ready_message()));
        for (size_t i = 0; i < addresses.size(); ++i) {
            if (int(i) == self_ || !needed[i]) continue;
            auto socket = std::make_shared<tcp::socket>(io_);
            tcp::endpoint ep;
            try {
                ep = resolve(io_, addresses[i]);
            } catch (const DistribError& e) {
                return fail_job(e.what());
            }
            socket->async_connect(ep, [this, socket, i, remaining,
                                       address =
                                           addresses[i]](boost::system::error_code ec) {
                if (ec) {
                    // Most likely that worker died: said as its loss, which the
                    // coordinator can recover from, not as this worker's refusal.
                    return fail_job("not reachable from worker " + std::to_string(self_) +
                                        " (" + address + ": " + ec.message() + ")",
                                    int(i));
                }
                auto conn = std::make_shared<Connection>(std::move(*socket), address);
                conn->on_frame = [](Frame&) {};
                conn->on_error = [](const std::string&) {
                };  // the coordinator sees the death
                conn->start();
                conn->send(hello_frame({options_.token, self_}));
                peers_[i] = conn;
                if (--*remaining == 0) coordinator_->send(message_frame(ready_message()));
            });
        }
    }

    void frame(const json& j) {
        if (!job_ || !done_) return fail_job("a frame before the previous one finished");
        FrameJob next = frame_job_from_json(j);
        if (next.expected_objects.size() != job_->frame.expected_objects.size())
            return fail_job("a frame for another number of workers");
        job_->frame = std::move(next);
        job_->inherited = false;
        done_ = false;
        prepare_then([this] { coordinator_->send(message_frame(ready_message())); });
    }

    // Parsing and building the boxes run beside the io thread, which meanwhile tells the
    // coordinator every second that this worker is busy, not hung; `next` runs on the io
    // thread when they succeed.
    void prepare_then(std::function<void()> next) {
        busy_ = true;
        busy_beat();
        preparing_ =
            std::thread([this, next = std::move(next), generation = generation_.load()] {
                std::string error;
                const bool ok = prepare(error);
                asio::post(io_, [this, ok, error, next, generation] {
                    if (generation != generation_) return;  // the job ended meanwhile
                    busy_ = false;
                    busy_timer_.cancel();
                    preparing_.join();
                    if (!ok) return fail_job(error);
                    next();
                });
            });
    }

    void busy_beat() {
        busy_timer_.expires_after(std::chrono::seconds(1));
        busy_timer_.async_wait([this](boost::system::error_code ec) {
            if (ec || !busy_ || !coordinator_) return;
            coordinator_->send(message_frame(BusyMessage{}));
            busy_beat();
        });
    }

    // `culprit`: the index of a peer that caused the failure (one this worker could
    // not reach, or one that sent it a malformed item frame; -1: none).
    void fail_job(const std::string& message, int culprit = -1) {
        coordinator_->send(message_frame(ErrorMessage{message, culprit}));
    }

    // Parses the scene at the job's animation values and builds this worker's boxes (off
    // the io thread: sends nothing; false with `error` set on a parse error).
    bool prepare(std::string& error) {
        if (options_.slow_prepare > 0)
            std::this_thread::sleep_for(
                std::chrono::duration<double>(options_.slow_prepare));
        const FixedJob& fixed = job_->fixed;
        parser::ParseOptions popts;
        popts.image_reader = options_.image_reader;
        popts.function_hooks = trace::parse_time_function_hooks();
        popts.object_queries = trace::parse_time_object_queries();
        popts.write_user_files = false;  // the coordinator's parse writes them
        fixed.apply_to(popts);
        job_->frame.animation.apply_to(popts);
        settings_.width = popts.image_width = fixed.width;
        settings_.height = popts.image_height = fixed.height;
        settings_.alpha = fixed.alpha;
        settings_.plan_everything_on = fixed.plan_everything_on;
        // The previous frame's boxes point into the previous scene: gone first.
        host_.reset();
        numbers_.reset();
        // Only the objects in this worker's boxes are kept (boxes_holding, the test
        // every process makes), so the worker never holds the whole scene.
        VirtualWalls walls(job_->walls);
        mine_.clear();
        for (size_t b = 0; b < owner_.size(); ++b) {
            if (owner_[b] == self_) mine_.push_back(int(b));
        }
        std::vector<uint8_t> hosted(size_t(walls.box_count()), 0);
        for (int b : mine_) hosted[size_t(b)] = 1;
        popts.expected_objects = job_->frame.expected_objects.at(size_t(self_));
        const std::vector<WalkReach>& walk = job_->frame.walk_reaches;
        auto whole = std::make_shared<trace::PovWholeScene>();
        auto keep = [&walls, &hosted, &walk](const Object& o) {
            for (int b : boxes_holding(walls, o, walk))
                if (hosted[size_t(b)]) return true;
            return false;
        };
        popts.keep_object = [&keep, &whole](const Object& o) {
            const bool kept = keep(o);
            whole->add(o, kept);
            return kept;
        };
        try {
            if (job_->inherited && options_.inherited_scene &&
                options_.inherited_objects) {
                // Forked after the coordinator's parse of this frame: no parse here.
                // Its object list stays in the inherited scene, never freed: the
                // process ends with _exit, and freeing would write to (copy) the pages
                // it still shares with the coordinator.
                const std::vector<uint32_t>& kept =
                    options_.inherited_objects->at(size_t(self_));
                size_t next = 0;
                for (size_t i = 0; i < options_.inherited_scene->objects.size(); ++i) {
                    const bool mine = next < kept.size() && kept[next] == i;
                    next += mine;
                    whole->add(options_.inherited_scene->objects[i], mine);
                }
                scene_ = take_scene_keeping(std::move(*options_.inherited_scene), kept);
                options_.inherited_scene = nullptr;  // later frames parse
            } else {
                scene_ = parser::parse_scene_text(fixed.scene, fixed.name, popts);
            }
        } catch (const std::exception& e) {
            error = e.what();
            return false;
        }
        fixed.override_settings(scene_);
        space_.results = fixed.results;
        space_.queue = fixed.queue;
        threads_ = options_.threads > 0 ? options_.threads : fixed.threads;
        if (threads_ <= 0)
            threads_ = int(std::max(1u, std::thread::hardware_concurrency()));
        numbers_ = std::make_unique<ObjectNumbers>(scene_);
        host_ = std::make_unique<BoxHost>(scene_, settings_, space_, &job_->frame.plan);
        host_->set_walls(std::move(walls));
        host_->set_whole_scene(std::move(whole));
        host_->build_boxes(mine_);
        if (options_.shared_sums &&
            options_.shared_sums_count == size_t(settings_.width) *
                                              size_t(settings_.height) *
                                              size_t(host_->sum_channels())) {
            host_->use_shared_sums(options_.shared_sums, options_.shared_sum_locks);
            // The pages exist (the coordinator populated them) but this process has no
            // entries for them yet: one call maps them all instead of a fault per 4 KB
            // page as the pixels come (no huge pages for shared memory here). Best
            // effort: kernels before 5.14 fault them in as before.
            madvise(options_.shared_sums, options_.shared_sums_count * sizeof(double),
                    MADV_POPULATE_WRITE);
        }
        if (options_.die_after_items >= 0 || options_.hang_after_items >= 0) {
            host_->on_processed = [this] {
                const long n = ++processed_;
                if (n == options_.die_after_items) _exit(9);
                if (n == options_.hang_after_items) raise(SIGSTOP);
            };
        }
        // Render threads share the outboxes; a worker that traces on its io thread
        // (inline_) has no other thread to exclude, and skips the lock (two atomic
        // operations per item sent).
        // For the tests: POVWALL_FAULT_MISROUTE=N makes worker 0 send its N-th item to
        // another worker under the number of a box it hosts itself, one the receiver
        // does not host: the receiver must refuse the frame.
        misroute_after_ = -1;
        if (const char* n = std::getenv("POVWALL_FAULT_MISROUTE"); n && self_ == 0)
            misroute_after_ = std::atol(n);
        host_->remote = [this](int box, Item&& item) {
            Outbox& o = *outboxes_[owner_[box]];
            std::unique_lock<std::mutex> lock(o.mutex, std::defer_lock);
            if (!inline_) lock.lock();
            const size_t before = o.records.size();
            const int named =
                misroute_after_ >= 0 && long(o.sent) == misroute_after_ && !mine_.empty()
                    ? mine_[0]
                    : box;
            write_item(o.records, named, item, *numbers_);
            const size_t bytes = o.records.size() - before;
            ++o.sent;
            if (++o.count, o.records.size() >= Outbox::kFlushBytes)
                post(owner_[box], o.take());
            return bytes;
        };
        host_->flush = [this] {
            for (size_t w = 0; w < outboxes_.size(); ++w) {
                Outbox& o = *outboxes_[w];
                std::unique_lock<std::mutex> lock(o.mutex, std::defer_lock);
                if (!inline_) lock.lock();
                if (o.count) post(int(w), o.take());
            }
        };
        return true;
    }

    ReadyMessage ready_message() const {
        ReadyMessage ready{mine_, {}, scene_.objects.size(), scene_.objects_left_out};
        for (int b : mine_) ready.primitives.push_back(host_->primitive_count(b));
        return ready;
    }

    void post(int worker, Buffer buf) {
        asio::post(io_, [this, worker, buf, generation = generation_.load()] {
            if (generation == generation_ && peers_[worker]) peers_[worker]->send(buf);
        });
    }

    // The coordinator closed its connection: after a finished frame (the job is over) or
    // in the middle (it failed, or gave this job up after losing another worker). With
    // --once the process ends; otherwise everything of the job goes and the worker waits
    // for the next coordinator, so a render that lost one worker can retry on the others.
    void end_job(bool finished) {
        if (options_.once) {
            if (!finished) exit_code_ = 3;
            io_.stop();
            return;
        }
        ++generation_;  // handlers posted for this job do nothing now
        if (host_) host_->stop();
        if (render_.joinable()) render_.join();
        inline_ = false;
        if (preparing_.joinable()) preparing_.join();
        status_timer_.cancel();
        busy_timer_.cancel();
        busy_ = false;
        for (auto& c : incoming_) c->close();
        for (auto& c : peers_) {
            if (c) c->close();
        }
        incoming_.clear();
        peers_.clear();
        outboxes_.clear();
        host_.reset();
        numbers_.reset();
        scene_ = Scene{};
        job_.reset();
        owner_.clear();
        mine_.clear();
        done_ = false;
        running_ = false;
        pending_samples_.clear();
        pending_photons_.clear();
        coordinator_.reset();
    }

    // A frame from the worker `from` (its hello's index): only item frames, for boxes
    // this worker hosts, come from peers.
    void from_peer(int from, const std::weak_ptr<Connection>& conn, Frame& f) {
        if (!job_ || size_t(from) >= job_->workers.size() || from == self_)
            return misbehaving_peer(from, conn, "a hello from a worker of no index here");
        if (f.type != FrameType::Items)
            return misbehaving_peer(from, conn, "a frame not of items");
        if (!items(f))
            return misbehaving_peer(
                from, conn, "a malformed item frame, or items for a box not hosted here");
    }

    // Names the peer to the coordinator, which takes it as lost (and recovery leaves it
    // out), and stops reading from it.
    void misbehaving_peer(int from, const std::weak_ptr<Connection>& conn,
                          const std::string& what) {
        if (const auto c = conn.lock()) c->close();
        const std::string said = "sent worker " + std::to_string(self_) + " " + what;
        std::fprintf(stderr, "povwall worker %d: worker %d %s\n", self_, from,
                     said.c_str());
        if (coordinator_ && !done_) fail_job(said, from);
    }

    // Queues a frame's items in their boxes' inboxes; false when it is malformed or holds
    // an item for a box this worker does not host.
    bool items(Frame& f) {
        if (!host_) return true;
        ItemReader rd(f.body, f.count, host_->item_limits(), *numbers_);
        // Records for one box in a row go into its inbox together.
        bool bad = false;
        while (!rd.done() && !bad) {
            const int64_t box = rd.next_box();
            if (box < 0 || box >= host_->box_count() || !host_->hosts(int(box))) {
                bad = true;
                break;
            }
            host_->inject_many(int(box), [&](Item& item) -> size_t {
                if (rd.done() || rd.next_box() != box) return 0;
                int read_box;
                size_t bytes = 0;
                if (!rd.read(read_box, item, bytes)) {
                    bad = true;
                    return 0;
                }
                return bytes;
            });
        }
        bad = bad || rd.bad();
        if (!bad && inline_) schedule_drain();
        return !bad;
    }

    // Inline tracing waits until the frames already received are in: one drain (and one
    // round of sends) for all of them, not one per frame.
    void schedule_drain() {
        if (drain_posted_) return;
        drain_posted_ = true;
        asio::post(io_, [this, generation = generation_.load()] {
            drain_posted_ = false;
            if (generation == generation_ && host_ && inline_) host_->drain();
        });
    }

    void send_status(long seq) {
        if (!coordinator_ || coordinator_->closed() || done_) return;
        // finished before created: a snapshot then never shows fewer created than exist.
        uint64_t finished = host_->finished();
        uint64_t created = host_->created();
        // Items sent to each worker so far: the coordinator keeps crowded local workers
        // on cores with those they trade most with.
        std::vector<uint64_t> sent;
        for (const auto& o : outboxes_) {
            std::unique_lock<std::mutex> lock(o->mutex, std::defer_lock);
            if (!inline_) lock.lock();
            sent.push_back(o->sent);
        }
        coordinator_->send(message_frame(StatusMessage{
            seq, created, finished, host_->pixels_emitted(), std::move(sent)}));
        if (seq < 0) {
            status_timer_.expires_after(std::chrono::milliseconds(10));
            status_timer_.async_wait([this](boost::system::error_code ec) {
                if (!ec) send_status(-1);
            });
        }
    }

    // A Samples frame: positions of the next wave, appended until "samples" ends them.
    void sample_positions(Frame& f) {
        // Samples lie within a pixel or so of the image; at most 64 per pixel on average
        // (the sums are 24-32 bytes per sample and thread).
        const double reach = double(std::max(settings_.width, settings_.height)) + 4;
        // (Focal blur: up to all of a sample's rays each.)
        const trace::FocalBlur* blur = host_ ? host_->focal_blur() : nullptr;
        const int rays = blur ? blur->max_rays() : 0;
        const size_t most = size_t(settings_.width) * size_t(settings_.height) * 64 *
                            size_t(std::max(rays, 1));
        if (!host_ || running_ || pending_samples_.size() + f.count > most ||
            !read_sample_positions(f.body, f.count, reach, pending_samples_, rays))
            return fail_job("bad sample frame");
    }

    void photon_records(Frame& f) {
        // At most 2^28 photons (5 GB): more is no map a scene asks for.
        constexpr size_t kMostPhotons = size_t(1) << 28;
        if (!host_ || running_ || pending_photons_.size() + f.count > kMostPhotons ||
            !read_photons(f.body, f.count, pending_photons_))
            return fail_job("bad photon frame");
    }

    void finish() {
        running_ = false;
        host_->stop();
        if (render_.joinable()) render_.join();
        if (inline_) host_->end_run();
        inline_ = false;
        status_timer_.cancel();
        if (host_->received_bad_result()) {  // as a malformed frame: this worker is lost
            std::fprintf(stderr, "povwall worker: malformed item frame (result slot)\n");
            exit_code_ = 3;
            io_.stop();
            return;
        }
        // Pixel sums, non-zero pixels only, as (index u32, r g b [transmit] f64) records
        // (transmit with alpha output only).
        const int channels = host_->sum_channels();
        const size_t kRecord = pixel_record_size(channels);
        // Frames of 256 KB: the coordinator's receive buffers stay that size.
        const size_t per_frame = (size_t(256) << 10) / kRecord;
        std::vector<uint8_t> body;
        body.reserve(per_frame * kRecord);
        uint32_t count = 0;
        auto flush_pixels = [&] {
            auto buf = std::make_shared<std::vector<uint8_t>>();
            encode_frame(FrameType::Pixels, count, body, *buf);
            coordinator_->send(buf);
            body.clear();
            count = 0;
        };
        host_->for_each_pixel_sum([&](size_t p, const double* s) {
            if (s[0] == 0 && s[1] == 0 && s[2] == 0 && s[3] == 0) return;
            write_pixel_sum(body, uint32_t(p), s, channels);
            if (++count == per_frame) flush_pixels();
        });
        if (count) flush_pixels();
        // Hosted boxes only, each named: the coordinator checks them against its owners.
        DoneMessage done;
        const std::vector<BoxStats> all = host_->box_stats();
        for (int index : mine_) done.boxes.push_back({index, all[size_t(index)]});
        done.peak_resident = peak_resident_bytes();
        coordinator_->send(message_frame(done));
        done_ = true;  // the coordinator closes the connection; then io_.run() returns
    }

    WorkerOptions options_;
    asio::io_context io_;
    tcp::acceptor acceptor_;
    asio::steady_timer status_timer_, busy_timer_;
    asio::steady_timer rendezvous_timer_, retry_timer_;  // launcher mode
    tcp::endpoint listening_;
    std::shared_ptr<Connection> registration_;
    std::thread preparing_;
    bool busy_ = false;  // io thread only
    std::shared_ptr<Connection> coordinator_;
    std::vector<std::shared_ptr<Connection>> incoming_, peers_;
    std::vector<std::unique_ptr<Outbox>> outboxes_;
    Scene scene_;
    trace::RenderSettings settings_;
    SpaceOptions space_;
    std::unique_ptr<ObjectNumbers> numbers_;
    std::unique_ptr<BoxHost> host_;
    std::optional<WorkerJob> job_;  // the job, with the current frame's values
    std::vector<int> owner_, mine_;
    int self_ = 0, threads_ = 1;
    std::thread render_;
    bool inline_ = false;  // this frame is traced on the io thread (one render thread)
    bool drain_posted_ = false;
    std::atomic<long> processed_{0};
    std::atomic<uint64_t> generation_{0};  // jobs served: stale handlers check it
    bool done_ = false;
    bool running_ = false;                                // between "start" and "finish"
    long misroute_after_ = -1;                            // POVWALL_FAULT_MISROUTE
    std::vector<trace::SamplePosition> pending_samples_;  // of the next "samples"
    std::vector<trace::Photon> pending_photons_;          // of the next "photons"
    int exit_code_ = 0;
};

}  // namespace

int run_worker(const WorkerOptions& given) {
    // A worker's buffers (frames, inboxes, queues) grow and shrink with the traffic; by
    // default glibc hands large blocks back to the kernel and the next growth faults
    // fresh pages in again (a quarter of a worker's kernel time). Kept instead: a
    // worker's peak is bounded by the rays in flight.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    try {
        WorkerOptions options = given;
        if (!options.rendezvous.empty()) {
            // Launched by srun/mpirun: one job, then the launch step may end.
            options.once = true;
            if (options.rank < 0 || options.size < 1) {
                std::optional<LauncherRank> r = launcher_rank(std::getenv);
                if (!r)
                    throw DistribError(
                        "--rendezvous needs this process's rank and size: start it "
                        "under srun or mpirun, or give --rank and --size");
                if (options.rank < 0) options.rank = r->rank;
                if (options.size < 1) options.size = r->size;
            }
            if (options.rank >= options.size)
                throw DistribError("--rank " + std::to_string(options.rank) +
                                   " is not below --size " +
                                   std::to_string(options.size));
        }
        if (options.inherited_scene) {
            // A forked worker, which ends with _exit: its state is never freed, since
            // freeing writes to (and so copies) pages it shares with the coordinator, at
            // 17-70 us a page on this VM.
            auto* forked = new Worker(options);
            return forked->run();
        }
        Worker w(options);
        return w.run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "povwall worker: error: %s\n", e.what());
        return 2;
    }
}

}  // namespace povwall::distrib
