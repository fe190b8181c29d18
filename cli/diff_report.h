// The report of an image comparison, as `povwall diff` prints it: shared by the diff,
// compare and bench commands (defined in cli/diff_command.cpp).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "output/diff.h"

namespace povwall::cli {

// The comparison's measures and status as JSON (--json).
nlohmann::json diff_json(const output::DiffResult& r);
// The same as text on stdout, `note` just before the PASS, WARNING or FAILURE line.
void print_diff(const output::DiffResult& r, const std::string& note = "");

}  // namespace povwall::cli
