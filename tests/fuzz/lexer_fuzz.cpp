// libFuzzer target: the lexer alone. Arbitrary bytes must give tokens (ending with End,
// each inside the text, each printable as a diagnostic) or a located ParseError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "parser/parser.h"
#include "parser/source.h"

using namespace povwall::parser;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    SourceManager sm;
    int index;
    try {
        index =
            sm.add("fuzz.pov", std::string(reinterpret_cast<const char*>(data), size));
    } catch (const ParseError&) {
        return 0;
    }
    const SourceFile& f = sm.file(index);
    if (f.tokens.empty() || f.tokens.back().kind != TokenKind::End) std::abort();
    for (const Token& t : f.tokens) {
        if (size_t(t.offset) + t.length > f.text.size()) std::abort();
    }
    // Diagnostics at the first and last tokens must format (line lookup, caret).
    (void)format_diagnostic(sm, f.tokens.front(), "error", "x");
    (void)format_diagnostic(sm, f.tokens.back(), "error", "x");
    return 0;
}
