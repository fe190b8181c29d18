// `function { ... }`: the function language compiled into a core::FunctionProgram (a
// stack program over doubles), and calls to functions from SDL expressions.
//
// The language, as POV-Ray 3.7 has it: floats only; parameters (x, y, z unless the
// function names its own; u reads x's and v y's, a missing one reads 0), numbers, float
// identifiers (their value when the function is declared), pi and the frame values, the
// float built-ins (int and div cast to a 32-bit int), min/max of two or more arguments,
// select with 3 or 4, other user functions (a vector function needs a member:
// `F(x).y`), sum and prod, functions.inc's internal(N) (all of POV-Ray's 0 ... 78), and
// POV-Ray's operators with its precedence: |, &, comparisons, + -, * /, one unary sign.
// No ?: and no !.
#include <algorithm>
#include <cmath>

#include "parser/interpreter.h"

namespace povwall::parser {

namespace {

using Op = FunctionProgram::Op;

int component_index(std::string_view w) {
    if (w == "x" || w == "u" || w == "red") return 0;
    if (w == "y" || w == "v" || w == "green") return 1;
    if (w == "z" || w == "blue") return 2;
    if (w == "t" || w == "filter") return 3;
    if (w == "transmit") return 4;
    return -1;
}

}  // namespace

class FunctionCompiler {
  public:
    FunctionCompiler(Interpreter& in, FunctionProgram& f) : in_(in), f_(f) {}

    void expression() { expression_level(); }

  private:
    // A call of `callee` from this function.
    void calls(const FunctionProgram& callee) {
        f_.call_depth = std::max(f_.call_depth, callee.call_depth + 1);
        if (f_.call_depth > kMaxFunctionCallDepth)
            in_.error(in_.peek(), "functions call each other too deeply (limit " +
                                      std::to_string(kMaxFunctionCallDepth) + ")");
    }
    void emit(Op op, uint32_t index = 0, uint8_t component = 0, int pops = 0,
              int pushes = 1) {
        f_.code.push_back({op, component, index});
        depth_ += pushes - pops;
        if (depth_ > f_.stack_size) f_.stack_size = depth_;
        if (f_.stack_size > kMaxFunctionStack)
            in_.error(in_.peek(), "function too deeply nested (limit " +
                                      std::to_string(kMaxFunctionStack) + " operands)");
    }
    void constant(double v) {
        f_.constants.push_back(v);
        emit(Op::Constant, uint32_t(f_.constants.size() - 1));
    }

    // A whole expression (the lowest level, |), counted against the nesting limit.
    void expression_level() {
        NestingGuard guard(in_, in_.peek());
        logical_or();
    }
    void logical_or() {
        logical_and();
        while (in_.accept_punct('|')) {
            logical_and();
            emit(Op::Or, 0, 0, 2);
        }
    }
    void logical_and() {
        comparison();
        while (in_.accept_punct('&')) {
            comparison();
            emit(Op::And, 0, 0, 2);
        }
    }
    void comparison() {
        additive();
        for (;;) {
            const Token& t = in_.peek();
            Op op;
            if (t.kind != TokenKind::Punct) return;
            if (t.text == "<")
                op = Op::Less;
            else if (t.text == "<=")
                op = Op::LessEqual;
            else if (t.text == "=")
                op = Op::Equal;
            else if (t.text == "!=")
                op = Op::NotEqual;
            else if (t.text == ">=")
                op = Op::GreaterEqual;
            else if (t.text == ">")
                op = Op::Greater;
            else
                return;
            in_.next();
            additive();
            emit(op, 0, 0, 2);
        }
    }
    void additive() {
        multiplicative();
        for (;;) {
            if (in_.accept_punct('+')) {
                multiplicative();
                emit(Op::Add, 0, 0, 2);
            } else if (in_.accept_punct('-')) {
                multiplicative();
                emit(Op::Subtract, 0, 0, 2);
            } else {
                return;
            }
        }
    }
    void multiplicative() {
        unary();
        for (;;) {
            if (in_.accept_punct('*')) {
                unary();
                emit(Op::Multiply, 0, 0, 2);
            } else if (in_.accept_punct('/')) {
                unary();
                emit(Op::Divide, 0, 0, 2);
            } else {
                return;
            }
        }
    }
    void unary() {
        if (in_.accept_punct('-')) {
            primary();
            emit(Op::Negate, 0, 0, 1);
        } else {
            in_.accept_punct('+');
            primary();
        }
    }

