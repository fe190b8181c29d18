// InteriorStack: the first 8 entries in the ray, the rest as shared links; every
// operation gives the entries POV-Ray's ray vector would hold.
#include "trace/interior_stack.h"

#include <gtest/gtest.h>

#include <type_traits>
#include <vector>

namespace povwall::trace {
namespace {

// Materials told apart by interior_id; ids 1..n.
std::vector<Material> materials(int n) {
    std::vector<Material> out((size_t(n)));
    for (int i = 0; i < n; ++i) out[size_t(i)].interior_id = uintptr_t(i + 1);
    return out;
}

std::vector<uintptr_t> ids(const InteriorStack& s) {
    std::vector<uintptr_t> out;
    s.for_each([&](const Material* m) { out.push_back(m->interior_id); });
    return out;
}

TEST(InteriorStack, IsPlainBytes) {
    // A ray is copied for every child it spawns.
    EXPECT_TRUE(std::is_trivially_copyable_v<InteriorStack>);
    EXPECT_LE(sizeof(InteriorStack), 88u);
}

TEST(InteriorStack, DeepEntriesKeepTheirOrderThroughEveryOperation) {
    const std::vector<Material> m = materials(20);
    InteriorStack s;
    for (int i = 0; i < 20; ++i) s.push(&m[size_t(i)]);
    ASSERT_EQ(s.size, 20);
    std::vector<uintptr_t> want;
    for (int i = 1; i <= 20; ++i) want.push_back(uintptr_t(i));
    EXPECT_EQ(ids(s), want);
    for (int i = 0; i < 20; ++i) EXPECT_EQ(s.at(i), &m[size_t(i)]);
    EXPECT_EQ(s.innermost(), &m[19]);
    EXPECT_EQ(s.find(3), 2);
    EXPECT_EQ(s.find(15), 14);
    EXPECT_EQ(s.find(99), -1);

    // Removing an inline entry moves the first deep one into the ray.
    InteriorStack a = s;
    EXPECT_TRUE(a.remove(2));
    want.erase(want.begin() + 1);
    EXPECT_EQ(ids(a), want);
    EXPECT_EQ(a.at(7), &m[8]);
    // A deep one from the middle, then the innermost.
    EXPECT_TRUE(a.remove(12));
    want.erase(want.begin() + 10);
    EXPECT_EQ(ids(a), want);
    EXPECT_TRUE(a.remove(20));
    want.pop_back();
    EXPECT_EQ(ids(a), want);
    EXPECT_EQ(a.innermost(), &m[18]);
    EXPECT_FALSE(a.remove(12));
    // The copy it came from is untouched (links are shared, never changed).
    EXPECT_EQ(s.size, 20);
    EXPECT_EQ(s.at(11), &m[11]);

    // The first entry of an interior entered twice is the one removed.
    InteriorStack twice = s;
    twice.push(&m[9]);
    EXPECT_EQ(twice.find(10), 9);
    EXPECT_TRUE(twice.remove(10));
    EXPECT_EQ(twice.find(10), 19);

    // replace() reaches inline and deep entries.
    const Material other;
    InteriorStack r = s;
    r.replace(&m[3], &other);
    r.replace(&m[16], &other);
    EXPECT_EQ(r.at(3), &other);
    EXPECT_EQ(r.at(16), &other);
    EXPECT_EQ(r.at(15), &m[15]);
    EXPECT_EQ(r.size, 20);
}

TEST(InteriorStack, EqualNestingsShareTheirLinks) {
    const std::vector<Material> m = materials(12);
    InteriorStack first;
    for (const Material& x : m) first.push(&x);
    const uint64_t links = deep_interior_links();
    InteriorStack again;
    for (const Material& x : m) again.push(&x);
    EXPECT_EQ(deep_interior_links(), links);
    EXPECT_EQ(first.deep, again.deep);
    const Material* all[InteriorStack::kCapacity];
    first.copy_to(all);
    const InteriorStack rebuilt = InteriorStack::of(all, first.size);
    EXPECT_EQ(rebuilt.deep, first.deep);
    EXPECT_EQ(ids(rebuilt), ids(first));
}

TEST(InteriorStack, StopsAtPovRaysCapacity) {
    const std::vector<Material> m = materials(InteriorStack::kCapacity + 5);
    InteriorStack s;
    for (const Material& x : m) s.push(&x);
    EXPECT_EQ(s.size, InteriorStack::kCapacity);
    EXPECT_EQ(s.innermost(), &m[InteriorStack::kCapacity - 1]);
    EXPECT_EQ(s.find(uintptr_t(InteriorStack::kCapacity)), InteriorStack::kCapacity - 1);
}

}  // namespace
}  // namespace povwall::trace
