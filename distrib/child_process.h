#pragma once
// Waiting for worker processes that this process started. A worker that has finished its
// work but does not exit (stuck in an exit handler, a sanitizer's leak check under
// ptrace) must never hang the render that already has its image: wait with a deadline,
// then kill.
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace povwall::distrib {

// Waits for `pid` up to `seconds`, then SIGKILLs it and reaps it. Returns the wait
// status.
int wait_child(pid_t pid, double seconds);

// Keeps process `pid` (0: this one) on one core: the `group`-th of those this process
// may run on (SpaceOptions::process_cores). False when it cannot.
bool keep_on_core(pid_t pid, int group);

// The time process `pid` has run on a CPU so far, in nanoseconds (/proc/PID/schedstat);
// 0 when unknown.
uint64_t cpu_nanoseconds(pid_t pid);

// "exit code 3", "killed by signal 9".
std::string describe_exit_status(int status);

// Fault injection for the recovery tests: with POVWALL_FAULT_KILL_WORKER="I,MS" in the
// environment, worker I of `pids` (the worker processes just started) is SIGKILLed MS
// milliseconds from now (it dies); with POVWALL_FAULT_STOP_WORKER="I,MS" it is sent
// SIGSTOP (it hangs: alive, pipes and sockets open, silent). Once per process: a retry
// is not hit again.
void maybe_inject_worker_fault(const std::vector<pid_t>& pids);

}  // namespace povwall::distrib
