// Black boxes in several processes, over TCP (Boost.Asio, included by
// distrib/connection.h only).
//
// A worker process (`povwall worker --listen HOST:PORT --token T`) hosts some boxes. The
// coordinator (`povwall render ... --procs N` or `--workers h:p,...`) sends every worker
// the scene source and its box assignment; each worker parses the scene and prepares only
// its boxes' local scenes. Rays and results travel worker to worker in framed, batched
// messages (distrib/wire/); camera rays start at the coordinator and pixel sums
// return to it.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "distrib/space_render.h"
#include "distrib/wire/job.h"
#include "trace/render.h"

namespace povwall::distrib {

struct TcpOptions {
    int procs = 0;                     // local worker processes to start on loopback
    std::vector<std::string> workers;  // or running workers, "host:port"
    std::string token;                 // job token (random when empty and procs > 0)
    std::string worker_binary;         // the povwall binary to start (procs > 0)
    // Local workers are forked from this process after its parse: they inherit the
    // parsed scene, so the first frame costs them no exec, no dynamic linking and no
    // parse. Only while this process runs one thread (a fork copies only the calling
    // thread, and a lock another thread held would stay taken in the child); otherwise,
    // or when false, `worker_binary` is executed.
    bool fork_workers = true;
    ImageReader image_reader;  // forked workers' image_map files (later frames' parses)
    double heartbeat_timeout =
        4.0;  // seconds without a message: dead (checked every 0.25 s)
    // A worker that dies, disconnects or goes silent: its boxes are given to the
    // remaining workers (procs - 1 new local processes, or the other running --workers)
    // and the frame is traced again, so the image is the one an undisturbed render gives.
    // Off: the render stops with the worker named.
    bool recover = true;
};

// A worker died, disconnected, went silent or refused the job; what() names it.
struct DistribError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A worker was lost (died, disconnected, went silent), as opposed to a job it refused.
struct WorkerLost : DistribError {
    explicit WorkerLost(const std::string& what, int index = -1)
        : DistribError(what), worker(index) {}
    int worker;  // its index among the coordinator's workers; -1: not known
};

class TcpCoordinator;

// Black boxes kept alive over a sequence of frames (the "framer"). The first frame starts
// (or connects to) the workers and sends each the job: scene source, walls, box owners,
// peers. A later frame sends only what changed, the animation values; each worker parses
// the scene again at its new clock and rebuilds its boxes, while processes, connections,
// walls and box owners stay. A frame whose job differs in anything else (size, options,
// scene text) starts new workers.
class TcpSession {
  public:
    explicit TcpSession(TcpOptions tcp);
    ~TcpSession();
    TcpSession(const TcpSession&) = delete;
    TcpSession& operator=(const TcpSession&) = delete;

    // One frame. A lost local worker with `recover` on: the frame is traced again on new
    // processes, one fewer (WorkerLost when none is left to lose); other failures throw
    // DistribError and end the session's workers.
    // `plan`: the scene's render plan when the caller made it already.
    Image render(const Scene& scene, const SceneSource& source,
                 const trace::RenderSettings& settings, const SpaceOptions& options,
                 SpaceStats* stats = nullptr, const trace::RenderPlan* plan = nullptr);

    // Ends the workers of the last frame (each exits when its connection closes) without
    // waiting for them: they wind down on the other cores while this process writes the
    // image, and the destructor only reaps them. The next render starts new workers.
    void release_workers();

    // Frames the current workers have rendered, this one included.
    int frames_on_these_workers() const;
    // Worker processes this session started (--procs), over all its frames.
    int processes_started() const;
    // Whether the current workers were forked from this process
    // (TcpOptions::fork_workers).
    bool workers_forked() const;

