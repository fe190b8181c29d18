// A derived structure a later stage attaches to scene data once the data are final (a
// large CSG's child index, trace/csg_children.h), built once by whichever thread asks
// first. A copy starts without one: its data may still change (a copied object is
// transformed, its children moved) before they are final.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>

namespace povwall {

// Serialises the builds of every slot (they happen once, when a scene is prepared).
std::mutex& derived_slot_mutex();

template <class T>
class DerivedSlot {
  public:
    DerivedSlot() = default;
    DerivedSlot(const DerivedSlot&) noexcept {}
    DerivedSlot& operator=(const DerivedSlot&) noexcept {
        value_.store(nullptr, std::memory_order_relaxed);
        owner_.reset();
        return *this;
    }

    const T* get() const { return value_.load(std::memory_order_acquire); }

    // The value, made by make() (a std::unique_ptr<T>) unless one is set already.
    template <class Make>
    const T* get_or_make(Make&& make) const {
        if (const T* v = get()) return v;
        std::lock_guard lock(derived_slot_mutex());
        if (const T* v = value_.load(std::memory_order_relaxed)) return v;
        owner_ = make();
        value_.store(owner_.get(), std::memory_order_release);
        return owner_.get();
    }

  private:
    mutable std::atomic<const T*> value_{nullptr};
    mutable std::shared_ptr<const T> owner_;
};

}  // namespace povwall