    // select(a, b, c[, d]): a, then a Branch to the code of b, c or d
    // (FunctionProgram::Op).
    void select(const Token& name) {
        in_.expect_punct('(', "after ", name.text);
        expression_level();
        int n = 1;
        const size_t table = f_.branches.size();
        f_.branches.push_back({});
        emit(Op::Branch, uint32_t(table), 0, 1, 0);
        const int base = depth_;
        std::vector<size_t> jumps;  // the ends of the branches but the last
        for (;;) {
            if (in_.accept_punct(')')) break;
            in_.expect_punct(',', "between the arguments of ", name.text);
            if (n > 1) {
                jumps.push_back(f_.code.size());
                emit(Op::Jump, 0, 0, 0, 0);
            }
            if (n <= 3) f_.branches[table][size_t(n - 1)] = uint32_t(f_.code.size());
            depth_ = base;
            expression_level();
            ++n;
        }
        if (n != 3 && n != 4)
            in_.error(name, "'select' takes 3 or 4 arguments, not " + std::to_string(n));
        if (n == 3) f_.branches[table][2] = f_.branches[table][1];
        for (size_t at : jumps) f_.code[at].index = uint32_t(f_.code.size());
    }
    // Comma-separated arguments inside parentheses; their count.
    int arguments(const Token& name) {
        in_.expect_punct('(', "after ", name.text);
        int n = 0;
        if (in_.accept_punct(')')) return 0;
        for (;;) {
            expression_level();
            ++n;
            if (in_.accept_punct(')')) return n;
            in_.expect_punct(',', "between the arguments of ", name.text);
        }
    }
    void argument_count(const Token& name, int got, int want) {
        if (got != want)
            in_.error(name, "'" + std::string(name.text) + "' takes " +
                                std::to_string(want) + " argument" +
                                (want == 1 ? "" : "s") + ", not " + std::to_string(got));
    }
    // ".x" after a vector function's call: the component index.
    int member(const Token& name) {
        Token dot = in_.next();
        if (!in_.is_punct(dot, '.'))
            in_.error(name, "'" + std::string(name.text) +
                                "' returns a vector: follow the call with a component, "
                                "such as .x");
        Token m = in_.next();
        int c = m.kind == TokenKind::Word ? component_index(m.text) : -1;
        if (m.kind == TokenKind::Word && (m.text == "gray" || m.text == "grey")) c = 5;
        // MegaPOV's height-field member, which POV-Ray 3.7 keeps: (red + green / 255) x
        // 0.996093 (a pigment's 16-bit height).
        if (m.kind == TokenKind::Word && m.text == "hf") c = 6;
        if (c < 0)
            in_.expected("a component name (x, y, z, t, red, gray, ...) after '.'", m);
        return c;
    }
    void spline_call(const Token& name, const std::shared_ptr<const Spline>& s) {
        argument_count(name, arguments(name), 1);
        const int c = member(name);
        if (c >= s->terms)
            in_.error(name, "the spline has no such component (it has " +
                                std::to_string(s->terms) + ")");
        f_.splines.push_back(s);
        emit(Op::SplineComponent, uint32_t(f_.splines.size() - 1), uint8_t(c), 1);
    }

