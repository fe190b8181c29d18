// The function program interpreter on hand-built programs (tests/lang/functions.pov
// compares compiled functions with POV-Ray's output).
#include "core/function.h"

#include <gtest/gtest.h>

#include <climits>
#include <cmath>

namespace povwall {
namespace {

using Op = FunctionProgram::Op;

TEST(Function, StackProgramWithCallsAndPovRayQuirks) {
    // inner(a) = int(a) ; outer(x, y) = min(y, inner(x) / 2, y * 3) with select
    auto inner = std::make_shared<FunctionProgram>();
    inner->parameter_names = {"a"};
    inner->code = {{Op::Parameter, 0, 0}, {Op::Int, 0, 0}};
    FunctionProgram outer;
    outer.parameter_names = {"x", "y"};
    outer.callees = {inner};
    outer.constants = {2, 3};
    outer.code = {{Op::Parameter, 0, 1}, {Op::Parameter, 0, 0}, {Op::Call, 0, 0},
                  {Op::Constant, 0, 0},  {Op::Divide, 0, 0},    {Op::Min, 0, 0},
                  {Op::Parameter, 0, 1}, {Op::Constant, 0, 1},  {Op::Multiply, 0, 0},
                  {Op::Min, 0, 0}};
    const FunctionHooks none;
    const double a[2] = {9.9, 5};
    EXPECT_EQ(evaluate_function(outer, a, none), 4.5);  // min(5, int(9.9)/2, 15)
    const double big[2] = {3e10, 5};
    EXPECT_EQ(evaluate_function(outer, big, none), double(INT_MIN) / 2);  // C's cast
    // An unordered comparison counts as "greater"; min takes a NaN, max keeps its value.
    FunctionProgram cmp;
    cmp.parameter_names = {"a", "b"};
    cmp.code = {{Op::Parameter, 0, 0}, {Op::Parameter, 0, 1}, {Op::Greater, 0, 0}};
    const double nan_zero[2] = {std::nan(""), 0};
    EXPECT_EQ(evaluate_function(cmp, nan_zero, none), 1.0);
    cmp.code[2].op = Op::Min;
    EXPECT_TRUE(std::isnan(evaluate_function(cmp, nan_zero, none)) == false);
    const double zero_nan[2] = {0, std::nan("")};
    EXPECT_TRUE(std::isnan(evaluate_function(cmp, zero_nan, none)));
    cmp.code[2].op = Op::Max;
    EXPECT_EQ(evaluate_function(cmp, zero_nan, none), 0.0);
}

}  // namespace
}  // namespace povwall
