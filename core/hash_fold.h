// Hashes of coordinates, where POV-Ray draws random numbers: the number depends only on
// where it is drawn (and which draw), so every render mode and thread count agrees.
#pragma once

#include <bit>
#include <cstdint>

namespace povwall {

// splitmix64's finaliser: every bit of `h` reaches every bit of the result.
constexpr uint64_t splitmix_finish(uint64_t h) {
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

// `h` with the bits of `v` folded in (boost's hash_combine step, then the finaliser).
inline uint64_t hash_fold(uint64_t h, double v) {
    h ^= std::bit_cast<uint64_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return splitmix_finish(h);
}

}  // namespace povwall
