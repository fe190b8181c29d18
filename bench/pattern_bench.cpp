// Time per evaluation of the patterns of textures II (block patterns, fractals, tilings,
// the cubic warp) against checker and bozo as yardsticks, over 4096 points of a plane.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "trace/pattern.h"

using namespace povwall;

namespace {

std::vector<Point3> plane_points() {
    std::vector<Point3> points;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j)
            points.push_back({-3.0 + i * 0.0937, 0.37 + j * 0.001, -2.5 + j * 0.0813});
    return points;
}

struct Case {
    std::string name;
    PatternSpec spec;
};

std::vector<Case> cases() {
    auto kind = [](PatternKind k, Real scalar = 0) {
        PatternSpec s;
        s.kind = k;
        s.scalar = scalar;
        return s;
    };
    std::vector<Case> c = {{"checker", kind(PatternKind::Checker)},
                           {"bozo", kind(PatternKind::Bozo)},
                           {"square", kind(PatternKind::Square)},
                           {"triangular", kind(PatternKind::Triangular)},
                           {"cubic", kind(PatternKind::Cubic)},
                           {"mandel 30", kind(PatternKind::Mandel, 30)},
                           {"julia 30", kind(PatternKind::Julia, 30)},
                           {"magnet 1 mandel 30", kind(PatternKind::Magnet, 30)}};
    PatternSpec mandel5 = kind(PatternKind::Mandel, 30);
    mandel5.fractal.exponent = 5;
    c.push_back({"mandel 30 exponent 5", mandel5});
    c[6].spec.fractal.c_re = -0.745;
    c[6].spec.fractal.c_im = 0.113;
    for (int n : {1, 5, 16, 22}) {
        c.push_back({"tiling " + std::to_string(n), kind(PatternKind::Tiling, n)});
    }
    PatternSpec warped = kind(PatternKind::Checker);
    Warp w;
    w.kind = Warp::Kind::Cubic;
    warped.warps.push_back(w);
    c.push_back({"checker warp { cubic }", warped});
    return c;
}

void BM_Pattern(benchmark::State& state) {
    static const std::vector<Point3> points = plane_points();
    static const std::vector<Case> all = cases();
    const Case& c = all[size_t(state.range(0))];
    const trace::PatternEnv env;
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            trace::evaluate_pattern(c.spec, points[i++ & (points.size() - 1)], env));
    }
    state.SetLabel(c.name);
}
BENCHMARK(BM_Pattern)->DenseRange(0, 13);

}  // namespace

BENCHMARK_MAIN();