    // sum(i, lo, hi, EXPR) / prod(...): EXPR is its own program of this function's
    // parameters and i.
    void sum_or_product(const Token& t) {
        in_.expect_punct('(', "after ", t.text);
        const Token var = in_.next_raw();
        if (var.kind != TokenKind::Word) in_.expected("the name of the counter", var);
        in_.expect_punct(',', "after the counter");
        expression_level();
        in_.expect_punct(',', "after the first value");
        expression_level();
        in_.expect_punct(',', "after the last value");
        auto body = std::make_shared<FunctionProgram>();
        body->parameter_names = f_.parameter_names;
        body->parameter_names.emplace_back(var.text);
        if (body->parameter_count() > kMaxFunctionParameters)
            in_.error(var, "too many parameters and counters (limit " +
                               std::to_string(kMaxFunctionParameters) + ")");
        FunctionCompiler(in_, *body).expression();
        in_.expect_punct(')', "to close ", t.text);
        calls(*body);
        f_.callees.push_back(std::move(body));
        emit(t.text == "sum" ? Op::Sum : Op::Product, uint32_t(f_.callees.size() - 1), 0,
             2);
    }

    void primary() {
        const Token t = in_.next();
        if (t.kind == TokenKind::Number) return constant(t.number);
        if (in_.is_punct(t, '(')) {
            expression_level();
            in_.expect_punct(')', "to close '('");
            return;
        }
        if (t.kind != TokenKind::Word) in_.expected("a function expression", t);
        const std::string_view w = t.text;
        for (size_t i = 0; i < f_.parameter_names.size(); ++i) {
            if (f_.parameter_names[i] == w) return emit(Op::Parameter, uint32_t(i));
        }
        if (w == "x" || w == "y" || w == "z" || w == "u" || w == "v") {
            // u reads the parameter named x (and x reads u), v reads y; none: 0.
            const std::string_view alias = w == "x"   ? "u"
                                           : w == "u" ? "x"
                                           : w == "y" ? "v"
                                           : w == "v" ? "y"
                                                      : "";
            for (size_t i = 0; i < f_.parameter_names.size(); ++i) {
                if (f_.parameter_names[i] == alias)
                    return emit(Op::Parameter, uint32_t(i));
            }
            return constant(0);
        }
        if (const Value* v = in_.lookup(t)) {
            if (auto n = std::get_if<Numeric>(v)) {
                if (n->size != 1)
                    in_.error(t, "a function works on floats: '" + std::string(w) +
                                     "' is a vector");
                return constant(n->c[0]);
            }
            if (auto fn = std::get_if<std::shared_ptr<const FunctionProgram>>(v)) {
                const std::shared_ptr<const FunctionProgram> callee = *fn;
                if (callee->spline) return spline_call(t, callee->spline);
                if (callee->transform) {
                    argument_count(t, arguments(t), 3);
                    const int c = member(t);
                    if (c > 2) in_.error(t, "a transform function has x, y and z only");
                    f_.transforms.push_back(callee->transform);
                    return emit(Op::TransformComponent,
                                uint32_t(f_.transforms.size() - 1), uint8_t(c), 3);
                }
                if (callee->pigment) {
                    argument_count(t, arguments(t), 3);
                    const int c = member(t);
                    f_.pigments.push_back(callee->pigment);
                    return emit(Op::PigmentComponent, uint32_t(f_.pigments.size() - 1),
                                uint8_t(c), 3);
                }
                const int got = arguments(t);
                argument_count(t, got, callee->parameter_count());
                calls(*callee);
                f_.callees.push_back(callee);
                emit(Op::Call, uint32_t(f_.callees.size() - 1), 0, got);
                return;
            }
            if (auto s = std::get_if<std::shared_ptr<const Spline>>(v)) {
                const std::shared_ptr<const Spline> keep = *s;
                return spline_call(t, keep);
            }
            in_.error(t, "a function works on floats: '" + std::string(w) + "' is a " +
                             std::string(type_name(*v)));
        }
        if (w == "pi") return constant(kPi);
        const ParseOptions& o = in_.options();
        if (w == "clock") return constant(o.clock);
        if (w == "clock_delta") return constant(o.clock_delta);
        if (w == "image_width") return constant(o.image_width);
        if (w == "image_height") return constant(o.image_height);
        if (w == "frame_number") return constant(o.frame_number);
        if (w == "initial_frame") return constant(o.initial_frame);
        if (w == "final_frame") return constant(o.final_frame);
        if (w == "initial_clock") return constant(o.initial_clock);
        if (w == "final_clock") return constant(o.final_clock);
        if (w == "min" || w == "max") {
            // Left to right, each argument against the running value (it matters for
            // NaN).
            in_.expect_punct('(', "after ", w);
            int n = 0;
            for (;;) {
                expression_level();
                if (++n > 1) emit(w == "min" ? Op::Min : Op::Max, 0, 0, 2);
                if (in_.accept_punct(')')) break;
                in_.expect_punct(',', "between the arguments of ", w);
            }
            if (n < 2)
                in_.error(t, "'" + std::string(w) + "' takes two or more arguments");
            return;
        }
        if (w == "select") return select(t);
        if (w == "int" || w == "div") {
            argument_count(t, arguments(t), w == "int" ? 1 : 2);
            return emit(w == "int" ? Op::Int : Op::Div, 0, 0, w == "int" ? 1 : 2);
        }
        if (const FloatBuiltin* b = find_float_builtin(w)) {
            argument_count(t, arguments(t), b->arity);
            f_.builtins.push_back(b);
            return emit(Op::Builtin, uint32_t(f_.builtins.size() - 1), 0, b->arity);
        }
        if (w == "sum" || w == "prod") return sum_or_product(t);
        in_.error(t,
                  "'" + std::string(w) + "' is not a parameter, float or function here");
    }

