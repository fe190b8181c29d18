#include "distrib/child_process.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>

namespace povwall::distrib {
namespace {

using Clock = std::chrono::steady_clock;

pid_t child_exiting_after(int milliseconds, int code) {
    const pid_t pid = fork();
    if (pid == 0) {
        usleep(useconds_t(milliseconds) * 1000);
        _exit(code);
    }
    return pid;
}

// The wait returns the child's own status when it exits before the deadline, whether it
// had exited already or exits during the wait.
TEST(WaitChild, ReturnsTheStatusOfAChildThatExits) {
    pid_t pid = child_exiting_after(0, 7);
    usleep(50'000);
    int status = wait_child(pid, 10.0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 7);

    pid = child_exiting_after(100, 3);
    const auto t0 = Clock::now();
    status = wait_child(pid, 10.0);
    const double waited = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);
    EXPECT_LT(waited, 9.0);  // ended by the exit, not by the deadline
    // Reaped: the process is gone.
    EXPECT_EQ(waitpid(pid, &status, WNOHANG), -1);
}

// A child that does not exit is killed at the deadline and reaped.
TEST(WaitChild, KillsAChildThatOutlivesTheDeadline) {
    const pid_t pid = child_exiting_after(60'000, 0);
    const auto t0 = Clock::now();
    const int status = wait_child(pid, 0.2);
    const double waited = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
    EXPECT_GE(waited, 0.19);
    int again = 0;
    EXPECT_EQ(waitpid(pid, &again, WNOHANG), -1);
}

}  // namespace
}  // namespace povwall::distrib
