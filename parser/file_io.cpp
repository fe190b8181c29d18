// #fopen, #fclose, #read and #write: a scene's own data files (POV-Ray 3.7 semantics).
// Reading: values separated by optional commas: floats (a sign, then a number), vectors
// of 2 to 5 numbers in <...>, and string literals. After the value that ends the file,
// the file closes and its identifier is undefined, so `#while (defined(F)) #read (F, V)`
// reads every value. Quirks of 3.7 kept: the token after a value is dropped even when it
// is not a comma, and an identifier holding a 2-, 4- or 5-component vector cannot be read
// into. Writing: strings as they are, floats with printf's %g, vectors as
// "<%g,...> " (with the space after '>').
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "parser/interpreter.h"

namespace povwall::parser {

namespace fs = std::filesystem;

namespace {

// `path` lies inside `root` (both absolute and normalised).
bool inside(const fs::path& path, const fs::path& root) {
    const fs::path rel = path.lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}

fs::path normalised(const std::string& dir_or_file) {
    std::error_code ec;
    fs::path p =
        fs::absolute(dir_or_file.empty() ? fs::path(".") : fs::path(dir_or_file), ec);
    fs::path c = fs::weakly_canonical(p, ec);
    return ec ? p.lexically_normal() : c;
}

// POV-Ray 3.7 reads into an undefined identifier or one holding a string, a float or a
// 3-component vector; not into a 2-, 4- or 5-component vector or a colour.
bool read_target(const Value& v) {
    if (std::holds_alternative<std::string>(v)) return true;
    const Numeric* n = std::get_if<Numeric>(&v);
    return n && !n->colour && (n->size == 1 || n->size == 3);
}

std::string describe_value(const Value& v) {
    const Numeric* n = std::get_if<Numeric>(&v);
    if (!n || n->size == 1) return std::string("a ") + type_name(v);
    if (n->colour) return "a colour";
    return "a " + std::to_string(n->size) + "-component vector";
}

// The raw integer formats of #write (POV-Ray 3.7: sint8 ... uint16be).
struct BinaryFormat {
    std::string_view keyword;
    int64_t min, max;
    int bytes;
    bool big_endian;
};
constexpr BinaryFormat kBinaryFormats[] = {
    {"sint8", -128, 127, 1, false},
    {"uint8", 0, 255, 1, false},
    {"sint16le", -32768, 32767, 2, false},
    {"sint16be", -32768, 32767, 2, true},
    {"uint16le", 0, 65535, 2, false},
    {"uint16be", 0, 65535, 2, true},
    {"sint32le", -2147483648LL, 2147483647LL, 4, false},
    {"sint32be", -2147483648LL, 2147483647LL, 4, true},
};

const BinaryFormat* binary_format(const Token& t) {
    if (t.kind != TokenKind::Word) return nullptr;
    for (const BinaryFormat& f : kBinaryFormats) {
        if (t.text == f.keyword) return &f;
    }
    return nullptr;
}

void write_binary(const BinaryFormat& f, const Numeric& n, std::ostream& out) {
    for (int i = 0; i < n.size; ++i) {
        const double x = n.c[i];
        int64_t v;
        if (!(x > double(f.min)))  // NaN writes the minimum, as POV-Ray's comparisons
            v = f.min;
        else if (x >= double(f.max))
            v = f.max;
        else
            v = int64_t(std::floor(x + 0.5));
        for (int j = 0; j < f.bytes; ++j) {
            const int shift = (f.big_endian ? f.bytes - 1 - j : j) * 8;
            out.put(char((uint64_t(v) >> shift) & 0xFF));
        }
    }
}

}  // namespace

// The file `name` stands for, inside the folders a scene may use (see
// ParseOptions::output_dir); empty when reading and no such file exists.
std::string Interpreter::user_file_path(const std::string& name, bool write,
                                        const Token& at) {
    std::vector<std::string> roots{options_.output_dir, scene_dir_};
    if (!write) {
        for (const auto& l : options_.library_paths) roots.push_back(l);
        roots.push_back(options_.standard_include_dir);
    }
    std::vector<fs::path> allowed;
    for (const auto& r : roots) allowed.push_back(normalised(r));
    auto permitted = [&](const fs::path& p) {
        for (const auto& root : allowed)
            if (inside(p, root)) return true;
        return false;
    };
    const fs::path given(name);
    if (name.empty()) error(at, "#fopen: empty file name");
    if (given.is_absolute() || write) {
        fs::path p = normalised(
            given.is_absolute()
                ? name
                : (fs::path(normalised(options_.output_dir)) / given).string());
        if (!permitted(p)) {
            error(at, std::string("#fopen: '") + name +
                          "' is outside the folders a scene may " +
                          (write ? "write (the output folder and the scene's folder)"
                                 : "read (the output folder, the scene's folder and the "
                                   "library paths)"));
        }
        std::error_code ec;
        if (!write && !fs::is_regular_file(p, ec)) return {};
        return p.string();
    }
    for (const auto& root : allowed) {
        fs::path p = normalised((root / given).string());
        std::error_code ec;
        if (permitted(p) && fs::is_regular_file(p, ec)) return p.string();
    }
    return {};
}

void Interpreter::directive_fopen(const Token& t) {
    Token name = next_raw();
    if (name.kind != TokenKind::Word) expected("a file identifier after #fopen", name);
    const Token name_at = peek();
    const std::string file_name = parse_string();
    const Token mode = next();
    auto file = std::make_shared<UserFile>();
    file->name = file_name;
    if (is_word(mode, "read")) {
        const std::string path = user_file_path(file_name, false, name_at);
        SourceText text;
        if (path.empty() || !text.read_file(path))
            error(name_at, "cannot open user file \"" + file_name + "\" for reading");
        file->reading = true;
        file->file = sources_.add(path, std::move(text));
    } else if (is_word(mode, "write") || is_word(mode, "append")) {
        const std::string path = user_file_path(file_name, true, name_at);
        for (int i = 0; i < sources_.count(); ++i) {
            std::error_code ec;
            if (sources_.file(i).text.mapped() &&
                fs::equivalent(path, sources_.file(i).path, ec)) {
                error(name_at, "#fopen: \"" + file_name +
                                   "\" is a source file being parsed; it cannot be "
                                   "written");
            }
        }
        if (options_.write_user_files) {
            auto out = std::make_unique<std::ofstream>(
                path, is_word(mode, "append") ? std::ios::binary | std::ios::app
                                              : std::ios::binary | std::ios::trunc);
            if (!*out)
                error(name_at, "cannot open user file \"" + file_name + "\" for " +
                                   std::string(mode.text));
            file->out = std::move(out);
        }
    } else {
        expected("read, write or append", mode);
    }
    (void)t;
    bind(scopes_[0], sources_.intern(name.text)).value = std::move(file);
}

// Closes the file and undefines its identifier; closing a file that is not open (or
// already closed at the end of a #read) does nothing, as in POV-Ray.
void Interpreter::directive_fclose() {
    Token name = next_raw();
    if (name.kind != TokenKind::Word) expected("a file identifier after #fclose", name);
    int scope = -1;
    Binding* b = find_binding(name.sym ? name.sym : sources_.intern(name.text), &scope);
    if (!b || !std::holds_alternative<std::shared_ptr<UserFile>>(b->value)) return;
    scopes_[size_t(scope)].erase(name.sym ? name.sym : sources_.intern(name.text));
}

std::shared_ptr<UserFile> Interpreter::user_file_argument(const Token& directive,
                                                          Token& id) {
    if (!accept_raw_punct('('))
        expected("'(' after #" + std::string(directive.text), peek());
    id = next_raw();
    const Value* v = id.kind == TokenKind::Word ? lookup(id) : nullptr;
    auto f = v ? std::get_if<std::shared_ptr<UserFile>>(v) : nullptr;
    if (!f) {
        if (id.kind == TokenKind::Word && !v)
            error(id, "'" + std::string(id.text) + "' is not an open file");
        expected("a file identifier", id);
    }
    return *f;
}

void Interpreter::directive_read(const Token& t) {
    // Held here: the identifier is undefined when the file ends.
    Token file_id;
    const std::shared_ptr<UserFile> held = user_file_argument(t, file_id);
    UserFile& file = *held;
    if (!file.reading)
        error(t, "cannot read from file \"" + file.name + "\": it is open for writing");
    const TokenArray& data = sources_.file(file.file).tokens;
    // POV-Ray's raw reads: the next token of the data file, remembering whether it was
    // the end (the state a #read reports back).
    auto get = [&]() {
        Token x = data[std::min(file.pos, data.size() - 1)];
        file.at_end = x.kind == TokenKind::End;
        if (!file.at_end) ++file.pos;
        return x;
    };
    auto unread = [&]() {
        --file.pos;
        file.at_end = false;
    };
    // A float literal with an optional sign; false (nothing read) when there is none.
    auto read_float = [&](double& out) {
        Token x = get();
        if (x.kind == TokenKind::End) return false;
        double sign = 1;
        if (is_punct(x, '-') || is_punct(x, '+')) {
            if (x.text[0] == '-') sign = -1;
            x = get();
            if (x.kind != TokenKind::Number) error(x, "expected a float literal");
        } else if (x.kind != TokenKind::Number) {
            unread();
            return false;
        }
        out = sign * x.number;
        return true;
    };
    // Reads the next value into `v`; true when the file ended (with or without a value).
    auto read_value = [&](Value& v, bool& got) {
        got = false;
        Token x = get();
        if (x.kind == TokenKind::End) return true;
        if (x.kind == TokenKind::Number || is_punct(x, '-') || is_punct(x, '+')) {
            unread();
            double d = 0;
            read_float(d);
            v = Numeric::scalar(d);
        } else if (is_punct(x, '<')) {
            Numeric n;
            n.size = 0;
            double d = 0;
            while (read_float(d)) {
                if (n.size == 5) error(x, "too many components in vector");
                n.c[n.size++] = d;
                Token c = get();
                if (c.kind == TokenKind::End) error(x, "incomplete vector");
                if (!is_punct(c, ',')) unread();
            }
            Token close = get();
            if (!is_punct(close, '>'))
                error(close.kind == TokenKind::End ? x : close,
                      "expected a vector component or '>'");
            if (n.size < 2) error(x, "not enough components in vector");
            n.colour = n.size == 5;
            v = n;
        } else if (x.kind == TokenKind::String) {
            v = std::string(x.text);
        } else {
            error(x, "expected a float, vector or string literal");
        }
        got = true;
        // POV-Ray 3.7 reads the token after a value and drops it, comma or not: "1 2 3"
        // reads as 1 and 3. (3.8 puts back a token that is not a comma.)
        get();
        return file.at_end;
    };
    accept_raw_punct(',');
    bool ended = false;
    for (;;) {
        Token x = next_raw();
        if (is_punct(x, ')')) break;
        if (is_punct(x, ',')) {
            if (!ended) expected("an identifier to read into", x);
            continue;
        }
        if (x.kind != TokenKind::Word) expected("an identifier to read into", x);
        if (ended) continue;
        Value v;
        bool got = false;
        ended = read_value(v, got);
        const uint32_t sym = x.sym ? x.sym : sources_.intern(x.text);
        int scope = -1;
        Binding* b = find_binding(sym, &scope);
        if (!got && !b) {
            // As in POV-Ray, reading at the end of the file still defines a new
            // identifier (with no value: any use of it is an error).
            bind(scopes_[0], sym);
        } else if (got) {
            if (!b) {
                bind(scopes_[0], sym).value = std::move(v);
            } else if (!read_target(b->value)) {
                error(x, "cannot #read into '" + std::string(x.text) + "': it holds " +
                             describe_value(b->value));
            } else if (b->ref_scope >= 0) {
                declare(std::string(x.text), std::move(v), false, x);
            } else {
                b->value = std::move(v);
            }
        }
        accept_raw_punct(',');
    }
    if (ended) {
        // The end of the file closes it and undefines its identifier.
        const uint32_t sym = file_id.sym ? file_id.sym : sources_.intern(file_id.text);
        int scope = -1;
        if (find_binding(sym, &scope)) scopes_[size_t(scope)].erase(sym);
    }
}

void Interpreter::directive_write(const Token& t) {
    // Held here: an item's macro could close or reopen the file.
    Token file_id;
    const std::shared_ptr<UserFile> held = user_file_argument(t, file_id);
    const UserFile& file = *held;
    if (file.reading)
        error(t, "cannot write to file \"" + file.name + "\": it is open for reading");
    std::ostream* out = file.out.get();
    accept_punct(',');
    for (;;) {
        if (accept_punct(')')) break;
        if (accept_punct(',')) continue;
        const Token at = peek();
        if (const BinaryFormat* format = binary_format(at)) {
            // `uint8 V`, `sint16le <a, b>`...: each component rounded, clamped to the
            // type's range and written as raw bytes, until the next ',' or ')'.
            next();
            do {
                const Token value_at = peek();
                const Value v = parse_expression_value();
                const Numeric* n = std::get_if<Numeric>(&v);
                if (!n)
                    error(value_at,
                          std::string("#write: expected a float or vector after '") +
                              std::string(at.text) + "' but found " + type_name(v));
                if (out) write_binary(*format, *n, *out);
            } while (!(peek().kind == TokenKind::Punct &&
                       (peek().text == "," || peek().text == ")")));
            continue;
        }
        Value v = parse_expression_value();
        std::string text;
        if (auto s = std::get_if<std::string>(&v)) {
            text = std::move(*s);
        } else if (auto n = std::get_if<Numeric>(&v)) {
            char buf[64];
            if (n->size == 1) {
                std::snprintf(buf, sizeof buf, "%g", n->c[0]);
                text = buf;
            } else {
                text = "<";
                for (int i = 0; i < n->size; ++i) {
                    std::snprintf(buf, sizeof buf, i ? ",%g" : "%g", n->c[i]);
                    text += buf;
                }
                text += "> ";
            }
        } else {
            error(at,
                  std::string("#write: expected a string, float or vector but found ") +
                      type_name(v));
        }
        if (out) *out << text;
    }
    if (out && !out->flush()) error(t, "cannot write to user file \"" + file.name + "\"");
}

}  // namespace povwall::parser
