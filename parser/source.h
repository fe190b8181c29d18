// Source files and tokens. Every token keeps its file and byte offset; line and column
// are computed only when a diagnostic is printed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/memory.h"
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

// Large buffers written once from start to end (a big file's token array, the object
// list) ask for huge pages or are mapped ahead: core/memory.h.
using povwall::advise_huge_pages;
using povwall::populate_for_write;

// A token as a file stores it: 12 bytes instead of a Token's 48, because machine-written
// files have tens of millions (a 1,000,000-triangle mesh2: 14 million, 690 MB as Tokens)
// and every byte of them is touched once more, for the first time, when they are
// written. `aux`: a Word's symbol, the index of a Number's value in TokenArray::numbers,
// of a String's text in SourceFile::strings, where a Directive's name starts after its
// '#', or a Punct's characters (first in the low byte). The kind shares a word with the
// length, which the lexer caps at kMaxTokenLength.
inline constexpr uint32_t kMaxTokenLength = (uint32_t(1) << 24) - 1;

struct PackedToken {
    uint32_t offset = 0, aux = 0;
    uint32_t length_and_kind = 0;  // length in the low 24 bits, the kind above them

    PackedToken() = default;
    PackedToken(uint32_t offset_, uint32_t length, uint32_t aux_, TokenKind kind)
        : offset(offset_), aux(aux_), length_and_kind(length | uint32_t(kind) << 24) {}
    TokenKind kind() const { return TokenKind(length_and_kind >> 24); }
    uint32_t length() const { return length_and_kind & kMaxTokenLength; }
    // A one-character Punct token that is `c`.
    bool is_punct(char c) const {
        return length_and_kind == (1u | uint32_t(TokenKind::Punct) << 24) &&
               aux == uint8_t(c);
    }
};
static_assert(sizeof(PackedToken) == 12);

struct SourceFile;

// A file's bytes: owned in a string, or, for a large file read from disk, mapped
// read-only from the page cache. Reading a 48 MB mesh2 file into fresh memory cost
// more system time (first touch of every page, on a VM) than lexing it.
class SourceText {
  public:
    SourceText() = default;
    SourceText(std::string text) : owned_(std::move(text)) {}  // NOLINT: implicit
    SourceText(SourceText&& other) noexcept { *this = std::move(other); }
    SourceText& operator=(SourceText&& other) noexcept;
    SourceText(const SourceText&) = delete;
    SourceText& operator=(const SourceText&) = delete;
    ~SourceText();

    // The file at `path`; false when it cannot be opened or read (or is a folder).
    bool read_file(const std::string& path);
    const char* data() const { return mapped_ ? mapped_ : owned_.data(); }
    size_t size() const { return mapped_ ? mapped_size_ : owned_.size(); }
    std::string_view view() const { return {data(), size()}; }
    operator std::string_view() const { return view(); }  // NOLINT: implicit
    // Mapped from its file: writing that file while it is parsed would change or cut
    // the bytes under the parser, so #fopen refuses to.
    bool mapped() const { return mapped_ != nullptr; }

  private:
    std::string owned_;
    const char* mapped_ = nullptr;
    size_t mapped_size_ = 0;
};

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
    SourceText text;
    std::vector<uint32_t> line_starts;
    int index = -1;                                     // in its SourceManager
    TokenArray tokens{*this};                           // always ends with an End token
    std::vector<std::unique_ptr<std::string>> strings;  // unescaped string literals
};

inline const char* TokenArray::text() const { return file_.text.data(); }

inline Token TokenArray::operator[](size_t i) const {
    const PackedToken& p = packed[i];
    Token t;
    t.kind = p.kind();
    t.file = file_.index;
    t.offset = p.offset;
    t.length = p.length();
    const char* at = file_.text.data() + p.offset;
    switch (t.kind) {
        case TokenKind::End:
            break;
        case TokenKind::Word:
            t.text = std::string_view(at, t.length);
            t.sym = p.aux;
            break;
        case TokenKind::Number:
            t.text = std::string_view(at, t.length);
            t.number = numbers[p.aux];
            break;
        case TokenKind::String:
            t.text = *file_.strings[p.aux];
            break;
        case TokenKind::Directive:
            t.text = std::string_view(at + p.aux, t.length - p.aux);
            break;
        case TokenKind::Punct:
            t.text = std::string_view(at, t.length);
            break;
    }
    return t;
}

class SourceManager {
  public:
    // Takes the text, splits lines and lexes; throws ParseError on a lexical error.
    int add(std::string path, SourceText text);
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
