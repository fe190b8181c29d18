// An optional value kept on the heap, with value semantics (copies copy the value).
//
// For large parts that most values leave out: a Texture's normal and texture-map
// pattern are each ~400 bytes, and every object holds its own Texture. Kept inline as
// std::optional they made each Texture 1.4 KB, most of it never used but copied and
// paged in for each of a scene's objects.
#pragma once

#include <memory>
#include <utility>

namespace povwall {

template <class T>
class HeapOptional {
  public:
    HeapOptional() = default;
    HeapOptional(const T& v) : p_(std::make_unique<T>(v)) {}
    HeapOptional(T&& v) : p_(std::make_unique<T>(std::move(v))) {}
    HeapOptional(const HeapOptional& o)
        : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
    HeapOptional(HeapOptional&&) noexcept = default;
    HeapOptional& operator=(const HeapOptional& o) {
        if (this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
        return *this;
    }
    HeapOptional& operator=(HeapOptional&&) noexcept = default;
    HeapOptional& operator=(const T& v) {
        if (p_)
            *p_ = v;
        else
            p_ = std::make_unique<T>(v);
        return *this;
    }
    HeapOptional& operator=(T&& v) {
        if (p_)
            *p_ = std::move(v);
        else
            p_ = std::make_unique<T>(std::move(v));
        return *this;
    }

    bool has_value() const { return p_ != nullptr; }
    explicit operator bool() const { return p_ != nullptr; }
    T& operator*() { return *p_; }
    const T& operator*() const { return *p_; }
    T* operator->() { return p_.get(); }
    const T* operator->() const { return p_.get(); }
    void reset() { p_.reset(); }

  private:
    std::unique_ptr<T> p_;
};

}  // namespace povwall
