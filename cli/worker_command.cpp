// `povwall worker`: hosts black boxes for a coordinator (`povwall render --workers`).
#include <CLI/CLI.hpp>

#include "cli/options.h"
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
    // Fault injection for the tests: the process dies or hangs after handling N work
    // items.
    app.add_option("--die-after-items", w.die_after_items)->group("");
    app.add_option("--hang-after-items", w.hang_after_items)->group("");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    w.image_reader = output::read_stored_image;
    return distrib::run_worker(w);
}

}  // namespace povwall::cli
