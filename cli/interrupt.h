// What a render in this process is doing, for the line SIGINT/SIGTERM print: parsing
// which file and line, preparing the scene, building the octree, tracing and how far,
// writing which image. run_render() keeps it current; the handler (main.cpp) reads it.
#pragma once

#include <atomic>
#include <cstddef>

#include "core/published_place.h"
#include "trace/render.h"

namespace povwall::cli {

enum class RenderPhase : int { None, Parsing, Rendering, Writing, Written };

struct RenderRecord {
    std::atomic<RenderPhase> phase{RenderPhase::None};
    std::atomic<int> frame{-1};  // the animation frame, -1 for a still image
    PublishedPlace parse;        // the parser's file and line (line 0: still reading it)
    PublishedPlace output;       // the image (its line unused)
    trace::RenderProgress progress;
};

// The process's one record. Constant-initialised, so a signal handler may read it at any
// time, even before the first render.
extern RenderRecord g_render_record;

// The line an interrupted render prints, e.g. "\npovwall: interrupted while parsing
// scene.pov:12; no image written\n". Async-signal-safe (lock-free loads, no allocation,
// no stdio): the handler calls it and exits, without unwinding the render, so it must
// not touch a lock the interrupted thread may hold. `partial_removed`: the handler
// removed the temporary of an image being written. Writes at most `capacity` - 1 bytes
// and a NUL; returns the length.
size_t interrupt_message(const RenderRecord& record, bool partial_removed, char* out,
                         size_t capacity) noexcept;

}  // namespace povwall::cli
