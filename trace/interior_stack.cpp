#include "trace/interior_stack.h"

#include <atomic>
#include <cstdio>
#include <deque>
#include <functional>
#include <mutex>
#include <unordered_map>

namespace povwall::trace {
namespace {

// Every deep link of the process, one per distinct (entry below, material): rays share
// them, so they are never freed. Past kMaxLinks (about 1 GB with the table) a stack stops
// growing, with a warning, as it stops at kCapacity.
class DeepLinks {
  public:
    static constexpr size_t kMaxLinks = size_t(1) << 24;

    const DeepInterior* link(const DeepInterior* below, const Material* m) {
        const std::lock_guard lock(mutex_);
        const Key key{below, m};
        if (const auto it = index_.find(key); it != index_.end()) return it->second;
        if (links_.size() >= kMaxLinks) {
            if (!warned_) {
                warned_ = true;
                std::fprintf(stderr,
                             "warning: more than %zu distinct nestings of over %d "
                             "interiors; rays keep no more of them\n",
                             kMaxLinks, InteriorStack::kInline);
            }
            return nullptr;
        }
        const DeepInterior* made = &links_.emplace_back(DeepInterior{below, m});
        index_.emplace(key, made);
        count_.store(links_.size(), std::memory_order_relaxed);
        return made;
    }
    uint64_t count() const { return count_.load(std::memory_order_relaxed); }

  private:
    struct Key {
        const DeepInterior* below;
        const Material* material;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            const auto a = reinterpret_cast<uintptr_t>(k.below);
            const auto b = reinterpret_cast<uintptr_t>(k.material);
            return std::hash<uintptr_t>()(a * 0x9E3779B97F4A7C15ull ^ b);
        }
    };
    std::mutex mutex_;
    std::deque<DeepInterior> links_;
    std::unordered_map<Key, const DeepInterior*, KeyHash> index_;
    std::atomic<uint64_t> count_{0};
    bool warned_ = false;
};

DeepLinks& deep_links() {
    static DeepLinks links;
    return links;
}

}  // namespace

uint64_t deep_interior_links() { return deep_links().count(); }

const Material* InteriorStack::deep_at(int i) const {
    const DeepInterior* d = deep;
    for (int k = size - 1; k > i; --k) d = d->below;
    return d->material;
}

int InteriorStack::deep_find(uintptr_t interior) const {
    // Walked innermost first: the last match seen is the first entry.
    int found = -1;
    int i = size - 1;
    for (const DeepInterior* d = deep; d; d = d->below, --i)
        if (d->material && d->material->interior_id == interior) found = i;
    return found;
}

void InteriorStack::deep_push(const Material* m) {
    if (size >= kCapacity) return;
    const DeepInterior* d = deep_links().link(deep, m);
    if (!d) return;
    deep = d;
    ++size;
}

void InteriorStack::copy_to(const Material** out) const {
    const int n = size < kInline ? size : kInline;
    for (int i = 0; i < n; ++i) out[i] = items[i];
    int i = size - 1;
    for (const DeepInterior* d = deep; i >= kInline; d = d->below, --i)
        out[i] = d->material;
}

InteriorStack InteriorStack::of(const Material* const* entries, int n) {
    InteriorStack s;
    for (int i = 0; i < n; ++i) s.push(entries[i]);
    return s;
}

void InteriorStack::replace(const Material* from, const Material* to) {
    const int n = size < kInline ? size : kInline;
    for (int i = 0; i < n; ++i)
        if (items[i] == from) items[i] = to;
    bool deeper = false;
    for (const DeepInterior* d = deep; d; d = d->below) deeper |= d->material == from;
    if (!deeper) return;
    const Material* all[kCapacity];
    copy_to(all);
    for (int i = kInline; i < size; ++i)
        if (all[i] == from) all[i] = to;
    *this = of(all, size);
}

bool InteriorStack::remove(uintptr_t interior) {
    const int i = find(interior);
    if (i < 0) return false;
    if (size <= kInline) {
        for (int j = i; j + 1 < size; ++j) items[j] = items[j + 1];
        --size;
        return true;
    }
    if (i == size - 1) {  // the innermost: its link's `below` is the stack without it
        deep = deep->below;
        --size;
        return true;
    }
    const Material* all[kCapacity];
    copy_to(all);
    for (int j = i; j + 1 < size; ++j) all[j] = all[j + 1];
    *this = of(all, size - 1);
    return true;
}

}  // namespace povwall::trace
