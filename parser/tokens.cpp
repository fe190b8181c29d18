// The token stream under the directives: raw and cooked tokens, one-token lookahead,
// array subscripts read as identifiers, symbol tables, and located diagnostics.
#include <algorithm>
#include <string>
#include <vector>

#include "parser/interpreter.h"

namespace povwall::parser {

Token Interpreter::next_raw() {
    while (!frames_.empty()) {
        Frame& f = frames_.back();
        if (f.pos < f.end && f.toks->packed[f.pos].kind() != TokenKind::End) [[likely]] {
            if (++tokens_since_clock_ == 4096) [[unlikely]]
                check_parse_limits((*f.toks)[f.pos]);
            return (*f.toks)[f.pos++];
        }
        // The frame is exhausted: a file or a macro body ends here.
        const SourceFile& file = sources_.file(f.file);
        const Token end_tok = file.tokens[std::min(f.pos, file.tokens.size() - 1)];
        while (!conds_.empty() && conds_.back().frame == frames_.size()) {
            const Cond& c = conds_.back();
            if (f.kind == Frame::Kind::Macro) break;
            std::string what =
                c.at.kind == TokenKind::Directive ? std::string(c.at.text) : "?";
            error(c.at, "#" + what + " has no matching #end");
        }
        if (frames_.size() == 1) return end_tok;
        scopes_.resize(f.scope_depth);
        if (f.kind == Frame::Kind::Macro) --macro_depth_;
        const bool file_ended = f.kind == Frame::Kind::File;
        frames_.pop_back();
        if (file_ended) {  // back in the includer, at the token after the #include
            const Frame& g = frames_.back();
            if (g.pos < g.end) publish_place(g.file, g.toks->packed[g.pos].offset);
        }
    }
    return Token{};
}

void Interpreter::unget(const Token& t) { pushback_.push_back(t); }

void Interpreter::fill_pushback() { pushback_.push_back(next()); }

Token Interpreter::next() {
    if (!pushback_.empty()) {
        Token t = pushback_.back();
        pushback_.pop_back();
        return t;
    }
    for (;;) {
        Token t = next_raw();
        if (t.kind == TokenKind::Directive && !is_directive_name(t.text)) {
            // POV-Ray's Parse_Directive hands back a word that names no directive and
            // drops the '#' (`#MyMacro()` calls the macro; `#cutaway_textures` is the
            // object modifier).
            const size_t word_length = t.text.size();
            t.kind = TokenKind::Word;
            t.offset = t.offset + t.length - uint32_t(word_length);
            t.length = uint32_t(word_length);
            t.sym = sources_.intern(t.text);
            const Value* v = lookup(t);
            if (!v || !std::holds_alternative<std::shared_ptr<Macro>>(*v))
                warn(t, "'#' before '" + std::string(t.text) +
                            "', which names no directive, is dropped (as POV-Ray does)");
        }
        if (t.kind == TokenKind::Directive) {
            run_directive(t);
        } else if (t.kind == TokenKind::Word) {
            const Value* v = lookup(t);
            if (!v) return t;
            if (auto m = std::get_if<std::shared_ptr<Macro>>(v)) {
                std::shared_ptr<Macro> keep = *m;
                invoke_macro(t, *keep);
            } else if (auto u = std::get_if<std::shared_ptr<UnsupportedValue>>(v)) {
                unsupported(t, (*u)->feature);
            } else if (auto a = std::get_if<std::shared_ptr<ArrayValue>>(v)) {
                const Frame& f = frames_.back();
                const auto& toks = sources_.file(f.file).tokens;
                if (f.pos < f.end && is_punct(toks[f.pos], '[')) {
                    std::shared_ptr<ArrayValue> keep = *a;
                    return subscript_token(t, *keep);
                }
                return t;
            } else {
                return t;
            }
        } else {
            return t;
        }
        // A directive or macro call may have looked one token ahead.
        if (!pushback_.empty()) {
            Token p = pushback_.back();
            pushback_.pop_back();
            return p;
        }
    }
}

// POV-Ray reads subscripts in its tokenizer, so an element can stand wherever an
// identifier can (`texture { T[i][j] }`). The element is bound to a name like "T[1][2]"
// (which no scene can spell) and that name is returned; a small rotating pool bounds the
// memory.
Token Interpreter::subscript_token(const Token& name, const ArrayValue& array) {
    std::string label(name.text);
    size_t flat = 0;
    uint32_t end_offset = name.offset + name.length;
    for (size_t d = 0; d < array.dims.size(); ++d) {
        if (!is_punct(peek(), '[')) break;
        next();
        Token at = peek();
        int i = parse_int();
        Token close = next();
        if (!is_punct(close, ']')) expected("']' after the subscript", close);
        if (i < 0 || i >= array.dims[d]) {
            error(at, "array subscript " + std::to_string(i) + " out of range 0.." +
                          std::to_string(array.dims[d] - 1));
        }
        flat = flat * size_t(array.dims[d]) + size_t(i);
        label += "[" + std::to_string(i) + "]";
        if (close.file == name.file) end_offset = close.offset + close.length;
    }
    const Value& item = array.items[flat];
    if (auto u = std::get_if<std::shared_ptr<UnsupportedValue>>(&item)) {
        Token whole = name;
        whole.length = end_offset - name.offset;
        unsupported(whole, (*u)->feature);
    }
    return hidden_name_token(name, label, item, end_offset);
}

Token Interpreter::hidden_name_token(const Token& like, const std::string& label,
                                     const Value& value, uint32_t end_offset) {
    constexpr size_t kPool = 256;
    if (element_names_.size() < kPool) element_names_.resize(kPool);
    std::string& slot = element_names_[next_element_name_];
    next_element_name_ = (next_element_name_ + 1) % kPool;
    if (!slot.empty()) scopes_[0].erase(sources_.intern(slot));
    slot = label;
    uint32_t sym = sources_.intern(slot);
    // An unset array element stays unbound: reading it is an error. (The same label
    // may still be bound from an earlier read, in another pool slot, before an #undef.)
    if (!std::holds_alternative<std::monostate>(value))
        bind(scopes_[0], sym).value = value;
    else
        scopes_[0].erase(sym);
    Token t = like;
    t.text = slot;
    t.sym = sym;
    t.length = end_offset - like.offset;
    return t;
}

bool Interpreter::accept_punct(char c) {
    if (is_punct(peek(), c)) {
        next();
        return true;
    }
    return false;
}

bool Interpreter::accept_semicolon() {
    // Looks at the raw stream so that a directive after the statement is not run before
    // the statement has taken effect; but past the end of a macro body or file, as
    // POV-Ray's ALLOW(SEMI_COLON_TOKEN) returns from a macro at its #end (Parse_Directive
    // does that even while Ok_To_Declare is false). So `#local D = Ret();`, where Ret's
    // body ends in an array or function, takes its `;` even when the frame that holds
    // the `;` is itself a macro body read as a value.
    if (!pushback_.empty()) return accept_punct(';');
    if (frames_.empty()) return false;
    if (!is_punct(peek_raw_past_frame_ends(), ';')) return false;
    ++frames_.back().pos;
    return true;
}

Token Interpreter::peek_raw_past_frame_ends() {
    const Token t = next_raw();
    // next_raw() hands back the end of the outermost file without moving past it.
    if (t.kind != TokenKind::End) --frames_.back().pos;
    return t;
}

bool Interpreter::raw_next_is_punct(char c) {
    if (!pushback_.empty()) return is_punct(pushback_.back(), c);
    if (frames_.empty()) return false;
    const Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    return f.pos < f.end && is_punct(toks[f.pos], c);
}

bool Interpreter::accept_raw_punct(char c) {
    if (!pushback_.empty()) return accept_punct(c);
    if (frames_.empty()) return false;
    Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    if (f.pos < f.end && is_punct(toks[f.pos], c)) {
        ++f.pos;
        return true;
    }
    return false;
}

bool Interpreter::accept_raw_word(std::string_view w) {
    // Like accept_semicolon: a directive after the item must not run before it is stored.
    if (!pushback_.empty()) return accept_word(w);
    if (frames_.empty()) return false;
    Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    if (f.pos < f.end && is_word(toks[f.pos], w)) {
        ++f.pos;
        return true;
    }
    return false;
}

bool Interpreter::accept_word(std::string_view w) {
    if (is_word(peek(), w)) {
        next();
        return true;
    }
    return false;
}

void Interpreter::expect_punct(char c, std::string_view what) {
    Token t = next();
    if (!is_punct(t, c)) {
        std::string want = std::string("'") + c + "'";
        if (!what.empty()) want += std::string(" ") + std::string(what);
        expected(want, t);
    }
}

void Interpreter::expect_punct(char c, std::string_view what, std::string_view name) {
    if (is_punct(peek(), c)) {
        next();
        return;
    }
    expect_punct(c, std::string(what) + "'" + std::string(name) + "'");
}

std::string Interpreter::describe(const Token& t) const {
    switch (t.kind) {
        case TokenKind::End:
            return "end of file";
        case TokenKind::String:
            return "string \"" + std::string(t.text) + "\"";
        case TokenKind::Directive:
            return "'#" + std::string(t.text) + "'";
        default:
            return "'" + std::string(t.text) + "'";
    }
}

void Interpreter::error(const Token& at, const std::string& message) {
    std::string text = format_diagnostic(sources_, at, "error", message);
    // Inside macros, also point at the call sites, innermost first. Deep recursion would
    // print thousands of identical notes: as clang does, only the innermost and outermost
    // few are shown, with a count of the rest between them.
    std::vector<const Token*> calls;
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it) {
        if (it->kind == Frame::Kind::Macro && it->call.file >= 0)
            calls.push_back(&it->call);
    }
    constexpr size_t kShownAtEachEnd = 5;
    for (size_t i = 0; i < calls.size(); ++i) {
        if (calls.size() > 2 * kShownAtEachEnd && i == kShownAtEachEnd) {
            size_t hidden = calls.size() - 2 * kShownAtEachEnd;
            text +=
                "\nnote: (" + std::to_string(hidden) + " more macro contexts not shown)";
            i += hidden - 1;
            continue;
        }
        std::string note = "in macro '";
        note += calls[i]->text;
        note += "' called from here";
        text += '\n';
        text += format_diagnostic(sources_, *calls[i], "note", note);
    }
    throw ParseError(ParseError::Kind::Syntax, text, message, sources_.location(at));
}

