#include "trace/pov_order.h"

#include <algorithm>
#include <numeric>

#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

// A node's box from its children's: the smallest and largest corners in double (corner
// plus length), rounded to float again as POV-Ray's calc_bbox does.
template <class Boxes>
PovBBox enclosing(const Boxes& boxes) {
    Bounds3 b;
    for (const PovBBox& x : boxes) b.extend(pov_bbox_bounds(x));
    return pov_bbox(b);
}

}  // namespace

void PovWholeScene::add(const Object& o, bool kept) {
    if (kept) kept_.push_back(uint32_t(first_frame_.size()));
    first_frame_.push_back(uint32_t(boxes_.size()));
    pov_for_frame_objects(o,
                          [&](const Object& f) { boxes_.push_back(pov_object_bbox(f)); });
}

PovBBox PovFrameList::box(size_t f) const {
    return objects.empty() ? boxes[f] : pov_object_bbox(*objects[f]);
}

PovFrameList pov_frame_list(const Scene& scene, size_t bounding_threshold,
                            const PovWholeScene* whole) {
    PovFrameList list;
    list.of_light.assign(scene.lights.size(), ~0u);
    list.first_of_object.assign(scene.objects.size(), 0);
    // Lights in the order they were placed among the objects (stable: scene order).
    std::vector<uint32_t> lights(scene.lights.size());
    std::iota(lights.begin(), lights.end(), 0u);
    std::stable_sort(lights.begin(), lights.end(), [&](uint32_t a, uint32_t b) {
        return scene.lights[a].objects_before < scene.lights[b].objects_before;
    });
    size_t next_light = 0;
    auto place_lights = [&](size_t objects_before) {
        for (; next_light < lights.size() &&
               scene.lights[lights[next_light]].objects_before <= objects_before;
             ++next_light) {
            const Light& l = scene.lights[lights[next_light]];
            if (l.looks_like.empty()) continue;  // no object: never intersected
            list.of_light[lights[next_light]] = uint32_t(list.size());
            if (whole)
                list.boxes.push_back(pov_object_bbox(l.looks_like.front()));
            else
                list.objects.push_back(&l.looks_like.front());
        }
    };
    if (whole) {
        std::vector<uint32_t> start(whole->object_count());
        for (size_t i = 0; i < whole->object_count(); ++i) {
            place_lights(i);
            start[i] = uint32_t(list.boxes.size());
            list.boxes.insert(list.boxes.end(),
                              whole->boxes().begin() + whole->first_frame(i),
                              whole->boxes().begin() + whole->first_frame(i + 1));
        }
        for (size_t k = 0; k < scene.objects.size() && k < whole->kept_count(); ++k)
            list.first_of_object[k] = start[whole->whole_index(k)];
    } else {
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            place_lights(i);
            list.first_of_object[i] = uint32_t(list.objects.size());
            pov_for_frame_objects(scene.objects[i],
                                  [&](const Object& f) { list.objects.push_back(&f); });
        }
    }
    place_lights(~size_t(0));
    list.slab_tree = bounding_threshold != kPovBoundingOff &&
                     pov_frame_objects(scene, whole) >= bounding_threshold;
    return list;
}

