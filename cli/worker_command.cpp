// `povwall worker`: hosts black boxes for a coordinator (`povwall render --workers`, or
// `--rendezvous` when a launcher such as srun or mpirun started the workers).
#include <CLI/CLI.hpp>

#include "cli/options.h"
#include "cli/parse_args.h"
#include "distrib/tcp.h"
#include "output/image_io.h"

namespace povwall::cli {

int run_worker_command(int argc, char** argv) {
    distrib::WorkerOptions w;
    CLI::App app{"Host black boxes for a distributed render", "povwall worker"};
    app.add_option("--listen", w.listen, "address to listen on (port 0: any, printed)")
        ->capture_default_str();
    app.add_option("--token", w.token, "job token a coordinator must present")
        ->required();
    app.add_option("--threads", w.threads, "render threads (0: all cores)");
    app.add_flag("--once", w.once,
                 "exit after one job (default: serve jobs until killed)");
    app.add_option("--rendezvous", w.rendezvous,
                   "launcher mode (srun, mpirun): register at the coordinator's "
                   "HOST:PORT, serve one job");
    app.add_option("--rank", w.rank, "this worker's rank (default: from srun/mpirun)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--size", w.size, "workers in the launch (default: from srun/mpirun)")
        ->check(CLI::PositiveNumber);
    app.add_option("--rendezvous-timeout", w.rendezvous_timeout,
                   "seconds to wait for the rendezvous and the coordinator's job")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    // Fault injection for the tests: the process dies or hangs after handling N work
    // items, or prepares S seconds longer.
    app.add_option("--die-after-items", w.die_after_items)->group("");
    app.add_option("--hang-after-items", w.hang_after_items)->group("");
    app.add_option("--slow-prepare", w.slow_prepare)->group("");
    if (auto done = parse_args(app, argc, argv)) return *done;
    w.image_reader = output::read_stored_image;
    return distrib::run_worker(w);
}

}  // namespace povwall::cli
