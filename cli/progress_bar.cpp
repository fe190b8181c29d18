#include "cli/progress_bar.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace povwall::cli {

ProgressBar::ProgressBar(const trace::RenderProgress& progress, bool enabled)
    : progress_(progress) {
    const char* term = std::getenv("TERM");
    if (!enabled || !isatty(STDERR_FILENO) || (term && std::strcmp(term, "dumb") == 0))
        return;
    thread_ = std::thread([this] { run(); });
}

ProgressBar::~ProgressBar() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
    if (drawn_) std::fputs("\r\033[K", stderr);  // the summary line takes its place
}

void ProgressBar::run() {
    using TickClock = std::chrono::steady_clock;
    const auto start = TickClock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_for(lock, std::chrono::milliseconds(500), [&] { return stop_; }))
        return;
    do {
        const double elapsed =
            std::chrono::duration<double>(TickClock::now() - start).count();
        const uint64_t done = progress_.pixels_done.load();
        const uint64_t total = progress_.pixels_total.load();
        if (total == 0) continue;  // a renderer that does not count (black boxes)
        const double share = std::min(1.0, double(done) / double(total));
        const double rays_per_s =
            elapsed > 0 ? double(progress_.rays.load()) / elapsed : 0;
        constexpr int kWidth = 30;
        std::string bar(size_t(share * kWidth), '#');
        bar.resize(kWidth, '.');
        char eta[32] = "--:--";
        if (share > 0.01) {
            const int left = int(elapsed * (1 - share) / share + 0.5);
            std::snprintf(eta, sizeof eta, "%d:%02d", left / 60, left % 60);
        }
        std::fprintf(stderr, "\r%3d%% [%s] %llu/%llu px  %.2f M rays/s  ETA %s\033[K",
                     int(share * 100), bar.c_str(), (unsigned long long)done,
                     (unsigned long long)total, rays_per_s / 1e6, eta);
        std::fflush(stderr);
        drawn_ = true;
    } while (
        !wake_.wait_for(lock, std::chrono::milliseconds(250), [&] { return stop_; }));
}

}  // namespace povwall::cli
