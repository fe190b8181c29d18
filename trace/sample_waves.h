// Anti-aliasing for renderers that trace many camera samples at once and learn their
// colours only when all are done (the black boxes): the samples go out in waves. The
// first wave holds what every render block starts with (pixel centres and the blocks'
// borders, or +AM2's pixel corners). After each wave every unfinished block is replayed
// with PixelSampler against the samples traced so far, keyed by exact position; what it
// lacks goes into the next wave, and after the first wave also (+AM1) the supersamples
// it will probably need, so that few waves follow. A block whose replay completes gives
// the one-process pixels: the same sampler decides on the same sample values.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/image.h"
#include "trace/pixel_sampler.h"
#include "trace/render.h"

namespace povwall::trace {

// Traces `positions` (POV-Ray pixel coordinates) into `rgbt`, 4 floats each, with
// CameraSamples' values: red, green, blue, and transmit (background transmit with +UA,
// else 0; 1 where the camera has no ray).
using TraceWave = std::function<void(const std::vector<SamplePosition>& positions,
                                     std::vector<float>& rgbt)>;

struct WaveStats {
    std::vector<size_t> samples;  // traced per wave
};

// The image of `settings`' render area (pixels outside it zero, as render_scene leaves
// them).
// With focal blur (`blur`) every sample is the average of its rays (focal_blur.h), which
// the waves trace by (position, ray index), batch by batch: any sampling method, 0 too.
class FocalBlur;
Image render_in_waves(const RenderSettings& settings, const SamplerSettings& sampling,
                      const TraceWave& trace_wave, WaveStats* stats = nullptr,
                      const FocalBlur* blur = nullptr);

}  // namespace povwall::trace
