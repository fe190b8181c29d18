// Scene preparation time (primitives, materials, octree) on one thread, in process: the
// seed scene, 1,200 copies of a mesh (scenes/bench/mesh_copies.pov), and 162 copies of
// one brick at one transform (scenes/stress/coincident_bricks.pov), whose octree build
// did not end before the build stopped splitting copies (docs/performance.md). Parsed
// once; each iteration prepares again.
// Run: build/bench/povwall_prepare_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <string>

#include "parser/parser.h"
#include "trace/prepared_scene.h"

namespace {

void prepare(benchmark::State& state, const std::string& path) {
    povwall::parser::ParseOptions options;
    const povwall::Scene scene = povwall::parser::parse_scene_file(path, options);
    povwall::trace::PrepareOptions one_thread;
    one_thread.threads = 1;
    uint64_t references = 0, primitives = 0;
    for (auto _ : state) {
        povwall::trace::PreparedScene prepared(scene, nullptr, one_thread);
        references = prepared.tree().stats().references;
        primitives = prepared.tree().primitive_count();
        benchmark::DoNotOptimize(references);
    }
    state.counters["primitives"] = double(primitives);
    state.counters["references"] = double(references);
}

void BM_PrepareSeedScene(benchmark::State& state) {
    prepare(state, POVWALL_SOURCE_DIR "/scenes/demo/walls.pov");
}
BENCHMARK(BM_PrepareSeedScene)->Unit(benchmark::kMillisecond);

void BM_PrepareCoincidentBricks(benchmark::State& state) {
    prepare(state, POVWALL_SOURCE_DIR "/scenes/stress/coincident_bricks.pov");
}
BENCHMARK(BM_PrepareCoincidentBricks)->Unit(benchmark::kMillisecond);

// 1,200 copies of one 480-triangle mesh, each at its own matrix (LeoCAD and LDraw
// exports): 1,200 primitives, each copy whole (they share the mesh's face tree, built on
// the first ray, not here). Before copies were shared, 576,000 triangles.
void BM_PrepareMeshCopies(benchmark::State& state) {
    prepare(state, POVWALL_SOURCE_DIR "/scenes/bench/mesh_copies.pov");
}
BENCHMARK(BM_PrepareMeshCopies)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
