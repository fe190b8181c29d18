// Expressions: precedence climbing over floats, vectors, colours and strings, with
// POV-Ray's built-in functions and constants.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>

#include "core/noise.h"
#include "core/pov_angles.h"
#include "parser/expression_program.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

constexpr double kPovEpsilon = 1e-10;

Numeric promote(const Numeric& a, int size) {
    if (a.size >= size) return a;
    Numeric r = a;
    if (a.size == 1) {
        for (int i = 1; i < size; ++i) r.c[i] = a.c[0];
    }
    r.size = size;
    return r;
}

Numeric combine(Numeric a, Numeric b, char op) {
    int size = std::max(a.size, b.size);
    a = promote(a, size);
    b = promote(b, size);
    Numeric r;
    r.size = size;
    r.colour = a.colour || b.colour;
    for (int i = 0; i < size; ++i) {
        switch (op) {
            case '+':
                r.c[i] = a.c[i] + b.c[i];
                break;
            case '-':
                r.c[i] = a.c[i] - b.c[i];
                break;
            case '*':
                r.c[i] = a.c[i] * b.c[i];
                break;
            case '/':
                r.c[i] = a.c[i] / b.c[i];
                break;
        }
    }
    return r;
}

// Rotation of a vector by <x,y,z> degrees, as the `rotate` transform does.
Vector3 rotate_vector(const Vector3& v, const Vector3& degrees) {
    return Transform::rotate(degrees).vector(v);
}

// POV-Ray 3.7 compares strings by UCS2_strcmp: the difference of the first code units
// that differ (a string's end counting as 0). Our strings hold the bytes POV-Ray reads
// as one code unit each.
int compare_strings(std::string_view a, std::string_view b) {
    size_t i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
    const int ca = i < a.size() ? (unsigned char)a[i] : 0;
    const int cb = i < b.size() ? (unsigned char)b[i] : 0;
    return ca - cb;
}

bool string_relation(BinaryOpCode code, int order) {
    using C = BinaryOpCode;
    switch (code) {
        case C::Lt:
            return order < 0;
        case C::Le:
            return order <= 0;
        case C::Eq:
            return order == 0;
        case C::Ne:
            return order != 0;
        case C::Ge:
            return order >= 0;
        case C::Gt:
            return order > 0;
        default:
            return false;
    }
}

Vector3 axis_rotate(const Vector3& v, const Vector3& axis, double degrees) {
    Vector3 k = normalize(axis);
    double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
    // Same sense as `rotate`: vaxis_rotate(x, y, 90) is -z in POV-Ray 3.7.
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

}  // namespace

BinaryOp binary_op(const Token& t, bool no_gt) {
    if (t.kind != TokenKind::Punct) return {};
    using C = BinaryOpCode;
    if (t.length == 1) {
        switch (t.text[0]) {
            case '|':
                return {kOrLevel, C::Or};
            case '&':
                return {kAndLevel, C::And};
            case '=':
                return {kComparisonLevel, C::Eq};
            case '<':
                return {kComparisonLevel, C::Lt};
            case '>':
                if (no_gt) return {};
                return {kComparisonLevel, C::Gt};
            case '+':
                return {kSumLevel, C::Add};
            case '-':
                return {kSumLevel, C::Sub};
            case '*':
                return {kProductLevel, C::Mul};
            case '/':
                return {kProductLevel, C::Div};
            default:
                return {};
        }
    }
    if (t.length == 2 && t.text[1] == '=') {
        switch (t.text[0]) {
            case '!':
                return {kComparisonLevel, C::Ne};
            case '<':
                return {kComparisonLevel, C::Le};
            case '>':
                return {kComparisonLevel, C::Ge};
            default:
                return {};
        }
    }
    return {};
}

Numeric apply_binary(BinaryOpCode code, const Numeric& a, const Numeric& b) {
    if (Numeric r = a; apply_to_floats(code, r, b)) return r;
    const double x = a.c[0], y = b.c[0];
    using C = BinaryOpCode;
    switch (code) {
        case C::Or:
            return Numeric::scalar((x != 0 || y != 0) ? 1 : 0);
        case C::And:
            return Numeric::scalar((x != 0 && y != 0) ? 1 : 0);
        // POV-Ray compares with a tolerance for equality.
        case C::Eq:
            return Numeric::scalar(std::fabs(x - y) < kPovEpsilon ? 1 : 0);
        case C::Ne:
            return Numeric::scalar(std::fabs(x - y) >= kPovEpsilon ? 1 : 0);
        case C::Lt:
            return Numeric::scalar(x < y ? 1 : 0);
        case C::Le:
            return Numeric::scalar(x <= y ? 1 : 0);
        case C::Gt:
            return Numeric::scalar(x > y ? 1 : 0);
        case C::Ge:
            return Numeric::scalar(x >= y ? 1 : 0);
        case C::Add:
            return combine(a, b, '+');
        case C::Sub:
            return combine(a, b, '-');
        case C::Mul:
            return combine(a, b, '*');
        case C::Div:
            return combine(a, b, '/');
    }
    return a;
}

