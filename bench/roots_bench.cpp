// Time per call of each quartic method on ray-torus quartics (bench/roots_cases.h), per
// minor/major ratio; docs/numerics.md pairs these with bench/roots_accuracy.cpp's errors.
#include <benchmark/benchmark.h>

#include "bench/roots_cases.h"
#include "trace/roots.h"

using namespace povwall;

namespace {

enum Method { FerrariNoPolish, FerrariNewton, FerrariCompensated, Sturm, Auto };

void BM_Quartic(benchmark::State& state) {
    const double ratio = bench::kRatios[state.range(1)];
    const auto cases = bench::torus_cases(ratio, 1024);
    const Method m = Method(state.range(0));
    size_t i = 0;
    for (auto _ : state) {
        const auto& q = cases[i++ & 1023].q;
        double roots[4];
        int n;
        switch (m) {
            case FerrariNoPolish:
            case FerrariNewton:
            case FerrariCompensated:
                n = trace::solve_quartic_ferrari(q.c, roots, trace::QuarticPolish(m));
                break;
            case Sturm:
                n = trace::solve_quartic_sturm(q.c, q.lo, q.hi, roots);
                break;
            default:
                n = trace::solve_quartic(q.c, q.lo, q.hi, roots);
                break;
        }
        benchmark::DoNotOptimize(n);
        benchmark::DoNotOptimize(roots[0]);
    }
    static const char* names[] = {"ferrari", "ferrari+newton", "ferrari+compensated",
                                  "sturm", "auto"};
    state.SetLabel(std::string(names[m]) + " r/R=" + std::to_string(ratio));
}
BENCHMARK(BM_Quartic)->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1, 2, 3, 4, 5}});

void BM_Quadratic(benchmark::State& state) {
    double b = -2e5 - 37.25, c = 1e5 * 37.25, r[2];
    for (auto _ : state) {
        benchmark::DoNotOptimize(b);
        int n = state.range(0) ? trace::solve_quadratic(1, b, c, r)
                               : trace::solve_quadratic_naive(1, b, c, r);
        benchmark::DoNotOptimize(n);
        benchmark::DoNotOptimize(r[0]);
    }
    state.SetLabel(state.range(0) ? "stable" : "naive");
}
BENCHMARK(BM_Quadratic)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
