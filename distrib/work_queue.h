// The order in which a black box handles its work.
//
// Results come before new rays (they release waiting parents and so bound the parent
// table), then deeper rays before shallower ones (finishing a ray tree before starting
// new ones), then arrival order. A FIFO policy is kept for the measurements the original
// paper motivates: its "too long local queues" came from breadth-first handling.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace povwall::distrib {

enum class QueuePolicy { Priority, Fifo };

// A FIFO of large items in one growing array: std::deque keeps items over 256 bytes one
// per 512-byte block, so every push allocated and every pop freed (Item is 360 bytes).
// Grows by doubling, never shrinks: a box's queue settles at its peak and then costs no
// allocation.
template <class T>
class RingQueue {
  public:
    bool empty() const { return size_ == 0; }
    size_t size() const { return size_; }
    void push_back(T&& v) {
        if (size_ == slots_.size()) grow();
        slots_[(head_ + size_) & (slots_.size() - 1)] = std::move(v);
        ++size_;
    }
    T& front() { return slots_[head_]; }
    void pop_front() {
        head_ = (head_ + 1) & (slots_.size() - 1);
        --size_;
    }

  private:
    void grow() {
        std::vector<T> bigger(std::max<size_t>(16, slots_.size() * 2));
        for (size_t i = 0; i < size_; ++i)
            bigger[i] = std::move(slots_[(head_ + i) & (slots_.size() - 1)]);
        slots_.swap(bigger);
        head_ = 0;
    }
    std::vector<T> slots_;  // size: 0 or a power of two
    size_t head_ = 0, size_ = 0;
};

template <class Item>
class WorkQueue {
  public:
    explicit WorkQueue(QueuePolicy policy = QueuePolicy::Priority) : policy_(policy) {}

    // `depth` is the ray's trace level (0..255). Items move once into a bucket and once
    // out: buckets per priority level instead of a heap, because items are large.
    void push(Item item, bool is_result, int depth) {
        if (policy_ == QueuePolicy::Fifo) {
            fifo_.push_back(std::move(item));
        } else if (is_result) {
            results_.push_back(std::move(item));
        } else {
            size_t d = size_t(std::clamp(depth, 0, 255));
            if (by_depth_.size() <= d) by_depth_.resize(d + 1);
            by_depth_[d].push_back(std::move(item));
            top_ = std::max(top_, d);
        }
        ++size_;
        peak_ = std::max(peak_, size_);
    }
    bool empty() const { return size_ == 0; }
    size_t size() const { return size_; }
    size_t peak() const { return peak_; }
    Item pop() {
        --size_;
        RingQueue<Item>* q = &fifo_;
        if (policy_ == QueuePolicy::Priority) {
            if (!results_.empty()) {
                q = &results_;
            } else {
                while (by_depth_[top_].empty()) --top_;
                q = &by_depth_[top_];
            }
        }
        Item item = std::move(q->front());
        q->pop_front();
        return item;
    }

  private:
    QueuePolicy policy_;
    RingQueue<Item> fifo_, results_;
    std::vector<RingQueue<Item>> by_depth_;
    size_t top_ = 0;
    size_t size_ = 0, peak_ = 0;
};

}  // namespace povwall::distrib