const FloatFunction* find_float_function(std::string_view name) {
    // The scene language's degrees() divides by POV-Ray's M_PI_180, where its function
    // compiler multiplies by 180 / M_PI: the last bits differ for some angles.
    static const FloatFunction kDegrees{
        "degrees", 1, [](const double* a) { return a[0] / kPovRadiansPerDegree; }};
    if (name == "degrees") return &kDegrees;
    return find_float_builtin(name);
}

const char* type_name(const Value& v) {
    switch (v.index()) {
        case 0:
            return "nothing";
        case 1:
            return std::get<Numeric>(v).size == 1 ? "float" : "vector";
        case 2:
            return "string";
        case 3:
            return "object";
        case 4:
            return "texture";
        case 5:
            return "pigment";
        case 6:
            return "finish";
        case 7:
            return "normal";
        case 8:
            return "interior";
        case 9:
            return "camera";
        case 10:
            return "light_source";
        case 11:
            return "array";
        case 12:
            return "transform";
        case 13:
            return "macro";
        case 14:
            return "material";
        case 15:
            return "color_map";
        case 16:
            return "sky_sphere";
        case 17:
            return "fog";
        case 18:
            return "unsupported feature";
        case 19:
            return "file";
        case 20:
            return "spline";
        case 21:
            return "function";
        case 22:
            return "media";
    }
    return "value";
}

// A small recursive-descent evaluator bound to the interpreter's token stream.
class ExpressionParser {
  public:
    // `hold`: directives and macro calls met where an operator could follow an operand
    // end the expression unrun (POV-Ray's Ok_To_Declare = false while it reads the value
    // of a #declare or #version, which is what lets a pre-3.5 `#declare X = 1` stand
    // without its semicolon before the next directive).
    ExpressionParser(Interpreter& in, bool no_gt, bool full = true, bool hold = false)
        : in_(in), no_gt_(no_gt), full_(full), hold_(hold) {}

    // POV-Ray's Parse_Float/Parse_Vector read only sums of terms (no comparisons, logic
    // or
    // ?: outside parentheses), which is what lets `box { <a> <b> }` read two vectors.
    // Before #version 1.5 they read a single factor (Parse_Num_Factor: a number, an
    // identifier, a call, a vector, a parenthesised expression, with unary signs and
    // `.x`), so `<-6.6 -0.0 -2.1>` is three components.
    Value parse() {
        NestingGuard guard(in_, in_.peek());
        if (full_) return ternary();
        return in_.effective_version() < 150 ? unary() : binary(kSumLevel);
    }

  private:
    static bool numeric(const Value& v) { return std::holds_alternative<Numeric>(v); }
    Numeric num(const Value& v, const Token& at) {
        if (auto n = std::get_if<Numeric>(&v)) return *n;
        in_.error(at,
                  std::string("expected a numeric expression but found ") + type_name(v));
    }

    // The token after an operand, where an operator may follow.
    const Token& peek_operator() { return in_.peek_after_operand(hold_); }

    // A value POV-Ray reads with Parse_Express, where a string can only start a
    // comparison: a string left over is missing its comparison operator.
    Numeric express_value(const Value& v, const Token& at) {
        if (std::holds_alternative<std::string>(v))
            in_.expected("a string comparison operator", in_.peek());
        return num(v, at);
    }

    Value ternary() {
        Token at = in_.peek();
        Value c = binary(kOrLevel);
        if (!numeric(c)) return c;
        if (in_.is_punct(peek_operator(), '?')) {
            in_.next();
            Token a_at = in_.peek();
            Value a = ternary();
            if (std::holds_alternative<std::string>(a)) express_value(a, a_at);
            in_.expect_punct(':', "in a conditional expression");
            Token b_at = in_.peek();
            Value b = ternary();
            if (std::holds_alternative<std::string>(b)) express_value(b, b_at);
            return num(c, at).c[0] != 0 ? a : b;
        }
        return c;
    }

