// Compiling repeated expressions into stack programs (see expression_program.h), and
// running them.
#include <algorithm>
#include <string_view>

#include "parser/expression_program.h"
#include "parser/interpreter.h"

namespace povwall::parser {

// Reads the raw tokens the way ExpressionParser would, emitting instructions instead of
// values. Returns false at the first construct it does not compile; the caller then
// leaves this position to ExpressionParser for good.
class ExpressionCompiler {
  public:
    ExpressionCompiler(const Interpreter& in, const TokenArray& toks, size_t end,
                       size_t start, ExpressionProgram& out)
        : in_(in), toks_(toks), end_(end), pos_(start), out_(out) {}

    bool compile(bool full, bool no_gt) {
        if (!expression(full, no_gt)) return false;
        // The token after the expression is only looked at by ExpressionParser; it must
        // be one whose reading runs nothing (no directive, no macro call, no frame end).
        if (pos_ >= end_) return false;
        const Token& t = toks_[pos_];
        switch (t.kind) {
            case TokenKind::Punct:
            case TokenKind::Number:
            case TokenKind::String:
                break;
            case TokenKind::Word:
                if (t.sym == 0 || in_.is_bound(t.sym)) return false;
                out_.keyword_syms.push_back(t.sym);
                break;
            default:
                return false;
        }
        out_.end = pos_;
        return true;
    }

  private:
    using Code = ExpressionProgram::Code;

    bool at_end() const { return pos_ >= end_; }
    bool punct(char c) const {
        const Token& t = toks_[pos_];
        return t.kind == TokenKind::Punct && t.length == 1 && t.text[0] == c;
    }
    bool accept(char c) {
        if (at_end() || !punct(c)) return false;
        ++pos_;
        return true;
    }
    void emit(Code code, uint32_t arg = 0, BinaryOpCode op = BinaryOpCode::Add) {
        out_.code.push_back({code, op, arg});
    }
    bool push(int n = 1) {
        stack_ += n;
        return stack_ <= ExpressionProgram::kMaxStack;
    }
    void pop(int n = 1) { stack_ -= n; }
    bool constant(const Numeric& n) {
        emit(Code::Constant, uint32_t(out_.constants.size()));
        out_.constants.push_back(n);
        return push();
    }

    // ExpressionParser::parse(): a full expression (no `?:` here) or a sum of terms.
    bool expression(bool full, bool no_gt) {
        if (++depth_ > 16) return false;
        out_.nesting = std::max(out_.nesting, depth_);
        bool ok = binary(full ? kOrLevel : kSumLevel, no_gt);
        if (ok && full && !at_end() && punct('?')) ok = false;
        --depth_;
        return ok;
    }

    bool binary(int min_level, bool no_gt) {
        if (!unary(no_gt)) return false;
        for (;;) {
            if (at_end()) return false;
            const BinaryOp op = binary_op(toks_[pos_], no_gt);
            if (op.level < min_level || op.level == kNotAnOperator) return true;
            ++pos_;
            if (!binary(op.level + 1, no_gt)) return false;
            emit(Code::Binary, 0, op.code);
            pop();
        }
    }

    bool unary(bool no_gt) {
        if (at_end()) return false;
        if (accept('-')) {
            if (!unary(no_gt)) return false;
            emit(Code::Negate);
            return true;
        }
        if (accept('+')) return unary(no_gt);
        if (accept('!')) {
            if (!unary(no_gt)) return false;
            emit(Code::Not);
            return true;
        }
        if (!primary()) return false;
        // Component access (`P.x`) is left to ExpressionParser.
        return !at_end() && !punct('.');
    }

    bool primary() {
        const Token& t = toks_[pos_++];
        switch (t.kind) {
            case TokenKind::Number:
                return constant(Numeric::scalar(t.number));
            case TokenKind::Punct:
                if (t.length != 1) return false;
                if (t.text[0] == '(') {
                    if (!expression(true, false)) return false;
                    return accept(')');
                }
                if (t.text[0] == '<') return vector();
                return false;
            case TokenKind::Word:
                return word(t);
            default:
                return false;
        }
    }

