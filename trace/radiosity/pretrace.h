// Radiosity's pretrace (POV-Ray 3.7's RadiosityTask): before the image, the image is
// traced on coarser grids, from pretrace_start of its larger side down to pretrace_end
// (halving each pass), which fills the irradiance cache the final render reads.
//
// Deterministic design (docs/radiosity.md), POV-Ray's high-reproducibility pretrace:
// pass p (from 0) deals the render blocks to 2^p chains (block k to chain k mod 2^p);
// one thread traces a chain's blocks in order, and a block reads the cache of the passes
// before (frozen during the pass) plus the entries its chain made in this pass. Once
// the pass is over, the chains' entries are added to the cache in chain order. The cache
// after each pass is therefore the same for any number of threads, and every process
// that runs the pretrace (screen-mode workers included) builds the same cache. (Reading
// only the block's own entries of the pass, as before, made every block gather its own
// deeper-bounce samples again: 7x the depth-1 gathers of POV-Ray on the Cornell box.)
#pragma once

#include <memory>

#include "trace/radiosity/gatherer.h"
#include "trace/radiosity/irradiance_cache.h"

namespace povwall::trace {
class PreparedScene;
class CameraInteriors;
struct RenderSettings;
}  // namespace povwall::trace

namespace povwall::trace::radiosity {

// What the final render reads: the settings and the finished cache.
struct RadiosityRender {
    RadiosityRender(const RadiositySettings& settings, const Point3& camera,
                    int max_trace_level)
        : frame(settings, camera, max_trace_level), cache(frame.address_factors()) {}
    RadiosityFrame frame;
    IrradianceCache cache;
    int passes = 0;
    uint64_t gathers = 0;  // samples gathered by the pretrace
};

// POV-Ray's pretrace step sizes in pixels, largest first (at least 1 pixel).
std::vector<double> pretrace_sizes(const RadiositySettings& s, int width, int height);

// How many chains of render blocks pretrace pass `pass` (from 0) deals its `blocks`
// blocks to: 1, then doubling per pass (POV-Ray's high-reproducibility pretrace), at
// most one per block. Block k goes to chain k mod groups.
size_t pretrace_groups(size_t pass, size_t blocks);

// Runs the pretrace of `prepared` (whose scene has radiosity on) with `threads` threads
// (0: every core). Null when the scene has no radiosity or the quality turns it off.
std::shared_ptr<const RadiosityRender> run_pretrace(const PreparedScene& prepared,
                                                    const CameraInteriors& interiors,
                                                    const RenderSettings& settings,
                                                    int threads);

}  // namespace povwall::trace::radiosity
