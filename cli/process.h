// Running another program (POV-Ray, or this binary for a job) without a shell.
#pragma once

#include <string>
#include <vector>

namespace povwall::cli {

// run_process's result when the program ran past its time limit and was killed.
constexpr int kProcessTimedOut = -2;

// Runs `args` (args[0] searched on PATH), stdout discarded, stderr to `log` ("" discards
// it too); returns its exit status, 128 + the signal number if it died of a signal, -1 if
// it cannot run. With `timeout_seconds` > 0 a program still running after that long is
// killed (SIGKILL: a hung render may ignore anything gentler) and kProcessTimedOut is
// returned. A non-empty `working_dir` is the program's current folder (files it writes
// with relative names land there). With `grace_seconds` > 0 a program past its time is
// first sent SIGTERM and given that long to end on its own (a povwall render then writes
// to the log where it was).
int run_process(const std::vector<std::string>& args, const std::string& log = "",
                double timeout_seconds = 0, const std::string& working_dir = "",
                double grace_seconds = 0);

}  // namespace povwall::cli