void Interpreter::unsupported(const Token& at, std::string_view feature,
                              bool deferrable) {
    std::string message = "unsupported: " + std::string(feature);
    throw ParseError(ParseError::Kind::Unsupported,
                     format_diagnostic(sources_, at, "error", message), message,
                     sources_.location(at), deferrable);
}

void Interpreter::expected(std::string_view what, const Token& found) {
    error(found, "expected " + std::string(what) + " but found " + describe(found));
}

// ------------------------------------------------------------------ symbols

Interpreter::Binding* Interpreter::find_binding(uint32_t sym, int* scope_index,
                                                size_t visible_scopes) {
    if (sym == 0 || sym >= bound_.size() || !bound_[sym]) return nullptr;
    for (int i = int(std::min(scopes_.size(), visible_scopes)) - 1; i >= 0; --i) {
        auto it = scopes_[i].find(sym);
        if (it != scopes_[i].end()) {
            if (scope_index) *scope_index = i;
            return &it->second;
        }
    }
    return nullptr;
}

const Value* Interpreter::lookup_symbol(uint32_t sym) const {
    // Most words are keywords, never bound: answered without touching the scopes.
    if (sym == 0 || sym >= bound_.size() || !bound_[sym]) return nullptr;
    for (int i = int(scopes_.size()) - 1; i >= 0; --i) {
        auto it = scopes_[i].find(sym);
        if (it != scopes_[i].end()) return &it->second.value;
    }
    return nullptr;
}

