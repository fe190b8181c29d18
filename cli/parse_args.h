// The command line of a povwall command through CLI11, the same way in every command.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "cli/exit_codes.h"

namespace povwall::cli {

// Parses argv into `app`. Nothing when the command goes on; else the code to exit with:
// 0 after --help, ExitCode::Error on a usage error (CLI11 has printed the message).
inline std::optional<int> parse_args(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? exit_code(ExitCode::Ok) : exit_code(ExitCode::Error);
    }
    return std::nullopt;
}

}  // namespace povwall::cli
