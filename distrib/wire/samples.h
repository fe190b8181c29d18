// Camera sample positions as the coordinator sends them to every worker before an
// anti-aliasing or focal-blur wave (Samples frames, wire/frame.h): one record per sample,
// (x f64, y f64) in POV-Ray pixel coordinates and the focal-blur ray (i32, -1: none)
// (trace::SamplePosition); the frames of one wave
// follow each other, and a "samples" control message with their total count ends them. A
// sample's slot is its place in the wave: the camera rays' and the pixel sums' index.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "trace/pixel_sampler.h"

namespace povwall::distrib {

constexpr size_t kSampleRecordSize = 20;
// Records per Samples frame (1.25 MB): larger waves go out in several frames.
constexpr size_t kSamplesPerFrame = size_t(1) << 16;

inline void write_sample_position(std::vector<uint8_t>& body,
                                  const trace::SamplePosition& p) {
    static_assert(sizeof(trace::SamplePosition::x) == 8);
    static_assert(sizeof(trace::SamplePosition::ray) == 4);
    uint8_t record[kSampleRecordSize];
    std::memcpy(record, &p.x, 8);
    std::memcpy(record + 8, &p.y, 8);
    std::memcpy(record + 16, &p.ray, 4);
    body.insert(body.end(), record, record + kSampleRecordSize);
}

// Appends the `count` records of `body` to `out`, after checking them all: false (and
// `out` unchanged) unless the body is exactly `count` records of finite positions within
// `reach` of the image (|x|, |y| <= reach: samples lie within a pixel or so of it) and
// rays from -1 to `rays` - 1 (`rays`: the camera's focal-blur rays per sample, or 0).
inline bool read_sample_positions(std::span<const uint8_t> body, uint32_t count,
                                  double reach, std::vector<trace::SamplePosition>& out,
                                  int rays = 0) {
    if (body.size() != size_t(count) * kSampleRecordSize) return false;
    const size_t before = out.size();
    out.resize(before + count);
    for (size_t k = 0; k < count; ++k) {
        trace::SamplePosition& p = out[before + k];
        std::memcpy(&p.x, body.data() + k * kSampleRecordSize, 8);
        std::memcpy(&p.y, body.data() + k * kSampleRecordSize + 8, 8);
        std::memcpy(&p.ray, body.data() + k * kSampleRecordSize + 16, 4);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > reach ||
            std::abs(p.y) > reach || p.ray < -1 || p.ray >= rays) {
            out.resize(before);
            return false;
        }
    }
    return true;
}

}  // namespace povwall::distrib
