// A command's scratch folder: temp/PREFIX-PID, removed when the command returns by any
// path (an error, a refusal, an interrupt that unwinds), unless the user asked to keep
// it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace povwall::cli {

class ScratchFolder {
  public:
    // KEEP empty: a fresh folder under the temp directory, removed at the end;
    // otherwise KEEP itself, created and left in place.
    ScratchFolder(const std::string& prefix, const std::string& keep = {})
        : path_(keep.empty() ? std::filesystem::temp_directory_path() /
                                   (prefix + "-" + std::to_string(getpid()))
                             : std::filesystem::path(keep)),
          remove_(keep.empty()) {
        std::filesystem::create_directories(path_);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    ~ScratchFolder() {
        std::error_code ignored;
        if (remove_) std::filesystem::remove_all(path_, ignored);
    }
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    bool remove_;
};

}  // namespace povwall::cli
