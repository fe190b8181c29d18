// Running the povwall binary from a test: exit code, stdout and stderr, in a scratch
// folder of this test process.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/scratch_folder.h"

namespace povwall_test {

struct RunResult {
    int code;
    std::string out, err;
};

inline std::filesystem::path scratch() { return process_scratch("povwall-cli-test"); }

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// `povwall ARGS` through the shell (ARGS may hold redirections of its own).
inline RunResult run(const std::string& args) {
    std::filesystem::path d = scratch();
    std::string cmd = std::string(POVWALL_BINARY) + " " + args + " >" +
                      (d / "out").string() + " 2>" + (d / "err").string();
    int status = std::system(cmd.c_str());
    return {WEXITSTATUS(status), slurp(d / "out"), slurp(d / "err")};
}

inline std::filesystem::path write_scene(const std::string& name,
                                         const std::string& text) {
    std::filesystem::path p = scratch() / name;
    std::ofstream(p) << text;
    return p;
}

}  // namespace povwall_test
