// Page-level memory advice for large arrays. On the VMs povwall runs on a page fault
// costs microseconds and a TLB miss a page walk: big arrays written once (a file's
// tokens) or read at random (octree nodes, sphere lanes) do better on transparent huge
// pages, which the kernel gives only where asked (THP "madvise" mode, its default).
#pragma once

#include <cstddef>
#include <utility>

namespace povwall {

// Asks for 2 MB pages on the whole 2 MB pages inside [data, data + bytes), before they
// are first touched; buffers under 8 MB are left alone.
void advise_huge_pages(void* data, size_t bytes);

// Maps the pages of [data, data + bytes) for writing in one call (MADV_POPULATE_WRITE):
// for a list written from start to end, one call per few hundred KB costs a fraction of
// a fault per page. A no-op where the kernel lacks it.
void populate_for_write(void* data, size_t bytes);

// A copy of `v` in storage asked for huge pages, when it is large enough to gain from
// them (the copy is made once, after a build).
template <class Vector>
void move_to_huge_pages(Vector& v) {
    if (v.size() * sizeof(typename Vector::value_type) < (size_t(8) << 20)) return;
    Vector copy(v.get_allocator());
    copy.reserve(v.size());
    advise_huge_pages(copy.data(), v.size() * sizeof(typename Vector::value_type));
    copy.assign(v.begin(), v.end());
    v = std::move(copy);
}

// v.resize(n), its new storage asked for huge pages when large (an image's pixels: the
// first touch of fresh 4 KB pages was most of the time a large texture took to load).
template <class Vector>
void resize_on_huge_pages(Vector& v, size_t n) {
    const size_t bytes = n * sizeof(typename Vector::value_type);
    if (bytes >= (size_t(8) << 20) && v.capacity() < n) {
        v.reserve(n);
        advise_huge_pages(v.data(), bytes);
    }
    v.resize(n);
}

}  // namespace povwall