PovTestOrder::PovTestOrder(const PovFrameList& list) : slab_tree_(list.slab_tree) {
    if (!slab_tree_) return;
    std::vector<uint32_t> finite, infinite;
    for (uint32_t f = 0; f < list.size(); ++f) {
        Node leaf;
        leaf.box = list.box(f);
        leaf.infinite = !pov_bbox_finite(leaf.box);
        leaf.object = f;
        (leaf.infinite ? infinite : finite).push_back(uint32_t(nodes_.size()));
        nodes_.push_back(leaf);
    }
    auto close_group = [&](const uint32_t* ids, size_t n, bool infinite_node) {
        Node node;
        node.first = uint32_t(children_.size());
        node.count = uint32_t(n);
        node.infinite = infinite_node;
        std::vector<PovBBox> boxes;
        for (size_t i = 0; i < n; ++i) {
            children_.push_back(ids[i]);
            boxes.push_back(nodes_[ids[i]].box);
        }
        node.box = enclosing(boxes);
        nodes_.push_back(node);
        return uint32_t(nodes_.size() - 1);
    };
    // `work` holds the nodes still to be grouped; each pass groups one level and appends
    // the new nodes, which the next pass groups in turn, until a pass closes one group.
    std::vector<uint32_t> work = finite;
    // Sorts and splits work[first, last): true when it closed the range into one node,
    // else the two parts to split in turn (the lower first, as POV-Ray's recursion).
    auto split = [&](size_t first, size_t last, size_t& at) -> bool {
        // The axis: the widest spread of the boxes' low corners, as POV-Ray's find_axis
        // measures it (its upper end follows a box's low corner whenever that box reaches
        // past the current upper end).
        Real lo[3] = {kBoundHuge, kBoundHuge, kBoundHuge};
        Real hi[3] = {-kBoundHuge, -kBoundHuge, -kBoundHuge};
        for (size_t i = first; i < last; ++i) {
            const PovBBox& b = nodes_[work[i]].box;
            for (int a = 0; a < 3; ++a) {
                if (b.lo[a] < lo[a]) lo[a] = b.lo[a];
                if (b.lo[a] + b.len[a] > hi[a]) hi[a] = b.lo[a];
            }
        }
        int axis = 0;
        Real widest = -kBoundHuge;
        for (int a = 0; a < 3; ++a) {
            if (hi[a] - lo[a] > widest) {
                widest = hi[a] - lo[a];
                axis = a;
            }
        }
        const size_t size = last - first;
        auto key = [&](uint32_t id) {
            const PovBBox& b = nodes_[id].box;
            return float(2.0 * Real(b.lo[axis]) + Real(b.len[axis]));
        };
        std::stable_sort(work.begin() + ptrdiff_t(first), work.begin() + ptrdiff_t(last),
                         [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
        // Surface-area heuristic (half areas): boxes first..first+i on the left,
        // first+i+1..last-1 on the right.
        std::vector<Real> left(size), right(size);
        auto area_table = [&](bool forward, std::vector<Real>& out) {
            Bounds3 b;
            for (size_t k = 0; k < size; ++k) {
                const size_t i = forward ? first + k : last - 1 - k;
                b.extend(pov_bbox_bounds(nodes_[work[i]].box));
                const Vector3 l = b.hi - b.lo;
                out[i - first] = l.x * (l.y + l.z) + l.y * l.z;
            }
        };
        area_table(true, left);
        area_table(false, right);
        Real best = right[0] * (Real(size) - 3.0);
        bool found = false;
        for (size_t i = 0; i + 1 < size; ++i) {
            const Real cost = Real(i + 1) * left[i] + Real(size - 1 - i) * right[i + 1];
            if (cost < best) {
                best = cost;
                at = first + i + 1;
                found = true;
            }
        }
        if (size > 4 && found) return false;
        const std::vector<uint32_t> group(work.begin() + ptrdiff_t(first),
                                          work.begin() + ptrdiff_t(last));
        work.push_back(close_group(group.data(), group.size(), false));
        root_ = work.back();
        return true;
    };
    // One level: true when its whole range closed into one node (the root).
    auto level = [&](size_t low, size_t high) {
        std::vector<std::pair<size_t, size_t>> todo{{low, high}};
        bool closed_whole = false;
        while (!todo.empty()) {
            const auto [first, last] = todo.back();
            todo.pop_back();
            size_t at = 0;
            if (split(first, last, at)) {
                closed_whole = closed_whole || (first == low && last == high);
                continue;
            }
            todo.push_back({at, last});
            todo.push_back({first, at});
        }
        return closed_whole;
    };
    if (!work.empty()) {
        size_t low = 0, high = work.size();
        while (!level(low, high)) {
            low = high;
            high = work.size();
        }
    }
    if (infinite.empty()) return;
    const uint32_t holder = close_group(infinite.data(), infinite.size(), true);
    if (root_ == ~0u) {
        root_ = holder;
        return;
    }
    // The infinite objects' node becomes the root's first child; the root is infinite.
    Node& root = nodes_[root_];
    std::vector<uint32_t> kids{holder};
    kids.insert(kids.end(), children_.begin() + root.first,
                children_.begin() + root.first + root.count);
    root.first = uint32_t(children_.size());
    root.count = uint32_t(kids.size());
    root.infinite = true;
    children_.insert(children_.end(), kids.begin(), kids.end());
}

template <class OnLeaf>
void PovTestOrder::walk(const Ray& ray, OnLeaf&& on_leaf) const {
    if (root_ == ~0u) return;
    const PovRay r(ray);
    struct Entry {
        Real key;
        uint32_t node;
    };
    // A binary min-heap at indices 1..size, as POV-Ray's priority queue.
    thread_local std::vector<Entry> heap;
    heap.assign(1, Entry{0, 0});
    auto push = [&](uint32_t id) {
        const Node& n = nodes_[id];
        Real key = -kMaxDistance;
        if (!n.infinite && !slab_tree_entry(n.box, r, key)) return;
        heap.push_back({key, id});
        size_t i = heap.size() - 1;
        // Rises only past strictly larger keys.
        while (i > 1 && key < heap[i / 2].key) {
            heap[i] = heap[i / 2];
            i /= 2;
        }
        heap[i] = {key, id};
    };
    auto pop = [&] {
        const Entry top = heap[1];
        heap[1] = heap.back();
        heap.pop_back();
        const size_t size = heap.size() - 1;
        size_t i = 1;
        while (2 * i <= size) {
            size_t j = 2 * i;
            // The smaller child; the right one when they are equal.
            if (j != size && !(heap[j].key < heap[j + 1].key)) ++j;
            if (!(heap[i].key > heap[j].key)) break;
            std::swap(heap[i], heap[j]);
            i = j;
        }
        return top.node;
    };
    push(root_);
    while (heap.size() > 1) {
        const Node& n = nodes_[pop()];
        if (n.count == 0) {
            if (on_leaf(n.object)) return;
            continue;
        }
        for (uint32_t k = 0; k < n.count; ++k) push(children_[n.first + k]);
    }
}

bool PovTestOrder::tests_first(const Ray& ray, uint32_t a, uint32_t b) const {
    if (!slab_tree_) return a < b;
    bool a_first = false;
    walk(ray, [&](uint32_t f) {
        if (f != a && f != b) return false;
        a_first = f == a;
        return true;
    });
    return a_first;
}

std::vector<uint32_t> PovTestOrder::order(const Ray& ray) const {
    std::vector<uint32_t> out;
    if (!slab_tree_) return out;
    walk(ray, [&](uint32_t f) {
        out.push_back(f);
        return false;
    });
    return out;
}

}  // namespace povwall::trace
