// `povwall parse`: read a scene as POV-Ray would and report what it holds, or why not.
// Exit codes: 0 parsed, 3 uses a feature povwall does not support yet, 2 error.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "output/image_io.h"
#include "parser/parser.h"
#include "trace/object_queries.h"
#include "trace/oracle.h"
#include "trace/pattern.h"

namespace povwall::cli {
namespace {

void count_shapes(const Object& o, std::map<std::string, int>& counts) {
    if (auto c = std::get_if<Csg>(&o.shape)) {
        static const char* kCsg[] = {"union", "merge", "intersection", "difference"};
        ++counts[kCsg[int(c->kind)]];
        for (const Object& ch : c->children) count_shapes(ch, counts);
        return;
    }
    ++counts[trace::shape_kind_name(o)];  // every shape kind's name, in one place
}

}  // namespace

void add_parse_limit_options(CLI::App& app, uint64_t& max_loop_iterations,
                             double& max_parse_seconds) {
    app.add_option("--max-loop-iterations", max_loop_iterations,
                   "runs of one #while/#for before it is stopped as runaway")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--max-parse-seconds", max_parse_seconds,
                   "stop parsing after this many seconds (0: no limit)")
        ->check(CLI::NonNegativeNumber);
}

int run_parse(int argc, char** argv) {
    CLI::App app{
        "Parse a scene and report its contents (exit 0 ok, 3 unsupported, 2 error)",
        "povwall parse"};
    std::string scene;
    std::vector<std::string> library_paths;
    bool json = false;
    app.add_option("SCENE", scene, "scene file")->required();
    app.add_option("-L", library_paths, "include folder (repeatable)");
    app.add_flag("--json", json, "print one JSON object");
    parser::ParseOptions popts;
    add_parse_limit_options(app, popts.max_loop_iterations, popts.max_parse_seconds);
    if (auto done = parse_args(app, argc, argv)) return *done;
    popts.library_paths = library_paths;
    popts.image_reader = output::read_stored_image;
    popts.function_hooks = trace::parse_time_function_hooks();
    popts.object_queries = trace::parse_time_object_queries();
    popts.messages = &std::cerr;  // #debug, #warning: POV-Ray's console streams
    nlohmann::json j;
    j["scene"] = scene;
    // The parse alone, as POV-Ray's "Parse Time": not the counting below, nor freeing the
    // scene.
    const auto t0 = std::chrono::steady_clock::now();
    auto parse_seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
            .count();
    };
    int code = 0;
    try {
        Scene s = parser::parse_scene_file(scene, popts);
        j["seconds"] = parse_seconds();
        std::map<std::string, int> counts;
        for (const Object& o : s.objects) count_shapes(o, counts);
        j["status"] = "ok";
        j["objects"] = s.objects.size();
        j["shapes"] = counts;
        j["lights"] = s.lights.size();
        j["language_version"] = s.language_version / 100.0;
        j["gamma_handling"] = s.gamma_handling();
        j["files"] = s.files;
    } catch (const parser::ParseError& e) {
        j["seconds"] = parse_seconds();
        const bool unsupported = e.kind() == parser::ParseError::Kind::Unsupported;
        code = exit_code(unsupported ? ExitCode::Unsupported : ExitCode::Error);
        j["status"] = unsupported ? "unsupported" : "error";
        j["message"] = e.message();
        if (e.loc().valid()) {
            j["line"] = e.loc().line;
            j["column"] = e.loc().column;
        }
        if (!json) std::cerr << e.what() << "\n";
    }
    if (json) {
        std::printf("%s\n", j.dump().c_str());
    } else if (code == 0) {
        std::printf("%s: %zu objects, %zu lights, #version %.2f\n", scene.c_str(),
                    size_t(j["objects"]), size_t(j["lights"]),
                    double(j["language_version"]));
        for (const auto& [name, n] : j["shapes"].items()) {
            std::printf("  %s: %d\n", name.c_str(), int(n));
        }
    }
    return code;
}

}  // namespace povwall::cli
