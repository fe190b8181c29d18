#include "trace/radiosity/pretrace.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

#include "core/hash_fold.h"
#include "trace/camera_interiors.h"
#include "trace/prepared_scene.h"
#include "trace/render.h"
#include "trace/tracer.h"

namespace povwall::trace::radiosity {
namespace {

// A number in [-1, 1) for the jitter of pretrace pixel `x`, `y` of pass `pass`:
// POV-Ray draws from a sequence seeded per pass and block; ours is a hash.
double jitter_value(int pass, double x, double y, int axis) {
    uint64_t h = 0x9e3779b97f4a7c15ull * uint64_t(pass * 2 + axis + 1);
    for (double v : {x, y}) h = hash_fold(h, v);
    return double(h >> 11) / double(1ull << 52) - 1;
}

}  // namespace

std::vector<double> pretrace_sizes(const RadiositySettings& s, int width, int height) {
    const double larger = double(std::max(width, height));
    double start = larger * s.pretrace_start;
    const double end = std::max(1.0, larger * s.pretrace_end);
    int steps =
        int(std::floor(std::log(start / end) / std::log(2.0) + (1.0 - 1e-10))) + 1;
    // POV-Ray allows at most 252 passes (its pass numbers are bytes).
    if (steps > 252) {
        steps = 252;
        start = end * std::pow(2.0, double(steps));
    }
    std::vector<double> sizes;
    for (int p = 0; p < steps; ++p)
        sizes.push_back(std::max(start * std::pow(0.5, p), end));
    return sizes;
}

size_t pretrace_groups(size_t pass, size_t blocks) {
    if (blocks == 0) return 1;
    const size_t doubled = pass < 30 ? size_t(1) << pass : blocks;
    return std::min(doubled, blocks);
}

std::shared_ptr<const RadiosityRender> run_pretrace(const PreparedScene& prepared,
                                                    const CameraInteriors& interiors,
                                                    const RenderSettings& settings,
                                                    int threads) {
    const Scene& scene = prepared.scene();
    if (!scene.settings.radiosity || prepared.plan().quality.level < 9) return nullptr;
    auto render = std::make_shared<RadiosityRender>(
        *scene.settings.radiosity, scene.camera.location, scene.settings.max_trace_level);
    const std::vector<PixelBlock> blocks =
        render_blocks(render_area(settings), settings.block_size);
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    const std::vector<double> sizes =
        pretrace_sizes(*scene.settings.radiosity, settings.width, settings.height);
    std::vector<uint64_t> gathers(size_t(threads), 0);
    for (size_t pass = 0; pass < sizes.size(); ++pass) {
        const double size = sizes[pass];
        const int pass_number = int(pass) + 1;
        // POV-Ray's high-reproducibility pretrace: the blocks are dealt to `groups`
        // chains (block k to chain k mod groups), each traced in block order by one
        // thread, reading the entries its own chain made in this pass.
        const size_t groups = pretrace_groups(pass, blocks.size());
        std::vector<IrradianceCache> group_entries(
            groups, IrradianceCache(render->frame.address_factors()));
        std::atomic<size_t> next{0};
        auto work = [&](int ti) {
            Tracer tracer(prepared);
            RadiosityGatherer gatherer(tracer, render->frame, &render->cache,
                                       pass_number);
            tracer.set_radiosity(&gatherer);
            CameraSamples samples(tracer, scene.camera, interiors, settings);
            float rgbt[4];
            const double jitter = std::min(1.0, size / 2);
            const double offset = (size - 1) / 2;
            for (size_t g; (g = next.fetch_add(1)) < groups;) {
                for (size_t k = g; k < blocks.size(); k += groups) {
                    const PixelBlock& b = blocks[k];
                    gatherer.begin_block(&group_entries[g]);
                    // POV-Ray's grid: multiples of the step size from the block's
                    // first pixel on, each jittered by up to half a step (at most a
                    // pixel).
                    const double x0 = std::ceil((double(b.x0) - 0.5) / size) * size;
                    const double y0 = std::ceil((double(b.y0) - 0.5) / size) * size;
                    for (double y = y0; y < double(b.y1); y += size) {
                        if (y < double(b.y0)) continue;
                        for (double x = x0; x < double(b.x1); x += size) {
                            if (x < double(b.x0)) continue;
                            samples.sample(
                                x + offset + jitter * jitter_value(pass_number, x, y, 0),
                                y + offset + jitter * jitter_value(pass_number, x, y, 1),
                                rgbt);
                        }
                    }
                    gatherer.begin_block(nullptr);
                }
            }
            gathers[size_t(ti)] += gatherer.gathers();
        };
        const int pass_threads = std::max(1, std::min(threads, int(groups)));
        std::vector<std::thread> pool;
        for (int i = 1; i < pass_threads; ++i) pool.emplace_back(work, i);
        work(0);
        for (auto& t : pool) t.join();
        for (const IrradianceCache& entries : group_entries)
            for (const CacheEntry& e : entries.entries()) render->cache.insert(e);
        ++render->passes;
    }
    for (uint64_t g : gathers) render->gathers += g;
    return render;
}

}  // namespace povwall::trace::radiosity
