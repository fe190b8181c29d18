#pragma once
// The image's pixel sums in one mapping shared by the coordinator and the worker
// processes it forks: a forked worker adds its contributions straight into it, so it
// neither zeroes an image-sized array of its own nor sends its sums back as records
// (eight workers on 600x600 had zeroed 69 MB and sent 2.2 M records; sharing took
// 2x2x2 over 8 from 1.050 to 1.000 s). Workers started any other way, or on other hosts,
// send their sums as before.
#include <cstddef>
#include <cstdint>
#include <span>

namespace povwall::distrib {

class SharedPixelSums {
  public:
    // The image's pixels fall into this many stripes (equal runs of pixel indices), each
    // with a lock word on a cache line of its own after the sums: a worker adds a batch
    // of contributions to one stripe under its lock, as plain adds (atomic adds, one per
    // value, waited for each cache miss in turn).
    static constexpr size_t kStripes = 64;
    static constexpr size_t kLockStride = 16;  // uint32_t words: 64 bytes
    SharedPixelSums() = default;
    // `count` doubles, zero (MAP_SHARED | MAP_ANONYMOUS: inherited by fork, not copied).
    // Throws std::bad_alloc when the mapping fails.
    explicit SharedPixelSums(size_t count);
    ~SharedPixelSums();
    SharedPixelSums(SharedPixelSums&& other) noexcept;
    SharedPixelSums& operator=(SharedPixelSums&& other) noexcept;
    SharedPixelSums(const SharedPixelSums&) = delete;
    SharedPixelSums& operator=(const SharedPixelSums&) = delete;

    double* data() const { return data_; }
    size_t size() const { return count_; }
    std::span<double> values() const { return {data_, count_}; }
    // kStripes lock words, kLockStride apart (0: free).
    uint32_t* stripe_locks() const { return locks_; }
    explicit operator bool() const { return data_ != nullptr; }

  private:
    size_t bytes() const;
    double* data_ = nullptr;
    uint32_t* locks_ = nullptr;
    size_t count_ = 0;
};

}  // namespace povwall::distrib
