// Pixel sums as a worker returns them to the coordinator (Pixels frames, wire/frame.h):
// one record per pixel with anything in it, (index u32, `channels` sums f64).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace povwall::distrib {

constexpr size_t pixel_record_size(int channels) { return 4 + size_t(channels) * 8; }

inline void write_pixel_sum(std::vector<uint8_t>& body, uint32_t index,
                            const double* sums, int channels) {
    uint8_t record[4 + 4 * 8];
    std::memcpy(record, &index, 4);
    std::memcpy(record + 4, sums, size_t(channels) * 8);
    body.insert(body.end(), record, record + pixel_record_size(channels));
}

// Calls add(index, sums) for each of the `count` records of `body`, after checking them
// all: false (and no call) unless the body is exactly `count` records with indices below
// `pixels`. channels is 3 or 4.
template <class Add>
bool read_pixel_sums(std::span<const uint8_t> body, uint32_t count, int channels,
                     size_t pixels, Add&& add) {
    const size_t record = pixel_record_size(channels);
    if (channels < 1 || channels > 4 || body.size() != size_t(count) * record)
        return false;
    for (size_t k = 0; k < count; ++k) {
        uint32_t index;
        std::memcpy(&index, body.data() + k * record, 4);
        if (index >= pixels) return false;
    }
    for (size_t k = 0; k < count; ++k) {
        const uint8_t* r = body.data() + k * record;
        uint32_t index;
        double sums[4];
        std::memcpy(&index, r, 4);
        std::memcpy(sums, r + 4, size_t(channels) * 8);
        add(index, static_cast<const double*>(sums));
    }
    return true;
}

}  // namespace povwall::distrib
