// libFuzzer target: the wire-protocol decoder of the distributed back end. Malformed,
// truncated or oversized frames must come back as Bad or NeedMore, never crash; a frame
// that decodes must encode back to the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include "distrib/message.h"

using namespace povwall::distrib;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::span<const uint8_t> bytes(data, size);
    while (!bytes.empty()) {
        Frame frame;
        const DecodeStatus status = decode_frame(bytes, frame);
        if (status != DecodeStatus::Complete) break;
        if (frame.consumed == 0 || frame.consumed > bytes.size()) std::abort();
        std::vector<uint8_t> again;
        if (frame.type == FrameType::Rays) {
            encode_rays(frame.rays, again);
        } else if (frame.type == FrameType::Results) {
            encode_results(frame.results, again);
        } else {
            bytes = bytes.subspan(frame.consumed);
            continue;
        }
        Frame second;
        if (decode_frame(again, second) != DecodeStatus::Complete ||
            second.rays.size() != frame.rays.size() ||
            second.results.size() != frame.results.size() ||
            second.consumed != again.size())
            std::abort();
        bytes = bytes.subspan(frame.consumed);
    }
    return 0;
}