    // ExpressionParser::vector_literal: 2 to 5 components, a comma after each of the
    // first four optional; each component contributes its first element.
    bool vector() {
        int size = 0;
        for (;;) {
            if (!expression(true, true)) return false;
            // No comma after a fifth component; more components (which overwrite the
            // fifth) are left to ExpressionParser.
            if (++size == 5) {
                if (!accept('>')) return false;
                break;
            }
            accept(',');
            if (size >= 2 && accept('>')) break;
            if (at_end()) return false;
        }
        if (size < 2) return false;
        emit(Code::Vector, uint32_t(size));
        pop(size - 1);
        return true;
    }

    bool word(const Token& t) {
        if (t.sym == 0) return false;
        if (in_.is_bound(t.sym)) {
            const Value* v = in_.lookup_symbol(t.sym);
            if (!v || !std::holds_alternative<Numeric>(*v)) return false;
            emit(Code::Variable, uint32_t(out_.numeric_syms.size()));
            out_.numeric_syms.push_back(t.sym);
            return push();
        }
        const std::string_view w = t.text;
        out_.keyword_syms.push_back(t.sym);
        if (w == "rand") {
            if (!accept('(') || at_end()) return false;
            const auto arg_token = uint32_t(pos_);
            if (!expression(true, false) || !accept(')')) return false;
            emit(Code::Rand, arg_token);
            return true;
        }
        if (const FloatFunction* f = find_float_function(w)) {
            if (!accept('(')) return false;
            for (int i = 0; i < f->arity; ++i) {
                if (i > 0) accept(',');
                // As ExpressionParser::call_float: one argument is a full expression,
                // two are sums.
                if (at_end() || !expression(f->arity == 1, false)) return false;
            }
            if (!accept(')')) return false;
            out_.code.push_back({Code::Call, BinaryOpCode::Add, 0, f});
            pop(f->arity - 1);
            return true;
        }
        const ParseOptions& o = in_.options();
        if (w == "clock") return constant(Numeric::scalar(o.clock));
        if (w == "image_width") return constant(Numeric::scalar(o.image_width));
        if (w == "image_height") return constant(Numeric::scalar(o.image_height));
        if (w == "tau") return constant(Numeric::scalar(2 * kPi));
        if (w == "pi") return constant(Numeric::scalar(kPi));
        if (w == "x") return constant(Numeric::vector({1, 0, 0}));
        if (w == "y") return constant(Numeric::vector({0, 1, 0}));
        if (w == "z") return constant(Numeric::vector({0, 0, 1}));
        return false;
    }