    // Binary operators by precedence climbing: one loop instead of a function per level,
    // so an operand costs one look at the next token rather than one per level. An error
    // names the first token of the left operand's chain. Reads the operators of
    // `min_level` and tighter (the right operand of a looser operator).
    //
    // A string operand is POV-Ray's relational string term (Parse_Rel_Term): it must be
    // compared with one string (UCS2_strcmp order), and the comparison is the whole
    // term: only `&`, `|` and `?:` may follow it. `string_term_` tells the caller that
    // the value it got ended with such a term. At the top (`min_level` kOrLevel) a string
    // without a comparison is returned as a string value for the caller to judge.
    Value binary(int min_level) {
        Token at = in_.peek();
        Value a = unary();
        bool string_term = false;
        if (auto s = std::get_if<std::string>(&a); s && min_level <= kComparisonLevel) {
            const BinaryOp op = binary_op(peek_operator(), false);
            if (op.level != kComparisonLevel) {
                string_term_ = false;
                if (min_level == kOrLevel) return a;
                in_.expected("a string comparison operator", in_.peek());
            }
            in_.next();
            const std::string rhs = in_.parse_string();
            a = Numeric::scalar(string_relation(op.code, compare_strings(*s, rhs)) ? 1
                                                                                   : 0);
            string_term = true;
        }
        for (;;) {
            string_term_ = string_term;
            if (!numeric(a)) return a;
            const BinaryOp op = binary_op(peek_operator(), no_gt_);
            if (op.level < min_level || op.level == kNotAnOperator) return a;
            if (string_term && op.level >= kComparisonLevel) return a;
            in_.next();
            Value b = binary(op.level + 1);
            string_term = string_term_;
            a = apply_binary(op.code, std::get<Numeric>(a), num(b, at));
        }
    }

    Value unary() {
        const Token& t = in_.peek();
        if (in_.is_punct(t, '-')) {
            Token at = in_.next();
            Numeric n = num(unary(), at);
            for (int i = 0; i < n.size; ++i) n.c[i] = -n.c[i];
            return n;
        }
        if (in_.is_punct(t, '+')) {
            in_.next();
            return unary();
        }
        if (in_.is_punct(t, '!')) {
            Token at = in_.next();
            return Numeric::scalar(num(unary(), at).c[0] == 0 ? 1 : 0);
        }
        return postfix();
    }

    Value postfix() {
        Value v = primary();
        // Only numbers take operators: after an object, texture, array... nothing is read
        // ahead, so a directive following it runs in order.
        while (numeric(v) && in_.is_punct(peek_operator(), '.')) {
            in_.next();
            Token m = in_.next();
            Numeric n = std::get<Numeric>(v);
            int index = -1;
            std::string_view w = m.text;
            if (m.kind != TokenKind::Word) in_.expected("a component name after '.'", m);
            if (w == "x" || w == "u" || w == "red")
                index = 0;
            else if (w == "y" || w == "v" || w == "green")
                index = 1;
            else if (w == "z" || w == "blue")
                index = 2;
            else if (w == "t" || w == "filter")
                index = 3;
            else if (w == "transmit")
                index = 4;
            else if (w == "gray" || w == "grey") {
                Numeric c = promote(n, 3);
                v = Numeric::scalar(c.c[0] * 0.297 + c.c[1] * 0.589 + c.c[2] * 0.114);
                continue;
            } else {
                in_.error(m, "unknown component '." + std::string(w) + "'");
            }
            if (n.size == 1) {
                v = n;  // POV-Ray promotes: <f,f,f,...>.x is f
                continue;
            }
            if (index >= n.size && !(n.colour && index < 5)) {
                in_.error(m, "the vector has no component '." + std::string(w) + "'");
            }
            v = Numeric::scalar(n.c[index]);
        }
        return v;
    }

    // POV-Ray 3.7's `< >`: two components, then a third, fourth and fifth while the next
    // token can start an expression; a comma after each of the first four is optional
    // (so `<1,2,>` is fine), none is read after the fifth, and further components
    // overwrite the fifth (`<1,2,3,4,5 6>` is <1,2,3,4,6>). Components are sums, so
    // `<1 -2 3>` is <-1, 3> (single factors before #version 1.5: <1, -2, 3>).
    Numeric vector_literal(const Token& open) {
        Numeric r;
        r.size = 0;
        for (;;) {
            const Token& next = in_.peek();
            if (r.size >= 2 && !in_.starts_expression(next)) break;
            if (r.size < 2 && in_.is_punct(next, '>'))
                in_.error(open, "a vector needs at least 2 components");
            Token at = next;
            const bool factor = in_.effective_version() < 150;
            Numeric c = num(ExpressionParser(in_, true, !factor).parse(), at);
            if (r.size == 5) {
                r.c[4] = c.c[0];
                continue;
            }
            r.c[r.size++] = c.c[0];
            if (r.size < 5) in_.accept_punct(',');
        }
        in_.expect_punct('>', "to close the vector");
        return r;
    }

