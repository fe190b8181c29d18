#include "distrib/wire/items.h"

#include <cstring>

namespace povwall::distrib {
namespace {

// One record built in place, appended to its frame once: a vector insert per field was
// a tenth of a worker's time.
struct RecordWriter {
    static constexpr size_t kCapacity = kMaxItemRecord;
    uint8_t bytes[kCapacity];
    uint8_t* p = bytes;
    template <class T>
    void raw(T v) {
        std::memcpy(p, &v, sizeof(T));
        p += sizeof(T);
    }
    void vec(const Vector3& v) { raw(v.x), raw(v.y), raw(v.z); }
    void rgb(const Rgb& c) { raw(c.r), raw(c.g), raw(c.b); }
    void append_to(std::vector<uint8_t>& out) const {
        out.insert(out.end(), static_cast<const uint8_t*>(bytes),
                   static_cast<const uint8_t*>(p));
    }
};
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the wire format is little-endian");

struct Reader {
    const uint8_t* p;
    const uint8_t* end;
    bool ok = true;
    template <class T>
    T raw() {
        T v{};
        if (end - p < ptrdiff_t(sizeof(T))) {
            ok = false;
            return v;
        }
        std::memcpy(&v, p, sizeof(T));
        p += sizeof(T);
        return v;
    }
    Vector3 vec() {
        Vector3 v;
        v.x = raw<Real>(), v.y = raw<Real>(), v.z = raw<Real>();
        return v;
    }
    Rgb rgb() {
        Rgb c;
        c.r = raw<float>(), c.g = raw<float>(), c.b = raw<float>();
        return c;
    }
};

void write_stack(RecordWriter& w, const trace::InteriorStack& s,
                 const ObjectNumbers& numbers) {
    w.raw(uint16_t(s.size));
    s.for_each([&](const trace::Material* m) { w.raw(numbers.number(m)); });
}

void read_stack(Reader& r, trace::InteriorStack& s, const ObjectNumbers& numbers) {
    const int n = r.raw<uint16_t>();
    if (n > trace::InteriorStack::kCapacity) {
        r.ok = false;
        return;
    }
    const trace::Material* entries[trace::InteriorStack::kCapacity];
    for (int i = 0; i < n && r.ok; ++i) entries[i] = numbers.material(r.raw<int32_t>());
    s = trace::InteriorStack::of(entries, r.ok ? n : 0);
}

// A ray record leaves out what holds its default value, and says so in its flags: the
// shadow-ray state (and light distance) of rays that are not shadow rays, the parent of
// rays whose colour goes to the pixel, a transmit factor of 0 or 1. Defaults are compared
// bit for bit, so the receiver rebuilds exactly the item that was sent. 149 -> about 110
// bytes per item on the demo scene.
enum RecordFlags : uint8_t {
    kIsResult = 1,
    kShadow = 2,
    kCounted = 4,
    kShadowState = 8,    // light distance and shadow state follow
    kParent = 16,        // parent, parent box, slot follow
    kTransmitOne = 32,   // transmit contribution 1 (not sent)
    kTransmitZero = 64,  // transmit contribution 0 (not sent)
    kBand = 128,         // a dispersion band follows (index, count)
};
// The ray-use byte's top bit: a continued ray (trace::TraceRay::continued).
constexpr uint8_t kContinuedUse = 128;

template <class T>
bool same_bits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool default_shadow_state(const RayItem& r) {
    const trace::ShadowState d;
    const trace::ShadowState& s = r.shadow_state;
    return same_bits(r.light_distance, Real(kInfinity)) &&
           same_bits(s.filter.r, d.filter.r) && same_bits(s.filter.g, d.filter.g) &&
           same_bits(s.filter.b, d.filter.b) && same_bits(s.t_min, d.t_min) &&
           same_bits(s.last_hit, d.last_hit) && s.blocked == d.blocked &&
           s.inside.size == 0 && s.light == d.light &&
           s.photon_caustics == d.photon_caustics && s.volume == d.volume;
}

void write_fields(RecordWriter& w, int box, const Item& item,
                  const ObjectNumbers& numbers) {
    w.raw(uint32_t(box));
    if (item.is_result) {
        w.raw(uint8_t(kIsResult));
        const ResultItem& r = item.result;
        w.raw(r.parent);
        w.raw(r.slot);
        w.rgb(r.result.colour);
        w.raw(r.result.transmit);
        return;
    }
    const RayItem& r = item.ray;
    const bool shadow_state = !default_shadow_state(r);
    const bool parent = r.parent != 0 || r.parent_box != -1 || r.slot != 0;
    uint8_t flags = (r.shadow ? kShadow : 0) | (r.counted ? kCounted : 0) |
                    (shadow_state ? kShadowState : 0) | (parent ? kParent : 0) |
                    (r.trace.band.monochromatic() ? kBand : 0);
    if (same_bits(r.transmit_contribution, 1.0f))
        flags |= kTransmitOne;
    else if (same_bits(r.transmit_contribution, 0.0f))
        flags |= kTransmitZero;
    w.raw(flags);
    w.vec(r.trace.ray.origin);
    w.vec(r.trace.ray.direction);
    w.raw(int32_t(r.trace.depth));
    w.raw(r.trace.weight);
    w.raw(uint8_t(uint8_t(r.trace.use) | (r.trace.continued ? kContinuedUse : 0)));
    write_stack(w, r.trace.interiors, numbers);
    if (flags & kBand) {
        w.raw(r.trace.band.index);
        w.raw(r.trace.band.count);
    }
    w.raw(r.t_from);
    if (shadow_state) {
        w.raw(r.light_distance);
        w.rgb(r.shadow_state.filter);
        w.raw(r.shadow_state.t_min);
        w.raw(r.shadow_state.last_hit);
        // Bit 0: blocked; bit 1: photon caustics; bit 2: no media or fog
        // (trace::ShadowState).
        w.raw(uint8_t(uint8_t(r.shadow_state.blocked) |
                      (r.shadow_state.photon_caustics ? 2 : 0) |
                      (r.shadow_state.volume ? 0 : 4)));
        write_stack(w, r.shadow_state.inside, numbers);
        w.raw(int32_t(r.shadow_state.light));
    }
    if (parent) {
        w.raw(r.parent);
        w.raw(r.parent_box);
        w.raw(r.slot);
    }
    w.raw(r.pixel);
    w.rgb(r.contribution);
    if (!(flags & (kTransmitOne | kTransmitZero))) w.raw(r.transmit_contribution);
}

bool read_record(Reader& rd, const ItemLimits& limits, int& box, Item& item,
                 const ObjectNumbers& numbers) {
    box = int(rd.raw<uint32_t>());
    const uint8_t flags = rd.raw<uint8_t>();
    // Only the forms write_fields() makes are read: a flag it never sets, or a field sent
    // though it holds its default, is a corrupt record.
    if (((flags & kIsResult) && flags != kIsResult) ||
        ((flags & kTransmitOne) && (flags & kTransmitZero)))
        return false;
    item.is_result = flags & kIsResult;
    if (item.is_result) {
        ResultItem& r = item.result;
        r.parent = rd.raw<uint64_t>();
        r.slot = rd.raw<uint16_t>();
        r.result.colour = rd.rgb();
        r.result.transmit = rd.raw<float>();
    } else {
        RayItem& r = item.ray;
        r.shadow = flags & kShadow;
        r.counted = flags & kCounted;
        r.trace.ray.origin = rd.vec();
        r.trace.ray.direction = rd.vec();
        r.trace.depth = rd.raw<int32_t>();
        r.trace.weight = rd.raw<float>();
        uint8_t use = rd.raw<uint8_t>();
        r.trace.continued = use & kContinuedUse;
        use &= uint8_t(~kContinuedUse);
        if (use > uint8_t(trace::kLastRayUse)) return false;
        r.trace.use = trace::RayUse(use);
        read_stack(rd, r.trace.interiors, numbers);
        r.trace.band = {};
        if (flags & kBand) {
            r.trace.band.index = rd.raw<uint16_t>();
            r.trace.band.count = rd.raw<uint16_t>();
            // A split makes 2 or more bands (the parser's minimum).
            if (r.trace.band.count < 2 || r.trace.band.index >= r.trace.band.count)
                return false;
        }
        r.t_from = rd.raw<Real>();
        if (flags & kShadowState) {
            r.light_distance = rd.raw<Real>();
            r.shadow_state.filter = rd.rgb();
            r.shadow_state.t_min = rd.raw<Real>();
            r.shadow_state.last_hit = rd.raw<Real>();
            const uint8_t bits = rd.raw<uint8_t>();
            if (bits > 7) return false;
            r.shadow_state.blocked = bits & 1;
            r.shadow_state.photon_caustics = bits & 2;
            r.shadow_state.volume = !(bits & 4);
            read_stack(rd, r.shadow_state.inside, numbers);
            r.shadow_state.light = rd.raw<int32_t>();
            if (default_shadow_state(r)) return false;
        } else {
            r.light_distance = kInfinity;
            r.shadow_state = trace::ShadowState{};
        }
        if (flags & kParent) {
            r.parent = rd.raw<uint64_t>();
            r.parent_box = rd.raw<int32_t>();
            r.slot = rd.raw<uint16_t>();
            if (r.parent == 0 && r.parent_box == -1 && r.slot == 0) return false;
        } else {
            r.parent = 0, r.parent_box = -1, r.slot = 0;
        }
        r.pixel = rd.raw<int32_t>();
        r.contribution = rd.rgb();
        if (flags & (kTransmitOne | kTransmitZero)) {
            r.transmit_contribution = (flags & kTransmitOne) ? 1.0f : 0.0f;
        } else {
            r.transmit_contribution = rd.raw<float>();
            if (same_bits(r.transmit_contribution, 1.0f) ||
                same_bits(r.transmit_contribution, 0.0f))
                return false;
        }
    }
    if (!rd.ok || box < 0 || box >= limits.boxes) return false;
    if (item.is_result) return true;
    const RayItem& r = item.ray;
    return r.trace.depth >= 0 && r.parent_box >= -1 && r.parent_box < limits.boxes &&
           r.pixel >= 0 && r.pixel < limits.pixels && r.shadow_state.light >= -1 &&
           r.shadow_state.light < limits.lights;
}

}  // namespace

void write_item(std::vector<uint8_t>& out, int box, const Item& item,
                const ObjectNumbers& numbers) {
    RecordWriter w;
    write_fields(w, box, item, numbers);
    w.append_to(out);
}

int64_t ItemReader::next_box() const {
    uint32_t box;
    if (done() || end_ - p_ < ptrdiff_t(sizeof box)) return -1;
    std::memcpy(&box, p_, sizeof box);
    return box;
}

bool ItemReader::read(int& box, Item& item, size_t& bytes) {
    if (done()) return false;
    Reader rd{p_, end_};
    if (!read_record(rd, limits_, box, item, numbers_)) {
        bad_ = true;
        return false;
    }
    bytes = size_t(rd.p - p_);
    p_ = rd.p;
    --left_;
    return true;
}

}  // namespace povwall::distrib
