// The povwall command: subcommands render, diff, compare, and POV-Ray's own +X switches.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli/options.h"

namespace povwall::cli {
namespace {

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
    "       povwall parse SCENE.pov [-L DIR]... [--json]   (exit 0 ok, 3 unsupported, 2 error)\n";

int render_main(const std::vector<std::string>& args) {
    RenderOptions o;
    CLI::App app{"Render a POV-Ray scene", "povwall render"};
    std::string scene;
    app.add_option("SCENE", scene, "scene file (.pov)");
    app.add_option("-o,--output", o.output, "output image (format from the extension)");
    app.add_option("-W,--width", o.width, "image width")->capture_default_str();
    app.add_option("-H,--height", o.height, "image height")->capture_default_str();
    app.add_option("-L,--library-path", o.library_paths, "include folder (repeatable)");
    app.add_option("--threads", o.render.threads, "threads (0: all cores)")
        ->capture_default_str();
    app.add_option("--stats", o.stats_file, "write render statistics as JSON");
    app.add_flag("-q,--quiet", o.quiet, "no timing summary, no #debug output");
    app.add_option("--boxes", o.boxes,
                   "black boxes: NxNxN equal slabs, N (balanced, N x N x N) or auto")
        ->capture_default_str();
    app.add_option("--results", o.results,
                   "how boxes return colours: forward contributions, parents, or auto")
        ->check(CLI::IsMember({"auto", "forward", "parents"}))
        ->capture_default_str();
    app.add_option("--queue", o.queue, "box work order: priority or fifo")
        ->check(CLI::IsMember({"priority", "fifo"}))
        ->capture_default_str();
    std::vector<std::string> pov, rest{"povwall render"};
    for (const auto& a : args) {
        if (looks_like_pov_switch(a) || looks_like_ini_file(a))
            pov.push_back(a);
        else
            rest.push_back(a);
    }
    std::vector<char*> argv;
    for (auto& r : rest) argv.push_back(r.data());
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    // Switches and .ini files apply in command-line order, later ones winning (as
    // POV-Ray).
    for (const auto& s : pov) {
        if (looks_like_ini_file(s))
            apply_ini_file(s, o);
        else if (!apply_pov_switch(s, o))
            throw UsageError("unknown switch '" + s + "'");
    }
    if (!scene.empty()) o.scene = scene;
    return run_render(o);
}

}  // namespace
}  // namespace povwall::cli

int main(int argc, char** argv) {
    using namespace povwall::cli;
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty()) {
            std::fputs(kUsage, stderr);
            return 2;
        }
        const std::string& cmd = args[0];
        if (cmd == "render") return render_main({args.begin() + 1, args.end()});
        if (cmd == "diff") return run_diff(argc - 1, argv + 1);
        if (cmd == "compare") return run_compare(argc - 1, argv + 1);
        if (cmd == "parse") return run_parse(argc - 1, argv + 1);
        if (cmd == "-h" || cmd == "--help" || cmd == "help") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (looks_like_pov_switch(cmd) || looks_like_ini_file(cmd))
            return render_main(args);
        throw UsageError("unknown command '" + cmd + "'");
    } catch (const UsageError& e) {
        std::string line = "povwall";
        for (int i = 1; i < argc; ++i) line += std::string(" ") + argv[i];
        std::fprintf(stderr, "povwall: error: %s\n  in: %s\n%s", e.what(), line.c_str(),
                     kUsage);
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "povwall: error: %s\n", e.what());
        return 2;
    }
}