    // A one-float argument is a full expression (POV-Ray's Parse_Float_Param); the
    // arguments of functions taking more, and vector arguments, are sums (Parse_Float,
    // Parse_Vector), which is what lets `vdot(<1,2,3> <4,5,6>)` read two vectors.
    double arg_float() {
        Token at = in_.peek();
        return express_value(ExpressionParser(in_, false).parse(), at).c[0];
    }
    double arg_sum() {
        Token at = in_.peek();
        return num(ExpressionParser(in_, false, false).parse(), at).c[0];
    }
    Vector3 arg_vector() {
        Token at = in_.peek();
        return num(ExpressionParser(in_, false, false).parse(), at).vec3();
    }
    std::string arg_string() { return in_.parse_string(); }

    Value call_float(const Token& t, int arity, double (*f)(const double*)) {
        in_.expect_punct('(', "after ", t.text);
        double a[3] = {0, 0, 0};
        for (int i = 0; i < arity; ++i) {
            if (i > 0) in_.accept_punct(',');
            a[i] = arity == 1 ? arg_float() : arg_sum();
        }
        in_.expect_punct(')');
        return Numeric::scalar(f(a));
    }

    Value primary() {
        Token t = in_.next();
        switch (t.kind) {
            case TokenKind::Number:
                return Numeric::scalar(t.number);
            case TokenKind::String:
                return std::string(t.text);
            case TokenKind::Punct:
                if (in_.is_punct(t, '(')) {
                    // POV-Ray's parenthesised expression is numeric: `("a")` is an error.
                    Token at = in_.peek();
                    Numeric v = express_value(ExpressionParser(in_, false).parse(), at);
                    in_.expect_punct(')', "to close '('");
                    return v;
                }
                if (in_.is_punct(t, '<')) return vector_literal(t);
                in_.expected("an expression", t);
            case TokenKind::Word:
                return word(t);
            default:
                in_.expected("an expression", t);
        }
    }

    Value word(const Token& t);

    Interpreter& in_;
    bool no_gt_;
    bool full_;
    bool hold_;
    bool string_term_ = false;  // see binary()
};

