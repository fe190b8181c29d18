#include "distrib/worker_processes.h"

#include <fcntl.h>
#include <malloc.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "distrib/tcp.h"

extern char** environ;

namespace povwall::distrib {
namespace {

// Reads the address each started worker prints on its pipe (the last `reads.size()`
// entries of `started`) and closes the pipes.
void read_worker_addresses(const std::vector<int>& reads,
                           std::vector<LocalWorker>& started, const std::string& what) {
    const size_t first = started.size() - reads.size();
    bool failed = false;
    for (size_t i = 0; i < reads.size(); ++i) {
        FILE* in = fdopen(reads[i], "r");
        char line[256] = {};
        const bool got = !failed && std::fgets(line, sizeof line, in) != nullptr;
        std::fclose(in);
        const char* prefix = "povwall worker: listening on ";
        if (failed || !got || std::strncmp(line, prefix, std::strlen(prefix)) != 0) {
            failed = true;
            continue;
        }
        std::string address = line + std::strlen(prefix);
        while (!address.empty() && (address.back() == '\n' || address.back() == '\r'))
            address.pop_back();
        started[first + i].address = address;
    }
    if (failed) throw WorkerLost(what + " did not start");
}

}  // namespace

void spawn_workers(const std::string& binary, const std::string& token, int threads,
                   int count, std::vector<LocalWorker>& started) {
    std::vector<std::string> env_text;
    for (char** e = environ; *e; ++e) {
        if (std::strncmp(*e, "GLIBC_TUNABLES=", 15) != 0) env_text.push_back(*e);
    }
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    std::string t = "GLIBC_TUNABLES=";
    if (tunables && *tunables) t += std::string(tunables) + ":";
    env_text.push_back(t + "glibc.malloc.hugetlb=1");
    env_text.push_back("POVWALL_HEAP_SET=1");
    std::vector<char*> envp;
    for (std::string& e : env_text) envp.push_back(e.data());
    envp.push_back(nullptr);
    const std::string thread_text = std::to_string(threads);
    const char* argv[] = {"povwall", "worker",      "--listen",  "127.0.0.1:0",
                          "--token", token.c_str(), "--threads", thread_text.c_str(),
                          "--once",  nullptr};
    std::vector<int> reads;
    for (int i = 0; i < count; ++i) {
        // Close-on-exec: a worker inherits no other worker's pipe; its stdout (the dup)
        // stays open.
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0)
            throw DistribError("cannot create a pipe for a worker process");
        // posix_spawn, not fork: the child runs no handler of ours (glibc sets caught
        // signals back to their default in it before it unblocks them), so a Ctrl-C
        // between the two cannot make a worker print the coordinator's message, and no
        // copy of the coordinator's page tables is made.
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
        pid_t pid = -1;
        const int rc = posix_spawn(&pid, binary.c_str(), &actions, nullptr,
                                   const_cast<char* const*>(argv), envp.data());
        posix_spawn_file_actions_destroy(&actions);
        if (rc == 0) {
            // A batch task, as forked workers are (fork_workers); set from here, as
            // posix_spawn's attributes take no SCHED_BATCH.
            const sched_param batch{};
            sched_setscheduler(pid, SCHED_BATCH, &batch);
        }
        close(fds[1]);
        if (rc != 0) {
            close(fds[0]);
            for (int fd : reads) close(fd);
            throw DistribError("cannot start a worker process " + binary + ": " +
                               std::strerror(rc));
        }
        started.push_back({pid, ""});
        reads.push_back(fds[0]);
    }
    read_worker_addresses(reads, started, "worker process " + binary);
}

bool single_threaded() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return false;
    char line[256];
    long threads = -1;
    while (std::fgets(line, sizeof line, f)) {
        if (std::strncmp(line, "Threads:", 8) == 0)
            threads = std::strtol(line + 8, nullptr, 10);
    }
    std::fclose(f);
    return threads == 1;
}

void fork_workers(const std::string& token, int threads, const ImageReader& image_reader,
                  Scene* scene, const std::vector<std::vector<uint32_t>>& objects,
                  const SharedPixelSums& sums, int count,
                  std::vector<LocalWorker>& started) {
    std::vector<int> reads;
    std::fflush(nullptr);  // nothing buffered is written twice
    for (int i = 0; i < count; ++i) {
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0)
            throw DistribError("cannot create a pipe for a worker process");
        // Signals blocked across the fork: a Ctrl-C cannot reach the child before it has
        // the default handlers (the coordinator's would print its message).
        sigset_t all, before;
        sigfillset(&all);
        pthread_sigmask(SIG_SETMASK, &all, &before);
        const pid_t pid = fork();
        if (pid == 0) {
            std::signal(SIGINT, SIG_DFL);
            std::signal(SIGTERM, SIG_DFL);
            // Workers share the cores with each other: as batch tasks, one that wakes
            // another by sending it rays is not preempted by it, and runs on through
            // its queue (8 workers on 2 cores: involuntary switches 2,855 -> 511).
            const sched_param batch{};
            sched_setscheduler(0, SCHED_BATCH, &batch);
            // One render thread: the preparing thread allocates from the main arena
            // too, not from a fresh one whose first touch faults in whole huge pages.
            if (threads == 1) mallopt(M_ARENA_MAX, 1);
            pthread_sigmask(SIG_SETMASK, &before, nullptr);
            if (dup2(fds[1], 1) < 0) _exit(127);
            // The coordinator's sockets and the other workers' pipes are not this
            // process's: a copy kept open would hide their closing from the peer.
            close_range(3, ~0U, 0);
            WorkerOptions w;
            w.token = token;
            w.threads = threads;
            w.once = true;
            w.image_reader = image_reader;
            w.inherited_scene = scene;
            w.inherited_objects = &objects;
            w.shared_sums = sums.data();
            w.shared_sums_count = sums.size();
            w.shared_sum_locks = sums.stripe_locks();
            _exit(run_worker(w));
        }
        const int fork_errno = errno;
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        close(fds[1]);
        if (pid < 0) {
            close(fds[0]);
            for (int fd : reads) close(fd);
            throw DistribError(std::string("cannot start a worker process: ") +
                               std::strerror(fork_errno));
        }
        started.push_back({pid, ""});
        reads.push_back(fds[0]);
    }
    read_worker_addresses(reads, started, "a forked worker process");
}

}  // namespace povwall::distrib
