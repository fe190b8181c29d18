// A progress line for long renders on a terminal: share of pixels done, rays per second,
// time left. Nothing at all when stderr is not a terminal (logs, CI, pipes) or with -q,
// and nothing for renders that end within the first half second.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "trace/render.h"

namespace povwall::cli {

class ProgressBar {
  public:
    // Shows `progress` on stderr when `enabled` and stderr is a terminal.
    ProgressBar(const trace::RenderProgress& progress, bool enabled);
    ~ProgressBar();  // stops and clears the line
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

  private:
    void run();
    const trace::RenderProgress& progress_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    bool drawn_ = false;
    std::thread thread_;
};

}  // namespace povwall::cli
