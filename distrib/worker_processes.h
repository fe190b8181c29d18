// Local worker processes: started with posix_spawn (a fresh `povwall worker`) or forked
// from the coordinator after its parse (the child holds the parsed scene already). Either
// way each prints its address on a pipe, which is read back here.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "distrib/shared_pixel_sums.h"

namespace povwall::distrib {

struct LocalWorker {
    pid_t pid = -1;
    std::string address;
};

// Starts `count` local workers of `binary` at once (each one's start-up overlaps the
// others') and appends them to `started` as they start, so that a failure leaves every
// started process where its owner can end it; then reads each one's address. The workers
// get glibc's huge-page heap in their environment, so they do not execute themselves
// again to get it. Throws WorkerLost when one does not start.
void spawn_workers(const std::string& binary, const std::string& token, int threads,
                   int count, std::vector<LocalWorker>& started);

// Whether this process runs only the calling thread (/proc/self/status says): only then
// may it fork workers (a fork copies only the calling thread).
bool single_threaded();

// The fork counterpart of spawn_workers: each child is a worker at once, holding the
// coordinator's parsed scene (`scene`, its own copy after the fork), and ends with
// _exit: it never returns into the coordinator's frames, runs none of its destructors
// and flushes none of its buffers. The caller has checked that no other thread runs.
void fork_workers(const std::string& token, int threads, const ImageReader& image_reader,
                  Scene* scene, const std::vector<std::vector<uint32_t>>& objects,
                  const SharedPixelSums& sums, int count,
                  std::vector<LocalWorker>& started);

}  // namespace povwall::distrib