  private:
    TcpOptions tcp_;
    std::unique_ptr<TcpCoordinator> coordinator_;
    int processes_started_before_ = 0;  // by coordinators already replaced
};

struct WorkerOptions {
    std::string listen = "127.0.0.1:0";  // port 0: any; the chosen one is printed
    std::string token;
    int threads = 0;
    ImageReader
        image_reader;  // image_map files named by the scene (the cli's OpenImageIO)
    // Fault injection for the tests, after this many items: the process exits (dies), or
    // stops itself with SIGSTOP (hangs: alive, connected, silent).
    long die_after_items = -1, hang_after_items = -1;
    // ... or its preparation takes this many seconds longer (busy meanwhile, as a worker
    // with a large share of the scene on a loaded machine).
    double slow_prepare = 0;
    // Serve one job and exit (the processes a coordinator starts itself); otherwise the
    // worker serves one job after another until it is killed.
    bool once = false;
    // Launcher mode (srun, mpirun): register at the coordinator's rendezvous address
    // with this process's rank, job size and listening address, then serve one job.
    // rank/size: -1/0 take them from the launcher's environment (launcher_rank).
    std::string rendezvous;
    int rank = -1, size = 0;
    // A forked local worker's copy of the coordinator's parsed scene (its own memory
    // after the fork): the first job, which says so, takes from it the objects of this
    // worker's boxes instead of parsing.
    Scene* inherited_scene = nullptr;
    // With it, every worker's objects: indices into the inherited scene of those that
    // overlap its boxes, ascending, by worker index (as the coordinator found them once,
    // instead of each worker testing every object).
    const std::vector<std::vector<uint32_t>>* inherited_objects = nullptr;
    // A forked local worker's view of the coordinator's pixel sums (SharedPixelSums):
    // it adds its contributions there instead of sending them. Used when the count
    // matches the job's image (width x height x channels).
    double* shared_sums = nullptr;
    size_t shared_sums_count = 0;
    uint32_t* shared_sum_locks = nullptr;  // SharedPixelSums::stripe_locks()
    // Seconds to wait for the rendezvous to answer and then for the coordinator's job;
    // past it the worker ends (exit 3) rather than wait forever under a launcher.
    double rendezvous_timeout = 120;
};

// A process started by a launcher: its rank in [0, size) and which variables told.
struct LauncherRank {
    int rank = 0, size = 1;
    std::string source;  // e.g. "SLURM_PROCID/SLURM_NTASKS"
};
// The rank and size a launcher set in the environment: srun (SLURM_PROCID with
// SLURM_STEP_NUM_TASKS or SLURM_NTASKS), Open MPI's mpirun (OMPI_COMM_WORLD_RANK/SIZE),
// MPICH/Hydra and other PMI launchers (PMI_RANK/PMI_SIZE). Nothing when none is set;
// DistribError when the values are not a rank below a size.
std::optional<LauncherRank> launcher_rank(
    const std::function<const char*(const char*)>& getenv);

// The coordinator's side of launcher mode: listens on `address` until every worker of one
// launch has registered, and returns their addresses in rank order (for --workers).
// `listening` hears the bound address (port 0 picks one). DistribError on a timeout
// (naming the missing ranks), on duplicate ranks or on disagreeing sizes; registrations
// without the job token are refused and said on stderr.
std::vector<std::string> gather_workers(
    const std::string& address, const std::string& token, double timeout_seconds,
    const std::function<void(const std::string&)>& listening = {});

// Serves jobs (each a sequence of frames) and returns the exit code; with `once`, after
// the first job: 0 when the coordinator closed the connection after a finished frame.
int run_worker(const WorkerOptions& options);

// The order in which the coordinator sends the image's camera-ray ranges: 0 .. count-1
// bit-reversed (those past the end skipped), so the ranges in flight at once lie all over
// the image and every worker whose boxes some part of the picture starts in has camera
// rays from the start. In scanline order the first ranges all went to the one or two
// workers hosting the boxes of the top rows while the others waited (2x2x2 over 8
// processes: 1.27 s -> 1.17 s at 600x600).
std::vector<int> spread_order(int count);

// A control frame (JSON text) as the protocol sends it, e.g. for tests that speak to a
// worker directly.
std::vector<uint8_t> encode_control_frame(const std::string& json);

}  // namespace povwall::distrib
