// The interiors a ray is inside of, innermost (last entered) last, as POV-Ray's ray
// keeps them: each entry is the material of a surface where the ray entered, and entries
// are told apart by Material::interior_id, so leaving one object of a shared interior
// leaves them all.
//
// A ray is copied for every child it spawns, so the stack is plain bytes: the first
// kInline entries live in the ray itself, and deeper nesting (a glow of many overlapping
// media spheres) is a chain of shared, immutable links, one per entry past kInline,
// interned for the whole process (the same chain for the same entries, so memory grows
// with the distinct nestings met, not with the rays). POV-Ray keeps up to 512 (its
// RAYINTERIOR_VECTOR_SIZE).
#pragma once

#include <cstdint>

#include "trace/prepared_scene.h"

namespace povwall::trace {

// One entry past the inline ones; `below` is the entry under it (nullptr at kInline).
struct DeepInterior {
    const DeepInterior* below;
    const Material* material;
};

struct InteriorStack {
    static constexpr int kInline = 8;
    static constexpr int kCapacity = 512;
    const Material* items[kInline] = {};
    const DeepInterior* deep = nullptr;  // entry size - 1 when size > kInline
    int size = 0;

    const Material* at(int i) const { return i < kInline ? items[i] : deep_at(i); }
    // Every entry `from` becomes `to`.
    void replace(const Material* from, const Material* to);
    bool contains(uintptr_t interior) const { return find(interior) >= 0; }
    // Index of the first entry of `interior`, or -1.
    int find(uintptr_t interior) const {
        const int n = size < kInline ? size : kInline;
        for (int i = 0; i < n; ++i)
            if (items[i] && items[i]->interior_id == interior) return i;
        return size > kInline ? deep_find(interior) : -1;
    }
    // Past kCapacity, the entry is not kept (as deep as POV-Ray's ray goes).
    void push(const Material* m) {
        if (size < kInline)
            items[size++] = m;
        else
            deep_push(m);
    }
    // Removes the first entry of `interior` (POV-Ray's RemoveInterior); false if none.
    bool remove(uintptr_t interior);
    const Material* innermost() const {
        return size == 0 ? nullptr : size <= kInline ? items[size - 1] : deep->material;
    }
    // All entries, outermost first, into out[0, size).
    void copy_to(const Material** out) const;
    // f(entry) for every entry, outermost first.
    template <class F>
    void for_each(F&& f) const {
        if (size <= kInline) {
            for (int i = 0; i < size; ++i) f(items[i]);
        } else {
            for_each_deep(f);
        }
    }
    // The stack of entries[0, n) (n <= kCapacity).
    static InteriorStack of(const Material* const* entries, int n);

  private:
    template <class F>
    [[gnu::noinline]] void for_each_deep(F& f) const {
        const Material* all[kCapacity];
        copy_to(all);
        for (int i = 0; i < size; ++i) f(all[i]);
    }
    const Material* deep_at(int i) const;
    int deep_find(uintptr_t interior) const;
    void deep_push(const Material* m);
};

// How many deep links the process holds (the memory the deep nestings cost).
uint64_t deep_interior_links();

}  // namespace povwall::trace
