// A place (a file name and a line) that one thread keeps current while another thread or
// a signal handler may read it at any moment: where a parse is, or which image is being
// written, for the message of an interrupted render (cli/interrupt.cpp). Lock-free and
// allocation-free on both sides, so the writer can update it from a hot loop and the
// reader needs no cooperation.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace povwall {

class PublishedPlace {
  public:
    static constexpr size_t kCapacity = 1024;  // longer names are cut

    // One writer at a time. Rewrites the name and the line.
    void set(std::string_view name, uint32_t line) noexcept {
        begin_write();
        const size_t n = std::min(name.size(), kCapacity - 1);
        for (size_t i = 0; i < n; ++i) name_[i].store(name[i], std::memory_order_relaxed);
        name_[n].store('\0', std::memory_order_relaxed);
        line_.store(line, std::memory_order_relaxed);
        end_write();
    }
    // Keeps the name: the cheap update a parser makes every few thousand tokens.
    void set_line(uint32_t line) noexcept {
        begin_write();
        line_.store(line, std::memory_order_relaxed);
        end_write();
    }
    void clear() noexcept { set({}, 0); }

    // Copies the name (cut to `capacity` - 1 bytes) and the line as one consistent pair.
    // False when a write was in progress on every try (its writer may be stopped in the
    // middle of it for good, by a signal handler that never returns): the caller goes
    // without.
    bool get(char* name, size_t capacity, uint32_t& line) const noexcept {
        if (capacity == 0) return false;
        for (int attempt = 0; attempt < 1000; ++attempt) {
            const uint32_t before = version_.load(std::memory_order_acquire);
            if (before & 1) continue;
            size_t i = 0;
            for (; i + 1 < capacity && i < kCapacity; ++i) {
                name[i] = name_[i].load(std::memory_order_relaxed);
                if (name[i] == '\0') break;
            }
            name[i] = '\0';  // where the copy stopped, if not at the name's end
            line = line_.load(std::memory_order_relaxed);
            std::atomic_thread_fence(std::memory_order_acquire);
            if (version_.load(std::memory_order_relaxed) == before) return true;
        }
        return false;
    }

  private:
    // A sequence lock: odd while a write is under way.
    void begin_write() noexcept {
        version_.store(version_.load(std::memory_order_relaxed) + 1,
                       std::memory_order_relaxed);
        std::atomic_thread_fence(std::memory_order_release);
    }
    void end_write() noexcept {
        version_.store(version_.load(std::memory_order_relaxed) + 1,
                       std::memory_order_release);
    }

    std::atomic<uint32_t> version_{0};
    std::atomic<uint32_t> line_{0};
    std::array<std::atomic<char>, kCapacity> name_{};
};

}  // namespace povwall
