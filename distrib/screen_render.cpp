#include "distrib/screen_render.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <functional>
#include <mutex>
#include <thread>

#include "distrib/child_process.h"
#include "trace/tile_render.h"

extern char** environ;

namespace povwall::distrib {
namespace {

constexpr uint32_t kReplyMagic = 0x70775331;      // "pwS1": protocol version 1
constexpr uint32_t kHeartbeatMagic = 0x70774831;  // "pwH1": still rendering the tile
constexpr double kHeartbeatSeconds = 1.0;

struct TileRequest {
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // x1 <= x0: stop
};

struct TileReply {
    uint32_t magic = kReplyMagic;
    int32_t x0 = 0, y0 = 0, x1 = 0,
            y1 = 0;             // all zero: "ready" after preparing the scene
    trace::TraceCounters rays;  // cumulative for the worker
};

// Moves all n bytes with ::read or ::write, retrying short transfers and EINTR; false on
// end of file or error.
template <class Transfer, class Byte>
bool transfer_all(Transfer transfer, int fd, Byte* p, size_t n) {
    while (n) {
        ssize_t done = transfer(fd, p, n);
        if (done < 0 && errno == EINTR) continue;
        if (done <= 0) return false;
        p += done;
        n -= size_t(done);
    }
    return true;
}

bool write_all(int fd, const void* data, size_t n) {
    return transfer_all(::write, fd, static_cast<const char*>(data), n);
}

bool read_all(int fd, void* data, size_t n) {
    return transfer_all(::read, fd, static_cast<char*>(data), n);
}

enum class ReadStatus { Ok, Closed, Silent };

// read_all, but a worker that sends nothing for `seconds` is Silent (hung or stopped).
ReadStatus read_within(int fd, void* data, size_t n, double seconds) {
    char* p = static_cast<char*>(data);
    while (n) {
        pollfd pfd{fd, POLLIN, 0};
        const int ready = ::poll(&pfd, 1, int(seconds * 1000));
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) return ReadStatus::Silent;
        if (ready < 0) return ReadStatus::Closed;
        ssize_t done = ::read(fd, p, n);
        if (done < 0 && errno == EINTR) continue;
        if (done <= 0) return ReadStatus::Closed;
        p += done;
        n -= size_t(done);
    }
    return ReadStatus::Ok;
}

struct WorkerProcess {
    pid_t pid = -1;
    int to = -1, from = -1;  // its stdin (we write), its stdout (we read)
};

WorkerProcess spawn_worker(const std::vector<std::string>& command) {
    int in[2], out[2];
    if (pipe2(in, O_CLOEXEC) != 0) throw ScreenError("cannot create a pipe for a worker");
    if (pipe2(out, O_CLOEXEC) != 0) {
        close(in[0]);
        close(in[1]);
        throw ScreenError("cannot create a pipe for a worker");
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    WorkerProcess w;
    int rc = posix_spawn(&w.pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(in[0]);
    close(out[1]);
    if (rc != 0) {
        close(in[1]);
        close(out[0]);
        throw ScreenError("cannot start worker '" + command[0] +
                          "': " + std::strerror(rc));
    }
    w.to = in[1];
    w.from = out[0];
    return w;
}

// Tiles handed out to the worker threads. A tile whose worker died goes back to the pool
// for another worker; a thread with nothing to take waits while tiles are still in other
// workers' hands, since one of those may come back.
class TilePool {
  public:
    explicit TilePool(int tiles) : tiles_(tiles) {}

    // The next tile, or -1 when every tile is done or the render stopped.
    int take() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            if (stopped_) return -1;
            if (!returned_.empty()) {
                const int t = returned_.back();
                returned_.pop_back();
                ++in_flight_;
                return t;
            }
            if (next_ < tiles_) {
                ++in_flight_;
                return next_++;
            }
            if (in_flight_ == 0) return -1;
            changed_.wait(lock);
        }
    }
    void done() {
        update([&] { --in_flight_; });
    }
    void give_back(int tile) {
        update([&] {
            --in_flight_;
            returned_.push_back(tile);
        });
    }
    void stop() {
        update([&] { stopped_ = true; });
    }
    bool all_done() {
        std::lock_guard<std::mutex> lock(mutex_);
        return !stopped_ && next_ == tiles_ && returned_.empty() && in_flight_ == 0;
    }

  private:
    template <class F>
    void update(F&& f) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            f();
        }
        changed_.notify_all();
    }
    std::mutex mutex_;
    std::condition_variable changed_;
    const int tiles_;
    int next_ = 0, in_flight_ = 0;
    std::vector<int> returned_;
    bool stopped_ = false;
};

}  // namespace

