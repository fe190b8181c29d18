// Pixels decided by a tie: where a ray meets two different surfaces at the same depth
// (coincident faces: a box on a plane, a cylinder's cap on a box's top), which surface a
// renderer sees depends on the order it tests objects in and on the last bits of each
// depth. POV-Ray's order is reproduced where its depths are bit for bit povwall's
// (trace/pov_order.h); where they are not, the pixel can differ from POV-Ray's without
// either being wrong. This finds those pixels: it traces a pixel's camera ray again (and
// the rays it spawns, to a given trace level) in double precision and reports whether
// any of them has another surface (another leaf object) within a relative distance of
// its nearest hit; or, a kind of its own, whether a nearest hit lies on a jump of its
// surface's pattern (the colour is then a tie between two map entries).
#pragma once

#include <memory>

#include "core/scene.h"
#include "trace/render.h"

namespace povwall::trace {

// Relative depth difference counted as a tie: far below any shape's depth tolerance
// (POV-Ray's DEPTH_TOLERANCE 1e-6 and MIN_ISECT_DEPTH 1e-4 in scene units at unit
// distance) and far above double rounding (1e-16), so a tie is coincident geometry that
// rounding decides, not two surfaces a renderer could tell apart.
constexpr Real kTieTolerance = 1e-9;

struct TieProbeOptions {
    Real tolerance = kTieTolerance;
    // Trace levels probed: 1 the camera ray, 2 also what its first hit spawns (the ray
    // refracted into a glass object, the reflected ray), and so on.
    int levels = 2;
};

class PreparedScene;
class CameraInteriors;
class Tracer;

class TieProbe {
  public:
    // `settings`: the render's (size, quality, alpha); one thread.
    TieProbe(const Scene& scene, const RenderSettings& settings,
             const TieProbeOptions& options = {});
    ~TieProbe();
    // What the rays of pixel (x, y)'s centre sample meet: two surfaces at one depth
    // (Surface), else a surface lying on a jump of its own pattern (Pattern, see
    // Tracer::pattern_ties), else None.
    enum class Kind : uint8_t { None, Surface, Pattern };
    Kind pixel(int x, int y);

  private:
    const Scene& scene_;
    RenderSettings settings_;
    std::unique_ptr<PreparedScene> prepared_;
    std::unique_ptr<CameraInteriors> interiors_;
    std::unique_ptr<Tracer> tracer_;
};

}  // namespace povwall::trace
