// Source files and tokens. Every token keeps its file and byte offset; line and column
// are computed only when a diagnostic is printed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/source_loc.h"

namespace povwall::parser {

enum class TokenKind : uint8_t {
    End,  // end of the file's token list
    Number,
    String,     // text holds the unescaped contents
    Word,       // identifier or keyword
    Directive,  // '#' followed by a word: text is the word
    Punct,      // one of { } ( ) [ ] < > , ; + - * / ? : = ! & | . and <= >= !=
};

struct Token {
    TokenKind kind = TokenKind::End;
    int32_t file = -1;
    uint32_t offset = 0, length = 0;
    double number = 0;
    std::string_view text;  // view into the file text, or into SourceFile::strings
    uint32_t sym = 0;       // Word: interned name (SourceManager::intern), 0 otherwise
};

// Large buffers written once from start to end (a big file's text and its token array,
// 48 bytes a token: 690 MB for a 1,000,000-triangle mesh2) take one page fault per 4 KB,
// which cost 1.1 s of system time for that mesh2 on a VM where a fault takes ~6 us. This
// asks for transparent huge pages on the whole 2 MB pages inside [data, data + bytes)
// (THP "madvise" mode, the kernel's default), so they are mapped 2 MB at a time; buffers
// under 8 MB are left alone.
void advise_huge_pages(void* data, size_t bytes);

struct SourceFile {
    std::string path;  // as it will be printed in diagnostics
    std::string text;
    std::vector<uint32_t> line_starts;
    std::vector<Token> tokens;                          // always ends with an End token
    std::vector<std::unique_ptr<std::string>> strings;  // unescaped string literals
};

class SourceManager {
  public:
    // Takes the text, splits lines and lexes; throws ParseError on a lexical error.
    int add(std::string path, std::string text);
    const SourceFile& file(int index) const { return *files_[index]; }
    int count() const { return int(files_.size()); }
    SourceLoc location(int file, uint32_t offset) const;
    SourceLoc location(const Token& t) const { return location(t.file, t.offset); }
    std::string_view line_text(int file, int line) const;
    // Identifiers are interned once when lexed, so symbol lookups hash integers.
    uint32_t intern(std::string_view name);
    uint32_t find_symbol(std::string_view name) const;  // 0 when never interned

  private:
    std::vector<std::unique_ptr<SourceFile>> files_;
    std::unordered_map<std::string, uint32_t> symbols_;
};

// "path:line:col: error: message", the source line and a caret under the token.
std::string format_diagnostic(const SourceManager& sm, const Token& at,
                              std::string_view severity, std::string_view message);
std::string format_diagnostic_at(const SourceManager& sm, int file, uint32_t offset,
                                 uint32_t length, std::string_view severity,
                                 std::string_view message);

}  // namespace povwall::parser
