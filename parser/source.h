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

// Large buffers written once from start to end (a big file's text and its token array)
// take one page fault per 4 KB, which cost 1.1 s of system time for a 1,000,000-triangle
// mesh2 on a VM where a fault takes ~6 us. This asks for transparent huge pages on the
// whole 2 MB pages inside [data, data + bytes) (THP "madvise" mode, the kernel's
// default), so they are mapped 2 MB at a time; buffers under 8 MB are left alone.
void advise_huge_pages(void* data, size_t bytes);

// A token as a file stores it: 16 bytes instead of a Token's 48, because machine-written
// files have tens of millions (a 1,000,000-triangle mesh2: 14 million, 690 MB as Tokens)
// and every byte of them is touched once more, for the first time, when they are
// written. `aux`: a Word's symbol, the index of a Number's value in TokenArray::numbers,
// of a String's text in SourceFile::strings, or where a Directive's name starts after
// its '#'.
struct PackedToken {
    uint32_t offset = 0, length = 0, aux = 0;
    TokenKind kind = TokenKind::End;
};

struct SourceFile;

// A file's tokens, read as Token values built from the packed entries.
class TokenArray {
  public:
    explicit TokenArray(const SourceFile& file) : file_(file) {}
    TokenArray(const TokenArray&) = delete;
    TokenArray& operator=(const TokenArray&) = delete;
    Token operator[](size_t i) const;
    size_t size() const { return packed.size(); }
    bool empty() const { return packed.empty(); }
    Token front() const { return (*this)[0]; }
    Token back() const { return (*this)[size() - 1]; }
    struct Iterator {
        const TokenArray* array;
        size_t i;
        Token operator*() const { return (*array)[i]; }
        Iterator& operator++() {
            ++i;
            return *this;
        }
        bool operator!=(const Iterator& o) const { return i != o.i; }
    };
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, size()}; }
    // The file's text: a packed token's characters start at text() + offset.
    const char* text() const;

    // Written by the lexer.
    std::vector<PackedToken> packed;
    std::vector<double> numbers;

  private:
    const SourceFile& file_;
};

struct SourceFile {
    std::string path;  // as it will be printed in diagnostics
    std::string text;
    std::vector<uint32_t> line_starts;
    int index = -1;                                     // in its SourceManager
    TokenArray tokens{*this};                           // always ends with an End token
    std::vector<std::unique_ptr<std::string>> strings;  // unescaped string literals
};

inline const char* TokenArray::text() const { return file_.text.data(); }

inline Token TokenArray::operator[](size_t i) const {
    const PackedToken& p = packed[i];
    Token t;
    t.kind = p.kind;
    t.file = file_.index;
    t.offset = p.offset;
    t.length = p.length;
    const char* at = file_.text.data() + p.offset;
    switch (p.kind) {
        case TokenKind::End:
            break;
        case TokenKind::Word:
            t.text = std::string_view(at, p.length);
            t.sym = p.aux;
            break;
        case TokenKind::Number:
            t.text = std::string_view(at, p.length);
            t.number = numbers[p.aux];
            break;
        case TokenKind::String:
            t.text = *file_.strings[p.aux];
            break;
        case TokenKind::Directive:
            t.text = std::string_view(at + p.aux, p.length - p.aux);
            break;
        case TokenKind::Punct:
            t.text = std::string_view(at, p.length);
            break;
    }
    return t;
}

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
