// libFuzzer target: the whole scene pipeline (lexer, directives and macros, expressions,
// scene builder) on arbitrary text. Any outcome but a scene or a ParseError is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "parser/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    povwall::parser::ParseOptions options;
    // No include folders: a standard include would be re-parsed on every input, dividing
    // the executions per second by hundreds (the seeds have their #include lines
    // removed).
    options.messages = nullptr;  // #debug output is not under test
    // Loops stop at a located error after 1,000 iterations (the option's default is 10
    // million) and a parse at 0.02 s (nested loops): mutants of the example scenes loop a
    // lot, and an input that spins must cost milliseconds for the campaign to get
    // anywhere. With 10,000 iterations and 0.1 s, the 4 % of inputs that reached a limit
    // took 97 % of the time (4.5 ms per input on average, 0.2 ms for the others). The
    // limit code runs either way.
    options.max_loop_iterations = 1'000;
    options.max_parse_seconds = 0.02;
    try {
        povwall::parser::parse_scene_text(text, "fuzz.pov", options);
    } catch (const povwall::parser::ParseError&) {
    }
    return 0;
}
