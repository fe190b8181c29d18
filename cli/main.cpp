// The povwall command: subcommands render, diff, compare, corpus, ... and POV-Ray's +X.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/exit_codes.h"
#include "cli/interrupt.h"
#include "cli/option_names.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "cli/tile_worker_job.h"
#include "core/self_exe.h"
#include "distrib/tcp.h"
#include "output/image_io.h"

namespace povwall::cli {
namespace {

// A worker's buffers (frames, inboxes) grow and shrink with the traffic of rays, and
// glibc's malloc takes fresh 4 KB pages from the kernel one fault at a time: 70,000
// faults for 8 workers at 600x600, a sixth of their time on a virtual machine. With
// glibc's huge-page tunable its heap is advised into 2 MB pages (18,000 faults). The
// tunable is read at start only, so a worker executes itself again once with it set
// (a launcher's or the user's own GLIBC_TUNABLES are kept, and extended); so does a
// render that forks its workers (--procs), as they inherit its heap.
void restart_with_huge_page_heap(char** argv) {
    constexpr const char* kTunable = "glibc.malloc.hugetlb=1";
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (std::getenv("POVWALL_HEAP_SET") ||
        (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")))
        return;
    std::string value = tunables && *tunables ? std::string(tunables) + ":" + kTunable
                                              : std::string(kTunable);
    setenv("GLIBC_TUNABLES", value.c_str(), 1);
    setenv("POVWALL_HEAP_SET", "1", 1);  // not twice, whatever the loader did with it
    // The binary's own path, not /proc/self/exe: the process's name (ps, top) is the
    // file name executed, and would read "exe".
    const std::string self = self_exe();
    if (self.empty()) return;
    // Between the exec and main() installing the handler again the disposition is the
    // default: a Ctrl-C there would end the render without a word (under ASan that
    // start takes most of a second). Blocked, it waits for main() to unblock it. The
    // mask outlives the exec.
    sigset_t interrupts, before;
    sigemptyset(&interrupts);
    sigaddset(&interrupts, SIGINT);
    sigaddset(&interrupts, SIGTERM);
    sigprocmask(SIG_BLOCK, &interrupts, &before);
    execv(self.c_str(), argv);
    // Could not: go on with the ordinary heap.
    sigprocmask(SIG_SETMASK, &before, nullptr);
}

const char* kUsage =
    "usage: povwall render SCENE.pov [-o OUT.png] [-W N] [-H N] [-L DIR]... [--threads "
    "N]\n"
    "                      [+POV-Ray switches]\n"
    "       povwall +ISCENE.pov +OOUT.png +W320 +H240 [+Ldir] [+A0.3] [+UA] ...\n"
    "       povwall OPTIONS.ini [+switches]\n"
    "       povwall diff A.png B.png [--json] [-o DIFF.png] [--fail T] [--failpercent "
    "P]\n"
    "                      [--warn T] [--warnpercent P] [--max-rmse R]\n"
    "       povwall compare SCENE.pov [-W N] [-H N] [--json] [--keep DIR] [--threads N]\n"
    "                      [-L DIR]... [+POV-Ray switches]\n"
    "       povwall bench SCENE.pov [-W N] [-H N] [--runs N] [--threads N] [--json]\n"
    "                      [+POV-Ray switches]   (against POV-Ray, alternating, "
    "medians)\n"
    "       povwall parse SCENE.pov [-L DIR]... [--json]   (exit 0 ok, 3 unsupported, 2 "
    "error)\n"
    "       povwall worker --listen HOST:PORT --token T [--threads N]\n"
    "       srun|mpirun ... povwall worker --rendezvous HOST:PORT --token T\n"
    "       povwall check-numerics SCENE.pov [-W N] [-H N] [-L DIR]... [--povray] "
    "[--json]\n"
    "       povwall batch JOBS... [--resume]   (scenes, .ini files, job files)\n"
    "       povwall sweep SCENE.pov [-W N] [-H N] [--repeat N] [--csv F] [--plot "
    "F.svg]\n"
    "       povwall corpus DIR|LIST [-W N] [-H N] [--html OUT/] [--root DIR]\n"
    "                      [--threads N] [--cache DIR] [--timeout S]   (HTML report)\n";

int render_main(const std::vector<std::string>& args) {
    RenderOptions o;
    // A screen worker: its settings are the coordinator's (cli/tile_worker_job.h).
    if (!args.empty() && args[0] == TileWorkerJob::kFlag) {
        TileWorkerJob::from_argv(args).apply_to(o);
        return run_render(o);
    }
    CLI::App app{"Render a POV-Ray scene", "povwall render"};
    std::string scene, output;
    app.add_option("SCENE", scene, "scene file (.pov)");
    app.add_option("-o,--output", output, "output image (format from the extension)");
    app.add_option("-W,--width", o.width, "image width")->capture_default_str();
    app.add_option("-H,--height", o.height, "image height")->capture_default_str();
    app.add_option("-L,--library-path", o.library_paths, "include folder (repeatable)");
    app.add_option("--threads", o.render.threads, "threads (0: all cores)")
        ->capture_default_str();
    app.add_option("--stats", o.stats_file,
                   "write render statistics as JSON (-: stdout)");
    app.add_flag("-q,--quiet", o.quiet, "no timing summary, no #debug output");
    app.add_option("--boxes", o.boxes,
                   "black boxes: NxNxN equal slabs, N (balanced, N x N x N) or auto");
    add_choice_option(
        app, "--mode", o.mode,
        "auto: screen subdivision when the scene fits --worker-memory, else "
        "space subdivision; single; screen; space");
    app.add_option(
        "--worker-memory", o.worker_memory,
        "memory a worker may hold (512M, 2G; default: half of this machine's)");
    add_choice_option(
        app, "--plan", o.plan,
        "auto: leave out what the scene does not need; all: leave nothing out");
    app.add_flag("--explain", o.explain, "print the render plan before rendering");
    app.add_option("--procs", o.procs,
                   "worker processes: screen tiles, or with --boxes black boxes over TCP "
                   "(loopback)");
    add_choice_option(
        app, "--results", o.results,
        "how boxes return colours: forward contributions, parents, or auto");
    add_choice_option(app, "--queue", o.queue, "box work order: priority or fifo");
    std::optional<int> max_trace_level;
    std::optional<double> adc_bailout;
    app.add_option("--max-trace-level", max_trace_level,
                   "override the scene's max_trace_level (1..256)")
        ->check(CLI::Range(1, 256));
    app.add_option("--adc-bailout", adc_bailout,
                   "override the scene's adc_bailout (0..1)")
        ->check(CLI::Range(0.0, 1.0));
    add_parse_limit_options(app, o.max_loop_iterations, o.max_parse_seconds);
    app.add_option("--workers", o.workers,
                   "black boxes in running workers, host:port,...")
        ->delimiter(',');
    app.add_option("--token", o.token, "job token of the running --workers");
    add_choice_option(
        app, "--worker-start", o.worker_start,
        "how --procs starts black-box workers: fork (they inherit the parsed "
        "scene) or exec (each parses it)");
    add_choice_option(
        app, "--worker-cores", o.worker_cores,
        "--procs workers that outnumber the cores: keep each on one core with "
        "those it trades most rays with (auto) or let the system place them "
        "(off)");
    app.add_option("--teams", o.teams,
                   "black-box workers in N teams that each host every box (fewer rays "
                   "between processes, more of the scene in each), or auto: the most "
                   "teams of 2 or more whose workers fit the memory budget")
        ->check([](const std::string& v) -> std::string {
            if (v == "auto") return "";
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != 0 || n < 1 || n > 4096)
                return "a count from 1 to 4096 or auto, not '" + v + "'";
            return "";
        })
        ->capture_default_str();
    std::string rendezvous;
    double rendezvous_timeout = 120;
    app.add_option("--rendezvous", rendezvous,
                   "black boxes in workers a launcher started (srun, mpirun): wait for "
                   "them to register at HOST:PORT");
    app.add_option("--rendezvous-timeout", rendezvous_timeout,
                   "seconds to wait for every rank to register")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    bool no_recover = false;
    app.add_flag("--no-recover", no_recover,
                 "a worker process that dies stops the render (default: its work goes to "
                 "the other workers)");
    std::vector<std::string> pov, rest{"povwall render"};
    for (const auto& a : args) {
        if (looks_like_pov_switch(a) || looks_like_ini_file(a))
            pov.push_back(a);
        else
            rest.push_back(a);
    }
    std::vector<char*> argv;
    for (auto& r : rest) argv.push_back(r.data());
    // POV-Ray's default INI ($POVINI, ./povray.ini, ~/.povray/3.7/povray.ini) first: the
    // named options parsed next, then the switches and .ini files, win over it.
    apply_default_ini(o);
    if (auto done = parse_args(app, int(argv.size()), argv.data())) return *done;
    // Switches and .ini files apply in command-line order, later ones winning (as
    // POV-Ray).
    for (const auto& s : pov) {
        if (looks_like_ini_file(s))
            apply_ini_file(s, o);
        else if (!apply_pov_switch(s, o))
            throw UsageError("unknown switch '" + s + "'");
    }
    // The named options win over the switches and .ini files (an INI's empty
    // Output_File_Name= must not undo `-o`).
    if (!scene.empty()) o.scene = scene;
    if (!output.empty()) o.output = output;
    o.recover = !no_recover;
    if (max_trace_level) o.max_trace_level = max_trace_level;
    if (adc_bailout) o.adc_bailout = adc_bailout;
    if (!rendezvous.empty()) {
        if (!o.workers.empty() || o.procs > 0)
            throw UsageError("--rendezvous finds the workers: no --workers or --procs");
        if (o.token.empty())
            throw UsageError("--rendezvous needs the --token the workers were given");
        try {
            o.workers = distrib::gather_workers(
                rendezvous, o.token, rendezvous_timeout, [&](const std::string& at) {
                    if (!o.quiet)
                        std::fprintf(stderr,
                                     "povwall: rendezvous on %s, waiting for the "
                                     "launched workers\n",
                                     at.c_str());
                });
        } catch (const distrib::DistribError& e) {
            std::fprintf(stderr, "povwall: error: %s (no image written)\n", e.what());
            return exit_code(ExitCode::WorkerLost);
        }
        // A launched worker serves one job: a lost rank cannot be replaced, and srun or
        // mpirun end the step with it anyway.
        o.recover = false;
    }
    return run_render(o);
}

}  // namespace
}  // namespace povwall::cli

// SIGINT/SIGTERM: nothing half-written stays behind (outputs go through a temporary name
// and a rename), and the user is told so, with what the render was doing. Only
// async-signal-safe calls here.
extern "C" void on_interrupt(int sig) {
    const bool removed = povwall::output::remove_partial_output();
    char msg[2 * povwall::PublishedPlace::kCapacity + 256];
    const size_t n = povwall::cli::interrupt_message(povwall::cli::g_render_record,
                                                     removed, msg, sizeof msg);
    ssize_t written = write(2, msg, n);
    (void)written;
    _exit(128 + sig);  // ExitCode::Interrupted for SIGINT
}

int main(int argc, char** argv) {
    using namespace povwall::cli;
    // Worker processes write no image: Ctrl-C (sent to the whole process group) ends
    // them quietly, and the coordinator says what happened. Their handler stays the
    // default from the start (set after a check, a Ctrl-C in between made a worker
    // print the coordinator's line).
    bool worker = argc > 1 && std::strcmp(argv[1], "worker") == 0;
    for (int i = 1; i < argc && !worker; ++i)
        worker = std::strcmp(argv[i], TileWorkerJob::kFlag) == 0;
    // Test hook: a Ctrl-C that lands after the restart's exec, before the handler is set.
    if (std::getenv("POVWALL_HEAP_SET") &&
        std::getenv("POVWALL_FAULT_INTERRUPT_AT_RESTART"))
        raise(SIGINT);
    if (!worker) {
        std::signal(SIGINT, on_interrupt);
        std::signal(SIGTERM, on_interrupt);
    }
    // A restart with the huge-page heap (below) execs with the two blocked; one that
    // came meanwhile is delivered here, to the disposition just set.
    sigset_t interrupts;
    sigemptyset(&interrupts);
    sigaddset(&interrupts, SIGINT);
    sigaddset(&interrupts, SIGTERM);
    sigprocmask(SIG_UNBLOCK, &interrupts, nullptr);
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty()) {
            std::fputs(kUsage, stderr);
            return exit_code(ExitCode::Error);
        }
        const std::string& cmd = args[0];
        // Black-box workers forked by a render (--procs) inherit its heap settings.
        const bool forks_workers =
            cmd == "render" &&
            std::any_of(args.begin(), args.end(), [](const std::string& a) {
                return a == "--procs" || a.rfind("--procs=", 0) == 0;
            });
        if (cmd == "worker" || forks_workers) restart_with_huge_page_heap(argv);
        if (cmd == "render") return render_main({args.begin() + 1, args.end()});
        if (cmd == "diff") return run_diff(argc - 1, argv + 1);
        if (cmd == "compare") return run_compare(argc - 1, argv + 1);
        if (cmd == "bench") return run_bench(argc - 1, argv + 1);
        if (cmd == "parse") return run_parse(argc - 1, argv + 1);
        if (cmd == "worker") return run_worker_command(argc - 1, argv + 1);
        if (cmd == "check-numerics") return run_check_numerics(argc - 1, argv + 1);
        if (cmd == "batch") return run_batch(argc - 1, argv + 1);
        if (cmd == "sweep") return run_sweep(argc - 1, argv + 1);
        if (cmd == "corpus") return run_corpus(argc - 1, argv + 1);
        if (cmd == "-h" || cmd == "--help" || cmd == "help") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (looks_like_pov_switch(cmd) || looks_like_ini_file(cmd))
            return render_main(args);
        throw UsageError("unknown command '" + cmd + "'");
    } catch (const IniFileError& e) {
        std::fprintf(stderr, "povwall: error: %s\n", e.what());
        return exit_code(ExitCode::Error);
    } catch (const UsageError& e) {
        std::string line = "povwall";
        for (int i = 1; i < argc; ++i) line += std::string(" ") + argv[i];
        std::fprintf(stderr, "povwall: error: %s\n  in: %s\n%s", e.what(), line.c_str(),
                     kUsage);
        return exit_code(ExitCode::Error);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "povwall: error: %s\n", e.what());
        return exit_code(ExitCode::Error);
    }
}
