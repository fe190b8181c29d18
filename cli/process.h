// Running another program (POV-Ray, or this binary for a job) without a shell.
#pragma once

#include <string>
#include <vector>

namespace povwall::cli {

// Runs `args` (args[0] searched on PATH), stdout discarded, stderr to `log` ("" discards
// it too); returns its exit status, 128 if it died of a signal, -1 if it cannot run.
int run_process(const std::vector<std::string>& args, const std::string& log = "");

}  // namespace povwall::cli
