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

// A value that lives on the heap from its first write; until then it reads as T{}.
// Reads (`->`, `*`, get()) never allocate, writes go through edit(). For parts most
// values leave at their defaults and that are read far more than written: a solid
// pigment's pattern (152 bytes) is never written, so a scene of solid-coloured objects
// keeps 8 bytes per texture for it instead of paging in the whole struct.
template <class T>
class HeapValue {
  public:
    HeapValue() = default;
    HeapValue(const T& v) : p_(std::make_unique<T>(v)) {}
    HeapValue(const HeapValue& o) : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
    HeapValue(HeapValue&&) noexcept = default;
    HeapValue& operator=(const HeapValue& o) {
        if (this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
        return *this;
    }
    HeapValue& operator=(HeapValue&&) noexcept = default;
    HeapValue& operator=(const T& v) {
        edit() = v;
        return *this;
    }

    const T& get() const { return p_ ? *p_ : default_value(); }
    const T& operator*() const { return get(); }
    const T* operator->() const { return &get(); }
    T& edit() {
        if (!p_) p_ = std::make_unique<T>();
        return *p_;
    }
    bool allocated() const { return p_ != nullptr; }
    // For a container: whether it holds nothing. Without a call: an unset value's read
    // goes through default_value()'s guarded static, and clip lists are asked this on
    // every inside test of a CSG.
    bool empty() const requires requires(const T& t) { t.empty(); }
    { return !p_ || p_->empty(); }
    void clear() { p_.reset(); }  // back to T{}

  private:
    static const T& default_value() {
        static const T value{};
        return value;
    }
    std::unique_ptr<T> p_;
};

// A value shared by its copies until one of them writes (copy on write); an unset one
// reads as T{}. For parts that many values hold alike: the 5,000 spheres of a #while
// loop that each say `finish { phong 0.7 reflection 0.4 }` can hold one Finish.
template <class T>
class SharedValue {
  public:
    SharedValue() = default;
    SharedValue(const T& v) : p_(std::make_shared<T>(v)) {}

    const T& get() const { return p_ ? *p_ : default_value(); }
    const T& operator*() const { return get(); }
    const T* operator->() const { return &get(); }
    // The value to write, this holder's own.
    T& edit() {
        if (!p_)
            p_ = std::make_shared<T>();
        else if (p_.use_count() > 1)
            p_ = std::make_shared<T>(*p_);
        return *p_;
    }
    bool allocated() const { return p_ != nullptr; }
    // How many holders share the value (0: unset); for memory estimates.
    long holders() const { return p_.use_count(); }

  private:
    static const T& default_value() {
        static const T value{};
        return value;
    }
    std::shared_ptr<T> p_;
};

}  // namespace povwall
