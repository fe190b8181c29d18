// POV-Ray's `spline { }`: points (t, value) kept sorted by t and evaluated in all five
// components with POV-Ray 3.7's formulas, in its order of operations, so the values match
// its bits. Plain data with free functions; the parser builds them, and a function or
// pattern evaluated at render time can hold one.
#pragma once

#include <array>
#include <vector>

namespace povwall {

struct Spline {
    enum class Kind { Linear, Quadratic, Cubic, Natural };
    struct Point {
        double t;
        std::array<double, 5> v;
    };
    Kind kind = Kind::Linear;
    int terms = 2;              // components a call returns: the widest point, at least 2
    std::vector<Point> points;  // ascending t
    // Natural splines' second derivatives per point and component (solved by insert()).
    std::vector<std::array<double, 5>> second_derivatives;
};

// Adds a point as POV-Ray 3.7 does: a point at an existing t replaces it, except that a
// repeat of the largest t (with two or more points) is dropped.
void spline_insert(Spline& s, double t, const std::array<double, 5>& v);
// The value at `p` as `kind` (POV-Ray's `S(p, kind)`); the values outside the points'
// range are the end values (cubic: the second and next-to-last points). Needs a point.
std::array<double, 5> spline_evaluate(const Spline& s, double p, Spline::Kind kind);
inline std::array<double, 5> spline_evaluate(const Spline& s, double p) {
    return spline_evaluate(s, p, s.kind);
}

}  // namespace povwall
