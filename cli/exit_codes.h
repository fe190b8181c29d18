// povwall's exit codes: one table for every command and every render mode (one process,
// --mode screen, --boxes, TCP workers). README.md, "Exit codes", lists the same table;
// tests/cli checks each code.
#pragma once

#include "output/diff.h"

namespace povwall::cli {

enum class ExitCode : int {
    Ok = 0,  // done: the image is written; the images match (a warning included)
    // compare, diff, bench, sweep: the images differ beyond the thresholds (or in size);
    // batch: a job failed.
    Differs = 1,
    Error = 2,          // bad usage, a scene error, an unreadable file: no image
    WorkerLost = 3,     // a worker lost with --no-recover, or one that cannot start
    Unsupported = 3,    // parse only: a feature povwall does not support yet
    NoPovRay = 77,      // compare, bench, corpus, sweep without `povray`: CTest's skip
    Interrupted = 130,  // Ctrl-C, SIGTERM (128 + SIGINT)
};

constexpr int exit_code(ExitCode c) { return static_cast<int>(c); }

// A comparison's code: a warning passes (it is within the thresholds), a failure or a
// size mismatch differs, an unreadable image is an error.
constexpr int exit_code(output::DiffResult::Status s) {
    switch (s) {
        case output::DiffResult::Status::Pass:
        case output::DiffResult::Status::Warn:
            return exit_code(ExitCode::Ok);
        case output::DiffResult::Status::Fail:
        case output::DiffResult::Status::SizeMismatch:
            return exit_code(ExitCode::Differs);
        case output::DiffResult::Status::Unreadable:
            return exit_code(ExitCode::Error);
    }
    return exit_code(ExitCode::Error);
}

}  // namespace povwall::cli
