#include "distrib/child_process.h"

#include <poll.h>
#include <sched.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace povwall::distrib {

int wait_child(pid_t pid, double seconds) {
    using WaitClock = std::chrono::steady_clock;
    const auto deadline = WaitClock::now() + std::chrono::duration<double>(seconds);
    // A pidfd becomes readable when the child exits, so the wait ends then rather than at
    // the next poll (at a frame's end the workers exit within a few milliseconds of one
    // another). Without pidfds (kernels before 5.3): a poll every 5 ms.
    const int pidfd = int(syscall(SYS_pidfd_open, pid, 0));
    int status = 0;
    for (;;) {
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid || (r < 0 && errno != EINTR)) break;  // < 0: not ours, or reaped
        const auto left =
            std::chrono::ceil<std::chrono::milliseconds>(deadline - WaitClock::now());
        if (left.count() <= 0) {
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        if (pidfd >= 0) {
            pollfd exited{pidfd, POLLIN, 0};
            poll(&exited, 1, int(std::min<long long>(left.count(), 60'000)));
        } else {
            std::this_thread::sleep_for(std::min(left, std::chrono::milliseconds(5)));
        }
    }
    if (pidfd >= 0) close(pidfd);
    return status;
}

bool keep_on_core(pid_t pid, int group) {
    cpu_set_t allowed;
    if (group < 0 || sched_getaffinity(0, sizeof allowed, &allowed) != 0) return false;
    for (int cpu = 0, seen = 0; cpu < CPU_SETSIZE; ++cpu) {
        if (!CPU_ISSET(cpu, &allowed) || seen++ != group) continue;
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(cpu, &one);
        return sched_setaffinity(pid, sizeof one, &one) == 0;
    }
    return false;
}

uint64_t cpu_nanoseconds(pid_t pid) {
    const std::string path = "/proc/" + std::to_string(pid) + "/schedstat";
    std::FILE* f = std::fopen(path.c_str(), "r");
    if (!f) return 0;
    unsigned long long ns = 0;
    if (std::fscanf(f, "%llu", &ns) != 1) ns = 0;
    std::fclose(f);
    return ns;
}

void maybe_inject_worker_fault(const std::vector<pid_t>& pids) {
    static std::atomic<bool> fired{false};
    int signal = SIGKILL;
    const char* spec = std::getenv("POVWALL_FAULT_KILL_WORKER");
    if (!spec) {
        spec = std::getenv("POVWALL_FAULT_STOP_WORKER");
        signal = SIGSTOP;
    }
    int index = -1, ms = 0;
    if (!spec || std::sscanf(spec, "%d,%d", &index, &ms) != 2) return;
    if (index < 0 || size_t(index) >= pids.size() || fired.exchange(true)) return;
    const pid_t victim = pids[size_t(index)];
    std::thread([victim, ms, signal] {
        std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        kill(victim, signal);
    }).detach();
}

std::string describe_exit_status(int status) {
    if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status))
        return "killed by signal " + std::to_string(WTERMSIG(status));
    return "stopped";
}

}  // namespace povwall::distrib
