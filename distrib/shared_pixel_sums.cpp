#include "distrib/shared_pixel_sums.h"

#include <sys/mman.h>

#include <new>
#include <utility>

namespace povwall::distrib {

SharedPixelSums::SharedPixelSums(size_t count) : count_(count) {
    if (count == 0) return;
    // Populated here, once: the workers' first writes would fault page by page.
    void* p = mmap(nullptr, count * sizeof(double), PROT_READ | PROT_WRITE,
                   MAP_SHARED | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<double*>(p);
}

SharedPixelSums::~SharedPixelSums() {
    if (data_) munmap(data_, count_ * sizeof(double));
}

SharedPixelSums::SharedPixelSums(SharedPixelSums&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      count_(std::exchange(other.count_, 0)) {}

SharedPixelSums& SharedPixelSums::operator=(SharedPixelSums&& other) noexcept {
    if (this != &other) {
        if (data_) munmap(data_, count_ * sizeof(double));
        data_ = std::exchange(other.data_, nullptr);
        count_ = std::exchange(other.count_, 0);
    }
    return *this;
}

}  // namespace povwall::distrib