Image render_screen(const trace::RenderSettings& settings, const ScreenOptions& options,
                    ScreenStats* stats) {
    auto t0 = std::chrono::steady_clock::now();
    const int W = settings.width, H = settings.height;
    const int r0 = std::clamp(settings.first_row, 0, H);
    const int r1 = settings.last_row < 0 ? H : std::min(settings.last_row + 1, H);
    const int c0 = std::clamp(settings.first_col, 0, W);
    const int c1 = settings.last_col < 0 ? W : std::min(settings.last_col + 1, W);
    const int T = std::max(1, options.tile);
    const int tiles_x = std::max(0, (c1 - c0 + T - 1) / T);
    const int tiles_y = std::max(0, (r1 - r0 + T - 1) / T);
    const int tiles = tiles_x * tiles_y;
    const int n = std::max(1, options.workers);

    // A worker that dies must not kill the coordinator with SIGPIPE: its write fails
    // instead.
    struct sigaction ignore {
    }, previous{};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous);

    std::vector<WorkerProcess> workers;
    std::string error;
    try {
        for (int i = 0; i < n; ++i)
            workers.push_back(spawn_worker(options.worker_command));
        std::vector<pid_t> pids;
        for (const WorkerProcess& w : workers) pids.push_back(w.pid);
        maybe_inject_worker_fault(pids);
    } catch (const ScreenError& e) {
        error = e.what();
    }
    Image image(W, H);
    if (settings.progress) settings.progress->start_pass(uint64_t(c1 - c0) * (r1 - r0));
    TilePool pool(tiles);
    if (!error.empty()) pool.stop();
    std::vector<std::string> lost;  // workers whose tiles went to the others
    std::vector<char> hung;         // killed for silence: their exit status says nothing
    std::mutex mutex;
    ScreenStats local;
    local.tiles = tiles;
    local.tiles_per_worker.assign(workers.size(), 0);
    auto serve = [&](size_t wi) {
        WorkerProcess& w = workers[wi];
        std::vector<float> pixels;
        TileReply ready;
        ReadStatus st = ReadStatus::Ok;
        // An answer: heartbeats (each within the timeout) until the real one.
        auto read_reply = [&](TileReply& reply) {
            for (;;) {
                st = read_within(w.from, &reply, sizeof reply, options.heartbeat_timeout);
                if (st != ReadStatus::Ok || reply.magic != kHeartbeatMagic) return;
            }
        };
        read_reply(ready);  // the scene is parsed and prepared
        bool ok = st == ReadStatus::Ok && ready.magic == kReplyMagic;
        trace::TraceCounters counts;  // the worker's, as last reported
        int t = -1;
        while (ok && (t = pool.take()) >= 0) {
            TileRequest rq;
            rq.x0 = c0 + (t % tiles_x) * T;
            rq.y0 = r0 + (t / tiles_x) * T;
            rq.x1 = std::min(rq.x0 + T, c1);
            rq.y1 = std::min(rq.y0 + T, r1);
            TileReply reply;
            ok = write_all(w.to, &rq, sizeof rq);
            if (ok) read_reply(reply);
            ok = ok && st == ReadStatus::Ok && reply.magic == kReplyMagic &&
                 reply.x0 == rq.x0 && reply.y0 == rq.y0 && reply.x1 == rq.x1 &&
                 reply.y1 == rq.y1;
            const int tw = rq.x1 - rq.x0;
            if (ok) {
                pixels.resize(size_t(tw) * (rq.y1 - rq.y0) * 4);
                st = read_within(w.from, pixels.data(), pixels.size() * sizeof(float),
                                 options.heartbeat_timeout);
                ok = st == ReadStatus::Ok;
            }
            if (!ok) {
                if (options.recover)
                    pool.give_back(t);
                else
                    pool.stop();
                break;
            }
            for (int y = rq.y0; y < rq.y1; ++y) {
                std::memcpy(image.pixel(rq.x0, y), &pixels[size_t(y - rq.y0) * tw * 4],
                            size_t(tw) * 4 * sizeof(float));
            }
            if (settings.progress) {
                settings.progress->rays += reply.rays.rays() - counts.rays();
                settings.progress->pixels_done += uint64_t(tw) * (rq.y1 - rq.y0);
            }
            counts = reply.rays;  // counters are cumulative per worker
            ++local.tiles_per_worker[wi];
            pool.done();
        }
        if (ok) {
            TileRequest stop;
            write_all(w.to, &stop, sizeof stop);
        }
        // Hung (stopped, looping, deadlocked): it will not exit on its own.
        const bool silent = !ok && st == ReadStatus::Silent;
        if (silent) kill(w.pid, SIGKILL);
        close(w.to);
        close(w.from);
        std::lock_guard<std::mutex> lock(mutex);
        local.rays += counts;
        if (!ok) {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%g", options.heartbeat_timeout);
            const std::string who =
                "screen worker " + std::to_string(wi + 1) + " (pid " +
                std::to_string(w.pid) + ") " +
                (silent ? std::string("sent nothing for ") + seconds + " s (hung): killed"
                        : std::string("stopped answering"));
            if (silent) hung[wi] = true;
            if (options.recover)
                lost.push_back(who);
            else if (error.empty())
                error = who;
        }
    };
    std::vector<std::thread> threads;
    hung.assign(workers.size(), false);
    for (size_t i = 0; i < workers.size(); ++i) threads.emplace_back(serve, i);
    for (auto& t : threads) t.join();
    // Every worker that could still render is out of tiles: what is left had nobody.
    if (error.empty() && !pool.all_done())
        error = "every screen worker stopped answering";
    for (size_t i = 0; i < workers.size(); ++i) {
        // Every tile is in (or the job failed): a worker gets 10 s to exit on its own.
        const int status = wait_child(workers[i].pid, 10.0);
        const bool clean = hung[i] || (WIFEXITED(status) && WEXITSTATUS(status) == 0);
        const std::string pid = "(pid " + std::to_string(workers[i].pid) + ")";
        if (!clean && error.find(pid) != std::string::npos)
            error += ": " + describe_exit_status(status);
        for (std::string& l : lost) {
            if (!clean && l.find(pid) != std::string::npos)
                l += " (" + describe_exit_status(status) + ")";
        }
    }
    if (error.empty()) {
        for (const std::string& l : lost)
            std::fprintf(stderr, "povwall: %s: its tiles went to the other workers\n",
                         l.c_str());
    }
    sigaction(SIGPIPE, &previous, nullptr);
    if (!error.empty()) throw ScreenError(error);
    local.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (stats) *stats = local;
    return image;
}