Value ExpressionParser::word(const Token& t) {
    const std::string_view w = t.text;
    // User identifiers shadow nothing built in: POV-Ray reserves keywords.
    if (const Value* v = in_.lookup(t)) {
        if (auto sp = std::get_if<std::shared_ptr<const Spline>>(v);
            sp && in_.raw_next_is_punct('(')) {
            std::shared_ptr<const Spline> keep = *sp;
            return in_.call_spline(*keep);
        }
        if (auto fn = std::get_if<std::shared_ptr<const FunctionProgram>>(v);
            fn && in_.raw_next_is_punct('(')) {
            std::shared_ptr<const FunctionProgram> keep = *fn;
            return in_.call_function(t, *keep);
        }
        Value value = *v;
        while (auto arr = std::get_if<std::shared_ptr<ArrayValue>>(&value)) {
            // Checked on the raw stream: `#declare D = Array` followed by a directive
            // must not run that directive before D exists.
            if (!in_.raw_next_is_punct('[')) break;
            std::shared_ptr<ArrayValue> a = *arr;
            size_t flat = 0;
            for (size_t d = 0; d < a->dims.size(); ++d) {
                Token open = in_.next();
                if (!in_.is_punct(open, '['))
                    in_.expected("'[' for the next subscript", open);
                Token at = in_.peek();
                double index = arg_float();
                in_.expect_punct(']');
                int i = saturating_int(index);
                if (i < 0 || i >= a->dims[d]) {
                    in_.error(at, "array subscript " + std::to_string(i) +
                                      " out of range 0.." +
                                      std::to_string(a->dims[d] - 1));
                }
                flat = flat * a->dims[d] + size_t(i);
            }
            value = a->items[flat];
            if (std::holds_alternative<std::monostate>(value)) {
                in_.error(t, "array element of '" + std::string(w) +
                                 "' used before it was set");
            }
        }
        return value;
    }
    // rand() first: generated scenes call it in their innermost loops.
    if (w == "rand") {
        in_.expect_punct('(');
        Token at = in_.peek();
        double s = arg_float();
        in_.expect_punct(')');
        return Numeric::scalar(in_.draw_random(saturating_int(s), at));
    }
    if (w == "pi") return Numeric::scalar(kPi);
    if (w == "tau") return Numeric::scalar(2 * kPi);
    if (w == "true" || w == "yes" || w == "on") return Numeric::scalar(1);
    if (w == "false" || w == "no" || w == "off") return Numeric::scalar(0);
    if (w == "x") return Numeric::vector({1, 0, 0});
    if (w == "y") return Numeric::vector({0, 1, 0});
    if (w == "z") return Numeric::vector({0, 0, 1});
    if (w == "t") {
        Numeric n;
        n.size = 4;
        n.c[3] = 1;
        return n;
    }
    if (w == "u") {
        Numeric n;
        n.size = 2;
        n.c[0] = 1;
        return n;
    }
    if (w == "v") {
        Numeric n;
        n.size = 2;
        n.c[1] = 1;
        return n;
    }
    const ParseOptions& o = in_.options();
    if (w == "clock") return Numeric::scalar(o.clock);
    if (w == "clock_delta") return Numeric::scalar(o.clock_delta);
    if (w == "clock_on") return Numeric::scalar(o.final_frame > o.initial_frame ? 1 : 0);
    if (w == "image_width") return Numeric::scalar(o.image_width);
    if (w == "image_height") return Numeric::scalar(o.image_height);
    if (w == "frame_number") return Numeric::scalar(o.frame_number);
    if (w == "initial_frame") return Numeric::scalar(o.initial_frame);
    if (w == "final_frame") return Numeric::scalar(o.final_frame);
    if (w == "initial_clock") return Numeric::scalar(o.initial_clock);
    if (w == "final_clock") return Numeric::scalar(o.final_clock);
    if (w == "version") return Numeric::scalar(in_.language_version() / 100.0);
    if (const FloatFunction* f = find_float_function(w))
        return call_float(t, f->arity, f->fn);
    if (w == "bitwise_and" || w == "bitwise_or" || w == "bitwise_xor") {
        in_.expect_punct('(');
        // Each further argument only after a comma, as POV-Ray requires.
        long long r = (long long)arg_sum();
        while (in_.accept_punct(',')) {
            long long b = (long long)arg_sum();
            r = w == "bitwise_and" ? (r & b) : w == "bitwise_or" ? (r | b) : (r ^ b);
        }
        in_.expect_punct(')');
        return Numeric::scalar(double(r));
    }
    if (w == "min" || w == "max") {
        in_.expect_punct('(', "after ", w);
        double r = arg_sum();
        while (in_.accept_punct(',')) {
            double b = arg_sum();
            r = w == "min" ? std::min(r, b) : std::max(r, b);
        }
        in_.expect_punct(')');
        return Numeric::scalar(r);
    }
    if (w == "select") {
        // select(c[,] a[,] b [, d]): the fourth argument only after a comma.
        in_.expect_punct('(');
        double c = arg_sum();
        in_.accept_punct(',');
        Value a = ExpressionParser(in_, false, false).parse();
        in_.accept_punct(',');
        Value b = ExpressionParser(in_, false, false).parse();
        Value r;
        if (in_.accept_punct(',')) {
            Value d = ExpressionParser(in_, false, false).parse();
            r = c < 0 ? a : (c == 0 ? b : d);
        } else {
            r = c < 0 ? a : b;
        }
        in_.expect_punct(')');
        return r;
    }
    if (w == "seed") {
        in_.expect_punct('(');
        double s = arg_float();
        in_.expect_punct(')');
        return Numeric::scalar(in_.new_random_stream(saturating_int(s)));
    }
    if (w == "vlength") {
        in_.expect_punct('(');
        Vector3 v = arg_vector();
        in_.expect_punct(')');
        return Numeric::scalar(length(v));
    }
    if (w == "min_extent" || w == "max_extent") {
        in_.expect_punct('(');
        Token id = in_.next();
        const Value* v = id.kind == TokenKind::Word ? in_.lookup(id) : nullptr;
        // max_extent of an image_map pigment: the image's size in pixels.
        if (auto pigment = v ? std::get_if<std::shared_ptr<Pigment>>(v) : nullptr;
            pigment && w == "max_extent") {
            const PatternSpec* spec = &(*pigment)->pattern.get();
            if (spec->kind != PatternKind::ImageMap || !spec->image)
                in_.error(id,
                          "the parameter to max_extent must be an image map pigment "
                          "identifier");
            if (!spec->image->pixels) in_.unsupported(t, "max_extent of an image");
            in_.expect_punct(')');
            return Numeric::vector(Vector3{double(spec->image->pixels->width),
                                           double(spec->image->pixels->height), 0.0});
        }
        auto object = v ? std::get_if<std::shared_ptr<Object>>(v) : nullptr;
        if (!object) in_.expected("an object identifier", id);
        in_.expect_punct(')');
        return Numeric::vector(in_.object_extent(t, **object, w == "max_extent"));
    }
    if (w == "trace") {
        in_.expect_punct('(');
        const std::shared_ptr<Object> object = in_.object_argument(in_.next());
        in_.accept_punct(',');
        const Vector3 origin = arg_vector();
        in_.accept_punct(',');
        const Vector3 direction = arg_vector();
        in_.accept_punct(',');
        // The optional fourth argument: a vector identifier, written in place.
        std::optional<Token> normal_id;
        if (const Token& n = in_.peek(); n.kind == TokenKind::Word) {
            const Value* nv = in_.lookup(n);
            auto num = nv ? std::get_if<Numeric>(nv) : nullptr;
            if (!num || num->size != 3 || num->colour)
                in_.expected("a vector identifier for trace's normal, or ')'", n);
            normal_id = in_.next();
        }
        in_.expect_punct(')');
        Vector3 normal;
        const Vector3 hit = in_.trace_object(
            t, object, Point3{origin.x, origin.y, origin.z}, direction, normal);
        if (normal_id && normal_id->sym)
            in_.declare_symbol(normal_id->sym, Numeric::vector(normal), false,
                               *normal_id);
        else if (normal_id)
            in_.declare(std::string(normal_id->text), Numeric::vector(normal), false,
                        *normal_id);
        return Numeric::vector(hit);
    }
    if (w == "inside") {
        in_.expect_punct('(');
        const Token id = in_.next();
        const std::shared_ptr<Object> object = in_.object_argument(id);
        in_.accept_punct(',');
        const Vector3 p = arg_vector();
        in_.expect_punct(')');
        return Numeric::scalar(
            in_.inside_object(t, id, object, Point3{p.x, p.y, p.z}) ? 1.0 : 0.0);
    }
    if (w == "vnormalize") {
        in_.expect_punct('(');
        Vector3 v = arg_vector();
        in_.expect_punct(')');
        return Numeric::vector(normalize(v));
    }
    if (w == "vdot" || w == "vcross" || w == "vrotate") {
        in_.expect_punct('(');
        Vector3 a = arg_vector();
        in_.accept_punct(',');
        Vector3 b = arg_vector();
        in_.expect_punct(')');
        if (w == "vdot") return Numeric::scalar(dot(a, b));
        if (w == "vcross") return Numeric::vector(cross(a, b));
        return Numeric::vector(rotate_vector(a, b));
    }
    if (w == "vaxis_rotate") {
        in_.expect_punct('(');
        Vector3 a = arg_vector();
        in_.accept_punct(',');
        Vector3 b = arg_vector();
        in_.accept_punct(',');
        double deg = arg_sum();
        in_.expect_punct(')');
        return Numeric::vector(axis_rotate(a, b, deg));
    }
    if (w == "vturbulence") {
        // vturbulence(Lambda, Omega, Octaves, <point>): POV-Ray's DTurbulence vector.
        in_.expect_punct('(');
        TurbulenceParams tp;
        // vturbulence(l[,] o[,] oct[,] P[,]): a comma after P is allowed too.
        tp.lambda = arg_sum();
        in_.accept_punct(',');
        tp.omega = arg_sum();
        in_.accept_punct(',');
        tp.octaves = std::clamp(saturating_int(arg_sum()), 1, 10);
        in_.accept_punct(',');
        Vector3 p = arg_vector();
        in_.accept_punct(',');
        in_.expect_punct(')');
        return Numeric::vector(dturbulence(p, tp));
    }
    if (w == "strcmp") {
        // strcmp(a[,] b): the difference of the first characters that differ, as
        // POV-Ray 3.7 returns it (0 when equal).
        in_.expect_punct('(');
        std::string a = arg_string();
        in_.accept_punct(',');
        std::string b = arg_string();
        in_.expect_punct(')');
        return Numeric::scalar(double(compare_strings(a, b)));
    }
    if (w == "strlen") {
        in_.expect_punct('(');
        std::string s = arg_string();
        in_.expect_punct(')');
        return Numeric::scalar(double(s.size()));
    }
    if (w == "val") {
        in_.expect_punct('(');
        std::string s = arg_string();
        in_.expect_punct(')');
        return Numeric::scalar(std::atof(s.c_str()));
    }
    if (w == "asc") {
        in_.expect_punct('(');
        std::string s = arg_string();
        in_.expect_punct(')');
        return Numeric::scalar(s.empty() ? 0 : (unsigned char)s[0]);
    }
    if (w == "file_exists") {
        in_.expect_punct('(');
        const Token at = in_.peek();
        std::string s = arg_string();
        in_.expect_punct(')');
        // Where #fopen would find it for reading (POV-Ray: Locate_File, as for reading).
        std::error_code ec;
        if (std::filesystem::path(s).is_absolute() || s.empty())
            return Numeric::scalar(std::filesystem::is_regular_file(s, ec) ? 1 : 0);
        return Numeric::scalar(in_.user_file_path(s, false, at).empty() ? 0 : 1);
    }
    if (w == "defined") {
        in_.expect_punct('(');
        Token id = in_.next();
        in_.expect_punct(')');
        return Numeric::scalar(in_.lookup(id) ? 1 : 0);
    }
    if (w == "dimensions" || w == "dimension_size") {
        in_.expect_punct('(');
        Token id = in_.next();
        // A copy: the argument may end the frame that holds the binding.
        std::shared_ptr<ArrayValue> arr;
        if (auto a = std::get_if<std::shared_ptr<ArrayValue>>(in_.lookup(id))) arr = *a;
        if (!arr) in_.error(id, "'" + std::string(id.text) + "' is not an array");
        double r;
        if (w == "dimensions") {
            r = double(arr->dims.size());
        } else {
            in_.accept_punct(',');
            int d = saturating_int(arg_sum());
            r = (d >= 1 && d <= int(arr->dims.size())) ? arr->dims[d - 1] : 0;
        }
        in_.expect_punct(')');
        return Numeric::scalar(r);
    }
    if (w == "now") {
        // Days since 2000-01-01 00:00 UTC, as POV-Ray's `now`.
        const double seconds = std::chrono::duration<double>(
                                   std::chrono::system_clock::now().time_since_epoch())
                                   .count();
        return Numeric::scalar((seconds - 946684800.0) / 86400.0);
    }
    if (w == "str" || w == "chr" || w == "concat" || w == "substr" || w == "strupr" ||
        w == "strlwr" || w == "vstr" || w == "datetime") {
        in_.unget(t);
        return in_.parse_string();
    }
    if (is_colour_keyword(w)) {
        in_.unget(t);
        return in_.parse_colour(hold_);
    }
    if (w.find('[') != std::string_view::npos) {
        in_.error(t, "array element '" + std::string(w) + "' used before it was set");
    }
    return in_.parse_item_value(t);
}

