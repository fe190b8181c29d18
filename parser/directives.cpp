// The directives: #declare, #if, #while, #macro, #include, ... They run when the token
// stream (tokens.cpp) reaches them, so they may appear anywhere.
#include <cmath>
#include <filesystem>

#include "parser/interpreter.h"

namespace povwall::parser {

namespace fs = std::filesystem;

// ------------------------------------------------------------------ directives

bool is_directive_name(std::string_view d) {
    static constexpr std::string_view kNames[] = {
        "break",      "case",    "debug",  "declare", "default", "else",  "elseif",
        "end",        "error",   "fclose", "fopen",   "for",     "if",    "ifdef",
        "ifndef",     "include", "local",  "macro",   "range",   "read",  "render",
        "statistics", "switch",  "undef",  "version", "warning", "while", "write"};
    for (std::string_view n : kNames)
        if (d == n) return true;
    return false;
}

void Interpreter::run_directive(const Token& t) {
    check_stack(t);
    const std::string_view d = t.text;
    if (d == "declare" || d == "local") return directive_declare(t, d == "local");
    if (d == "if") return directive_if(t, parse_condition() != 0);
    if (d == "ifdef" || d == "ifndef") {
        expect_punct('(');
        Token name = next_raw();
        if (name.kind != TokenKind::Word) expected("an identifier", name);
        bool defined = lookup(name) != nullptr;
        if (defined && is_punct(peek(), '[')) {
            // #ifdef(A[i]): defined when that element has been assigned.
            // A copy: the subscripts may end the frame that holds the binding.
            std::shared_ptr<ArrayValue> arr;
            if (auto a = std::get_if<std::shared_ptr<ArrayValue>>(lookup(name))) arr = *a;
            if (!arr) error(peek(), "'" + std::string(name.text) + "' is not an array");
            const size_t flat = parse_subscripts(*arr);
            defined = !std::holds_alternative<std::monostate>(arr->items[flat]);
        }
        expect_punct(')');
        return directive_if(t, d == "ifdef" ? defined : !defined);
    }
    if (d == "else" || d == "elseif") {
        if (conds_.empty() || (conds_.back().kind != Cond::Kind::If &&
                               conds_.back().kind != Cond::Kind::Switch)) {
            error(t, "#" + std::string(d) + " without a matching #if");
        }
        if (conds_.back().kind == Cond::Kind::Switch) {
            // A taken #case body reaching #else: the switch is finished.
            skip_switch_clauses(t);
            return;
        }
        conds_.pop_back();
        skip_conditional(t, false);
        return;
    }
    if (d == "end") return directive_end(t);
    if (d == "while") return directive_while(t);
    if (d == "for") return directive_for(t);
    if (d == "switch") return directive_switch(t);
    if (d == "case" || d == "range") {
        if (conds_.empty() || conds_.back().kind != Cond::Kind::Switch) {
            error(t, "#" + std::string(d) + " outside #switch");
        }
        // Fall through from the previous clause: skip this clause's value.
        expect_punct('(');
        parse_numeric();
        if (d == "range") {
            accept_punct(',');
            parse_float();
        }
        expect_punct(')');
        return;
    }
    if (d == "break") {
        if (!conds_.empty() && conds_.back().kind == Cond::Kind::Switch) {
            skip_switch_clauses(t);
        }
        return;
    }
    if (d == "macro") return directive_macro(t);
    if (d == "include") return directive_include(t);
    if (d == "version") {
        if (is_word(peek(), "unofficial")) {
            const Token w = next();
            unsupported(w, is_word(peek(), "megapov")
                               ? "MegaPOV scene"
                               : "scene for an unofficial POV-Ray");
        }
        const Token at = peek();
        const double v = parse_numeric(false, true).c[0];
        set_version(at, int(v * 100 + 0.5));
        check_semicolon(t, false);
        return;
    }
    if (d == "undef") {
        Token name = next_raw();
        if (name.kind != TokenKind::Word) expected("an identifier", name);
        // Raw: a directive after the name must not run before the #undef.
        if (raw_next_is_punct('[')) {
            // #undef A[i]: the element is unassigned again (POV-Ray's Remove_Symbol);
            // one never assigned is POV-Ray's parse error.
            std::shared_ptr<ArrayValue> arr;
            if (const Value* v = lookup(name))
                if (auto a = std::get_if<std::shared_ptr<ArrayValue>>(v)) arr = *a;
            if (!arr) error(peek(), "'" + std::string(name.text) + "' is not an array");
            const size_t flat = parse_subscripts(*arr);
            if (std::holds_alternative<std::monostate>(arr->items[flat]))
                error(name, "Attempt to access uninitialized array element.");
            arr->items[flat] = std::monostate{};
            return;
        }
        uint32_t key = sources_.intern(name.text);
        for (int i = int(scopes_.size()) - 1; i >= 0; --i) {
            if (scopes_[i].erase(key)) break;
        }
        return;
    }
    if (d == "default") return directive_default();
    if (d == "debug" || d == "warning" || d == "render" || d == "statistics") {
        std::string s = parse_string();
        if (options_.messages) {
            if (d == "warning") {
                *options_.messages << format_diagnostic(sources_, t, "warning", s)
                                   << "\n";
            } else {
                *options_.messages << s;
            }
        }
        return;
    }
    if (d == "error") {
        std::string s = parse_string();
        error(t, "#error: " + s);
    }
    if (d == "fopen") return directive_fopen(t);
    if (d == "fclose") return directive_fclose();
    if (d == "read") return directive_read(t);
    if (d == "write") return directive_write(t);
    error(t, "unknown directive '#" + std::string(d) + "'");
}

// `[i][j]...` after an array's name, one subscript per dimension: the element's index
// in the row-major items, with the expression evaluator's range errors.
size_t Interpreter::parse_subscripts(const ArrayValue& a) {
    size_t flat = 0;
    for (size_t d = 0; d < a.dims.size(); ++d) {
        expect_punct('[', "for the next subscript");
        const Token at = peek();
        const int i = parse_int();
        expect_punct(']');
        if (i < 0 || i >= a.dims[d])
            error(at, "array subscript " + std::to_string(i) + " out of range 0.." +
                          std::to_string(a.dims[d] - 1));
        flat = flat * size_t(a.dims[d]) + size_t(i);
    }
    return flat;
}

void Interpreter::directive_if(const Token& t, bool taken) {
    for (;;) {
        if (taken) {
            conds_.push_back({Cond::Kind::If, frames_.size(), 0, {}, 0, 1, t});
            return;
        }
        // Skip to the matching #else, #elseif or #end.
        const Frame& f = frames_.back();
        const auto& toks = sources_.file(f.file).tokens;
        int depth = 0;
        for (;;) {
            if (f.pos >= f.end || toks[f.pos].kind == TokenKind::End) {
                error(t, "#" + std::string(t.text) + " has no matching #end");
            }
            const Token& s = toks[frames_.back().pos++];
            if (s.kind != TokenKind::Directive) continue;
            std::string_view n = s.text;
            if (n == "if" || n == "ifdef" || n == "ifndef" || n == "while" ||
                n == "for" || n == "switch" || n == "macro") {
                ++depth;
            } else if (n == "end") {
                if (depth == 0) return;
                --depth;
            } else if (depth == 0 && n == "else") {
                conds_.push_back({Cond::Kind::If, frames_.size(), 0, {}, 0, 1, t});
                return;
            } else if (depth == 0 && n == "elseif") {
                taken = parse_condition() != 0;
                break;
            }
        }
    }
}

void Interpreter::skip_conditional(const Token& at, bool) {
    Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    int depth = 0;
    for (;;) {
        if (f.pos >= f.end || toks[f.pos].kind == TokenKind::End) {
            error(at, "#" + std::string(at.text) + " has no matching #end");
        }
        const Token& s = toks[f.pos++];
        if (s.kind != TokenKind::Directive) continue;
        std::string_view n = s.text;
        if (n == "if" || n == "ifdef" || n == "ifndef" || n == "while" || n == "for" ||
            n == "switch" || n == "macro") {
            ++depth;
        } else if (n == "end") {
            if (depth == 0) return;
            --depth;
        }
    }
}

void Interpreter::directive_switch(const Token& t) {
    double value = parse_condition();
    // Find the first clause that matches.
    Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    int depth = 0;
    for (;;) {
        if (f.pos >= f.end || toks[f.pos].kind == TokenKind::End) {
            error(t, "#switch has no matching #end");
        }
        const Token& s = toks[f.pos++];
        if (s.kind != TokenKind::Directive) continue;
        std::string_view n = s.text;
        if (n == "if" || n == "ifdef" || n == "ifndef" || n == "while" || n == "for" ||
            n == "switch" || n == "macro") {
            ++depth;
        } else if (n == "end") {
            if (depth == 0) return;
            --depth;
        } else if (depth == 0 && (n == "case" || n == "range")) {
            expect_punct('(');
            double a = parse_numeric().c[0];
            bool match;
            if (n == "range") {
                accept_punct(',');
                double b = parse_numeric().c[0];
                match = value >= a && value <= b;
            } else {
                match = std::fabs(value - a) < 1e-10;
            }
            expect_punct(')');
            if (match) {
                conds_.push_back({Cond::Kind::Switch, frames_.size(), 0, {}, 0, 1, t});
                return;
            }
        } else if (depth == 0 && n == "else") {
            conds_.push_back({Cond::Kind::Switch, frames_.size(), 0, {}, 0, 1, t});
            return;
        }
    }
}

void Interpreter::skip_switch_clauses(const Token& at) {
    conds_.pop_back();
    skip_conditional(at, false);
}

void Interpreter::directive_while(const Token& t) {
    size_t directive_pos = frames_.back().pos - 1;
    uint64_t key =
        (uint64_t(uint32_t(frames_.back().file)) << 32) | uint64_t(directive_pos);
    if (parse_condition() != 0) {
        // A loop that never ends would hang the parse: stop it with a located error.
        if (++loop_counts_[key] > options_.max_loop_iterations) {
            loop_counts_.erase(key);
            error(t, "#while loop ran " + std::to_string(options_.max_loop_iterations) +
                         " times: runaway loop? (--max-loop-iterations)");
        }
        conds_.push_back({Cond::Kind::While, frames_.size(), directive_pos, {}, 0, 1, t});
    } else {
        loop_counts_.erase(key);
        skip_conditional(t, false);
    }
}

// POV-Ray's #for runs while the variable is within EPSILON (1e-10) past the end, so
// accumulated rounding (0.1 added ten times) does not drop the last pass.
constexpr double kForEpsilon = 1e-10;

void Interpreter::directive_for(const Token& t) {
    expect_punct('(');
    Token var = next_raw();
    if (var.kind != TokenKind::Word) expected("a loop variable", var);
    accept_punct(',');
    double start = parse_float();
    accept_punct(',');
    double end = parse_float();
    // #for (I[,] a[,] b[,] [step]): a comma after b is allowed without a step.
    accept_punct(',');
    double step = 1;
    if (starts_float(peek())) step = parse_float();
    expect_punct(')');
    if (std::fabs(step) < kForEpsilon) error(t, "#for loop increment must be non-zero.");
    // The loop variable belongs to the current scope, as a #local (POV-Ray's
    // Parse_For_Param adds it to the innermost table): a macro's loop leaves its caller's
    // variable of the same name alone.
    declare(std::string(var.text), Numeric::scalar(start), true, var);
    bool run = step > 0 ? start < end + kForEpsilon : start > end - kForEpsilon;
    if (!run) {
        skip_conditional(t, false);
        return;
    }
    Cond c{Cond::Kind::For,
           frames_.size(),
           frames_.back().pos,
           std::string(var.text),
           end,
           step,
           t};
    conds_.push_back(c);
}

void Interpreter::directive_end(const Token& t) {
    if (conds_.empty() || conds_.back().frame != frames_.size()) {
        error(t, "#end without a matching #if, #while, #for, #switch or #macro");
    }
    Cond c = conds_.back();
    conds_.pop_back();
    switch (c.kind) {
        case Cond::Kind::While:
            frames_.back().pos = c.pos;  // back to the #while: it re-tests the condition
            break;
        case Cond::Kind::For: {
            const Value* v = lookup(c.var);
            const Numeric* n = v ? std::get_if<Numeric>(v) : nullptr;
            if (!n)
                error(t, "#for loop variable '" + c.var + "' was undefined in the loop");
            double value = n->c[0] + c.step;
            declare(c.var, Numeric::scalar(value), true, t);
            if (c.step > 0 ? value <= c.end + kForEpsilon
                           : value >= c.end - kForEpsilon) {
                if (++c.iterations > options_.max_loop_iterations) {
                    error(c.at, "#for loop ran " +
                                    std::to_string(options_.max_loop_iterations) +
                                    " times: runaway loop? (--max-loop-iterations)");
                }
                conds_.push_back(c);
                frames_.back().pos = c.pos;
            }
            break;
        }
        default:
            break;
    }
}

namespace {
// A deep copy: arrays held in elements are copied too.
std::shared_ptr<ArrayValue> copy_array(const ArrayValue& a) {
    auto copy = std::make_shared<ArrayValue>(a);
    for (Value& item : copy->items) {
        if (auto inner = std::get_if<std::shared_ptr<ArrayValue>>(&item))
            item = copy_array(**inner);
    }
    return copy;
}
}  // namespace

void Interpreter::directive_declare(const Token& t, bool local) {
    Token name = next_raw();
    if (is_word(name, "deprecated")) {
        // #declare deprecated [once] ["message"] NAME = ...: the note is for POV-Ray's
        // console.
        name = next_raw();
        if (is_word(name, "once")) name = next_raw();
        if (name.kind == TokenKind::String) name = next_raw();
    }
    if (name.kind != TokenKind::Word)
        expected("an identifier after #" + std::string(t.text), name);
    std::string key(name.text);
    // Element assignment: #declare A[i][j] = value
    std::vector<int> indices;
    while (is_punct(peek(), '[')) {
        next();
        indices.push_back(parse_int());
        expect_punct(']');
    }
    expect_punct('=', "after the identifier");
    // A right-hand side using an unsupported feature does not stop the parse (include
    // files declare many things a scene never uses); the identifier errors only when
    // used.
    const size_t frame_count = frames_.size(), cond_count = conds_.size();
    const size_t scope_count = scopes_.size();
    const int macro_depth = macro_depth_;
    const bool can_recover = pushback_.empty();
    const size_t rhs_pos = frames_.back().pos;
    Value v;
    try {
        Token first = next();
        v = parse_declared_value(first);
    } catch (const ParseError& e) {
        if (e.kind() != ParseError::Kind::Unsupported || !can_recover || !e.deferrable())
            throw;
        frames_.resize(frame_count);
        conds_.resize(cond_count);
        scopes_.resize(scope_count);
        macro_depth_ = macro_depth;
        pushback_.clear();
        frames_.back().pos = rhs_pos;
        skip_declaration_rest();
        std::string feature = e.message().substr(std::string("unsupported: ").size());
        v = std::make_shared<UnsupportedValue>(UnsupportedValue{feature});
    }
    const bool numeric = std::holds_alternative<Numeric>(v);
    // POV-Ray copies an array on assignment (`#declare B = A;` then `#declare B[0] = 5;`
    // leaves A as it was). Shared, it would also let `#declare A[0] = A;` make a cycle
    // that is never freed. A new array (the only owner) needs no copy.
    if (auto arr = std::get_if<std::shared_ptr<ArrayValue>>(&v);
        arr && arr->use_count() > 1)
        v = copy_array(**arr);
    if (!indices.empty()) {
        const Value* existing = lookup(key);
        auto arr =
            existing ? std::get_if<std::shared_ptr<ArrayValue>>(existing) : nullptr;
        if (!arr) error(name, "'" + key + "' is not an array");
        const auto& dims = (*arr)->dims;
        if (indices.size() != dims.size())
            error(name, "wrong number of array subscripts");
        size_t flat = 0;
        for (size_t i = 0; i < dims.size(); ++i) {
            if (indices[i] < 0 || indices[i] >= dims[i]) {
                error(name,
                      "array subscript " + std::to_string(indices[i]) + " out of range");
            }
            flat = flat * dims[i] + size_t(indices[i]);
        }
        (*arr)->items[flat] = std::move(v);
    } else if (local && scopes_.size() > scope_count) {
        // The right-hand side was a macro call whose frame (and scope) ends only when the
        // next token is read: the #local belongs to the scope the directive began in.
        Binding& b = bind(scopes_[scope_count - 1], sources_.intern(key));
        b.value = std::move(v);
        b.ref_scope = -1;
    } else {
        // The lexer interned the name already. POV-Ray finds the identifier a #declare
        // assigns before it reads the value: a #local of the same name in a macro the
        // value called (`#declare S = M();` where M ends in its own local S) is not it.
        declare_symbol(name.sym ? name.sym : sources_.intern(key), std::move(v), local,
                       name, scope_count);
    }
    // POV-Ray's Parse_Semi_Colon(true) after a float, vector or colour; other values only
    // allow one. Then the directive allows one more (Parse_Declare's after_hash):
    // `#local A = 1;;` is a declaration.
    if (numeric)
        check_semicolon(t, true);
    else
        accept_semicolon();
    accept_semicolon();
}

void Interpreter::check_semicolon(const Token& at, bool forced) {
    if (accept_semicolon()) return;
    if (forced && version_ >= 350) {
        error(at,
              "All #declares of float, vector, and color require semi-colon ';' at end "
              "if the language version is set to 3.5 or higher. Either add the "
              "semi-colon or set the language version to 3.1 or lower.");
    }
    if (version_ >= 310)
        warn(at,
             "All #version and #declares of float, vector, and color require "
             "semi-colon ';' at end.");
}

// Skips the rest of a declaration's right-hand side without running it: up to a ';' or
// the brace that closes its block, or to the next directive of an expression with no ';'.
void Interpreter::skip_declaration_rest() {
    Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    int depth = 0;
    while (f.pos < f.end && toks[f.pos].kind != TokenKind::End) {
        const Token& t = toks[f.pos];
        if (depth == 0 && t.kind == TokenKind::Directive) return;
        ++f.pos;
        if (t.kind != TokenKind::Punct || t.length != 1) continue;
        char c = t.text[0];
        if (c == '{' || c == '(' || c == '[') {
            ++depth;
        } else if (c == '}' || c == ')' || c == ']') {
            if (--depth <= 0) {
                depth = 0;
                // A layered texture continues with another `texture {`.
                if (c == '}' && !(f.pos < f.end && is_word(toks[f.pos], "texture")))
                    return;
            }
        } else if (c == ';' && depth == 0) {
            --f.pos;  // left for accept_semicolon
            return;
        }
    }
}

size_t Interpreter::find_matching_end(const Token& at) {
    Frame& f = frames_.back();
    const auto& toks = sources_.file(f.file).tokens;
    int depth = 0;
    for (size_t i = f.pos; i < f.end && toks[i].kind != TokenKind::End; ++i) {
        if (toks[i].kind != TokenKind::Directive) continue;
        std::string_view n = toks[i].text;
        if (n == "if" || n == "ifdef" || n == "ifndef" || n == "while" || n == "for" ||
            n == "switch" || n == "macro") {
            ++depth;
        } else if (n == "end") {
            if (depth == 0) return i;
            --depth;
        }
    }
    error(at, "#" + std::string(at.text) + " has no matching #end");
}

void Interpreter::directive_macro(const Token& t) {
    Token name = next_raw();
    if (name.kind != TokenKind::Word) expected("a macro name", name);
    auto m = std::make_shared<Macro>();
    m->name = std::string(name.text);
    Token open = next_raw();
    if (!is_punct(open, '(')) expected("'(' after the macro name", open);
    // POV-Ray 3.7: each parameter name may be followed by a comma (a trailing one too);
    // `)` ends the list.
    Token p = next_raw();
    while (!is_punct(p, ')')) {
        if (p.kind != TokenKind::Word) expected("a parameter name", p);
        m->params.emplace_back(p.text);
        p = next_raw();
        if (is_punct(p, ',')) p = next_raw();
    }
    m->file = frames_.back().file;
    m->body_begin = frames_.back().pos;
    m->body_end = find_matching_end(t);
    frames_.back().pos = m->body_end + 1;
    declare(m->name, m, false, name);
}

void Interpreter::invoke_macro(const Token& name, const Macro& m) {
    if (macro_depth_ >= kMaxMacroDepth) {
        error(name, "macro '" + m.name + "' nested too deeply (limit " +
                        std::to_string(kMaxMacroDepth) + "): runaway recursion?");
    }
    expect_punct('(', "after macro name ", m.name);
    // As POV-Ray 3.7 reads a call: each argument is a right-hand side (numbers at the
    // sum level, so `M(1 -2)` is one argument), optionally followed by a comma; after
    // the declared number of arguments `)` is required.
    Scope params;
    for (size_t i = 0; i < m.params.size(); ++i) {
        const Token& a = peek();
        if (a.kind == TokenKind::End ||
            (a.kind == TokenKind::Punct && !is_punct(a, '(') && !is_punct(a, '<') &&
             !is_punct(a, '-') && !is_punct(a, '+') && !is_punct(a, '!'))) {
            error(a, "macro '" + m.name + "' expects " + std::to_string(m.params.size()) +
                         " parameter" + (m.params.size() == 1 ? "" : "s") + " but only " +
                         std::to_string(i) + (i == 1 ? " was" : " were") + " found");
        }
        Binding b;
        // An identifier that is the whole argument is passed by reference.
        if (a.kind == TokenKind::Word) {
            int scope = -1;
            uint32_t key = a.sym;
            Binding* existing = find_binding(key, &scope);
            if (existing &&
                !std::holds_alternative<std::shared_ptr<Macro>>(existing->value)) {
                const bool number = std::holds_alternative<Numeric>(existing->value);
                const bool callable =
                    std::holds_alternative<std::shared_ptr<const FunctionProgram>>(
                        existing->value) ||
                    std::holds_alternative<std::shared_ptr<const Spline>>(
                        existing->value);
                // Its value now: the lookahead below may end the macro whose local
                // it is (`M(Get(1))` where Get's body ends in a #local's name), and
                // POV-Ray reads an identifier's value when it meets the token.
                const Value captured = existing->value;
                Token id = next();
                const Token& after = peek();
                const bool continues =
                    (number && (is_punct(after, '+') || is_punct(after, '-') ||
                                is_punct(after, '*') || is_punct(after, '/') ||
                                is_punct(after, '.'))) ||
                    (callable && is_punct(after, '('));
                // Looking ahead may end the frame this call started in (an argument
                // list running past its macro body's #end), which frees that frame's
                // scope: find the binding again rather than keep a pointer into it.
                existing = continues ? nullptr : find_binding(key, &scope);
                // A number's identifier followed by another identifier, no comma
                // between: POV-Ray passes the one it looked ahead to (Parse_RValue
                // takes the reference from the current token, which the look-ahead
                // past a numeric identifier has moved on when it is an identifier
                // too; punctuation and literals leave it). `M(P Q R)` binds Q, R, R.
                if (existing && number && after.kind == TokenKind::Word) {
                    int next_scope = -1;
                    const uint32_t next_key = after.sym;
                    if (const Binding* next = find_binding(next_key, &next_scope);
                        next &&
                        !std::holds_alternative<std::shared_ptr<Macro>>(next->value)) {
                        warn(after, "macro argument '" + std::string(id.text) +
                                        "' is followed by '" + std::string(after.text) +
                                        "' with no comma: POV-Ray 3.7 passes '" +
                                        std::string(after.text) + "' in its place");
                        key = next_key;
                        scope = next_scope;
                        existing = find_binding(key, &scope);
                    }
                }
                if (existing || !continues) {
                    b.value = existing ? existing->value : captured;
                    if (existing) {  // else its scope has ended: passed by value
                        b.ref_scope = scope;
                        b.ref_name = key;
                    }
                    bind(params, sources_.intern(m.params[i])) = std::move(b);
                    accept_punct(',');
                    continue;
                }
                if (!find_binding(key, &scope))
                    id = hidden_name_token(id, std::string(id.text) + "@ended", captured,
                                           id.offset + id.length);
                unget(id);
            }
        }
        b.value = parse_value_additive();
        bind(params, sources_.intern(m.params[i])) = std::move(b);
        accept_punct(',');
    }
    expect_punct(')', "after the arguments of ", m.name);
    Frame f{m.file,
            m.body_begin,
            m.body_end,
            Frame::Kind::Macro,
            scopes_.size(),
            name,
            &sources_.file(m.file).tokens};
    scopes_.push_back(std::move(params));
    frames_.push_back(f);
    ++macro_depth_;
}

std::string Interpreter::resolve_include(const std::string& name, int from_file,
                                         bool try_inc) const {
    auto exists = [](const fs::path& p) {
        std::error_code ec;
        return fs::is_regular_file(p, ec);
    };
    fs::path p(name);
    if (p.is_absolute()) return exists(p) ? name : std::string();
    // POV-Ray's FindFilePath tries the name as given first (relative to the working
    // folder), then the library paths; the including file's folder and the scene's come
    // after the first, so a scene rendered from elsewhere still finds its neighbours.
    std::vector<fs::path> dirs;
    dirs.emplace_back();
    dirs.push_back(fs::path(sources_.file(from_file).path).parent_path());
    dirs.push_back(scene_dir_);
    for (const auto& l : options_.library_paths) dirs.emplace_back(l);
    dirs.emplace_back(options_.standard_include_dir);
    for (const auto& d : dirs) {
        fs::path c = d.empty() ? p : d / p;
        if (exists(c)) return c.string();
        if (!try_inc) continue;
        // POV-Ray also tries the name with ".inc" appended.
        fs::path inc = c;
        inc += ".inc";
        if (exists(inc)) return inc.string();
    }
    return {};
}

void Interpreter::directive_include(const Token& t) {
    Token nt = peek();
    std::string name = parse_string();
    if (frames_.size() >= size_t(kMaxIncludeDepth)) {
        error(nt, "#include nested too deeply (limit " +
                      std::to_string(kMaxIncludeDepth) + ")");
    }
    std::string path = resolve_include(name, frames_.back().file);
    if (path.empty()) error(nt, "cannot find include file \"" + name + "\"");
    // Reading and lexing a large include takes a while: meanwhile the parse is here.
    publish_place(nt.file, nt.offset);
    SourceText text;
    if (!text.read_file(path)) error(nt, "cannot open include file \"" + path + "\"");
    int index = sources_.add(path, std::move(text));
    scopes_.emplace_back();
    frames_.push_back({index,
                       0,
                       sources_.file(index).tokens.size(),
                       Frame::Kind::File,
                       scopes_.size() - 1,
                       {},
                       &sources_.file(index).tokens});
    publish_place(index, sources_.file(index).tokens.front().offset);
}

// #default { texture {...} | pigment {...} | finish {...} | normal {...} }: what later
// textures start from. Each block edits the current default, so #defaults accumulate
// (POV-Ray's Parse_Default); a texture starts from the current default too and must be
// plain and single-layered.
void Interpreter::directive_default() {
    expect_punct('{', "after #default");
    in_default_ = true;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) {
            in_default_ = false;
            return;
        }
        if (is_word(t, "texture") || is_word(t, "pigment")) default_pigment_given_ = true;
        if (is_word(t, "texture")) {
            LayeredTexture layers = parse_texture_block();
            if (layers.back().map_pattern)
                error(t, "the default texture cannot be patterned");
            if (layers.size() > 1) error(t, "the default texture cannot be layered");
            default_texture_ = layers.back();
        } else if (is_word(t, "pigment")) {
            parse_pigment_into(default_texture_.pigment);
        } else if (is_word(t, "finish")) {
            parse_finish_into(default_texture_.finish);
        } else if (is_word(t, "normal")) {
            parse_normal_into(default_texture_.normal);
        } else {
            expected("texture, pigment, finish or normal in #default", t);
        }
    }
}

