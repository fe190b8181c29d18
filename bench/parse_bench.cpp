// Parse time of the issue-3 speed bar scenes, in process (no start-up, no output): the
// 5000-sphere seed scene, the 100,000-iteration #while benchmark and a 1,000,000-triangle
// mesh2 written here the way exporters write them. Side by side with POV-Ray:
// scripts/bench-parse (docs/performance.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "parser/parser.h"

namespace {

using povwall::parser::ParseOptions;

void parse_file(benchmark::State& state, const std::string& path) {
    ParseOptions options;
    for (auto _ : state) {
        povwall::Scene scene = povwall::parser::parse_scene_file(path, options);
        benchmark::DoNotOptimize(scene.objects.size());
    }
}

// A grid of `triangles` triangles over a wavy surface, one `<x, y, z>,` per line.
std::string mesh2_text(int triangles) {
    int side = std::max(1, int(std::sqrt(triangles / 2.0)));
    int rows = (triangles + 2 * side - 1) / (2 * side);
    std::string text = "#version 3.7;\nmesh2 {\n  vertex_vectors {\n    ";
    text += std::to_string((rows + 1) * (side + 1)) + ",\n";
    char line[96];
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= side; ++i) {
            double u = double(i) / side, v = double(j) / rows;
            std::snprintf(line, sizeof line, "    <%.6f, %.6f, %.6f>,\n", u,
                          0.05 * std::sin(9 * u) * std::cos(7 * v), v);
            text += line;
        }
    }
    text += "  }\n  face_indices {\n    " + std::to_string(triangles) + ",\n";
    int written = 0;
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < side; ++i) {
            int a = j * (side + 1) + i;
            int faces[2][3] = {{a, a + 1, a + side + 2}, {a, a + side + 2, a + side + 1}};
            for (auto& f : faces) {
                if (written++ >= triangles) break;
                std::snprintf(line, sizeof line, "    <%d, %d, %d>,\n", f[0], f[1], f[2]);
                text += line;
            }
        }
    }
    text += "  }\n  pigment { color rgb 1 }\n}\n";
    return text;
}

void BM_ParseSeedScene(benchmark::State& state) {
    parse_file(state, POVWALL_SOURCE_DIR "/scenes/demo/walls.pov");
}
BENCHMARK(BM_ParseSeedScene)->Unit(benchmark::kMillisecond);

void BM_ParseManySpheres(benchmark::State& state) {
    parse_file(state, POVWALL_SOURCE_DIR "/scenes/bench/many_spheres.pov");
}
BENCHMARK(BM_ParseManySpheres)->Unit(benchmark::kMillisecond);

void BM_ParseMesh2(benchmark::State& state) {
    std::string text = mesh2_text(int(state.range(0)));
    ParseOptions options;
    for (auto _ : state) {
        povwall::Scene scene =
            povwall::parser::parse_scene_text(text, "mesh2.pov", options);
        benchmark::DoNotOptimize(scene.objects.size());
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(text.size()));
}
BENCHMARK(BM_ParseMesh2)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