namespace {

// While a tile renders, a heartbeat every second tells the coordinator this worker is
// alive (a tile may take long). Only then: between tiles nobody reads the pipe.
class Heartbeat {
  public:
    Heartbeat(int fd, std::mutex& write_mutex)
        : fd_(fd), write_mutex_(write_mutex), thread_([this] { run(); }) {}
    ~Heartbeat() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            quit_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    void set_rendering(bool on) {  // with write_mutex held
        rendering_ = on;
    }

  private:
    void run() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::duration<double>(kHeartbeatSeconds),
                               [this] { return quit_; })) {
            std::lock_guard<std::mutex> write(write_mutex_);
            if (!rendering_) continue;
            TileReply beat;
            beat.magic = kHeartbeatMagic;
            write_all(fd_, &beat, sizeof beat);
        }
    }
    const int fd_;
    std::mutex& write_mutex_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool quit_ = false;
    bool rendering_ = false;  // guarded by write_mutex_
    std::thread thread_;
};

}  // namespace

int serve_tiles(const std::function<Scene()>& load_scene,
                const trace::RenderSettings& settings, int in_fd, int out_fd,
                int exit_after_tiles) {
    std::mutex write_mutex;  // replies and heartbeats never interleave
    Heartbeat heartbeat(out_fd, write_mutex);
    {
        std::lock_guard<std::mutex> lock(write_mutex);
        heartbeat.set_rendering(true);  // parsing and preparing: busy too
    }
    const Scene scene = load_scene();
    trace::TileRenderer renderer(scene, settings);
    {
        std::lock_guard<std::mutex> lock(write_mutex);
        heartbeat.set_rendering(false);
        TileReply ready;
        if (!write_all(out_fd, &ready, sizeof ready)) return 1;
    }
    std::vector<float> pixels;
    for (;;) {
        TileRequest rq;
        if (!read_all(in_fd, &rq, sizeof rq)) return 1;  // coordinator gone
        if (rq.x1 <= rq.x0) return 0;
        if (exit_after_tiles >= 0 && exit_after_tiles-- == 0) return 3;
        if (rq.x0 < 0 || rq.y0 < 0 || rq.x1 > settings.width || rq.y1 > settings.height ||
            rq.y1 < rq.y0)
            return 1;
        pixels.resize(size_t(rq.x1 - rq.x0) * (rq.y1 - rq.y0) * 4);
        {
            std::lock_guard<std::mutex> lock(write_mutex);
            heartbeat.set_rendering(true);
        }
        renderer.render(rq.x0, rq.y0, rq.x1, rq.y1, pixels.data());
        std::lock_guard<std::mutex> lock(write_mutex);
        heartbeat.set_rendering(false);
        TileReply reply;
        reply.x0 = rq.x0;
        reply.y0 = rq.y0;
        reply.x1 = rq.x1;
        reply.y1 = rq.y1;
        reply.rays = renderer.counters();
        if (!write_all(out_fd, &reply, sizeof reply) ||
            !write_all(out_fd, pixels.data(), pixels.size() * sizeof(float)))
            return 1;
    }
}

}  // namespace povwall::distrib
