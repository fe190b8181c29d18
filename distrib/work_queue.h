// The order in which a black box handles its work.
//
// Results come before new rays (they release waiting parents and so bound the parent table),
// then deeper rays before shallower ones (finishing a ray tree before starting new ones), then
// arrival order. A FIFO policy is kept for the measurements the original paper motivates:
// its "too long local queues" came from breadth-first handling.
#pragma once

#include <cstdint>
#include <queue>
#include <vector>

namespace povwall::distrib {

enum class QueuePolicy { Priority, Fifo };

template <class Item>
class WorkQueue {
public:
    explicit WorkQueue(QueuePolicy policy = QueuePolicy::Priority) : policy_(policy) {}

    void push(Item item, bool is_result, int depth) {
        uint64_t key;
        if (policy_ == QueuePolicy::Fifo) {
            key = 0;
        } else {
            key = (uint64_t(is_result ? 1 : 0) << 8) | uint64_t(depth & 0xff);
        }
        heap_.push(Slot{key, sequence_++, std::move(item)});
        peak_ = std::max(peak_, heap_.size());
    }
    bool empty() const { return heap_.empty(); }
    size_t size() const { return heap_.size(); }
    size_t peak() const { return peak_; }
    Item pop() {
        Item item = std::move(const_cast<Slot&>(heap_.top()).item);
        heap_.pop();
        return item;
    }

private:
    struct Slot {
        uint64_t key;
        uint64_t sequence;
        Item item;
        bool operator<(const Slot& o) const {
            // std::priority_queue pops the largest: high key first, then low sequence.
            return key != o.key ? key < o.key : sequence > o.sequence;
        }
    };
    QueuePolicy policy_;
    std::priority_queue<Slot> heap_;
    uint64_t sequence_ = 0;
    size_t peak_ = 0;
};

}  // namespace povwall::distrib
