// libFuzzer target: POV-Ray .ini option files and the +X switches they expand to. Any
// outcome but options or a UsageError is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "cli/options.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    povwall::cli::RenderOptions options;
    try {
        povwall::cli::apply_ini_stream(in, "fuzz.ini", options);
        povwall::cli::resolve_partial_render(options);
    } catch (const povwall::cli::UsageError&) {
    }
    return 0;
}
