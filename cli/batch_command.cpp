// `povwall batch`: many renders unattended. Each job runs as its own `povwall render`
// process, so a job that fails (or crashes) cannot take the others down; the batch keeps
// going, prints a summary table and exits 1 if any job failed. With --resume every job
// gets +C: images that already exist (always complete: they are renamed into place) are
// kept.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "core/self_exe.h"

extern char** environ;

namespace povwall::cli {
namespace {

namespace fs = std::filesystem;

struct Job {
    std::string label;              // as shown in the table
    std::vector<std::string> args;  // arguments of `povwall render`
};

// A job file line: arguments separated by blanks, "double quotes" around one with blanks.
std::vector<std::string> split_line(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    bool quoted = false, any = false;
    for (char c : line) {
        if (c == '"') {
            quoted = !quoted;
            any = true;
        } else if (!quoted && (c == ' ' || c == '\t')) {
            if (any) out.push_back(cur);
            cur.clear();
            any = false;
        } else {
            cur += c;
            any = true;
        }
    }
    if (quoted) throw UsageError("unbalanced quote in job line: " + line);
    if (any) out.push_back(cur);
    return out;
}

std::vector<Job> read_jobs(const std::vector<std::string>& specs) {
    std::vector<Job> jobs;
    for (const std::string& spec : specs) {
        const std::string ext = fs::path(spec).extension().string();
        if (ext == ".pov" || ext == ".ini" || ext == ".INI" || ext == ".POV") {
            jobs.push_back({spec, {spec}});
            continue;
        }
        std::ifstream in(spec);
        if (!in) throw UsageError("cannot open job file '" + spec + "'");
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
            const size_t start = line.find_first_not_of(" \t");
            if (start == std::string::npos || line[start] == '#') continue;
            Job j;
            j.args = split_line(line);
            j.label = spec + ":" + std::to_string(number);
            jobs.push_back(std::move(j));
        }
    }
    return jobs;
}

// What a SIGINT/SIGTERM handler prints: kept up to date after every job.
char g_interrupt_message[256] =
    "\npovwall: batch interrupted before its first job finished\n";

extern "C" void on_batch_interrupt(int sig) {
    ssize_t w = write(2, g_interrupt_message, std::strlen(g_interrupt_message));
    (void)w;
    _exit(128 + sig);  // ExitCode::Interrupted for SIGINT
}

int run_job(const std::string& exe, const Job& job, bool resume) {
    std::vector<std::string> args = {exe, "render"};
    args.insert(args.end(), job.args.begin(), job.args.end());
    if (resume) args.push_back("+C");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid;
    if (posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
        return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

int run_batch(int argc, char** argv) {
    CLI::App app{
        "Run many renders: scenes, .ini files or job files (one render per line)",
        "povwall batch"};
    std::vector<std::string> specs;
    bool resume = false;
    app.add_option("JOBS", specs, "scenes (.pov), option files (.ini) or job files")
        ->required();
    app.add_flag(
        "--resume", resume,
        "keep the images that already exist (+C for every job, frames included)");
    if (auto done = parse_args(app, argc, argv)) return *done;
    const std::vector<Job> jobs = read_jobs(specs);
    const std::string exe = self_exe();
    if (exe.empty()) throw UsageError("cannot find the povwall binary");
    std::signal(SIGINT, on_batch_interrupt);
    std::signal(SIGTERM, on_batch_interrupt);
    struct Row {
        int code;
        double seconds;
    };
    std::vector<Row> rows;
    int failed = 0;
    for (size_t i = 0; i < jobs.size(); ++i) {
        auto t0 = std::chrono::steady_clock::now();
        const int code = run_job(exe, jobs[i], resume);
        rows.push_back(
            {code, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                       .count()});
        failed += code != 0;
        std::snprintf(
            g_interrupt_message, sizeof g_interrupt_message,
            "\npovwall: batch interrupted: %zu of %zu jobs finished (%d failed); their "
            "images are kept, the running job's is not (rerun with --resume)\n",
            i + 1, jobs.size(), failed);
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    std::printf("%-4s %-40s %-10s %8s\n", "#", "job", "status", "seconds");
    for (size_t i = 0; i < jobs.size(); ++i) {
        const int c = rows[i].code;
        const std::string status = c == 0 ? "ok" : "failed(" + std::to_string(c) + ")";
        std::printf("%-4zu %-40s %-10s %8.2f\n", i + 1, jobs[i].label.c_str(),
                    status.c_str(), rows[i].seconds);
    }
    std::printf("%zu jobs: %zu ok, %d failed\n", jobs.size(),
                jobs.size() - size_t(failed), failed);
    return exit_code(failed ? ExitCode::Differs : ExitCode::Ok);
}

}  // namespace povwall::cli
