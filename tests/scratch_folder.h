// A scratch folder for one test process, removed when the process exits: ctest runs
// every test in its own process, so folders left behind would pile up in /tmp.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <map>
#include <string>
#include <system_error>

namespace povwall_test {

// temp/PREFIX-PID, created on first use. A forked child that leaves through exit()
// does not remove its parent's folder.
inline std::filesystem::path process_scratch(const std::string& prefix) {
    struct Folder {
        std::filesystem::path path;
        pid_t owner = 0;
        ~Folder() {
            std::error_code ignored;
            if (owner == getpid()) std::filesystem::remove_all(path, ignored);
        }
    };
    static std::map<std::string, Folder> folders;
    Folder& f = folders[prefix];
    if (f.path.empty()) {
        f.owner = getpid();
        f.path = std::filesystem::temp_directory_path() /
                 (prefix + "-" + std::to_string(f.owner));
    }
    std::filesystem::create_directories(f.path);
    return f.path;
}

}  // namespace povwall_test
