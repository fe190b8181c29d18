// Spline rules that POV-Ray 3.7 shows (tests/lang/splines.pov compares every kind with
// povray's own output, bit for bit).
#include "core/spline.h"

#include <gtest/gtest.h>

namespace povwall {
namespace {

Spline make(Spline::Kind kind, std::initializer_list<std::pair<double, double>> pts) {
    Spline s;
    s.kind = kind;
    for (auto [t, v] : pts) spline_insert(s, t, {v, 2 * v, 0, 0, 0});
    return s;
}

TEST(Spline, LinearClampsOutsideAndInterpolatesInside) {
    Spline s = make(Spline::Kind::Linear, {{2, 4}, {0, 0}});  // sorted on insert
    EXPECT_EQ(s.points[0].t, 0);
    EXPECT_EQ(spline_evaluate(s, 0.5)[0], 1.0);
    EXPECT_EQ(spline_evaluate(s, 0.5)[1], 2.0);
    EXPECT_EQ(spline_evaluate(s, -7)[0], 0.0);
    EXPECT_EQ(spline_evaluate(s, 9)[0], 4.0);
}

TEST(Spline, RepeatedTReplacesExceptTheLargest) {
    Spline s =
        make(Spline::Kind::Linear, {{0, 1}, {1, 2}, {2, 3}, {1, 7}, {2, 9}, {0, 5}});
    ASSERT_EQ(s.points.size(), 3u);
    EXPECT_EQ(s.points[0].v[0], 5);  // replaced
    EXPECT_EQ(s.points[1].v[0], 7);  // replaced
    EXPECT_EQ(s.points[2].v[0], 3);  // POV-Ray 3.7 drops a repeat of the largest t
    Spline one = make(Spline::Kind::Linear, {{0, 1}, {0, 4}});
    EXPECT_EQ(one.points[0].v[0], 4);  // with one point the repeat replaces it
}

TEST(Spline, CubicUsesTheOuterPointsOnlyAsControls) {
    Spline two = make(Spline::Kind::Cubic, {{0, 1}, {2, 5}});
    EXPECT_EQ(spline_evaluate(two, 0.3)[0], 3.0);  // the average, for every p
    Spline three = make(Spline::Kind::Cubic, {{0, 1}, {1, 4}, {2, 9}});
    EXPECT_EQ(spline_evaluate(three, 1.7)[0], 4.0);  // always the middle point
    Spline four = make(Spline::Kind::Cubic, {{0, 0}, {1, 1}, {2, 2}, {3, 3}});
    EXPECT_EQ(spline_evaluate(four, 1.5)[0], 1.5);  // a straight line stays straight
    EXPECT_EQ(spline_evaluate(four, 0.2)[0], 1.0);  // below the second point
    EXPECT_EQ(spline_evaluate(four, 2.9)[0], 2.0);  // past the next-to-last
}

TEST(Spline, NaturalHasZeroCurvatureAtTheEnds) {
    Spline s = make(Spline::Kind::Natural, {{0, 0}, {1, 1}, {2, 0}});
    EXPECT_EQ(s.second_derivatives[1][0], -3.0);
    EXPECT_EQ(s.second_derivatives[0][0], 0.0);
    EXPECT_EQ(s.second_derivatives[2][0], 0.0);
    EXPECT_DOUBLE_EQ(spline_evaluate(s, 0.5)[0], 0.6875);
    // The kind can be chosen per call, the spline unchanged (POV-Ray's S(p, kind)).
    EXPECT_EQ(spline_evaluate(s, 0.5, Spline::Kind::Linear)[0], 0.5);
}

}  // namespace
}  // namespace povwall
