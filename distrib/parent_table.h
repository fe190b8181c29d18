// Parent rays waiting for their children's results, keyed by ray id.
//
// A box parks a hit's shading record with the number of children it spawned; each
// returning result is stored into the record; the last one releases it for the colour to
// be combined. Only scenes with non-linear shading need this (see the render plan);
// linear ones forward weighted contributions instead and never park anything.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>

namespace povwall::distrib {

template <class Record>
class ParentTable {
  public:
    void park(uint64_t id, Record record, int children) {
        entries_.emplace(id, Entry{std::move(record), children});
        peak_ = std::max(peak_, entries_.size());
    }

    // Calls store(record) for the waiting parent `id`; when that was its last pending
    // child, removes and returns the record. Unknown ids (duplicate or stray results)
    // return nullopt and are counted.
    template <class Store>
    std::optional<Record> deliver(uint64_t id, Store&& store) {
        auto it = entries_.find(id);
        if (it == entries_.end()) {
            ++stray_;
            return std::nullopt;
        }
        store(it->second.record);
        if (--it->second.pending > 0) return std::nullopt;
        Record done = std::move(it->second.record);
        entries_.erase(it);
        return done;
    }

    size_t size() const { return entries_.size(); }
    size_t peak() const { return peak_; }
    uint64_t stray_results() const { return stray_; }

  private:
    struct Entry {
        Record record;
        int pending;
    };
    std::unordered_map<uint64_t, Entry> entries_;
    size_t peak_ = 0;
    uint64_t stray_ = 0;
};

}  // namespace povwall::distrib