Value Interpreter::parse_expression_value(bool hold_directives) {
    peek();
    if (Numeric n; try_compiled_expression(true, false, n)) return n;
    return ExpressionParser(*this, false, true, hold_directives).parse();
}

const Token& Interpreter::peek_after_operand(bool hold_directives) {
    if (!hold_directives || !pushback_.empty()) return peek();
    // The raw token, past the ends of finished macro bodies and files as next() goes;
    // left in the stream, so that a directive or macro call runs after the value is
    // stored (POV-Ray hands back its HASH or MACRO_ID token unrun).
    const Token t = peek_raw_past_frame_ends();
    if (t.kind == TokenKind::End) return peek();
    bool held = t.kind == TokenKind::Directive;
    if (t.kind == TokenKind::Word) {
        const Value* v = lookup(t);
        held = v && std::holds_alternative<std::shared_ptr<Macro>>(*v);
    }
    if (!held) return peek();
    held_token_ = t;
    return held_token_;
}

void Interpreter::not_numeric(const Value& v, const Token& at) {
    // POV-Ray's Parse_Express meets a string as the left side of a comparison.
    if (std::holds_alternative<std::string>(v))
        expected("a string comparison operator", peek());
    error(at, std::string("expected a numeric expression but found ") + type_name(v));
}
Value Interpreter::parse_value_additive() {
    peek();
    if (Numeric n; try_compiled_expression(false, false, n)) return n;
    return ExpressionParser(*this, false, false).parse();
}

