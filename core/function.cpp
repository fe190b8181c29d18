// The function program's interpreter and the float built-ins (see core/function.h).
#include "core/function.h"

#include <climits>
#include <cmath>

#include "core/internal_function.h"
#include "core/pov_angles.h"

namespace povwall {

const FloatBuiltin* find_float_builtin(std::string_view name) {
    using F = FloatBuiltin;
    static const F kFunctions[] = {
        {"abs", 1, [](const double* a) { return std::fabs(a[0]); }},
        {"acos", 1, [](const double* a) { return std::acos(a[0]); }},
        {"acosh", 1, [](const double* a) { return std::acosh(a[0]); }},
        {"asin", 1, [](const double* a) { return std::asin(a[0]); }},
        {"asinh", 1, [](const double* a) { return std::asinh(a[0]); }},
        {"atan", 1, [](const double* a) { return std::atan(a[0]); }},
        {"atanh", 1, [](const double* a) { return std::atanh(a[0]); }},
        {"ceil", 1, [](const double* a) { return std::ceil(a[0]); }},
        {"cos", 1, [](const double* a) { return std::cos(a[0]); }},
        {"cosh", 1, [](const double* a) { return std::cosh(a[0]); }},
        // As POV-Ray's function compiler rounds them (times 180 / M_PI, times M_PI / 180,
        // which is its M_PI_180): the scene language's degrees() divides instead
        // (parser/expressions.cpp).
        {"degrees", 1, [](const double* a) { return a[0] * (180 / kPi); }},
        {"radians", 1, [](const double* a) { return a[0] * kPovRadiansPerDegree; }},
        {"exp", 1, [](const double* a) { return std::exp(a[0]); }},
        {"floor", 1, [](const double* a) { return std::floor(a[0]); }},
        {"int", 1, [](const double* a) { return std::trunc(a[0]); }},
        {"ln", 1, [](const double* a) { return std::log(a[0]); }},
        {"log", 1, [](const double* a) { return std::log10(a[0]); }},
        {"sin", 1, [](const double* a) { return std::sin(a[0]); }},
        {"sinh", 1, [](const double* a) { return std::sinh(a[0]); }},
        {"sqrt", 1, [](const double* a) { return std::sqrt(a[0]); }},
        {"tan", 1, [](const double* a) { return std::tan(a[0]); }},
        {"tanh", 1, [](const double* a) { return std::tanh(a[0]); }},
        {"atan2", 2, [](const double* a) { return std::atan2(a[0], a[1]); }},
        {"pow", 2, [](const double* a) { return std::pow(a[0], a[1]); }},
        {"mod", 2, [](const double* a) { return std::fmod(a[0], a[1]); }},
        {"div", 2, [](const double* a) { return std::trunc(a[0] / a[1]); }},
    };
    for (const F& f : kFunctions) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

namespace {

// C's (int) conversion as x86-64 does it: out of range (and NaN) gives INT_MIN.
double int32_cast(double v) {
    if (!(v > -2147483649.0 && v < 2147483648.0)) return double(INT_MIN);
    return double(int(v));
}

}  // namespace

double evaluate_function(const FunctionProgram& f, const double* args,
                         const FunctionHooks& hooks) {
    using Op = FunctionProgram::Op;
    double stack[kMaxFunctionStack];
    int top = 0;  // stack[top - 1] is the top
    const size_t end = f.code.size();
    for (size_t next = 0; next < end;) {
        const FunctionProgram::Instruction& in = f.code[next++];
        switch (in.op) {
            case Op::Constant:
                stack[top++] = f.constants[in.index];
                break;
            case Op::Parameter:
                stack[top++] = args[in.index];
                break;
            case Op::Negate:
                stack[top - 1] = -stack[top - 1];
                break;
            case Op::Int:
                stack[top - 1] = int32_cast(stack[top - 1]);
                break;
            case Op::Builtin: {
                const FloatBuiltin* b = f.builtins[in.index];
                top -= b->arity;
                stack[top] = b->fn(stack + top);
                ++top;
                break;
            }
            case Op::Branch: {
                const double a = stack[--top];
                const std::array<uint32_t, 3>& to = f.branches[in.index];
                next = a < 0 ? to[0] : a == 0 ? to[1] : to[2];
                break;
            }
            case Op::Jump:
                next = in.index;
                break;
            case Op::Call: {
                const FunctionProgram& callee = *f.callees[in.index];
                top -= callee.parameter_count();
                stack[top] = evaluate_function(callee, stack + top, hooks);
                ++top;
                break;
            }
            case Op::SplineComponent: {
                const auto v = spline_evaluate(*f.splines[in.index], stack[top - 1]);
                stack[top - 1] = v[in.component];
                break;
            }
            case Op::Pattern: {
                top -= 3;
                const Point3 p(stack[top], stack[top + 1], stack[top + 2]);
                stack[top] = hooks.pattern
                                 ? hooks.pattern(*f.patterns[in.index], p, hooks.context)
                                 : 0.0;
                ++top;
                break;
            }
            case Op::PigmentComponent: {
                top -= 3;
                const Point3 p(stack[top], stack[top + 1], stack[top + 2]);
                float c[5] = {0, 0, 0, 0, 0};
                if (hooks.pigment)
                    hooks.pigment(*f.pigments[in.index], p, hooks.context, c);
                // Component 5: gray; 6: MegaPOV's .hf, (red + green / 255) x 0.996093.
                stack[top] =
                    in.component == 5 ? double(c[0]) * 0.297 + double(c[1]) * 0.589 +
                                            double(c[2]) * 0.114
                    : in.component == 6
                        ? (double(c[0]) + double(c[1]) * (1.0 / 255.0)) * 0.996093
                        : double(c[in.component]);
                ++top;
                break;
            }
            case Op::Internal: {
                top -= 3 + internal_extra(int(in.index));
                stack[top] = internal_function(int(in.index), stack + top, hooks);
                ++top;
                break;
            }
            case Op::TransformComponent: {
                top -= 3;
                const Point3 p = f.transforms[in.index]->point(
                    Point3(stack[top], stack[top + 1], stack[top + 2]));
                stack[top] = in.component == 0 ? p.x : in.component == 1 ? p.y : p.z;
                ++top;
                break;
            }
            case Op::Sum:
            case Op::Product: {
                const FunctionProgram& body = *f.callees[in.index];
                const int n = f.parameter_count();
                double a[kMaxFunctionParameters + 1];
                for (int i = 0; i < n; ++i) a[i] = args[i];
                top -= 2;
                const double hi = stack[top + 1];
                double acc = in.op == Op::Sum ? 0.0 : 1.0;
                for (a[n] = stack[top]; a[n] <= hi; a[n] += 1) {
                    if (hooks.iterations_left && (*hooks.iterations_left)-- == 0) {
                        *hooks.iterations_left = 0;
                        break;
                    }
                    const double v = evaluate_function(body, a, hooks);
                    acc = in.op == Op::Sum ? acc + v : acc * v;
                }
                stack[top++] = acc;
                break;
            }
            default: {
                const double b = stack[--top];
                double& a = stack[top - 1];
                switch (in.op) {
                    case Op::Add:
                        a = a + b;
                        break;
                    case Op::Subtract:
                        a = a - b;
                        break;
                    case Op::Multiply:
                        a = a * b;
                        break;
                    case Op::Divide:
                        a = a / b;
                        break;
                    case Op::Less:
                        a = b > a ? 1.0 : 0.0;
                        break;
                    case Op::LessEqual:
                        a = (b > a || a == b) ? 1.0 : 0.0;
                        break;
                    case Op::Equal:
                        a = a == b ? 1.0 : 0.0;
                        break;
                    case Op::NotEqual:
                        a = a == b ? 0.0 : 1.0;
                        break;
                    case Op::GreaterEqual:
                        a = b > a ? 0.0 : 1.0;
                        break;
                    case Op::Greater:
                        a = (b > a || a == b) ? 0.0 : 1.0;
                        break;
                    case Op::Div:
                        a = int32_cast(a / b);
                        break;
                    case Op::And:
                        a = (a != 0 && b != 0) ? 1.0 : 0.0;
                        break;
                    case Op::Or:
                        a = (a != 0 || b != 0) ? 1.0 : 0.0;
                        break;
                    case Op::Min:
                        if (!(b >= a)) a = b;
                        break;
                    case Op::Max:
                        if (b > a) a = b;
                        break;
                    default:
                        break;
                }
            }
        }
    }
    return top > 0 ? stack[top - 1] : 0.0;
}

}  // namespace povwall