const Value* Interpreter::lookup(std::string_view name) const {
    return lookup_symbol(sources_.find_symbol(name));
}

void Interpreter::declare_symbol(uint32_t sym, Value v, bool local, const Token& at,
                                 size_t visible_scopes) {
    (void)at;
    if (local) {
        // #local of a parameter passed by reference, in its own macro's scope, writes
        // through to the caller's variable as #declare does (POV-Ray's parameter entry
        // points at the caller's data; macro4.pov's Inc(V)). Anything else is a new
        // local.
        const auto it = scopes_.back().find(sym);
        if (it == scopes_.back().end() || it->second.ref_scope < 0) {
            Binding& b = bind(scopes_.back(), sym);
            b.value = std::move(v);
            b.ref_scope = -1;
            return;
        }
    }
    // #declare: an existing macro parameter passed by reference writes through to the
    // caller's variable; otherwise the identifier is global.
    int index = -1;
    Binding* b = find_binding(sym, &index, visible_scopes);
    uint32_t target = sym;
    while (b && b->ref_scope >= 0) {
        int target_scope = b->ref_scope;
        target = b->ref_name;
        b->value = v;
        auto it = scopes_[target_scope].find(target);
        if (it == scopes_[target_scope].end()) {
            b = nullptr;
            break;
        }
        b = &it->second;
        index = target_scope;
    }
    if (b) {
        // An existing identifier (global, or a #local of an enclosing scope) is updated.
        b->value = std::move(v);
        return;
    }
    bind(scopes_[0], target).value = std::move(v);
}