Numeric Interpreter::parse_numeric(bool no_gt, bool hold_directives) {
    Token at = peek();
    if (Numeric n; try_compiled_expression(false, no_gt, n)) return n;
    Value v = ExpressionParser(*this, no_gt, false, hold_directives).parse();
    if (auto n = std::get_if<Numeric>(&v)) return *n;
    error(at, std::string("expected a numeric expression but found ") + type_name(v));
}

Numeric Interpreter::parse_express(bool hold_directives) {
    Token at = peek();
    if (Numeric n; try_compiled_expression(true, false, n)) return n;
    Value v = ExpressionParser(*this, false, true, hold_directives).parse();
    if (auto n = std::get_if<Numeric>(&v)) return *n;
    not_numeric(v, at);
}

double Interpreter::parse_float() {
    Numeric n = parse_numeric();
    return n.c[0];
}

double Interpreter::parse_single() {
    const double v = parse_float();
    // Past float's range the conversion is undefined in C++; the FPU gives infinity.
    if (std::fabs(v) > double(std::numeric_limits<float>::max()) && std::isfinite(v))
        return std::copysign(std::numeric_limits<double>::infinity(), v);
    return double(static_cast<float>(v));
}

double Interpreter::parse_condition() {
    Token open = next();
    if (!is_punct(open, '(')) {
        unget(open);
        return parse_float();
    }
    Token at = peek();
    if (Numeric n; try_compiled_expression(true, false, n)) {
        expect_punct(')', "to close the condition");
        return n.c[0];
    }
    Value v = ExpressionParser(*this, false).parse();
    const Numeric* np = std::get_if<Numeric>(&v);
    if (!np) not_numeric(v, at);
    Numeric n = *np;
    expect_punct(')', "to close the condition");
    return n.c[0];
}

