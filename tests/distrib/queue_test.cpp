#include <gtest/gtest.h>

#include <string>

#include "distrib/parent_table.h"
#include "distrib/work_queue.h"

namespace povwall::distrib {
namespace {

TEST(ParentTable, ReleasesParentAfterLastChild) {
    ParentTable<std::string> t;
    t.park(10, "p", 3);
    t.park(11, "q", 1);
    EXPECT_EQ(t.peak(), 2u);
    EXPECT_FALSE(t.deliver(10, [](std::string& r) { r += "a"; }));
    EXPECT_FALSE(t.deliver(10, [](std::string& r) { r += "b"; }));
    auto done = t.deliver(10, [](std::string& r) { r += "c"; });
    ASSERT_TRUE(done);
    EXPECT_EQ(*done, "pabc");
    EXPECT_EQ(t.size(), 1u);
    EXPECT_FALSE(t.deliver(10, [](std::string&) {}));  // duplicate: refused, counted
    EXPECT_EQ(t.stray_results(), 1u);
}

TEST(WorkQueue, ResultsFirstThenDeeperRaysThenArrivalOrder) {
    // Results release waiting parents: they go first, in arrival order.
    WorkQueue<std::string> q;
    q.push("ray d1 a", false, 1);
    q.push("ray d3", false, 3);
    q.push("ray d1 b", false, 1);
    q.push("result d1", true, 1);
    q.push("result d2", true, 2);
    std::vector<std::string> order;
    while (!q.empty()) order.push_back(q.pop());
    EXPECT_EQ(order, (std::vector<std::string>{"result d1", "result d2", "ray d3",
                                               "ray d1 a", "ray d1 b"}));
}

TEST(WorkQueue, FifoPolicyKeepsArrivalOrder) {
    WorkQueue<int> q(QueuePolicy::Fifo);
    for (int i = 0; i < 5; ++i) q.push(i, i % 2 == 0, i);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(q.pop(), i);
    EXPECT_EQ(q.peak(), 5u);
}

}  // namespace
}  // namespace povwall::distrib

namespace povwall::distrib {
namespace {

// Pushes and pops interleaved across the ring's growth and wrap-around keep FIFO order.
TEST(RingQueue, KeepsOrderAcrossGrowthAndWrapAround) {
    RingQueue<int> q;
    int next_in = 0, next_out = 0;
    for (int round = 0; round < 200; ++round) {
        for (int i = 0; i < round % 37 + 1; ++i) q.push_back(int(next_in++));
        for (int i = 0; i < round % 23 && !q.empty(); ++i) {
            ASSERT_EQ(q.front(), next_out++);
            q.pop_front();
        }
        ASSERT_EQ(q.size(), size_t(next_in - next_out));
    }
    while (!q.empty()) {
        ASSERT_EQ(q.front(), next_out++);
        q.pop_front();
    }
    EXPECT_EQ(next_out, next_in);
    EXPECT_GT(next_in, 1000);
}

}  // namespace
}  // namespace povwall::distrib
