#include "cli/process.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

extern char** environ;

namespace povwall::cli {
namespace {

using Clock = std::chrono::steady_clock;

int exit_code_of(int status) {
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

int wait_blocking(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return exit_code_of(status);
}

// Waits at most until `deadline`; true (and the exit code) when the child ended. A pidfd
// wakes us the moment the child exits, so short renders are timed exactly; kernels
// without pidfd_open (before 5.3) fall back to polling every millisecond.
bool wait_until(pid_t pid, Clock::time_point deadline, int& code) {
    const int pidfd = int(syscall(SYS_pidfd_open, pid, 0));
    for (;;) {
        int status = 0;
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid) {
            if (pidfd >= 0) close(pidfd);
            code = exit_code_of(status);
            return true;
        }
        if (r < 0 && errno != EINTR) {  // not our child any more: nothing to wait for
            if (pidfd >= 0) close(pidfd);
            code = -1;
            return true;
        }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - Clock::now());
        if (left.count() <= 0) {
            if (pidfd >= 0) close(pidfd);
            return false;
        }
        if (pidfd >= 0) {
            pollfd p{pidfd, POLLIN, 0};
            poll(&p, 1, int(std::min<long long>(left.count() + 1, 1000)));
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }
}

}  // namespace

int run_process(const std::vector<std::string>& args, const std::string& log,
                double timeout_seconds, const std::string& working_dir,
                double grace_seconds) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 2, log.empty() ? "/dev/null" : log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    if (!working_dir.empty())
        posix_spawn_file_actions_addchdir_np(&fa, working_dir.c_str());
    pid_t pid;
    const auto start = Clock::now();
    int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) return -1;
    if (timeout_seconds <= 0) return wait_blocking(pid);
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(timeout_seconds));
    int code = 0;
    if (wait_until(pid, deadline, code)) return code;
    if (grace_seconds > 0) {
        kill(pid, SIGTERM);
        const auto grace = std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(grace_seconds));
        if (wait_until(pid, Clock::now() + grace, code)) return kProcessTimedOut;
    }
    kill(pid, SIGKILL);
    wait_blocking(pid);  // reap it: no zombie left behind
    return kProcessTimedOut;
}

}  // namespace povwall::cli