void Interpreter::set_version(const Token& at, int version) {
    if (version > 370) {
        unsupported(at, "#version " + std::to_string(version / 100) + "." +
                            std::to_string(version % 100 / 10) +
                            " (povwall renders POV-Ray 3.7 scenes)");
    }
    version_ = version;
    version_set_ = true;
    // POV-Ray updates its gamma mode at once: image files read later in the parse are
    // decoded by it.
    const bool modern = effective_version() >= 370;
    if (gamma_mode_ == GammaMode::Assumed36 || gamma_mode_ == GammaMode::Assumed37)
        gamma_mode_ = modern ? GammaMode::Assumed37 : GammaMode::Assumed36;
    else
        gamma_mode_ = modern ? GammaMode::Implied37 : GammaMode::None;
}

void Interpreter::finish_version_state() {
    if (!noise_generator_given_) scene_.settings.noise_generator = version_ < 350 ? 1 : 2;
    if (gamma_mode_ != GammaMode::Assumed36 && gamma_mode_ != GammaMode::Assumed37)
        gamma_mode_ = effective_version() < 370 ? GammaMode::None : GammaMode::Implied37;
    // A version given with +MV / Version= of 3.7 or more turns output gamma on even when
    // the scene ends as a legacy one (POV-Ray's front end does).
    if (gamma_mode_ == GammaMode::None && options_.language_version &&
        *options_.language_version >= 370)
        gamma_mode_ = GammaMode::Implied37;
    // Scenes that end below 3.5 are raised to it once parsed (POV-Ray warns that 3.1's
    // bugs are not reproduced).
    if (version_ < 350) version_ = 350;
    scene_.language_version = effective_version();
    scene_.version_set = version_set_;
    scene_.gamma_mode = gamma_mode_;
}

}  // namespace povwall::parser
