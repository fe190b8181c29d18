#include "distrib/shared_pixel_sums.h"

#include <sys/mman.h>

#include <new>
#include <utility>

namespace povwall::distrib {

namespace {
size_t sums_bytes(size_t count) { return (count * sizeof(double) + 63) / 64 * 64; }
}  // namespace

size_t SharedPixelSums::bytes() const {
    return sums_bytes(count_) + kStripes * kLockStride * sizeof(uint32_t);
}

SharedPixelSums::SharedPixelSums(size_t count) : count_(count) {
    if (count == 0) return;
    // Populated here, once: the workers' first writes would fault page by page.
    void* p = mmap(nullptr, bytes(), PROT_READ | PROT_WRITE,
                   MAP_SHARED | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<double*>(p);
    locks_ = reinterpret_cast<uint32_t*>(static_cast<char*>(p) + sums_bytes(count));
}

SharedPixelSums::~SharedPixelSums() {
    if (data_) munmap(data_, bytes());
}

SharedPixelSums::SharedPixelSums(SharedPixelSums&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      locks_(std::exchange(other.locks_, nullptr)),
      count_(std::exchange(other.count_, 0)) {}

SharedPixelSums& SharedPixelSums::operator=(SharedPixelSums&& other) noexcept {
    if (this != &other) {
        if (data_) munmap(data_, bytes());
        data_ = std::exchange(other.data_, nullptr);
        locks_ = std::exchange(other.locks_, nullptr);
        count_ = std::exchange(other.count_, 0);
    }
    return *this;
}

}  // namespace povwall::distrib
