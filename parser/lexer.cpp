// Lexer: one pass over a file's bytes into a token vector.
#include <algorithm>
#include <array>
#include <charconv>
#include <cstdlib>
#include <cstring>

#include "parser/parser.h"
#include "parser/source.h"

namespace povwall::parser {

namespace {

bool is_ident_start(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_ident(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// One-character punctuation, by table: a string search (memchr) per token was 4 % of a
// mesh2 file's parse.
constexpr std::array<bool, 256> kPunctTable = [] {
    std::array<bool, 256> t{};
    for (char c : std::string_view("{}()[]<>,;+-*/?:=!&|.")) t[uint8_t(c)] = true;
    return t;
}();
bool is_punct_char(char c) { return kPunctTable[uint8_t(c)]; }

constexpr double kPowersOfTen[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

[[noreturn]] void lex_error(const SourceManager& sm, int file, uint32_t offset,
                            uint32_t length, const std::string& message) {
    throw ParseError(ParseError::Kind::Syntax,
                     format_diagnostic_at(sm, file, offset, length, "error", message),
                     message, sm.location(file, offset));
}

void lex(SourceManager& sm, int file_index, SourceFile& f) {
    const std::string_view s = f.text.view();
    const size_t n = s.size();
    size_t i = 0;
    // Dense machine-written files average about 3.5 bytes per token; reserving up front
    // avoids copying a large token vector as it grows (untouched pages cost nothing).
    std::vector<PackedToken>& tokens = f.tokens.packed;
    std::vector<double>& numbers = f.tokens.numbers;
    tokens.reserve(n / 3 + 16);
    advise_huge_pages(tokens.data(), tokens.capacity() * sizeof(PackedToken));
    // About two in five tokens of such files are numbers.
    numbers.reserve(n / 8 + 16);
    advise_huge_pages(numbers.data(), numbers.capacity() * sizeof(double));
    auto push = [&](TokenKind kind, size_t start, size_t len, uint32_t aux = 0) {
        if (len > kMaxTokenLength) {
            lex_error(sm, file_index, uint32_t(start), 1,
                      "token longer than " + std::to_string(kMaxTokenLength) + " bytes");
        }
        tokens.emplace_back(uint32_t(start), uint32_t(len), aux, kind);
    };
    while (i < n) {
        char c = s[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' ||
            c == '\x1a') {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < n && s[i + 1] == '/') {
            while (i < n && s[i] != '\n' && s[i] != '\r')
                ++i;  // CR alone ends a line too
            continue;
        }
        if (c == '/' && i + 1 < n && s[i + 1] == '*') {
            // POV-Ray block comments nest.
            size_t start = i;
            int depth = 0;
            while (i < n) {
                if (s[i] == '/' && i + 1 < n && s[i + 1] == '*') {
                    ++depth;
                    i += 2;
                } else if (s[i] == '*' && i + 1 < n && s[i + 1] == '/') {
                    i += 2;
                    if (--depth == 0) break;
                } else {
                    ++i;
                }
            }
            if (depth != 0)
                lex_error(sm, file_index, uint32_t(start), 2, "unterminated comment");
            continue;
        }
        size_t start = i;
        if (is_digit(c) || (c == '.' && i + 1 < n && is_digit(s[i + 1]))) {
            // The digits as an integer, for the exact fast path below.
            uint64_t mantissa = 0;
            int digits = 0, fraction_digits = 0;
            while (i < n && is_digit(s[i])) {
                mantissa = mantissa * 10 + uint64_t(s[i++] - '0');
                ++digits;
            }
            bool point = false;
            if (i < n && s[i] == '.') {
                point = true;
                ++i;
                while (i < n && is_digit(s[i])) {
                    mantissa = mantissa * 10 + uint64_t(s[i++] - '0');
                    ++digits;
                    ++fraction_digits;
                }
            }
            bool exponent = false;
            if (i < n && (s[i] == 'e' || s[i] == 'E')) {
                size_t j = i + 1;
                if (j < n && (s[j] == '+' || s[j] == '-')) ++j;
                if (j < n && is_digit(s[j])) {
                    exponent = true;
                    i = j;
                    while (i < n && is_digit(s[i])) ++i;
                }
            }
            // POV-Ray's tokenizer stops at a second point ("0.0.95", "1e5.2"), not
            // reading it as the start of another number.
            if (i < n && s[i] == '.' && (point || exponent))
                lex_error(sm, file_index, uint32_t(i), 1,
                          "unexpected additional '.' in floating-point number");
            push(TokenKind::Number, start, i - start, uint32_t(numbers.size()));
            double& value = numbers.emplace_back();
            if (!exponent && digits <= 15) {
                // Up to 15 digits and no exponent: the integer and 10^k are exact doubles
                // and one correctly rounded division gives the correctly rounded value,
                // as from_chars would (which was 13 % of a mesh2 file's parse).
                value = double(mantissa) / kPowersOfTen[size_t(fraction_digits)];
                continue;
            }
            // from_chars: no allocation or locale; strtod only for what it does not take.
            auto [end, ec] = std::from_chars(s.data() + start, s.data() + i, value);
            if (ec != std::errc() || end != s.data() + i) {
                value =
                    std::strtod(std::string(s.substr(start, i - start)).c_str(), nullptr);
            }
            continue;
        }
        if (is_ident_start(c)) {
            while (i < n && is_ident(s[i])) ++i;
            push(TokenKind::Word, start, i - start,
                 sm.intern(std::string_view(s).substr(start, i - start)));
            continue;
        }
        if (c == '#') {
            size_t j = i + 1;
            while (j < n && (s[j] == ' ' || s[j] == '\t')) ++j;
            if (j < n && is_ident_start(s[j])) {
                size_t w = j;
                while (j < n && is_ident(s[j])) ++j;
                push(TokenKind::Directive, start, j - start, uint32_t(w - start));
                i = j;
                continue;
            }
            // A stray '#' before a line break or brace: POV-Ray reads past it.
            ++i;
            continue;
        }
        if (c == '"') {
            ++i;
            auto value = std::make_unique<std::string>();
            // A line break is part of the string, as in POV-Ray (shapes3.inc has one);
            // a backslash right before it is an error there.
            while (i < n && s[i] != '"') {
                if (s[i] == '\\' && i + 1 < n) {
                    char e = s[i + 1];
                    if (e == '\n' || e == '\r')
                        lex_error(
                            sm, file_index, uint32_t(i), 1,
                            "unterminated string literal (a backslash before a line "
                            "break)");
                    switch (e) {
                        case 'n':
                            value->push_back('\n');
                            break;
                        case 't':
                            value->push_back('\t');
                            break;
                        case 'r':
                            value->push_back('\r');
                            break;
                        case '"':
                            value->push_back('"');
                            break;
                        case '\\':
                            value->push_back('\\');
                            break;
                        case 'a':
                            value->push_back('\a');
                            break;
                        case 'b':
                            value->push_back('\b');
                            break;
                        case 'f':
                            value->push_back('\f');
                            break;
                        case 'v':
                            value->push_back('\v');
                            break;
                        case '\'':
                            value->push_back('\'');
                            break;
                        default:
                            // POV-Ray keeps unknown escapes (Windows paths) as written.
                            value->push_back('\\');
                            value->push_back(e);
                    }
                    i += 2;
                    continue;
                }
                value->push_back(s[i++]);
            }
            if (i >= n || s[i] != '"') {
                lex_error(sm, file_index, uint32_t(start), 1, "unterminated string");
            }
            ++i;
            push(TokenKind::String, start, i - start, uint32_t(f.strings.size()));
            f.strings.push_back(std::move(value));
            continue;
        }
        if ((c == '<' || c == '>' || c == '!') && i + 1 < n && s[i + 1] == '=') {
            push(TokenKind::Punct, start, 2, uint8_t(c) | uint32_t('=') << 8);
            i += 2;
            continue;
        }
        if (is_punct_char(c)) {
            push(TokenKind::Punct, start, 1, uint8_t(c));
            ++i;
            continue;
        }
        lex_error(sm, file_index, uint32_t(start), 1,
                  std::string("unexpected character '") + c + "'");
    }
    push(TokenKind::End, n, 0);
}

}  // namespace

int SourceManager::add(std::string path, SourceText text) {
    if (text.size() >= size_t(UINT32_MAX)) {
        const std::string msg = "'" + path + "' is larger than 4 GiB";
        throw ParseError(ParseError::Kind::Io, "povwall: error: " + msg, msg, {});
    }
    auto f = std::make_unique<SourceFile>();
    f->path = std::move(path);
    f->text = std::move(text);
    f->line_starts.push_back(0);
    // memchr from line to line: a byte loop was 6 % of a 48 MB mesh2 file's parse.
    const char* begin = f->text.data();
    const char* end = begin + f->text.size();
    // A carriage return alone ends a line too (classic Mac files), as POV-Ray reads it;
    // CR LF is one line break. Files without a lone CR take the memchr path.
    bool lone_cr = false;
    for (const char* p = begin; p < end && !lone_cr;) {
        const void* cr = std::memchr(p, '\r', size_t(end - p));
        if (!cr) break;
        p = static_cast<const char*>(cr) + 1;
        lone_cr = p == end || *p != '\n';
    }
    if (lone_cr) {
        for (const char* p = begin; p < end; ++p) {
            if (*p == '\n' || (*p == '\r' && (p + 1 == end || p[1] != '\n')))
                f->line_starts.push_back(uint32_t(p + 1 - begin));
        }
    } else {
        for (const char* p = begin; p < end;) {
            const void* nl = std::memchr(p, '\n', size_t(end - p));
            if (!nl) break;
            p = static_cast<const char*>(nl) + 1;
            f->line_starts.push_back(uint32_t(p - begin));
        }
    }
    int index = int(files_.size());
    f->index = index;
    files_.push_back(std::move(f));
    lex(*this, index, *files_.back());
    return index;
}

uint32_t SourceManager::intern(std::string_view name) {
    auto it = symbols_.find(std::string(name));
    if (it != symbols_.end()) return it->second;
    uint32_t id = uint32_t(symbols_.size()) + 1;
    symbols_.emplace(std::string(name), id);
    return id;
}

uint32_t SourceManager::find_symbol(std::string_view name) const {
    auto it = symbols_.find(std::string(name));
    return it == symbols_.end() ? 0 : it->second;
}

SourceLoc SourceManager::location(int file, uint32_t offset) const {
    if (file < 0 || file >= count()) return {};
    const auto& ls = files_[file]->line_starts;
    auto it = std::upper_bound(ls.begin(), ls.end(), offset);
    int line = int(it - ls.begin());
    return {file, line, int(offset - ls[line - 1]) + 1};
}

std::string_view SourceManager::line_text(int file, int line) const {
    const SourceFile& f = *files_[file];
    if (line < 1 || line > int(f.line_starts.size())) return {};
    size_t start = f.line_starts[line - 1];
    size_t end = line < int(f.line_starts.size()) ? f.line_starts[line] : f.text.size();
    std::string_view v(f.text);
    v = v.substr(start, end - start);
    while (!v.empty() && (v.back() == '\n' || v.back() == '\r')) v.remove_suffix(1);
    return v;
}

std::string format_diagnostic_at(const SourceManager& sm, int file, uint32_t offset,
                                 uint32_t length, std::string_view severity,
                                 std::string_view message) {
    SourceLoc loc = sm.location(file, offset);
    std::string out;
    if (!loc.valid()) {
        out += "povwall: ";
        out += severity;
        out += ": ";
        out += message;
        return out;
    }
    out += sm.file(file).path + ":" + std::to_string(loc.line) + ":" +
           std::to_string(loc.column) + ": " + std::string(severity) + ": " +
           std::string(message) + "\n";
    // Source line with tabs expanded to 8 columns, then the caret at the same visual
    // column.
    std::string_view line = sm.line_text(file, loc.line);
    std::string shown, pad;
    for (size_t i = 0; i < line.size(); ++i) {
        char c = line[i];
        bool before = int(i) < loc.column - 1;
        if (c == '\t') {
            size_t w = 8 - shown.size() % 8;
            shown.append(w, ' ');
            if (before) pad.append(w, ' ');
        } else {
            shown.push_back(c);
            if (before) pad.push_back(' ');
        }
    }
    out += shown + "\n" + pad + "^";
    uint32_t line_left = uint32_t(line.size()) - uint32_t(loc.column - 1);
    uint32_t tilde = std::min(length, line_left);
    if (tilde > 1) out.append(tilde - 1, '~');
    return out;
}

std::string format_diagnostic(const SourceManager& sm, const Token& at,
                              std::string_view severity, std::string_view message) {
    return format_diagnostic_at(sm, at.file, at.offset, std::max<uint32_t>(at.length, 1),
                                severity, message);
}

}  // namespace povwall::parser