Vector3 Interpreter::parse_vector() { return parse_numeric().vec3(); }

ProfilePoint Interpreter::parse_uv_vector() {
    const Token at = peek();
    // POV-Ray's Parse_Rel_Factor: no comparisons, so `<0, 0> <1, 0>` is two points.
    const Numeric v = parse_numeric();
    if (v.size > 2) error(at, "UV_Vector expected but vector or color expression found");
    return {v.c[0], v.size == 1 ? v.c[0] : v.c[1]};
}

std::string Interpreter::parse_string() {
    Token t = next();
    if (t.kind == TokenKind::String) return std::string(t.text);
    if (t.kind == TokenKind::Word) {
        std::string_view w = t.text;
        if (lookup(t)) {
            unget(t);
            // An operand only: `S = "a"` after it is the caller's comparison.
            Value val = ExpressionParser(*this, false, false).parse();
            if (auto s = std::get_if<std::string>(&val)) return *s;
            error(t, std::string("expected a string but found ") + type_name(val));
        }
        if (w == "str") {
            expect_punct('(');
            double v = parse_float();
            accept_punct(',');
            // Past the buffer a width or precision changes nothing but the cost.
            int width = std::clamp(parse_int(), -500, 500);
            accept_punct(',');
            int prec = std::clamp(parse_int(), -1, 100);
            expect_punct(')');
            char buf[512];
            if (prec < 0) {
                // A negative precision means printf's default (6 digits), as POV-Ray
                // prints.
                std::snprintf(buf, sizeof buf, width < 0 ? "%0*f" : "%*f",
                              std::abs(width), v);
            } else {
                std::snprintf(buf, sizeof buf, width < 0 ? "%0*.*f" : "%*.*f",
                              std::abs(width), prec, v);
            }
            return buf;
        }
        if (w == "datetime") {
            // datetime(DAYS [, FORMAT]): DAYS since 2000-01-01 00:00 UTC through
            // strftime, in UTC.
            expect_punct('(');
            const Token at = peek();
            const double days = parse_float();
            std::string format = "%Y-%m-%d %H:%M:%SZ";
            accept_punct(',');  // datetime(t[,] [format]): `datetime(t,)` too
            if (!accept_punct(')')) {
                format = parse_string();
                expect_punct(')');
            }
            const double secs = std::floor(days * 86400.0 + 946684800.0);
            if (!(std::fabs(secs) < 1e15))
                error(at, "datetime: the time is out of range");
            const std::time_t when = std::time_t(secs);
            std::tm tm{};
            gmtime_r(&when, &tm);
            char buf[512];
            const size_t n =
                format.empty() ? 0 : std::strftime(buf, sizeof buf, format.c_str(), &tm);
            return std::string(buf, n);
        }
        if (w == "vstr") {
            expect_punct('(');
            Token dims_at = peek();
            double dims = parse_float();
            if (!(dims >= 2 && dims < 6))
                error(dims_at, "vstr: the number of components must be 2 to 5");
            accept_punct(',');
            Numeric v = parse_numeric();
            accept_punct(',');
            std::string sep = parse_string();
            accept_punct(',');
            int width = std::clamp(parse_int(), -100, 100);
            accept_punct(',');
            int prec = std::clamp(parse_int(), -1, 60);
            expect_punct(')');
            std::string out;
            v = promote(v, int(dims));
            for (int i = 0; i < int(dims) && i < 5; ++i) {
                char buf[128];
                std::snprintf(buf, sizeof buf, "%*.*f", width, prec, v.c[i]);
                if (i) out += sep;
                out += buf;
            }
            return out;
        }
        if (w == "chr") {
            expect_punct('(');
            int c = parse_int();
            expect_punct(')');
            return std::string(1, char(c));
        }
        if (w == "concat") {
            expect_punct('(');
            // concat(a[,] b[,] c ...): strings with optional commas between them.
            std::string s = parse_string();
            while (!accept_punct(')')) {
                accept_punct(',');
                s += parse_string();
            }
            return s;
        }
        if (w == "substr") {
            expect_punct('(');
            std::string s = parse_string();
            accept_punct(',');
            int start = parse_int();
            accept_punct(',');
            int len = parse_int();
            expect_punct(')');
            if (start < 1 || int64_t(start) - 1 + len > int64_t(s.size()) || len < 0) {
                error(t, "substr arguments out of range");
            }
            return s.substr(size_t(start - 1), size_t(len));
        }
        if (w == "strupr" || w == "strlwr") {
            expect_punct('(');
            std::string s = parse_string();
            expect_punct(')');
            for (char& c : s) c = char(w == "strupr" ? std::toupper(c) : std::tolower(c));
            return s;
        }
    }
    expected("a string", t);
}

}  // namespace povwall::parser