    Interpreter& in_;
    FunctionProgram& f_;
    int depth_ = 0;
};

// After `function`. Declared (`#declare F = function ...`, macro arguments):
// `[(a, b, ...)] { EXPR | internal(N) | pattern {...} | pigment {...} | spline {...} }`.
// Inline (a pattern's `function { EXPR }`): an expression of x, y, z only.
std::shared_ptr<const FunctionProgram> Interpreter::parse_function_block(
    bool inline_form) {
    auto f = std::make_shared<FunctionProgram>();
    bool named = false;
    if (!inline_form && accept_punct('(')) {
        named = true;
        for (;;) {
            Token p = next_raw();
            if (p.kind != TokenKind::Word) expected("a parameter name", p);
            // A repeated name is allowed; the first one is the one read.
            f->parameter_names.emplace_back(p.text);
            if (f->parameter_count() > kMaxFunctionParameters)
                error(p, "too many function parameters (limit " +
                             std::to_string(kMaxFunctionParameters) + ")");
            if (accept_raw_punct(')')) break;
            accept_raw_punct(',');  // optional, as POV-Ray reads the list
        }
    } else {
        f->parameter_names = {"x", "y", "z"};
    }
    expect_punct('{', "to open the function");
    const Token first = peek();
    auto no_parameters = [&](const char* kind) {
        if (named)
            error(first, std::string("a ") + kind + " function takes no parameter list");
    };
    if (!inline_form && is_word(first, "pattern")) {
        next();
        no_parameters("pattern");
        auto spec = std::make_shared<PatternSpec>();
        expect_punct('{', "after pattern");
        Token k = next();
        // The patterns that read a surface have none here: POV-Ray refuses them, and
        // pavement, which its pattern functions do not list.
        if (is_word(k, "slope") || is_word(k, "aoi") || is_word(k, "pavement") ||
            !try_pattern_keyword(k, *spec))
            expected("a pattern", k);
        for (;;) {
            Token m = next();
            if (is_punct(m, '}')) break;
            if (!try_pattern_modifier(m, *spec)) expected("a pattern modifier or '}'", m);
        }
        f->patterns.push_back(std::move(spec));
        f->code = {{Op::Parameter, 0, 0},
                   {Op::Parameter, 0, 1},
                   {Op::Parameter, 0, 2},
                   {Op::Pattern, 0, 0}};
        f->stack_size = 3;
    } else if (!inline_form && is_word(first, "spline")) {
        next();
        no_parameters("spline");
        f->spline = parse_spline_block();
        f->parameter_names = {"x"};
    } else if (!inline_form && is_word(first, "pigment")) {
        next();
        no_parameters("pigment");
        f->pigment = std::make_shared<Pigment>(parse_pigment_block());
        refuse_uv_mapping(*f->pigment, first, "a pigment function");
    } else if (!inline_form && is_word(first, "internal")) {
        next();
        expect_punct('(', "after internal");
        const Token at = peek();
        const int n = parse_int();
        expect_punct(')', "after internal's number");
        const int extra = internal_extra(n);
        if (extra < 0)  // POV-Ray 3.7 has internal(0) ... internal(78)
            error(at, "Function 'internal(" + std::to_string(n) + ")' does not exist.");
        // The internal function's own parameters, whatever list was written.
        f->parameter_names = {"x", "y", "z"};
        for (int i = 0; i < extra; ++i)
            f->parameter_names.push_back("P" + std::to_string(i));
        for (uint32_t i = 0; i < uint32_t(3 + extra); ++i)
            f->code.push_back({Op::Parameter, 0, i});
        f->code.push_back({Op::Internal, 0, uint32_t(n)});
        f->stack_size = 3 + extra;
    } else if (!inline_form && is_word(first, "transform")) {
        next();
        no_parameters("transform");
        expect_punct('{', "after transform");
        f->transform = std::make_shared<Transform>(parse_transform_block());
    } else {
        FunctionCompiler(*this, *f).expression();
    }
    expect_punct('}', "to close the function");
    return f;
}

// F(a, b, ...) in an SDL expression: a float, or a spline function's vector.
Numeric Interpreter::call_function(const Token& name, const FunctionProgram& f) {
    // As POV-Ray 3.7 reads a call from SDL: exactly the function's number of sums, a
    // comma between two of them optional, then ')' (no trailing comma).
    expect_punct('(', "after ", name.text);
    double args[kMaxFunctionParameters + 1] = {};
    const int count = std::min(f.parameter_count(), kMaxFunctionParameters + 1);
    for (int i = 0; i < count; ++i) {
        if (i > 0) accept_punct(',');
        if (is_punct(peek(), ')'))
            error(name, "'" + std::string(name.text) + "' takes " +
                            std::to_string(count) + " argument" +
                            (count == 1 ? "" : "s") + ", not " + std::to_string(i));
        args[i] = parse_float();
    }
    if (!is_punct(peek(), ')')) {
        expect_punct(')', "after the " + std::to_string(count) + " argument" +
                              (count == 1 ? "" : "s") + " of '" + std::string(name.text) +
                              "'");
    }
    next();
    if (f.spline) {
        const auto v = spline_evaluate(*f.spline, args[0]);
        Numeric r;
        r.size = f.spline->terms;
        r.colour = r.size == 5;
        for (int i = 0; i < 5; ++i) r.c[i] = v[size_t(i)];
        return r;
    }
    if (f.transform) {
        return Numeric::vector(
            Vector3(f.transform->point(Point3(args[0], args[1], args[2]))));
    }
    if (f.pigment) {
        const FunctionHooks& h = parse_time_hooks();
        if (!h.pigment)
            error(name, "a pigment function cannot be called while this command parses");
        float c[5] = {0, 0, 0, 0, 0};
        h.pigment(*f.pigment, Point3(args[0], args[1], args[2]), h.context, c);
        Numeric r;
        r.size = 5;
        r.colour = true;
        for (int i = 0; i < 5; ++i) r.c[i] = double(c[i]);
        return r;
    }
    FunctionHooks hooks = parse_time_hooks();
    uint64_t left = options_.max_loop_iterations;
    hooks.iterations_left = &left;
    const double v = evaluate_function(f, args, hooks);
    if (left == 0)
        error(name, "sum/prod in '" + std::string(name.text) + "' ran more than " +
                        std::to_string(options_.max_loop_iterations) +
                        " iterations (--max-loop-iterations)");
    return Numeric::scalar(v);
}

}  // namespace povwall::parser

namespace povwall::parser {

FunctionHooks Interpreter::parse_time_hooks() const {
    FunctionHooks h = options_.function_hooks;
    h.noise_generator = scene_.settings.noise_generator;
    if (h.use_settings)
        h.use_settings(h.context, scene_.settings.noise_generator,
                       scene_.settings.number_of_waves);
    return h;
}

}  // namespace povwall::parser
