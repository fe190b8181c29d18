// Reference renders by POV-Ray 3.7 (the `povray` on PATH) of the scene povwall renders:
// one command line built from povwall's options, and a cache keyed by everything the
// image depends on, so compare, sweep and corpus render each reference once.
#pragma once

#include <string>
#include <vector>

#include "cli/options.h"

namespace povwall::cli {

// The povray command that renders `o` (size, anti-aliasing, alpha, partial render,
// language version, animation or clock, include folders, declares) into the PNG
// `out_png` (numbered per frame for an animation, as POV-Ray numbers them) with
// `threads` threads (0: all cores). `extra` switches are appended as given.
std::vector<std::string> povray_command(const RenderOptions& o,
                                        const std::string& out_png, int threads,
                                        const std::vector<std::string>& extra = {});

// The same render by this povwall binary as a process of its own (as POV-Ray runs: from
// start to exit): the scene, size and include folders of `o`, `threads` threads (0: its
// default), quiet; then `extra` switches. Throws UsageError when the binary cannot be
// found.
std::vector<std::string> povwall_command(const RenderOptions& o,
                                         const std::string& out_png, int threads,
                                         const std::vector<std::string>& extra = {});

struct PovrayRun {
    enum class Status { Ok, NotInstalled, SceneError, Failed } status = Status::Ok;
    // Wall time of the render; for a cached image the time recorded when it was made (0
    // when the cache entry predates recording).
    double seconds = 0;
    bool cached = false;     // the image came from the cache
    bool timed_out = false;  // killed after the time limit (status Failed)
    int exit_code = 0;       // POV-Ray's, when it failed
    std::string log;         // POV-Ray's console output when it failed
    // POV-Ray's image of this scene is random (an area light with `jitter`, photons or a
    // rainbow's `jitter`: it draws them from per-run sequences), so pixels are to be
    // compared as block means.
    // Known when the scene was parsed for a cache key (with a cache folder; corpus always
    // has one).
    bool random = false;
};

// Runs `cmd` (from povray_command) unless `cache_dir` holds its image already; the image
// ends at cmd's +O path. A scene that does not parse for povwall gives SceneError (its
// message printed) when a cache key is needed. With `timeout_seconds` > 0 a render still
// running after that long is killed: Failed with timed_out set, no image left behind.
// A non-empty `working_dir` is POV-Ray's current folder (where the files a scene writes
// with #fopen go).
PovrayRun run_povray(const RenderOptions& o, const std::vector<std::string>& cmd,
                     const std::string& cache_dir, const std::string& log_path,
                     double timeout_seconds = 0, const std::string& working_dir = "");

// The option file a scene comes with, as a user renders it (`povray scene.ini`): the
// file of the same name ending in .ini in the scene's folder, or "" when there is none.
std::string scene_ini_file(const std::string& scene);

// The error message of a failed POV-Ray run, unwrapped onto one line ("File 'x.pov'
// line 3: Parse Error: ..."), or empty when its log names none.
std::string povray_error_lines(const std::string& log);

}  // namespace povwall::cli
