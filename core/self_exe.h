// This process's executable: the path worker processes, batch jobs and benchmarks start
// again (/proc/self/exe resolved, so the processes' names read "povwall", not "exe").
#pragma once

#include <string>

namespace povwall {

// Empty when /proc/self/exe cannot be read.
std::string self_exe();

}  // namespace povwall