// ------------------------------------------------------------------ lookahead helpers

float Interpreter::parse_map_value(bool average) {
    // `average` map entries may leave out their weight (1 by default).
    if (average && !starts_float(peek())) return 1.0f;
    return float(parse_float());
}

void Interpreter::require_operand(std::string_view what) {
    // Commas are optional, so a missing value shows up as the block's closing token.
    const Token& t = peek();
    if (t.kind == TokenKind::End || is_punct(t, '}') || is_punct(t, ']') ||
        is_punct(t, ')') || is_punct(t, ',') || is_punct(t, ';')) {
        expected(what, t);
    }
}

bool Interpreter::starts_float(const Token& t) {
    if (t.kind == TokenKind::Number) return true;
    if (t.kind == TokenKind::Punct) {
        return is_punct(t, '(') || is_punct(t, '-') || is_punct(t, '+') ||
               is_punct(t, '!');
    }
    if (t.kind != TokenKind::Word) return false;
    if (const Value* v = lookup(t)) {
        if (auto f = std::get_if<std::shared_ptr<const FunctionProgram>>(v))
            return !(*f)->spline && !(*f)->transform && !(*f)->pigment;
        auto n = std::get_if<Numeric>(v);
        return n && n->size == 1;
    }
    // Float keywords POV-Ray 3.7 also has (CASE_FLOAT).
    static constexpr std::string_view kMoreFloatWords[] = {
        "acosh",         "asinh",       "atanh",         "strcmp",      "bitwise_and",
        "bitwise_or",    "bitwise_xor", "dimensions",    "file_exists", "clock_on",
        "initial_frame", "final_frame", "initial_clock", "final_clock", "inside"};
    for (std::string_view w : kMoreFloatWords) {
        if (t.text == w) return true;
    }
    static constexpr std::string_view kFloatWords[] = {
        "on",           "off",         "true",        "false",
        "yes",          "no",          "pi",          "tau",
        "clock",        "abs",         "acos",        "asin",
        "atan",         "atan2",       "ceil",        "cos",
        "cosh",         "degrees",     "radians",     "div",
        "exp",          "floor",       "int",         "ln",
        "log",          "max",         "min",         "mod",
        "pow",          "rand",        "select",      "sin",
        "sinh",         "sqrt",        "tan",         "tanh",
        "vdot",         "vlength",     "image_width", "image_height",
        "frame_number", "clock_delta", "version",     "strlen",
        "val",          "asc",         "defined",     "dimension_size",
        "now",          "seed"};
    for (std::string_view w : kFloatWords) {
        if (t.text == w) return true;
    }
    return false;
}

bool Interpreter::starts_expression(const Token& t) {
    if (starts_float(t) || is_punct(t, '<')) return true;
    if (t.kind != TokenKind::Word) return false;
    if (const Value* v = lookup(t)) {
        return std::holds_alternative<Numeric>(*v) ||
               std::holds_alternative<std::shared_ptr<const FunctionProgram>>(*v) ||
               std::holds_alternative<std::shared_ptr<const Spline>>(*v);
    }
    // x y z t u v, the vector functions, the colour keywords.
    if (t.text.size() == 1)
        return std::string_view("xyztuv").find(t.text[0]) != std::string_view::npos;
    static constexpr std::string_view kWords[] = {
        "vaxis_rotate", "vcross",     "vnormalize", "vrotate",      "vturbulence",
        "trace",        "min_extent", "max_extent", "eval_pigment", "color",
        "colour",       "rgb",        "rgbf",       "rgbt",         "rgbft",
        "srgb",         "srgbf",      "srgbt",      "srgbft",       "red",
        "green",        "blue",       "filter",     "transmit",     "gray",
        "grey"};
    for (std::string_view w : kWords) {
        if (t.text == w) return true;
    }
    return false;
}

bool Interpreter::parse_bool_opt() {
    // `hollow`, `hollow on`, `hollow false`: a following float expression is the value.
    if (starts_float(peek())) return parse_float() != 0;
    return true;
}

}  // namespace povwall::parser
