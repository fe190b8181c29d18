// Screen subdivision: worker processes each hold the whole scene and render the tiles the
// coordinator hands out one at a time, so a worker that finishes early takes the next
// tile and no core idles at the end of a frame (the way PVMPOV and MPI-POVRay work).
//
// Workers are local processes talking over pipes: the coordinator writes a TileRequest to
// a worker's stdin and reads the TileReply (header + RGBA floats) from its stdout; a busy
// worker sends heartbeats, so one that hangs is found within seconds.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "trace/render.h"
#include "trace/tracer.h"

namespace povwall::distrib {

struct ScreenOptions {
    // argv of one worker process; it must run serve_tiles() on stdin/stdout.
    std::vector<std::string> worker_command;
    int workers = 2;
    int tile = 32;  // tile side in pixels
    // A worker that dies or hangs: its tile goes to the others (true) or the render stops
    // (false).
    bool recover = true;
    // A busy worker (parsing, preparing, rendering a tile) sends a heartbeat every
    // second; silent this long, it is hung and killed.
    double heartbeat_timeout = 4.0;
};

struct ScreenStats {
    int tiles = 0;
    std::vector<int> tiles_per_worker;
    trace::TraceCounters rays;
    double seconds = 0;
};

struct ScreenError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Coordinator: the image of `settings` (size, partial-render bounds), tiles handed out
// dynamically to `options.workers` processes. Throws ScreenError (naming the worker) when
// a worker fails; no image is returned then.
Image render_screen(const trace::RenderSettings& settings, const ScreenOptions& options,
                    ScreenStats* stats = nullptr);

// Worker: loads the scene (`load_scene`, whose exceptions pass through) and prepares it
// once, then answers tile requests from `in_fd` on `out_fd` until told to stop, with
// heartbeats on `out_fd` whenever it is busy. Returns the process exit code.
// `exit_after_tiles` >= 0 makes it exit with code 3 after that many tiles (fault
// injection for the tests).
int serve_tiles(const std::function<Scene()>& load_scene,
                const trace::RenderSettings& settings, int in_fd, int out_fd,
                int exit_after_tiles = -1);

}  // namespace povwall::distrib
