// Item records: rays and results as they travel between processes (Items frames,
// wire/frame.h). A record leaves out the fields that hold their default value and says so
// in its flags; the reader rebuilds exactly the item that was written, bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/scene.h"
#include "distrib/item.h"
#include "trace/prepared_scene.h"

namespace povwall::distrib {

// Interior stacks hold Material pointers; on the wire they are numbers of objects (CSG
// children included) in a walk every process makes of the same scene, and each process
// keeps one Material per object (the stack only uses its object and interior). A worker
// that parsed only its part of the scene numbers its objects as in the whole scene
// (Scene::object_first_node); a number it does not hold reads as a stand-in that keeps
// the number (a ray inside a media container that crosses a worker without it keeps the
// container for the workers that hold it) and what the parse kept of the object's
// interior for interior stacks (Scene::left_out_nodes: ior, media, hollow flag).
class ObjectNumbers {
  public:
    explicit ObjectNumbers(const Scene& scene)
        : scene_(scene), sparse_(scene.objects_filtered()) {
        int32_t next = 0;
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            if (sparse_) next = int32_t(scene.object_first_node[i]);
            add(scene.objects[i], next);
        }
        if (sparse_) next = int32_t(scene.object_nodes_total);
        for (const Light& l : scene.lights) {
            for (const Object& o : l.looks_like) add(o, next);
        }
        end_number_ = next;
        materials_.resize(objects_.size());
        for (size_t i = 0; i < objects_.size(); ++i) {
            const Object& o = *objects_[i];
            materials_[i] = trace::material_of(o, o.texture);
            if (sparse_) by_number_.emplace(numbers_[i], i);
        }
    }
    int32_t number(const trace::Material* m) const {
        if (!m || !m->object) return -1;
        auto it = index_.find(m->object);
        if (it != index_.end()) return numbers_[it->second];
        std::lock_guard lock(stand_ins_mutex_);
        auto s = stand_in_numbers_.find(m->object);
        return s == stand_in_numbers_.end() ? -1 : s->second;
    }
    // Objects numbered (CSG children and lights' looks_like shapes included).
    size_t size() const { return materials_.size(); }
    const trace::Material* material(int32_t n) const {
        if (sparse_) {
            auto it = by_number_.find(n);
            return it != by_number_.end()      ? &materials_[it->second]
                   : n >= 0 && n < end_number_ ? stand_in(n)
                                               : nullptr;
        }
        return n >= 0 && size_t(n) < materials_.size() ? &materials_[n] : nullptr;
    }

  private:
    struct StandIn {
        Object object;
        trace::Material material;
    };
    const trace::Material* stand_in(int32_t n) const {
        std::lock_guard lock(stand_ins_mutex_);
        auto& s = stand_ins_[n];
        if (!s) {
            s = std::make_unique<StandIn>();
            s->material.object = &s->object;
            s->material.interior_id = trace::interior_key(s->object);
            if (const LeftOutNode* left = scene_.left_out_node(uint32_t(n))) {
                s->object.hollow = left->hollow;
                s->material.interior = left->interior;
                if (left->interior && left->interior->id != 0)
                    s->material.interior_id = left->interior->id;
            }
            stand_in_numbers_.emplace(&s->object, n);
        }
        return &s->material;
    }
    void add(const Object& o, int32_t& next) {
        index_.emplace(&o, objects_.size());
        objects_.push_back(&o);
        numbers_.push_back(next++);
        if (auto c = std::get_if<Csg>(&o.shape)) {
            for (const Object& ch : c->children) add(ch, next);
        }
    }
    const Scene& scene_;
    bool sparse_;
    int32_t end_number_ = 0;  // one past the last number of the whole scene
    std::vector<const Object*> objects_;
    std::vector<int32_t> numbers_;  // per entry of objects_
    std::unordered_map<const Object*, size_t> index_;
    std::unordered_map<int32_t, size_t> by_number_;  // sparse numbering only
    std::vector<trace::Material> materials_;
    mutable std::mutex stand_ins_mutex_;
    mutable std::unordered_map<int32_t, std::unique_ptr<StandIn>> stand_ins_;
    mutable std::unordered_map<const Object*, int32_t> stand_in_numbers_;
};

// Appends the record of `item`, bound for `box`, to `out` (at most kMaxItemRecord bytes).
void write_item(std::vector<uint8_t>& out, int box, const Item& item,
                const ObjectNumbers& numbers);
// 147 bytes besides the two interior stacks (the ray's and its shadow state's), each a
// 2-byte count and 4 bytes an entry, up to InteriorStack::kCapacity entries.
constexpr size_t kMaxItemRecord = 147 + 2 * (2 + 4 * trace::InteriorStack::kCapacity);

// What a received record may name: a record outside these is refused, so that nothing
// a peer sends indexes past a receiver's arrays.
struct ItemLimits {
    int boxes = 0;       // boxes of the render
    int lights = 0;      // lights of the scene
    int64_t pixels = 0;  // pixel sums (or camera samples) of the frame
};

// Reads the `count` records of an Items frame body in order. A record that is cut short,
// or names a box, light or pixel outside `limits`, or holds an impossible value (a ray
// use, an interior stack deeper than it can be, a negative depth) is refused (bad()), as
// are bytes left after the last record.
class ItemReader {
  public:
    ItemReader(std::span<const uint8_t> body, uint32_t count, const ItemLimits& limits,
               const ObjectNumbers& numbers)
        : p_(body.data()),
          end_(body.data() + body.size()),
          left_(count),
          limits_(limits),
          numbers_(numbers) {}
    // Every record read (and no bytes after them), or a bad record met.
    bool done() const { return left_ == 0 || bad_; }
    bool bad() const { return bad_ || (left_ == 0 && p_ != end_); }
    // The box of the next record, without reading it; -1 when none is left.
    int64_t next_box() const;
    // Reads the next record; false when it is bad. Returns its size in `bytes`.
    bool read(int& box, Item& item, size_t& bytes);

  private:
    const uint8_t* p_;
    const uint8_t* end_;
    uint32_t left_;
    ItemLimits limits_;
    const ObjectNumbers& numbers_;
    bool bad_ = false;
};

}  // namespace povwall::distrib