    const Interpreter& in_;
    const TokenArray& toks_;
    size_t end_, pos_;
    ExpressionProgram& out_;
    int depth_ = 0, stack_ = 0;
};

namespace {

// Field by field: GCC compiles the 48-byte assignment (and memcpy) to `rep movs`, whose
// start-up cost was a third of the programs' time.
inline void copy_numeric(Numeric& d, const Numeric& v) {
    d.size = v.size;
    d.colour = v.colour;
    d.c[0] = v.c[0], d.c[1] = v.c[1], d.c[2] = v.c[2], d.c[3] = v.c[3], d.c[4] = v.c[4];
}

}  // namespace

bool Interpreter::in_repeated_code() const {
    if (macro_depth_ > 0 || !loop_counts_.empty()) return true;
    for (const Cond& c : conds_) {
        if (c.kind == Cond::Kind::For) return true;
    }
    return false;
}

bool Interpreter::try_compiled_expression(bool full, bool no_gt, Numeric& out) {
    // Before #version 1.5 vectors and floats are single factors (ExpressionParser).
    if (effective_version() < 150) return false;
    // Only an expression whose first token was peeked straight from the current frame:
    // not a token put back by a directive, not an array element.
    if (pushback_.size() != 1 || frames_.empty()) return false;
    Frame& f = frames_.back();
    if (f.pos == 0 || f.pos > f.end) return false;
    const size_t start = f.pos - 1;
    const Token& first = pushback_[0];
    const Token raw = (*f.toks)[start];
    if (first.kind != raw.kind || first.file != f.file || first.offset != raw.offset ||
        first.length != raw.length || first.sym != raw.sym) {
        return false;
    }
    if (!options_.compile_expressions || !in_repeated_code()) return false;

    const uint64_t key = (uint64_t(uint32_t(f.file)) << 40) | (uint64_t(start) << 2) |
                         (full ? 2u : 0u) | (no_gt ? 1u : 0u);
    // A loop body's few expressions stay in the direct-mapped slots; the map holds all.
    RecentProgram& recent =
        recent_programs_[(key ^ (key >> 13)) % std::size(recent_programs_)];
    if (recent.key != key) {
        auto [it, inserted] = program_by_position_.try_emplace(key, -1);
        if (inserted) {
            ExpressionProgram program;
            if (ExpressionCompiler(*this, *f.toks, f.end, start, program)
                    .compile(full, no_gt)) {
                it->second = int32_t(programs_.size());
                programs_.push_back(std::move(program));
                if (options_.expression_counts) ++options_.expression_counts->compiled;
            }
        }
        recent = {key, it->second};
    }
    if (recent.program < 0) return false;
    const ExpressionProgram& p = programs_[size_t(recent.program)];
    // A macro body shares its file's tokens but ends earlier.
    if (p.end >= f.end) return false;

    // Every guard before anything runs: rand() draws cannot be undone. Where
    // ExpressionParser would pass the nesting limit, it reads the tokens and reports it.
    if (nesting_depth_ + p.nesting > kMaxNesting) return false;
    check_stack(first);
    const Numeric* vars[ExpressionProgram::kMaxStack * 4];
    if (p.numeric_syms.size() > std::size(vars)) return false;
    for (size_t i = 0; i < p.numeric_syms.size(); ++i) {
        const Value* v = lookup_symbol(p.numeric_syms[i]);
        vars[i] = v ? std::get_if<Numeric>(v) : nullptr;
        if (!vars[i]) return false;
    }
    for (uint32_t sym : p.keyword_syms) {
        if (is_bound(sym)) return false;
    }

    // Left uninitialised: zeroing 32 Numerics cost more than most programs.
    union Slot {
        Numeric n;
        Slot() {}
    } slots[ExpressionProgram::kMaxStack];
    auto stack = [&slots](int i) -> Numeric& { return slots[i].n; };
    auto push = [&](int& top, const Numeric& v) { copy_numeric(slots[top++].n, v); };
    int top = 0;
    using Code = ExpressionProgram::Code;
    for (const ExpressionProgram::Instruction& in : p.code) {
        switch (in.code) {
            case Code::Constant:
                push(top, p.constants[in.arg]);
                break;
            case Code::Variable:
                push(top, *vars[in.arg]);
                break;
            case Code::Negate: {
                Numeric& n = stack(top - 1);
                for (int i = 0; i < n.size; ++i) n.c[i] = -n.c[i];
                break;
            }
            case Code::Not:
                stack(top - 1) = Numeric::scalar(stack(top - 1).c[0] == 0 ? 1 : 0);
                break;
            case Code::Binary: {
                Numeric& a = stack(top - 2);
                const Numeric& b = stack(top - 1);
                --top;
                if (!apply_to_floats(in.op, a, b))
                    copy_numeric(a, apply_binary(in.op, a, b));
                break;
            }
            case Code::Vector: {
                Numeric v;
                v.size = int(in.arg);
                top -= int(in.arg);
                for (int i = 0; i < v.size; ++i) v.c[i] = stack(top + i).c[0];
                push(top, v);
                break;
            }
            case Code::Call: {
                double a[3] = {0, 0, 0};
                const int n = in.function->arity;
                top -= n;
                for (int i = 0; i < n; ++i) a[i] = stack(top + i).c[0];
                stack(top++) = Numeric::scalar(in.function->fn(a));
                break;
            }
            case Code::Rand:
                stack(top - 1) = Numeric::scalar(
                    draw_random(saturating_int(stack(top - 1).c[0]), (*f.toks)[in.arg]));
                break;
        }
    }
    copy_numeric(out, stack(0));

    // As if ExpressionParser had read the tokens: the next read is the token after.
    pushback_.clear();
    tokens_since_clock_ += uint32_t(p.end - start - 1);
    if (tokens_since_clock_ >= 4096) tokens_since_clock_ = 4095;  // next read checks
    f.pos = p.end;
    if (options_.expression_counts) ++options_.expression_counts->runs;
    return true;
}

}  // namespace povwall::parser
