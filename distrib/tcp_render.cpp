// Black boxes over TCP: the worker process and the coordinator. The only translation unit
// that includes Boost.Asio (compile time).
//
// One io_context per process, on one thread; render threads hand finished frames to it
// with post(). Every handler holds a shared_ptr to its connection, which owns the read
// chunk and the queue of outgoing buffers, so buffers live until their operation
// completes.
//
// clang-format off
// Protocol (all frames: distrib/message.h header, version checked, body <= kMaxBodySize):
//   peer -> worker    Control hello {token, from: index or -1}: first frame, else closed
//   coord -> worker   Control job (scene source, walls, box owners, worker addresses)
//   worker -> coord   Control busy every second while parsing and building its boxes
//   worker -> coord   Control ready (primitive count per hosted box)
//   coord -> worker   Control start (each box's reach), then Items (camera rays)
//   worker -> worker  Items (rays and results for the receiver's boxes)
//   worker -> coord   Control status (items created/finished) every 10 ms: heartbeat, flow
//                     control, and the answer to probes (termination waves)
//   coord -> worker   Control finish; worker -> coord Pixels (sums), then Control done
//   coord -> worker   Control frame (new animation values): the next frame, from "busy"
// clang-format on
#include <fcntl.h>
#include <malloc.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

// clang-format off
#include <utility>  // before Asio: Boost 1.74 uses std::exchange without it
#include <boost/asio.hpp>
// clang-format on
#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>
#include <unordered_map>

#include "core/memory.h"
#include "distrib/box_host.h"
#include "distrib/child_process.h"
#include "distrib/distribution_plan.h"
#include "distrib/message.h"
#include "distrib/shared_pixel_sums.h"
#include "distrib/stats_json.h"
#include "distrib/tcp.h"
#include "parser/parser.h"
#include "trace/pattern.h"

namespace povwall::distrib {
namespace {

namespace asio = boost::asio;
using asio::ip::tcp;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// ---- Work items on the wire
// -------------------------------------------------------------

// Interior stacks hold Material pointers; on the wire they are numbers of objects (CSG
// children included) in a walk every process makes of the same scene, and each process
// keeps one Material per object (the stack only uses its object and interior). A worker
// that parsed only its part of the scene numbers its objects as in the whole scene
// (Scene::object_first_node); a number it does not hold reads as no object.
class ObjectNumbers {
  public:
    explicit ObjectNumbers(const Scene& scene) : sparse_(scene.objects_filtered()) {
        int32_t next = 0;
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            if (sparse_) next = int32_t(scene.object_first_node[i]);
            add(scene.objects[i], next);
        }
        if (sparse_) next = int32_t(scene.object_nodes_total);
        for (const Light& l : scene.lights) {
            for (const Object& o : l.looks_like) add(o, next);
        }
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
        return it == index_.end() ? -1 : numbers_[it->second];
    }
    const trace::Material* material(int32_t n) const {
        if (sparse_) {
            auto it = by_number_.find(n);
            return it == by_number_.end() ? nullptr : &materials_[it->second];
        }
        return n >= 0 && size_t(n) < materials_.size() ? &materials_[n] : nullptr;
    }

  private:
    void add(const Object& o, int32_t& next) {
        index_.emplace(&o, objects_.size());
        objects_.push_back(&o);
        numbers_.push_back(next++);
        if (auto c = std::get_if<Csg>(&o.shape)) {
            for (const Object& ch : c->children) add(ch, next);
        }
    }
    bool sparse_;
    std::vector<const Object*> objects_;
    std::vector<int32_t> numbers_;  // per entry of objects_
    std::unordered_map<const Object*, size_t> index_;
    std::unordered_map<int32_t, size_t> by_number_;  // sparse numbering only
    std::vector<trace::Material> materials_;
};

// The coordinator's render plan, sent with every frame: a worker that parsed only its
// part of the scene must not decide from that part which rays the scene needs.
json plan_to_json(const trace::RenderPlan& p) {
    json lights = json::array();
    for (const trace::LightPlan& l : p.lights)
        lights.push_back({l.shadow_rays, l.unoccluded, l.reason});
    return {{"everything_on", p.everything_on},
            {"quality", p.quality.level},
            {"reflection_rays", p.reflection_rays},
            {"transmission_rays", p.transmission_rays},
            {"refraction_rays", p.refraction_rays},
            {"lights", lights},
            {"skip_unlit_shadow_rays", p.skip_unlit_shadow_rays},
            {"flat_threshold", p.flat_threshold},
            {"parent_tracking", p.parent_tracking},
            {"parents_required", p.parents_required},
            {"parent_reason", p.parent_reason},
            {"finite_primitives", p.finite_primitives},
            {"infinite_primitives", p.infinite_primitives}};
}

trace::RenderPlan plan_from_json(const json& j) {
    trace::RenderPlan p;
    p.everything_on = j.at("everything_on").get<bool>();
    p.quality = trace::Quality::of(j.at("quality").get<int>());
    p.reflection_rays = j.at("reflection_rays").get<bool>();
    p.transmission_rays = j.at("transmission_rays").get<bool>();
    p.refraction_rays = j.at("refraction_rays").get<bool>();
    for (const json& l : j.at("lights")) {
        trace::LightPlan lp;
        lp.shadow_rays = l.at(0).get<bool>();
        lp.unoccluded = l.at(1).get<bool>();
        lp.reason = l.at(2).get<std::string>();
        p.lights.push_back(std::move(lp));
    }
    p.skip_unlit_shadow_rays = j.at("skip_unlit_shadow_rays").get<bool>();
    p.flat_threshold = j.at("flat_threshold").get<int>();
    p.parent_tracking = j.at("parent_tracking").get<bool>();
    p.parents_required = j.at("parents_required").get<bool>();
    p.parent_reason = j.at("parent_reason").get<std::string>();
    p.finite_primitives = j.at("finite_primitives").get<size_t>();
    p.infinite_primitives = j.at("infinite_primitives").get<size_t>();
    return p;
}

struct Writer {
    std::vector<uint8_t>& out;
    template <class T>
    void raw(T v) {  // little-endian hosts only (checked below)
        uint8_t b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        out.insert(out.end(), b, b + sizeof(T));
    }
};
// One record built in place, appended to its frame once: a vector insert per field was
// a tenth of a worker's time.
struct RecordWriter {
    static constexpr size_t kCapacity = 256;  // an item record is at most 213 bytes
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
    w.raw(uint8_t(s.size));
    for (int i = 0; i < s.size && i < trace::InteriorStack::kCapacity; ++i) {
        w.raw(numbers.number(s.items[i]));
    }
}

void read_stack(Reader& r, trace::InteriorStack& s, const ObjectNumbers& numbers) {
    int n = r.raw<uint8_t>();
    if (n > trace::InteriorStack::kCapacity) {
        r.ok = false;
        return;
    }
    s.size = n;
    for (int i = 0; i < n; ++i) s.items[i] = numbers.material(r.raw<int32_t>());
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
};

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
           s.inside.size == 0 && s.light == d.light;
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
                    (shadow_state ? kShadowState : 0) | (parent ? kParent : 0);
    if (same_bits(r.transmit_contribution, 1.0f))
        flags |= kTransmitOne;
    else if (same_bits(r.transmit_contribution, 0.0f))
        flags |= kTransmitZero;
    w.raw(flags);
    w.vec(r.trace.ray.origin);
    w.vec(r.trace.ray.direction);
    w.raw(int32_t(r.trace.depth));
    w.raw(r.trace.weight);
    w.raw(uint8_t(r.trace.use));
    write_stack(w, r.trace.interiors, numbers);
    w.raw(r.t_from);
    if (shadow_state) {
        w.raw(r.light_distance);
        w.rgb(r.shadow_state.filter);
        w.raw(r.shadow_state.t_min);
        w.raw(r.shadow_state.last_hit);
        w.raw(uint8_t(r.shadow_state.blocked));
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

void write_item(std::vector<uint8_t>& out, int box, const Item& item,
                const ObjectNumbers& numbers) {
    RecordWriter w;
    write_fields(w, box, item, numbers);
    w.append_to(out);
}

bool read_item(Reader& rd, int box_count, int& box, Item& item,
               const ObjectNumbers& numbers) {
    box = int(rd.raw<uint32_t>());
    const uint8_t flags = rd.raw<uint8_t>();
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
        if (use > uint8_t(trace::RayUse::Shadow)) return false;
        r.trace.use = trace::RayUse(use);
        read_stack(rd, r.trace.interiors, numbers);
        r.t_from = rd.raw<Real>();
        if (flags & kShadowState) {
            r.light_distance = rd.raw<Real>();
            r.shadow_state.filter = rd.rgb();
            r.shadow_state.t_min = rd.raw<Real>();
            r.shadow_state.last_hit = rd.raw<Real>();
            r.shadow_state.blocked = rd.raw<uint8_t>() != 0;
            read_stack(rd, r.shadow_state.inside, numbers);
            r.shadow_state.light = rd.raw<int32_t>();
        } else {
            r.light_distance = kInfinity;
            r.shadow_state = trace::ShadowState{};
        }
        if (flags & kParent) {
            r.parent = rd.raw<uint64_t>();
            r.parent_box = rd.raw<int32_t>();
            r.slot = rd.raw<uint16_t>();
        } else {
            r.parent = 0, r.parent_box = -1, r.slot = 0;
        }
        r.pixel = rd.raw<int32_t>();
        r.contribution = rd.rgb();
        r.transmit_contribution = (flags & kTransmitOne)    ? 1.0f
                                  : (flags & kTransmitZero) ? 0.0f
                                                            : rd.raw<float>();
    }
    return rd.ok && box >= 0 && box < box_count;
}

using Buffer = std::shared_ptr<std::vector<uint8_t>>;

// The boxes' reach as sent to the workers: six bit patterns per box, so that every
// process routes with exactly the same doubles (infinities included, which JSON lacks).
json reach_to_json(const std::vector<Bounds3>& reach) {
    json out = json::array();
    for (const Bounds3& b : reach) {
        out.push_back({std::bit_cast<uint64_t>(b.lo.x), std::bit_cast<uint64_t>(b.lo.y),
                       std::bit_cast<uint64_t>(b.lo.z), std::bit_cast<uint64_t>(b.hi.x),
                       std::bit_cast<uint64_t>(b.hi.y), std::bit_cast<uint64_t>(b.hi.z)});
    }
    return out;
}

bool reach_from_json(const json& j, int boxes, std::vector<Bounds3>& reach) {
    if (!j.is_array() || j.size() != size_t(boxes)) return false;
    for (const json& b : j) {
        if (!b.is_array() || b.size() != 6) return false;
        Real v[6];
        for (int k = 0; k < 6; ++k) {
            if (!b[size_t(k)].is_number_unsigned()) return false;
            v[k] = std::bit_cast<Real>(b[size_t(k)].get<uint64_t>());
            if (std::isnan(v[k])) return false;
        }
        reach.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
    }
    return true;
}

Buffer control_frame(const json& j) {
    auto buf = std::make_shared<std::vector<uint8_t>>();
    std::string text = j.dump();
    encode_opaque(FrameType::Control, 0,
                  {reinterpret_cast<const uint8_t*>(text.data()), text.size()}, *buf);
    return buf;
}

// Items for one destination process, batched; frames stay well below the body cap.
struct Outbox {
    static constexpr size_t kFlushBytes = 256 << 10;
    std::mutex mutex;
    std::vector<uint8_t> records;
    uint32_t count = 0;
    uint64_t sent = 0;  // items for this process so far (the status's "sent")
    Buffer take() {     // with mutex held
        auto buf = std::make_shared<std::vector<uint8_t>>();
        encode_opaque(FrameType::Items, count, records, *buf);
        records.clear();
        count = 0;
        return buf;
    }
};

// ---- Connections
// -------------------------------------------------------------------------

// A dead peer shows as end of file or as a reset, depending on unread data in its socket.
std::string disconnected(const boost::system::error_code& ec) {
    if (ec == asio::error::eof || ec == asio::error::connection_reset ||
        ec == asio::error::broken_pipe)
        return "disconnected (connection lost)";
    return "disconnected (" + ec.message() + ")";
}

class Connection : public std::enable_shared_from_this<Connection> {
  public:
    Connection(tcp::socket socket, std::string name)
        : socket_(std::move(socket)), name_(std::move(name)) {
        boost::system::error_code ec;
        socket_.set_option(tcp::no_delay(true), ec);
    }
    std::function<void(Frame&)> on_frame;
    std::function<void(const std::string&)> on_error;
    const std::string& name() const { return name_; }

    void start() { read(); }
    void send(Buffer buf) {  // io thread only
        if (closed_) return;
        queue_.push_back(std::move(buf));
        if (writing_ == 0) write();
    }
    void close() {
        closed_ = true;
        boost::system::error_code ec;
        socket_.shutdown(tcp::socket::shutdown_both, ec);
        socket_.close(ec);
    }
    bool closed() const { return closed_; }

  private:
    void read() {
        auto self = shared_from_this();
        // Received bytes land after the unparsed ones in `pending_` (kept at its largest
        // size, so no fresh pages per frame); parsed frames are dropped by moving only
        // the partial frame that follows them to the front.
        if (pending_size_ < filled_ + chunk_)
            grow_pending(std::max(2 * pending_size_, filled_ + chunk_));
        socket_.async_read_some(
            asio::buffer(pending_.get() + filled_, chunk_),
            [this, self](boost::system::error_code ec, size_t n) {
                if (closed_) return;
                if (ec) return fail(disconnected(ec));
                filled_ += n;
                if (n == chunk_) chunk_ = kChunk;  // a stream of items: read more at once
                size_t used = 0;
                for (;;) {
                    DecodeStatus st = decode_frame(
                        std::span(pending_.get() + used, filled_ - used), frame_);
                    if (st == DecodeStatus::NeedMore) break;
                    if (st == DecodeStatus::Bad)
                        return fail("malformed frame or wrong protocol version");
                    used += frame_.consumed;
                    on_frame(frame_);
                    if (closed_) return;
                }
                if (used) {
                    std::memmove(pending_.get(), pending_.get() + used, filled_ - used);
                    filled_ -= used;
                }
                read();
            });
    }
    // Everything queued goes out in one write (one system call for many small frames).
    void write() {
        auto self = shared_from_this();
        writing_ = queue_.size();
        gather_.clear();
        for (const Buffer& b : queue_) gather_.push_back(asio::buffer(*b));
        asio::async_write(
            socket_, gather_, [this, self](boost::system::error_code ec, size_t) {
                if (closed_) return;
                if (ec) return fail(disconnected(ec));
                queue_.erase(queue_.begin(), queue_.begin() + ptrdiff_t(writing_));
                writing_ = 0;
                if (!queue_.empty()) write();
            });
    }
    // Not zeroed: a page of it is first touched when bytes arrive there, so a connection
    // that only sends (or only receives control frames) never faults its 64 KB in.
    void grow_pending(size_t size) {
        auto grown = std::make_unique_for_overwrite<uint8_t[]>(size);
        if (filled_) std::memcpy(grown.get(), pending_.get(), filled_);
        pending_ = std::move(grown);
        pending_size_ = size;
    }
    void fail(const std::string& why) {
        if (closed_) return;
        close();
        if (on_error) on_error(why);
    }

    tcp::socket socket_;
    std::string name_;
    // Reads start small: most connections carry control frames only, or nothing (a
    // worker's connections to its peers only send); a full read goes up to kChunk.
    static constexpr size_t kChunk = 64 << 10;
    size_t chunk_ = 4 << 10;
    std::unique_ptr<uint8_t[]> pending_;
    size_t pending_size_ = 0;
    size_t filled_ = 0;  // bytes of pending_ received and not yet parsed
    Frame frame_;        // reused: its body keeps its capacity
    std::deque<Buffer> queue_;
    size_t writing_ = 0;  // buffers at the front of queue_ being written
    std::vector<asio::const_buffer> gather_;
    bool closed_ = false;
};

json parse_control(const Frame& f) {
    return json::parse(f.body.begin(), f.body.end(), nullptr, false);
}

tcp::endpoint resolve(asio::io_context& io, const std::string& address) {
    auto colon = address.rfind(':');
    if (colon == std::string::npos)
        throw DistribError("bad address '" + address + "' (HOST:PORT)");
    tcp::resolver resolver(io);
    boost::system::error_code ec;
    auto results =
        resolver.resolve(address.substr(0, colon), address.substr(colon + 1), ec);
    if (ec || results.empty())
        throw DistribError("cannot resolve '" + address + "': " + ec.message());
    return *results.begin();
}

// ---- Worker
// ------------------------------------------------------------------------------

// The process's peak resident memory (VmHWM), in bytes; 0 when unknown.
uint64_t peak_resident_bytes() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    unsigned long long kb = 0;
    while (std::fgets(line, sizeof line, f)) {
        if (std::sscanf(line, "VmHWM: %llu kB", &kb) == 1) break;
    }
    std::fclose(f);
    return uint64_t(kb) * 1024;
}

class Worker {
  public:
    explicit Worker(const WorkerOptions& options)
        : options_(options),
          acceptor_(io_),
          status_timer_(io_),
          busy_timer_(io_),
          rendezvous_timer_(io_),
          retry_timer_(io_) {}

    int run() {
        tcp::endpoint ep = resolve(io_, options_.listen);
        acceptor_.open(ep.protocol());
        acceptor_.set_option(tcp::acceptor::reuse_address(true));
        acceptor_.bind(ep);
        acceptor_.listen();
        auto local = acceptor_.local_endpoint();
        std::printf("povwall worker: listening on %s:%u\n",
                    local.address().to_string().c_str(), unsigned(local.port()));
        std::fflush(stdout);
        accept();
        if (!options_.rendezvous.empty()) register_at_rendezvous(local);
        io_.run();
        if (preparing_.joinable()) preparing_.join();
        if (host_) host_->stop();
        if (render_.joinable()) render_.join();
        return exit_code_;
    }

  private:
    // Launcher mode: tell the coordinator's rendezvous this rank's address, retrying
    // while the coordinator is not up yet. A coordinator that never comes ends the
    // worker, so a launch step cannot hang.
    void register_at_rendezvous(tcp::endpoint listening) {
        listening_ = listening;
        rendezvous_timer_.expires_after(
            std::chrono::milliseconds(long(options_.rendezvous_timeout * 1000)));
        rendezvous_timer_.async_wait([this](boost::system::error_code ec) {
            if (ec || coordinator_) return;
            std::fprintf(
                stderr,
                "povwall worker: error: rank %d: no coordinator came through the "
                "rendezvous %s within %g s\n",
                options_.rank, options_.rendezvous.c_str(), options_.rendezvous_timeout);
            exit_code_ = 3;
            io_.stop();
        });
        try_register();
    }

    void try_register() {
        if (coordinator_) return;
        auto socket = std::make_shared<tcp::socket>(io_);
        socket->async_connect(
            resolve(io_, options_.rendezvous),
            [this, socket](boost::system::error_code ec) {
                if (ec) {
                    retry_timer_.expires_after(std::chrono::milliseconds(200));
                    retry_timer_.async_wait([this](boost::system::error_code e) {
                        if (!e) try_register();
                    });
                    return;
                }
                // Listening on every interface: the one that reaches the coordinator is
                // the address its peers can use.
                boost::system::error_code le;
                asio::ip::address host = listening_.address();
                if (host.is_unspecified()) host = socket->local_endpoint(le).address();
                const std::string address =
                    host.to_string() + ":" + std::to_string(listening_.port());
                registration_ =
                    std::make_shared<Connection>(std::move(*socket), options_.rendezvous);
                registration_->on_frame = [](Frame&) {};
                registration_->on_error = [](const std::string&) {};
                registration_->start();
                registration_->send(control_frame({{"type", "register"},
                                                   {"token", options_.token},
                                                   {"rank", options_.rank},
                                                   {"size", options_.size},
                                                   {"address", address}}));
            });
    }

    void accept() {
        acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
            if (ec) return;
            std::string peer = "?";
            boost::system::error_code pe;
            auto rep = socket.remote_endpoint(pe);
            if (!pe) peer = rep.address().to_string() + ":" + std::to_string(rep.port());
            auto conn = std::make_shared<Connection>(std::move(socket), peer);
            std::weak_ptr<Connection> weak = conn;
            conn->on_frame = [this, weak](Frame& f) { hello(weak.lock(), f); };
            conn->on_error = [](const std::string&) {};
            conn->start();
            accept();
        });
    }

    void hello(std::shared_ptr<Connection> conn, Frame& f) {
        json j = f.type == FrameType::Control ? parse_control(f) : json();
        if (!j.is_object() || j.value("type", "") != "hello" ||
            j.value("token", "") != options_.token) {
            std::fprintf(
                stderr,
                "povwall worker: rejected a connection from %s: no valid job token\n",
                conn->name().c_str());
            conn->close();
            return;
        }
        int from = j.value("from", -2);
        if (from == -1 && !coordinator_) {
            coordinator_ = conn;
            if (registration_) registration_->close();
            conn->on_frame = [this](Frame& fr) { from_coordinator(fr); };
            conn->on_error = [this](const std::string& why) {
                if (!done_) {
                    std::fprintf(stderr, "povwall worker: coordinator lost: %s\n",
                                 why.c_str());
                }
                end_job(done_);
            };
        } else if (from >= 0) {
            incoming_.push_back(conn);
            conn->on_frame = [this](Frame& fr) { items(fr); };
        } else {
            conn->close();
        }
    }

    void from_coordinator(Frame& f) {
        if (f.type == FrameType::Items) return items(f);
        json j = parse_control(f);
        const std::string type = j.is_object() ? j.value("type", "") : "";
        if (type == "job") {
            job(j);
        } else if (type == "frame") {
            frame(j);
        } else if (type == "start") {
            std::vector<Bounds3> reach;
            if (!reach_from_json(j.at("reach"), host_->box_count(), reach))
                return fail_job("bad box reach table");
            host_->set_box_reach(std::move(reach));
            // One render thread: the io thread traces itself, between network events.
            inline_ = threads_ == 1;
            if (inline_) {
                host_->begin_run(1);
                // Peers that started first may have sent items already (another
                // connection: no order with this message); they wait in the inboxes, and
                // this worker may get nothing else to wake it (a team without pixels).
                schedule_drain();
            } else {
                render_ = std::thread([this] { host_->run(threads_, false); });
            }
            send_status(-1);
        } else if (type == "pixels") {
            const int total = settings_.width * settings_.height;
            const int begin = j.at("begin").get<int>(), end = j.at("end").get<int>();
            if (!host_ || begin < 0 || begin > end || end > total)
                return fail_job("bad pixel range");
            host_->emit_pixels(begin, end);
            if (inline_) schedule_drain();
        } else if (type == "probe") {
            send_status(j.at("seq").get<long>());
        } else if (type == "finish") {
            finish();
        }
    }

    // The first frame: the whole job. Later frames arrive as "frame" with new animation
    // values only; processes, peer connections, walls and owners stay.
    void job(const json& j) {
        if (job_.is_object()) return fail_job("a second job on one connection");
        job_ = j;
        owner_ = j.at("owner").get<std::vector<int>>();
        self_ = j.at("index").get<int>();
        prepare_then([this] { connect_peers(); });
    }

    // After the first frame's preparation: connect to every other worker, then ready.
    void connect_peers() {
        const auto addresses = job_.at("workers").get<std::vector<std::string>>();
        peers_.resize(addresses.size());
        for (size_t i = 0; i < addresses.size(); ++i)
            outboxes_.push_back(std::make_unique<Outbox>());
        // Only the workers of its team (those its owner table names) get its rays.
        std::vector<uint8_t> needed(addresses.size(), 0);
        for (int o : owner_)
            if (o >= 0 && size_t(o) < needed.size()) needed[size_t(o)] = 1;
        int to_connect = 0;
        for (size_t i = 0; i < addresses.size(); ++i)
            to_connect += int(i) != self_ && needed[i];
        auto remaining = std::make_shared<int>(to_connect);
        if (to_connect == 0) coordinator_->send(control_frame(ready_message()));
        for (size_t i = 0; i < addresses.size(); ++i) {
            if (int(i) == self_ || !needed[i]) continue;
            auto socket = std::make_shared<tcp::socket>(io_);
            tcp::endpoint ep;
            try {
                ep = resolve(io_, addresses[i]);
            } catch (const DistribError& e) {
                return fail_job(e.what());
            }
            socket->async_connect(
                ep, [this, socket, i, remaining,
                     address = addresses[i]](boost::system::error_code ec) {
                    if (ec) {
                        // Most likely that worker died: said as its loss, which the
                        // coordinator can recover from, not as this worker's refusal.
                        return fail_job(
                            "cannot connect to worker " + address + ": " + ec.message(),
                            int(i));
                    }
                    auto conn = std::make_shared<Connection>(std::move(*socket), address);
                    conn->on_frame = [](Frame&) {};
                    conn->on_error = [](const std::string&) {
                    };  // the coordinator sees the death
                    conn->start();
                    conn->send(control_frame(
                        {{"type", "hello"}, {"token", options_.token}, {"from", self_}}));
                    peers_[i] = conn;
                    if (--*remaining == 0)
                        coordinator_->send(control_frame(ready_message()));
                });
        }
    }

    void frame(const json& j) {
        if (!job_.is_object() || !done_)
            return fail_job("a frame before the previous one finished");
        job_["animation"] = j.at("animation");
        job_["plan"] = j.at("plan");
        job_["inherited"] = false;
        job_["expected_objects"] = j.at("expected_objects");
        done_ = false;
        prepare_then([this] { coordinator_->send(control_frame(ready_message())); });
    }

    // Parsing and building the boxes run beside the io thread, which meanwhile tells the
    // coordinator every second that this worker is busy, not hung; `next` runs on the io
    // thread when they succeed.
    void prepare_then(std::function<void()> next) {
        busy_ = true;
        busy_beat();
        preparing_ =
            std::thread([this, next = std::move(next), generation = generation_.load()] {
                std::string error;
                const bool ok = prepare(error);
                asio::post(io_, [this, ok, error, next, generation] {
                    if (generation != generation_) return;  // the job ended meanwhile
                    busy_ = false;
                    busy_timer_.cancel();
                    preparing_.join();
                    if (!ok) return fail_job(error);
                    next();
                });
            });
    }

    void busy_beat() {
        busy_timer_.expires_after(std::chrono::seconds(1));
        busy_timer_.async_wait([this](boost::system::error_code ec) {
            if (ec || !busy_ || !coordinator_) return;
            coordinator_->send(control_frame({{"type", "busy"}}));
            busy_beat();
        });
    }

    // `unreachable`: the index of a peer this worker could not reach (-1: none).
    void fail_job(const std::string& message, int unreachable = -1) {
        json error = {{"type", "error"}, {"message", message}};
        if (unreachable >= 0) error["unreachable"] = unreachable;
        coordinator_->send(control_frame(error));
    }

    // Parses the scene at the job's animation values and builds this worker's boxes (off
    // the io thread: sends nothing; false with `error` set on a parse error).
    bool prepare(std::string& error) {
        const json& j = job_;
        parser::ParseOptions popts;
        popts.image_reader = options_.image_reader;
        popts.function_hooks = trace::parse_time_function_hooks();
        popts.write_user_files = false;  // the coordinator's parse writes them
        popts.library_paths = j.at("library_paths").get<std::vector<std::string>>();
        popts.declares = j.at("declares").get<std::map<std::string, double>>();
        if (!j.at("language_version").is_null())
            popts.language_version = j.at("language_version").get<int>();
        popts.output_file_type = j.at("output_file_type").get<std::string>().at(0);
        const json& anim = j.at("animation");
        popts.clock = anim.at(0), popts.clock_delta = anim.at(1);
        popts.initial_clock = anim.at(2), popts.final_clock = anim.at(3);
        popts.frame_number = anim.at(4), popts.initial_frame = anim.at(5);
        popts.final_frame = anim.at(6);
        popts.max_loop_iterations = j.at("max_loop_iterations").get<uint64_t>();
        settings_.width = popts.image_width = j.at("width").get<int>();
        settings_.height = popts.image_height = j.at("height").get<int>();
        settings_.alpha = j.at("alpha").get<bool>();
        settings_.plan_everything_on = j.at("plan_everything_on").get<bool>();
        // The previous frame's boxes point into the previous scene: gone first.
        host_.reset();
        numbers_.reset();
        // Only the objects that overlap this worker's boxes are kept (the same test as
        // BoxHost::build_boxes), so the worker never holds the whole scene.
        VirtualWalls walls(j.at("walls").get<std::array<std::vector<Real>, 3>>());
        mine_.clear();
        for (size_t b = 0; b < owner_.size(); ++b) {
            if (owner_[b] == self_) mine_.push_back(int(b));
        }
        std::vector<uint8_t> hosted(size_t(walls.box_count()), 0);
        for (int b : mine_) hosted[size_t(b)] = 1;
        popts.expected_objects = j.at("expected_objects").at(size_t(self_)).get<size_t>();
        popts.keep_object = [&walls, &hosted](const Object& o) {
            for (int b : walls.boxes_overlapping(trace::object_world_bounds(o)))
                if (hosted[size_t(b)]) return true;
            return false;
        };
        try {
            if (j.value("inherited", false) && options_.inherited_scene &&
                options_.inherited_objects) {
                // Forked after the coordinator's parse of this frame: no parse here.
                // Its object list stays in the inherited scene, never freed: the
                // process ends with _exit, and freeing would write to (copy) the pages
                // it still shares with the coordinator.
                scene_ =
                    take_scene_keeping(std::move(*options_.inherited_scene),
                                       options_.inherited_objects->at(size_t(self_)));
                options_.inherited_scene = nullptr;  // later frames parse
            } else {
                scene_ = parser::parse_scene_text(j.at("scene").get<std::string>(),
                                                  j.at("name").get<std::string>(), popts);
            }
        } catch (const std::exception& e) {
            error = e.what();
            return false;
        }
        if (!j.at("max_trace_level").is_null())
            scene_.settings.max_trace_level = j.at("max_trace_level").get<int>();
        if (!j.at("adc_bailout").is_null())
            scene_.settings.adc_bailout = float(j.at("adc_bailout").get<double>());
        space_.results = SpaceOptions::Results(j.at("results").get<int>());
        space_.queue = QueuePolicy(j.at("queue").get<int>());
        threads_ = options_.threads > 0 ? options_.threads : j.at("threads").get<int>();
        if (threads_ <= 0)
            threads_ = int(std::max(1u, std::thread::hardware_concurrency()));
        numbers_ = std::make_unique<ObjectNumbers>(scene_);
        const trace::RenderPlan plan = plan_from_json(j.at("plan"));
        host_ = std::make_unique<BoxHost>(scene_, settings_, space_, &plan);
        host_->set_walls(std::move(walls));
        host_->build_boxes(mine_);
        if (options_.shared_sums &&
            options_.shared_sums_count == size_t(settings_.width) *
                                              size_t(settings_.height) *
                                              size_t(host_->sum_channels())) {
            host_->use_shared_sums(options_.shared_sums, options_.shared_sum_locks);
            // The pages exist (the coordinator populated them) but this process has no
            // entries for them yet: one call maps them all instead of a fault per 4 KB
            // page as the pixels come (no huge pages for shared memory here). Best
            // effort: kernels before 5.14 fault them in as before.
            madvise(options_.shared_sums, options_.shared_sums_count * sizeof(double),
                    MADV_POPULATE_WRITE);
        }
        if (options_.die_after_items >= 0 || options_.hang_after_items >= 0) {
            host_->on_processed = [this] {
                const long n = ++processed_;
                if (n == options_.die_after_items) _exit(9);
                if (n == options_.hang_after_items) raise(SIGSTOP);
            };
        }
        // Render threads share the outboxes; a worker that traces on its io thread
        // (inline_) has no other thread to exclude, and skips the lock (two atomic
        // operations per item sent).
        host_->remote = [this](int box, Item&& item) {
            Outbox& o = *outboxes_[owner_[box]];
            std::unique_lock<std::mutex> lock(o.mutex, std::defer_lock);
            if (!inline_) lock.lock();
            const size_t before = o.records.size();
            write_item(o.records, box, item, *numbers_);
            const size_t bytes = o.records.size() - before;
            ++o.sent;
            if (++o.count, o.records.size() >= Outbox::kFlushBytes)
                post(owner_[box], o.take());
            return bytes;
        };
        host_->flush = [this] {
            for (size_t w = 0; w < outboxes_.size(); ++w) {
                Outbox& o = *outboxes_[w];
                std::unique_lock<std::mutex> lock(o.mutex, std::defer_lock);
                if (!inline_) lock.lock();
                if (o.count) post(int(w), o.take());
            }
        };
        return true;
    }

    json ready_message() const {
        json ready = {{"type", "ready"},
                      {"boxes", mine_},
                      {"objects_kept", scene_.objects.size()},
                      {"objects_left_out", scene_.objects_left_out}};
        std::vector<size_t> counts;
        for (int b : mine_) counts.push_back(host_->primitive_count(b));
        ready["primitives"] = counts;
        return ready;
    }

    void post(int worker, Buffer buf) {
        asio::post(io_, [this, worker, buf, generation = generation_.load()] {
            if (generation == generation_ && peers_[worker]) peers_[worker]->send(buf);
        });
    }

    // The coordinator closed its connection: after a finished frame (the job is over) or
    // in the middle (it failed, or gave this job up after losing another worker). With
    // --once the process ends; otherwise everything of the job goes and the worker waits
    // for the next coordinator, so a render that lost one worker can retry on the others.
    void end_job(bool finished) {
        if (options_.once) {
            if (!finished) exit_code_ = 3;
            io_.stop();
            return;
        }
        ++generation_;  // handlers posted for this job do nothing now
        if (host_) host_->stop();
        if (render_.joinable()) render_.join();
        inline_ = false;
        if (preparing_.joinable()) preparing_.join();
        status_timer_.cancel();
        busy_timer_.cancel();
        busy_ = false;
        for (auto& c : incoming_) c->close();
        for (auto& c : peers_) {
            if (c) c->close();
        }
        incoming_.clear();
        peers_.clear();
        outboxes_.clear();
        host_.reset();
        numbers_.reset();
        scene_ = Scene{};
        job_ = json();
        owner_.clear();
        mine_.clear();
        done_ = false;
        coordinator_.reset();
    }

    void items(Frame& f) {
        if (f.type != FrameType::Items || !host_) return;
        Reader rd{f.body.data(), f.body.data() + f.body.size()};
        // Records for one box in a row go into its inbox together.
        uint32_t done = 0;
        bool bad = false;
        auto next_box = [&]() -> int64_t {
            uint32_t box;
            if (rd.end - rd.p < ptrdiff_t(sizeof box)) return -1;
            std::memcpy(&box, rd.p, sizeof box);
            return box;
        };
        while (done < f.count && !bad) {
            const int64_t box = next_box();
            if (box < 0 || box >= host_->box_count() || !host_->hosts(int(box))) {
                bad = true;
                break;
            }
            host_->inject_many(int(box), [&](Item& item) -> size_t {
                if (done == f.count || next_box() != box) return 0;
                const uint8_t* record = rd.p;
                int read_box;
                if (!read_item(rd, host_->box_count(), read_box, item, *numbers_)) {
                    bad = true;
                    return 0;
                }
                ++done;
                return size_t(rd.p - record);
            });
        }
        if (!bad && inline_) schedule_drain();
        if (bad) {
            std::fprintf(stderr, "povwall worker: malformed item frame\n");
            exit_code_ = 3;
            io_.stop();
        }
    }

    // Inline tracing waits until the frames already received are in: one drain (and one
    // round of sends) for all of them, not one per frame.
    void schedule_drain() {
        if (drain_posted_) return;
        drain_posted_ = true;
        asio::post(io_, [this, generation = generation_.load()] {
            drain_posted_ = false;
            if (generation == generation_ && host_ && inline_) host_->drain();
        });
    }

    void send_status(long seq) {
        if (!coordinator_ || coordinator_->closed() || done_) return;
        // finished before created: a snapshot then never shows fewer created than exist.
        uint64_t finished = host_->finished();
        uint64_t created = host_->created();
        // Items sent to each worker so far: the coordinator keeps crowded local workers
        // on cores with those they trade most with.
        std::vector<uint64_t> sent;
        for (const auto& o : outboxes_) {
            std::unique_lock<std::mutex> lock(o->mutex, std::defer_lock);
            if (!inline_) lock.lock();
            sent.push_back(o->sent);
        }
        coordinator_->send(control_frame({{"type", "status"},
                                          {"seq", seq},
                                          {"created", created},
                                          {"finished", finished},
                                          {"pixels", host_->pixels_emitted()},
                                          {"sent", sent}}));
        if (seq < 0) {
            status_timer_.expires_after(std::chrono::milliseconds(10));
            status_timer_.async_wait([this](boost::system::error_code ec) {
                if (!ec) send_status(-1);
            });
        }
    }

    void finish() {
        host_->stop();
        if (render_.joinable()) render_.join();
        if (inline_) host_->end_run();
        inline_ = false;
        status_timer_.cancel();
        // Pixel sums, non-zero pixels only, as (index u32, r g b [transmit] f64) records
        // (transmit with alpha output only).
        const int channels = host_->sum_channels();
        const size_t kRecord = 4 + size_t(channels) * 8;
        // Frames of 256 KB: the coordinator's receive buffers stay that size.
        const size_t per_frame = (size_t(256) << 10) / kRecord;
        std::vector<uint8_t> body;
        body.reserve(per_frame * kRecord);
        uint32_t count = 0;
        auto flush_pixels = [&] {
            auto buf = std::make_shared<std::vector<uint8_t>>();
            encode_opaque(FrameType::Pixels, count, body, *buf);
            coordinator_->send(buf);
            body.clear();
            count = 0;
        };
        host_->for_each_pixel_sum([&](size_t p, const double* s) {
            if (s[0] == 0 && s[1] == 0 && s[2] == 0 && s[3] == 0) return;
            Writer w{body};
            w.raw(uint32_t(p));
            for (int c = 0; c < channels; ++c) w.raw(s[c]);
            if (++count == per_frame) flush_pixels();
        });
        if (count) flush_pixels();
        // Hosted boxes only, in box order: the coordinator reads them against its owners.
        json boxes = json::array();
        const std::vector<BoxStats> all = host_->box_stats();
        for (int index : mine_) {
            const BoxStats& b = all[size_t(index)];
            boxes.push_back(box_stats_json(b));
        }
        coordinator_->send(control_frame({{"type", "done"},
                                          {"stats", boxes},
                                          {"peak_resident", peak_resident_bytes()}}));
        done_ = true;  // the coordinator closes the connection; then io_.run() returns
    }

    WorkerOptions options_;
    asio::io_context io_;
    tcp::acceptor acceptor_;
    asio::steady_timer status_timer_, busy_timer_;
    asio::steady_timer rendezvous_timer_, retry_timer_;  // launcher mode
    tcp::endpoint listening_;
    std::shared_ptr<Connection> registration_;
    std::thread preparing_;
    bool busy_ = false;  // io thread only
    std::shared_ptr<Connection> coordinator_;
    std::vector<std::shared_ptr<Connection>> incoming_, peers_;
    std::vector<std::unique_ptr<Outbox>> outboxes_;
    Scene scene_;
    trace::RenderSettings settings_;
    SpaceOptions space_;
    std::unique_ptr<ObjectNumbers> numbers_;
    std::unique_ptr<BoxHost> host_;
    json job_;  // the job, with the current frame's animation values
    std::vector<int> owner_, mine_;
    int self_ = 0, threads_ = 1;
    std::thread render_;
    bool inline_ = false;  // this frame is traced on the io thread (one render thread)
    bool drain_posted_ = false;
    std::atomic<long> processed_{0};
    std::atomic<uint64_t> generation_{0};  // jobs served: stale handlers check it
    bool done_ = false;
    int exit_code_ = 0;
};

// ---- Coordinator
// -------------------------------------------------------------------------

struct LocalWorker {
    pid_t pid = -1;
    std::string address;
};

// Reads the address each started worker prints on its pipe (the last `reads.size()`
// entries of `started`) and closes the pipes.
void read_worker_addresses(const std::vector<int>& reads,
                           std::vector<LocalWorker>& started, const std::string& what) {
    const size_t first = started.size() - reads.size();
    bool failed = false;
    for (size_t i = 0; i < reads.size(); ++i) {
        FILE* in = fdopen(reads[i], "r");
        char line[256] = {};
        const bool got = !failed && std::fgets(line, sizeof line, in) != nullptr;
        std::fclose(in);
        const char* prefix = "povwall worker: listening on ";
        if (failed || !got || std::strncmp(line, prefix, std::strlen(prefix)) != 0) {
            failed = true;
            continue;
        }
        std::string address = line + std::strlen(prefix);
        while (!address.empty() && (address.back() == '\n' || address.back() == '\r'))
            address.pop_back();
        started[first + i].address = address;
    }
    if (failed) throw WorkerLost(what + " did not start");
}

// Starts `count` local workers at once (each one's start-up overlaps the others') and
// appends them to `started` as they are forked, so that a failure leaves every started
// process where its owner can end it; then reads each one's address. The workers get
// glibc's huge-page heap in their environment (see the cli's worker start), so they do
// not have to execute themselves again to get it.
void spawn_workers(const std::string& binary, const std::string& token, int threads,
                   int count, std::vector<LocalWorker>& started) {
    std::vector<std::string> env_text;
    for (char** e = environ; *e; ++e) {
        if (std::strncmp(*e, "GLIBC_TUNABLES=", 15) != 0) env_text.push_back(*e);
    }
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    std::string t = "GLIBC_TUNABLES=";
    if (tunables && *tunables) t += std::string(tunables) + ":";
    env_text.push_back(t + "glibc.malloc.hugetlb=1");
    env_text.push_back("POVWALL_HEAP_SET=1");
    std::vector<char*> envp;
    for (std::string& e : env_text) envp.push_back(e.data());
    envp.push_back(nullptr);
    const std::string thread_text = std::to_string(threads);
    const char* argv[] = {"povwall", "worker",      "--listen",  "127.0.0.1:0",
                          "--token", token.c_str(), "--threads", thread_text.c_str(),
                          "--once",  nullptr};
    std::vector<int> reads;
    for (int i = 0; i < count; ++i) {
        // Close-on-exec: a worker inherits no other worker's pipe; its stdout (the dup)
        // stays open.
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0)
            throw DistribError("cannot create a pipe for a worker process");
        // posix_spawn, not fork: the child runs no handler of ours (glibc sets caught
        // signals back to their default in it before it unblocks them), so a Ctrl-C
        // between the two cannot make a worker print the coordinator's message, and no
        // copy of the coordinator's page tables is made.
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
        pid_t pid = -1;
        const int rc = posix_spawn(&pid, binary.c_str(), &actions, nullptr,
                                   const_cast<char* const*>(argv), envp.data());
        posix_spawn_file_actions_destroy(&actions);
        if (rc == 0) {
            // A batch task, as forked workers are (fork_workers); set from here, as
            // posix_spawn's attributes take no SCHED_BATCH.
            const sched_param batch{};
            sched_setscheduler(pid, SCHED_BATCH, &batch);
        }
        close(fds[1]);
        if (rc != 0) {
            close(fds[0]);
            for (int fd : reads) close(fd);
            throw DistribError("cannot start a worker process " + binary + ": " +
                               std::strerror(rc));
        }
        started.push_back({pid, ""});
        reads.push_back(fds[0]);
    }
    read_worker_addresses(reads, started, "worker process " + binary);
}

// Whether this process runs only the calling thread (/proc/self/status says).
bool single_threaded() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return false;
    char line[256];
    long threads = -1;
    while (std::fgets(line, sizeof line, f)) {
        if (std::strncmp(line, "Threads:", 8) == 0)
            threads = std::strtol(line + 8, nullptr, 10);
    }
    std::fclose(f);
    return threads == 1;
}

// The fork counterpart of spawn_workers: each child is a worker at once, holding the
// coordinator's parsed scene (`scene`, its own copy after the fork), and ends with
// _exit: it never returns into the coordinator's frames, runs none of its destructors
// and flushes none of its buffers. The caller has checked that no other thread runs.
void fork_workers(const std::string& token, int threads, const ImageReader& image_reader,
                  Scene* scene, const std::vector<std::vector<uint32_t>>& objects,
                  const SharedPixelSums& sums, int count,
                  std::vector<LocalWorker>& started) {
    std::vector<int> reads;
    std::fflush(nullptr);  // nothing buffered is written twice
    for (int i = 0; i < count; ++i) {
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0)
            throw DistribError("cannot create a pipe for a worker process");
        // Signals blocked across the fork: a Ctrl-C cannot reach the child before it has
        // the default handlers (the coordinator's would print its message).
        sigset_t all, before;
        sigfillset(&all);
        pthread_sigmask(SIG_SETMASK, &all, &before);
        const pid_t pid = fork();
        if (pid == 0) {
            std::signal(SIGINT, SIG_DFL);
            std::signal(SIGTERM, SIG_DFL);
            // Workers share the cores with each other: as batch tasks, one that wakes
            // another by sending it rays is not preempted by it, and runs on through
            // its queue (8 workers on 2 cores: involuntary switches 2,855 -> 511).
            const sched_param batch{};
            sched_setscheduler(0, SCHED_BATCH, &batch);
            // One render thread: the preparing thread allocates from the main arena
            // too, not from a fresh one whose first touch faults in whole huge pages.
            if (threads == 1) mallopt(M_ARENA_MAX, 1);
            pthread_sigmask(SIG_SETMASK, &before, nullptr);
            if (dup2(fds[1], 1) < 0) _exit(127);
            // The coordinator's sockets and the other workers' pipes are not this
            // process's: a copy kept open would hide their closing from the peer.
            close_range(3, ~0U, 0);
            WorkerOptions w;
            w.token = token;
            w.threads = threads;
            w.once = true;
            w.image_reader = image_reader;
            w.inherited_scene = scene;
            w.inherited_objects = &objects;
            w.shared_sums = sums.data();
            w.shared_sums_count = sums.size();
            w.shared_sum_locks = sums.stripe_locks();
            _exit(run_worker(w));
        }
        const int fork_errno = errno;
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        close(fds[1]);
        if (pid < 0) {
            close(fds[0]);
            for (int fd : reads) close(fd);
            throw DistribError(std::string("cannot start a worker process: ") +
                               std::strerror(fork_errno));
        }
        started.push_back({pid, ""});
        reads.push_back(fds[0]);
    }
    read_worker_addresses(reads, started, "a forked worker process");
}

// Everything of a job but the animation values: a frame with the same fixed part can go
// to the workers of the previous frame.
json fixed_job(const SceneSource& source, const trace::RenderSettings& settings,
               const SpaceOptions& options) {
    return {{"type", "job"},
            {"scene", source.text},
            {"name", source.display_name},
            {"library_paths", source.library_paths},
            {"declares", source.declares},
            {"language_version",
             source.language_version ? json(*source.language_version) : json()},
            {"output_file_type", std::string(1, source.output_file_type)},
            {"max_loop_iterations", source.max_loop_iterations},
            {"max_trace_level",
             source.max_trace_level ? json(*source.max_trace_level) : json()},
            {"adc_bailout", source.adc_bailout ? json(*source.adc_bailout) : json()},
            {"width", settings.width},
            {"height", settings.height},
            {"alpha", settings.alpha},
            {"plan_everything_on", settings.plan_everything_on},
            {"results", int(options.results)},
            {"queue", int(options.queue)},
            {"threads", settings.threads},
            {"boxes", options.boxes},
            {"balanced", options.balanced}};
}

json animation_values(const SceneSource& source) {
    return {source.clock,       source.clock_delta,  source.initial_clock,
            source.final_clock, source.frame_number, source.initial_frame,
            source.final_frame};
}

}  // namespace

// The coordinator of one set of workers: starts or connects to them on the first frame,
// then renders frames on them until a frame fails.
class TcpCoordinator {
  public:
    TcpCoordinator(const TcpOptions& tcp_options, json fixed)
        : tcp_(tcp_options), fixed_(std::move(fixed)), timer_(io_) {}

    ~TcpCoordinator() {
        // Failed: take the job down (before closing, so no worker reports the close).
        if (failed_ || in_frame_) {
            for (const LocalWorker& l : local_) kill(l.pid, SIGKILL);
        }
        for (auto& w : workers_) {
            if (w.conn) w.conn->close();  // workers between frames exit on their own
        }
        for (const LocalWorker& l : local_) wait_child(l.pid, 10.0);
    }

    const json& fixed() const { return fixed_; }
    bool failed() const { return failed_; }
    // Workers between frames exit when their connection closes; the destructor reaps
    // them.
    void release_workers() {
        for (auto& w : workers_) {
            if (w.conn) w.conn->close();
        }
        released_ = true;
    }
    bool released() const { return released_; }
    int frames() const { return frames_; }
    int processes_started() const { return int(local_.size()); }
    bool forked() const { return forked_; }

    Image render(const Scene& scene, const SceneSource& source,
                 const trace::RenderSettings& settings, const SpaceOptions& options,
                 SpaceStats* stats, const trace::RenderPlan* plan) {
        auto t0 = Clock::now();
        settings_ = &settings;
        options_ = &options;
        emitter_ = std::make_unique<BoxHost>(scene, settings, options, plan);
        numbers_ = std::make_unique<ObjectNumbers>(scene);
        scene_ = &scene;
        in_frame_ = true;
        if (workers_.empty()) {
            emitter_->place_walls();
            // Before forked workers share this process's pages: written after, every
            // page it touches is copied.
            emitter_->build_boxes({});
            start_workers(source);
        } else {
            emitter_->set_walls(emitter_walls_);
            for (WorkerState& w : workers_) {
                w.conn->send(control_frame({{"type", "frame"},
                                            {"animation", animation_values(source)},
                                            {"plan", plan_to_json(emitter_->plan())},
                                            {"expected_objects", objects_per_worker()}}));
            }
            emitter_->build_boxes({});
        }
        const int boxes = emitter_->walls().box_count();
        if (shared_sums_) {
            // Forked workers add into these (fresh zero pages for the first frame). A
            // kept worker may have this frame's message already, but adds nothing
            // before its first camera range, which io_.run() below sends.
            if (frames_ > 0) std::fill(sums_.begin(), sums_.end(), 0.0);
        } else {
            // Sums of the whole image, on 2 MB pages (thousands of 4 KB faults
            // otherwise).
            const size_t sum_count = size_t(settings.width) * size_t(settings.height) *
                                     (settings.alpha ? 4 : 3);
            if (own_sums_.capacity() < sum_count) {
                own_sums_ = std::vector<double>();
                own_sums_.reserve(sum_count);
                advise_huge_pages(own_sums_.data(), sum_count * sizeof(double));
            }
            own_sums_.assign(sum_count, 0.0);
            sums_ = own_sums_;
        }
        empty_.assign(boxes, 1);
        box_stats_ = emitter_->box_stats();
        for (BoxStats& b : box_stats_) {  // the workers' reports fill them
            const Bounds3 region = b.region;
            b = BoxStats{};
            b.region = region;
        }
        created_ = 0;
        pixels_emitted_ = 0;
        next_range_ = 0;
        wave_pending_ = -1;
        last_wave_.clear();
        started_ = false;
        progress_reported_ = 0;
        if (settings.progress)
            settings.progress->start_pass(uint64_t(settings.width) * settings.height);
        for (WorkerState& w : workers_) {
            w.ready = w.done = false;
            w.created = w.finished = 0;
            w.pixels_sent = w.pixels_done = 0;
            w.wave_seq = -1;
            w.last_seen = Clock::now();
        }
        watch();
        io_.restart();
        io_.run();
        if (failed_) {
            if (lost_) throw WorkerLost(error_, lost_worker_);
            throw DistribError(error_);
        }
        in_frame_ = false;
        ++frames_;
        Image image =
            image_from_sums(sums_, settings.width, settings.height, settings.alpha);
        trace::finish_pixels_without_camera_ray(image, scene.camera, settings);
        if (stats) {
            stats->parent_tracking = emitter_->parent_tracking();
            stats->boxes = box_stats_;
            stats->worker_peak_resident.clear();
            stats->worker_objects_kept.clear();
            stats->worker_objects_left_out.clear();
            for (const WorkerState& w : workers_) {
                stats->worker_peak_resident.push_back(w.peak_resident);
                stats->worker_objects_kept.push_back(w.objects_kept);
                stats->worker_objects_left_out.push_back(w.objects_left_out);
            }
            stats->worker_cores = worker_cores_;
            stats->teams = teams_;
            stats->seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        }
        return image;
    }

  private:
    // Each worker's objects: the indices of those overlapping its boxes (the test of
    // BoxHost::build_boxes), ascending.
    std::vector<std::vector<uint32_t>> objects_of_workers() const {
        const VirtualWalls& walls = emitter_walls_;
        const size_t workers = size_t(team_size_);
        std::vector<std::vector<uint32_t>> objects(workers);
        for (size_t i = 0; i < scene_->objects.size(); ++i) {
            for (int b : walls.boxes_overlapping(
                     trace::object_world_bounds(scene_->objects[i]))) {
                const auto w = size_t(owner_[size_t(b)]);
                if (w < objects.size() &&
                    (objects[w].empty() || objects[w].back() != uint32_t(i)))
                    objects[w].push_back(uint32_t(i));
            }
        }
        // Worker t * team_size_ + k hosts the boxes of the team's k.
        for (int t = 1; t < teams_; ++t)
            for (size_t k = 0; k < workers; ++k) objects.push_back(objects[k]);
        return objects;
    }
    // The owner table team `t`'s workers route by (worker indices among all).
    std::vector<int> owners_of_team(int t) const {
        std::vector<int> owners = owner_;
        for (int& o : owners) o += t * team_size_;
        return owners;
    }
    // How many of the scene's objects each worker will keep, so it can reserve its
    // object list.
    std::vector<size_t> objects_per_worker() const {
        std::vector<size_t> count;
        for (const auto& o : objects_of_workers()) count.push_back(o.size());
        return count;
    }

    struct WorkerState {
        std::string address;
        std::shared_ptr<Connection> conn;
        Clock::time_point last_seen;
        bool ready = false, done = false;
        uint64_t created = 0, finished = 0;  // latest status
        // Pixels of the ranges sent to this worker, and handled by it (latest status).
        uint64_t pixels_sent = 0, pixels_done = 0;
        uint64_t peak_resident = 0;  // the process's VmHWM at its last "done"
        size_t objects_kept = 0, objects_left_out = 0;  // by its parse (ready)
        long wave_seq = -1;                             // latest probe answered
        uint64_t wave_created = 0, wave_finished = 0;
        std::vector<uint64_t> sent;  // items sent to each worker (latest status)
    };

    void start_workers(const SceneSource& source) {
        std::string token = tcp_.token;
        std::vector<std::string> addresses = tcp_.workers;
        const int n = int(addresses.size()) + std::max(0, tcp_.procs);
        if (n == 0) throw DistribError("no workers");
        // Walls stay for the whole sequence: the outer boxes are unbounded, so any
        // frame's objects fall in some box; only the balance may drift.
        emitter_walls_ = emitter_->walls();
        // Teams that divide the workers (after a lost worker, fewer may).
        teams_ = std::clamp(options_->teams, 1, n);
        while (n % teams_ != 0) --teams_;
        team_size_ = n / teams_;
        owner_ = box_owners(emitter_walls_.slabs(), team_size_, scene_->camera.direction,
                            options_->process_grid);
        // Before any fork: forked workers take their objects from these lists.
        worker_objects_ = objects_of_workers();
        std::vector<size_t> expected;
        for (const auto& o : worker_objects_) expected.push_back(o.size());
        if (tcp_.procs > 0) {
            if (token.empty()) {
                std::random_device rd;
                char hex[33];
                std::snprintf(hex, sizeof hex, "%08x%08x%08x%08x", rd(), rd(), rd(),
                              rd());
                token = hex;
            }
            unsigned cores = std::max(1u, std::thread::hardware_concurrency());
            int threads = settings_->threads > 0
                              ? settings_->threads
                              : int(std::max(1u, cores / unsigned(tcp_.procs)));
            const size_t before = local_.size();
            forked_ = tcp_.fork_workers && single_threaded();
            if (forked_) {
                // The sums exist before the fork, so every worker maps them; the frame's
                // size is fixed for this coordinator (fixed_job).
                shared_sums_ =
                    SharedPixelSums(size_t(settings_->width) * size_t(settings_->height) *
                                    (settings_->alpha ? 4 : 3));
                sums_ = shared_sums_.values();
                // The child's copy of the scene is its own to take objects from.
                fork_workers(token, threads, tcp_.image_reader,
                             const_cast<Scene*>(scene_), worker_objects_, shared_sums_,
                             tcp_.procs, local_);
            } else {
                spawn_workers(tcp_.worker_binary, token, threads, tcp_.procs, local_);
            }
            for (size_t i = before; i < local_.size(); ++i)
                addresses.push_back(local_[i].address);
            std::vector<pid_t> pids;
            for (const LocalWorker& l : local_) pids.push_back(l.pid);
            maybe_inject_worker_fault(pids);
        }
        json job = fixed_;
        job["animation"] = animation_values(source);
        job["walls"] = std::array<std::vector<Real>, 3>{
            emitter_walls_.walls(0), emitter_walls_.walls(1), emitter_walls_.walls(2)};
        job["workers"] = addresses;
        job["plan"] = plan_to_json(emitter_->plan());
        job["expected_objects"] = expected;
        job["inherited"] = forked_;  // this frame's scene is in the workers already
        workers_.resize(n);
        for (int i = 0; i < n; ++i) {
            WorkerState& w = workers_[i];
            w.address = addresses[i];
            tcp::socket socket(io_);
            boost::system::error_code ec;
            socket.connect(resolve(io_, w.address), ec);
            // Hello and job written at once, not queued for the io loop: the workers
            // prepare while this process sets up the rest of the frame (zeroing the
            // image sums took 10 ms before the first job left).
            if (!ec) {
                job["index"] = i;
                job["owner"] = owners_of_team(i / team_size_);
                const Buffer hello =
                    control_frame({{"type", "hello"}, {"token", token}, {"from", -1}});
                const Buffer work = control_frame(job);
                asio::write(socket, std::array{asio::buffer(*hello), asio::buffer(*work)},
                            ec);
            }
            if (ec) {
                failed_ = true;
                throw WorkerLost("cannot connect to worker " + std::to_string(i) + " (" +
                                     w.address + "): " + ec.message(),
                                 i);
            }
            w.conn = std::make_shared<Connection>(std::move(socket), w.address);
            w.conn->on_frame = [this, i](Frame& f) { from_worker(i, f); };
            w.conn->on_error = [this, i](const std::string& why) { fail(i, why); };
            w.conn->start();
        }
    }

    // "worker 1 (host:port, boxes 1, 3, 5-7)": its boxes, runs of neighbours joined.
    std::string describe(int i) const {
        std::string list;
        int count = 0;
        const int k = i % team_size_;  // its boxes: those of its place in its team
        for (size_t b = 0; b < owner_.size(); ++b) {
            if (owner_[b] != k || (b > 0 && owner_[b - 1] == k)) continue;
            size_t last = b;
            while (last + 1 < owner_.size() && owner_[last + 1] == k) ++last;
            if (!list.empty()) list += ", ";
            list += std::to_string(b);
            if (last > b) list += "-" + std::to_string(last);
            count += int(last - b) + 1;
        }
        return "worker " + std::to_string(i) + " (" + workers_[i].address + ", " +
               (count == 1 ? "box " : "boxes ") + list + ")";
    }

    // `lost`: the worker is gone (a job it refused is not a loss another try could mend).
    // A worker that dies between frames shows here at the next frame.
    void fail(int i, const std::string& why, bool lost = true) {
        if (failed_) return;
        failed_ = true;
        lost_ = lost;
        lost_worker_ = i;
        error_ = describe(i) + ": " + why;
        io_.stop();
    }

    void watch() {  // heartbeat: a worker silent for the timeout is taken as dead
        timer_.expires_after(std::chrono::milliseconds(250));
        timer_.async_wait([this](boost::system::error_code ec) {
            if (ec || !in_frame_) return;
            for (size_t i = 0; i < workers_.size(); ++i) {
                double silent =
                    std::chrono::duration<double>(Clock::now() - workers_[i].last_seen)
                        .count();
                // Status every 10 ms while tracing, "busy" every second while preparing.
                if (!workers_[i].done && silent > tcp_.heartbeat_timeout) {
                    return fail(int(i),
                                "no message for " + std::to_string(int(silent)) + " s");
                }
            }
            watch();
        });
    }

    void from_worker(int i, Frame& f) {
        WorkerState& w = workers_[i];
        w.last_seen = Clock::now();
        if (f.type == FrameType::Pixels) {
            Reader rd{f.body.data(), f.body.data() + f.body.size()};
            const size_t channels = settings_->alpha ? 4 : 3;
            for (uint32_t k = 0; k < f.count; ++k) {
                uint32_t p = rd.raw<uint32_t>();
                double v[4];
                for (size_t c = 0; c < channels; ++c) v[c] = rd.raw<double>();
                if (!rd.ok || size_t(p) * channels >= sums_.size())
                    return fail(i, "bad pixel frame");
                for (size_t c = 0; c < channels; ++c)
                    sums_[size_t(p) * channels + c] += v[c];
            }
            return;
        }
        if (f.type != FrameType::Control) return fail(i, "unexpected frame");
        json j = parse_control(f);
        const std::string type = j.is_object() ? j.value("type", "") : "";
        if (type == "error") {
            // A peer it cannot reach is taken as lost (a worker killed while the others
            // connect to it shows here first), so recovery can leave it out.
            const int unreachable = j.value("unreachable", -1);
            if (unreachable >= 0 && unreachable < int(workers_.size()) &&
                unreachable != i)
                return fail(unreachable, "not reachable from worker " +
                                             std::to_string(i) + " (" +
                                             j.value("message", "error") + ")");
            return fail(i, j.value("message", "error"), false);
        } else if (type == "ready") {
            auto mine = j.at("boxes").get<std::vector<int>>();
            auto counts = j.at("primitives").get<std::vector<size_t>>();
            w.objects_kept = j.at("objects_kept").get<size_t>();
            w.objects_left_out = j.at("objects_left_out").get<size_t>();
            for (size_t k = 0; k < mine.size() && k < counts.size(); ++k)
                empty_[mine[k]] = counts[k] == 0;
            w.ready = true;
            for (const WorkerState& o : workers_) {
                if (!o.ready) return;
            }
            std::vector<Bounds3> reach = emitter_->box_reach();
            for (size_t b = 0; b < reach.size(); ++b) {
                if (empty_[b]) reach[b] = Bounds3{};
            }
            emitter_->set_box_reach(reach);
            started_ = true;
            measure_for_cores();
            const json start = {{"type", "start"}, {"reach", reach_to_json(reach)}};
            // For the tests: POVWALL_FAULT_LATE_START="I,MS" sends worker I its start MS
            // milliseconds after the others, so that its peers' items come first.
            int late = -1, late_ms = 0;
            if (const char* spec = std::getenv("POVWALL_FAULT_LATE_START"))
                if (std::sscanf(spec, "%d,%d", &late, &late_ms) != 2) late = -1;
            for (size_t k = 0; k < workers_.size(); ++k) {
                if (int(k) != late) {
                    workers_[k].conn->send(control_frame(start));
                    continue;
                }
                auto timer = std::make_shared<asio::steady_timer>(
                    io_, std::chrono::milliseconds(late_ms));
                timer->async_wait([this, timer, k, frame = control_frame(start)](
                                      boost::system::error_code ec) {
                    if (!ec && in_frame_) workers_[k].conn->send(frame);
                });
            }
            emit();
        } else if (type == "status") {
            w.created = j.at("created").get<uint64_t>();
            const uint64_t finished = j.at("finished").get<uint64_t>();
            // Progress: items (rays and results) the workers have finished.
            if (settings_->progress && finished > w.finished)
                settings_->progress->rays += finished - w.finished;
            w.finished = finished;
            w.pixels_done = j.value("pixels", uint64_t(0));
            if (j.contains("sent") && j["sent"].is_array() &&
                j["sent"].size() == workers_.size())
                w.sent = j["sent"].get<std::vector<uint64_t>>();
            report_progress();
            long seq = j.at("seq").get<long>();
            if (seq >= 0) {
                w.wave_seq = seq;
                w.wave_created = w.created;
                w.wave_finished = w.finished;
                check_wave();
            }
            emit();
        } else if (type == "done") {
            const json& boxes = j.at("stats");
            size_t k = 0;
            for (size_t b = 0; b < owner_.size(); ++b) {
                if (owner_[b] != i % team_size_ || k >= boxes.size()) continue;
                // Every team hosts the box: its copies' reports add up.
                add_box_stats(box_stats_[b], boxes[k++]);
            }
            w.peak_resident = j.value("peak_resident", uint64_t(0));
            w.done = true;
            for (const WorkerState& o : workers_) {
                if (!o.done) return;
            }
            // The frame is whole; the workers wait for the next one (or the close).
            if (settings_->progress) {
                const uint64_t total = uint64_t(settings_->width) * settings_->height;
                settings_->progress->pixels_done += total - progress_reported_;
                progress_reported_ = total;
            }
            in_frame_ = false;
            timer_.cancel();
            io_.stop();
        }
    }

    // The workers' last reported counters (pixels_done_estimate); made exact when the
    // frame is whole.
    void report_progress() {
        if (!settings_->progress) return;
        uint64_t created = created_, finished = 0;
        for (const WorkerState& w : workers_) {
            created += w.created;
            finished += w.finished;
        }
        const uint64_t done =
            pixels_done_estimate(uint64_t(pixels_emitted_), created, finished);
        if (done > progress_reported_) {
            settings_->progress->pixels_done += done - progress_reported_;
            progress_reported_ = done;
        }
    }

    // Camera rays while the last reported traffic is below the in-flight bound. The
    // workers make them: each range of pixels goes to the worker hosting the box where
    // the range's middle camera ray starts (camera rays of one range mostly start in one
    // box), which queues those starting in its boxes and forwards the others. A range
    // counts as one created item until a worker finishes it, and as its pixels for the
    // flow control until the worker has handled it.
    void emit() {
        if (!started_ || !in_frame_) return;
        constexpr int kRange = 512;
        const int total = settings_->width * settings_->height;
        int64_t live = int64_t(created_);
        for (const WorkerState& w : workers_) {
            live += int64_t(w.created) - int64_t(w.finished);
            live += int64_t(w.pixels_sent) - int64_t(w.pixels_done);
        }
        const int ranges = (total + kRange - 1) / kRange;
        if (range_order_.size() != size_t(ranges)) range_order_ = spread_order(ranges);
        while (next_range_ < ranges && live < int64_t(options_->max_rays_in_flight)) {
            const int begin = range_order_[size_t(next_range_++)] * kRange;
            const int end = std::min(total, begin + kRange);
            Item item;
            const int box = emitter_->camera_item((begin + end) / 2, item);
            // The teams in turn: a team traces its rays' whole paths.
            const int team = next_range_ % teams_;
            WorkerState& w = workers_[size_t(team * team_size_ +
                                             (box >= 0 ? owner_[size_t(box)] : 0))];
            w.conn->send(
                control_frame({{"type", "pixels"}, {"begin", begin}, {"end", end}}));
            w.pixels_sent += uint64_t(end - begin);
            ++created_;
            live += 1 + (end - begin);
            pixels_emitted_ += end - begin;
        }
        if (!cpu_at_start_.empty() && pixels_emitted_ * 4 >= total) keep_on_cores();
        if (next_range_ >= ranges && live == 0 && wave_pending_ < 0) probe();
    }

    // Local workers that outnumber the cores: the CPU time each has used since the
    // start, with a quarter of the image handed out (in spread order, so from all over
    // it), is its share of the work, and the items each has sent each other its traffic;
    // each is then kept on a core with those it trades most with (core_groups). The
    // pilot's box visits had not told the work apart (4x4x4 over 8: one core got 57 %
    // of the samples).
    void measure_for_cores() {
        cpu_at_start_.clear();
        if (!worker_cores_.empty() || options_->keep_on_cores <= 1 ||
            local_.size() != workers_.size() ||
            int(local_.size()) <= options_->keep_on_cores)
            return;
        for (const LocalWorker& l : local_) {
            const uint64_t ns = cpu_nanoseconds(l.pid);
            if (ns == 0) return cpu_at_start_.clear();
            cpu_at_start_.push_back(ns);
        }
    }
    void keep_on_cores() {
        std::vector<double> work;
        for (size_t i = 0; i < local_.size(); ++i) {
            const uint64_t ns = cpu_nanoseconds(local_[i].pid);
            work.push_back(ns > cpu_at_start_[i] ? double(ns - cpu_at_start_[i]) : 0.0);
        }
        cpu_at_start_.clear();
        std::vector<std::vector<uint64_t>> traffic;
        for (const WorkerState& w : workers_) traffic.push_back(w.sent);
        worker_cores_ = core_groups(work, traffic, options_->keep_on_cores);
        for (size_t i = 0; i < worker_cores_.size(); ++i)
            keep_on_core(local_[i].pid, worker_cores_[i]);
    }

    // Termination: two consecutive probe waves with identical counters of every worker
    // mean the counters held at one instant between them; created == finished then means
    // no ray or result was queued, being traced, or on the wire anywhere.
    void probe() {
        wave_pending_ = ++wave_seq_;
        for (WorkerState& w : workers_) {
            w.conn->send(control_frame({{"type", "probe"}, {"seq", wave_seq_}}));
        }
    }

    void check_wave() {
        if (wave_pending_ < 0) return;
        uint64_t created = created_, finished = 0;
        std::vector<std::pair<uint64_t, uint64_t>> counts;
        for (const WorkerState& w : workers_) {
            if (w.wave_seq != wave_pending_) return;
            created += w.wave_created;
            finished += w.wave_finished;
            counts.emplace_back(w.wave_created, w.wave_finished);
        }
        wave_pending_ = -1;
        const bool same = counts == last_wave_;
        last_wave_ = counts;
        if (created != finished) return;  // traffic remains: later statuses probe again
        if (!same) return probe();
        for (WorkerState& w : workers_) w.conn->send(control_frame({{"type", "finish"}}));
    }

    const TcpOptions tcp_;
    const json fixed_;
    asio::io_context io_;
    asio::steady_timer timer_;
    // The current frame.
    const trace::RenderSettings* settings_ = nullptr;
    const SpaceOptions* options_ = nullptr;
    std::unique_ptr<BoxHost> emitter_;  // walls and camera rays; hosts no box
    const Scene* scene_ = nullptr;      // this frame's
    std::unique_ptr<ObjectNumbers> numbers_;
    std::vector<uint8_t> empty_;
    std::vector<BoxStats> box_stats_;
    // The image's sums: own_sums_, or shared_sums_ when the workers were forked.
    std::span<double> sums_;
    std::vector<double> own_sums_;
    SharedPixelSums shared_sums_;
    std::vector<std::pair<uint64_t, uint64_t>> last_wave_;
    uint64_t created_ = 0;
    int pixels_emitted_ = 0;  // pixels of the ranges sent so far (progress)
    int next_range_ = 0;      // into range_order_
    std::vector<int> range_order_;
    uint64_t progress_reported_ = 0;
    long wave_pending_ = -1;
    bool started_ = false, in_frame_ = false;
    // The whole sequence.
    VirtualWalls emitter_walls_;
    std::vector<LocalWorker> local_;
    std::vector<WorkerState> workers_;
    // Which worker of a team hosts each box (an index within the team); worker
    // t * team_size_ + k is team t's k (SpaceOptions::teams).
    std::vector<int> owner_;
    int teams_ = 1, team_size_ = 1;
    long wave_seq_ = 0;
    int frames_ = 0;
    bool forked_ = false;  // the local workers were forked (else executed, or none)
    // Each worker's objects in the first frame (objects_of_workers); forked workers
    // read them from their copy of this process.
    std::vector<std::vector<uint32_t>> worker_objects_;
    bool failed_ = false, lost_ = false;
    bool released_ = false;  // release_workers(): no frame after it
    // Keeping local workers on cores: their CPU time at the start (until measured), then
    // each one's core group (kept for later frames).
    std::vector<uint64_t> cpu_at_start_;
    std::vector<int> worker_cores_;
    int lost_worker_ = -1;
    std::string error_;
};

std::vector<int> spread_order(int count) {
    int bits = 0;
    while ((1 << bits) < count) ++bits;
    std::vector<int> order;
    order.reserve(size_t(count));
    for (int k = 0; k < (1 << bits); ++k) {
        int r = 0;
        for (int b = 0; b < bits; ++b) r |= ((k >> b) & 1) << (bits - 1 - b);
        if (r < count) order.push_back(r);
    }
    return order;
}

TcpSession::TcpSession(TcpOptions tcp) : tcp_(std::move(tcp)) {}
TcpSession::~TcpSession() = default;

int TcpSession::frames_on_these_workers() const {
    return coordinator_ ? coordinator_->frames() : 0;
}

bool TcpSession::workers_forked() const { return coordinator_ && coordinator_->forked(); }

int TcpSession::processes_started() const {
    return processes_started_before_ +
           (coordinator_ ? coordinator_->processes_started() : 0);
}

void TcpSession::release_workers() {
    if (coordinator_) coordinator_->release_workers();
}

Image TcpSession::render(const Scene& scene, const SceneSource& source,
                         const trace::RenderSettings& settings,
                         const SpaceOptions& options, SpaceStats* stats,
                         const trace::RenderPlan* plan) {
    json fixed = fixed_job(source, settings, options);
    auto retire = [&] {
        if (!coordinator_) return;
        processes_started_before_ += coordinator_->processes_started();
        coordinator_.reset();
    };
    if (coordinator_ && (coordinator_->failed() || coordinator_->released() ||
                         coordinator_->fixed() != fixed))
        retire();
    for (;;) {
        if (!coordinator_) coordinator_ = std::make_unique<TcpCoordinator>(tcp_, fixed);
        try {
            return coordinator_->render(scene, source, settings, options, stats, plan);
        } catch (const WorkerLost& e) {
            retire();
            if (!tcp_.recover) throw;
            if (!tcp_.workers.empty()) {
                // Running workers are someone else's: the lost one is left out, the
                // others (back to waiting for a job) take its boxes.
                if (e.worker < 0 || size_t(e.worker) >= tcp_.workers.size() ||
                    tcp_.workers.size() <= 1)
                    throw;
                tcp_.workers.erase(tcp_.workers.begin() + e.worker);
                std::fprintf(
                    stderr,
                    "povwall: %s: its boxes went to the other workers; the frame "
                    "is traced again on %zu running worker%s\n",
                    e.what(), tcp_.workers.size(), tcp_.workers.size() == 1 ? "" : "s");
                continue;
            }
            if (tcp_.procs <= 1) throw;
            tcp_.procs -= 1;
            std::fprintf(stderr,
                         "povwall: %s: its boxes went to the other workers; the frame is "
                         "traced again on %d worker process%s\n",
                         e.what(), tcp_.procs, tcp_.procs == 1 ? "" : "es");
        } catch (const DistribError&) {
            retire();
            throw;
        } catch (const std::exception& e) {
            retire();
            throw DistribError(e.what());
        }
    }
}

std::vector<uint8_t> encode_control_frame(const std::string& text) {
    std::vector<uint8_t> out;
    encode_opaque(FrameType::Control, 0,
                  {reinterpret_cast<const uint8_t*>(text.data()), text.size()}, out);
    return out;
}

std::optional<LauncherRank> launcher_rank(
    const std::function<const char*(const char*)>& getenv) {
    auto number = [&](const char* name, int& out) {
        const char* v = getenv(name);
        if (!v || !*v) return false;
        char* end = nullptr;
        errno = 0;
        long n = std::strtol(v, &end, 10);
        if (*end || errno || n < 0 || n > 1'000'000)
            throw DistribError(std::string(name) + "='" + v +
                               "' is not a rank or a size");
        out = int(n);
        return true;
    };
    struct Pair {
        const char* rank;
        const char* size;
    };
    // srun's step task count first: SLURM_NTASKS is the allocation's.
    for (Pair p : {Pair{"SLURM_PROCID", "SLURM_STEP_NUM_TASKS"},
                   Pair{"SLURM_PROCID", "SLURM_NTASKS"},
                   Pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                   Pair{"PMI_RANK", "PMI_SIZE"}}) {
        LauncherRank r;
        if (!number(p.rank, r.rank) || !number(p.size, r.size)) continue;
        r.source = std::string(p.rank) + "/" + p.size;
        if (r.size < 1 || r.rank >= r.size)
            throw DistribError(std::string(p.rank) + "=" + std::to_string(r.rank) +
                               " is not below " + p.size + "=" + std::to_string(r.size));
        return r;
    }
    return std::nullopt;
}

std::vector<std::string> gather_workers(
    const std::string& address, const std::string& token, double timeout_seconds,
    const std::function<void(const std::string&)>& listening) {
    asio::io_context io;
    tcp::endpoint ep = resolve(io, address);
    tcp::acceptor acceptor(io);
    boost::system::error_code ec;
    acceptor.open(ep.protocol(), ec);
    if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
    if (!ec) acceptor.bind(ep, ec);
    if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
    if (ec)
        throw DistribError("cannot listen on rendezvous " + address + ": " +
                           ec.message());
    const tcp::endpoint bound = acceptor.local_endpoint();
    const std::string shown =
        bound.address().to_string() + ":" + std::to_string(bound.port());
    if (listening) listening(shown);

    std::vector<std::string> by_rank;
    int size = 0, registered = 0;
    std::string error;
    std::vector<std::shared_ptr<Connection>> connections;
    auto on_register = [&](const std::shared_ptr<Connection>& conn, Frame& f) {
        json j = f.type == FrameType::Control ? parse_control(f) : json();
        if (!j.is_object() || j.value("type", "") != "register" ||
            j.value("token", "") != token || !j["rank"].is_number_integer() ||
            !j["size"].is_number_integer() || !j["address"].is_string()) {
            std::fprintf(stderr,
                         "povwall: rejected a registration from %s: no valid job token\n",
                         conn->name().c_str());
            conn->close();
            return;
        }
        const int rank = j["rank"].get<int>(), n = j["size"].get<int>();
        const std::string where = j["address"].get<std::string>();
        if (size == 0 && n >= 1 && n <= 4096) {
            size = n;
            by_rank.assign(size_t(n), std::string());
        }
        if (size == 0) {
            error = "a worker registered a launch size of " + std::to_string(n) +
                    " (1 to 4096)";
        } else if (n != size) {
            error = "workers disagree on the launch size (" + std::to_string(size) +
                    " and " + std::to_string(n) + ")";
        } else if (rank < 0 || rank >= size) {
            error = "a worker registered as rank " + std::to_string(rank) + " of " +
                    std::to_string(size);
        } else if (!by_rank[size_t(rank)].empty()) {
            error = "two workers registered as rank " + std::to_string(rank) + " (" +
                    by_rank[size_t(rank)] + " and " + where + ")";
        } else {
            by_rank[size_t(rank)] = where;
            if (++registered < size) return;
        }
        io.stop();
    };
    std::function<void()> accept = [&] {
        acceptor.async_accept([&](boost::system::error_code aec, tcp::socket socket) {
            if (aec) return;
            boost::system::error_code pe;
            auto rep = socket.remote_endpoint(pe);
            std::string peer =
                pe ? "?" : rep.address().to_string() + ":" + std::to_string(rep.port());
            auto conn = std::make_shared<Connection>(std::move(socket), peer);
            std::weak_ptr<Connection> weak = conn;
            conn->on_frame = [&, weak](Frame& f) {
                if (auto c = weak.lock()) on_register(c, f);
            };
            conn->on_error = [](const std::string&) {};
            conn->start();
            connections.push_back(conn);
            accept();
        });
    };
    accept();
    io.run_for(std::chrono::milliseconds(long(timeout_seconds * 1000)));
    for (auto& c : connections) c->close();
    if (!error.empty()) throw DistribError("rendezvous " + shown + ": " + error);
    if (size == 0 || registered < size) {
        std::string missing;
        for (int r = 0; r < size; ++r) {
            if (!by_rank[size_t(r)].empty()) continue;
            missing += (missing.empty() ? "" : ", ") + std::to_string(r);
        }
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", timeout_seconds);
        throw DistribError(
            size == 0
                ? "rendezvous " + shown + ": no worker registered within " + seconds +
                      " s"
                : "rendezvous " + shown + ": only " + std::to_string(registered) +
                      " of " + std::to_string(size) + " workers registered within " +
                      seconds + " s (missing ranks: " + missing + ")");
    }
    return by_rank;
}

int run_worker(const WorkerOptions& given) {
    // A worker's buffers (frames, inboxes, queues) grow and shrink with the traffic; by
    // default glibc hands large blocks back to the kernel and the next growth faults
    // fresh pages in again (a quarter of a worker's kernel time). Kept instead: a
    // worker's peak is bounded by the rays in flight.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    try {
        WorkerOptions options = given;
        if (!options.rendezvous.empty()) {
            // Launched by srun/mpirun: one job, then the launch step may end.
            options.once = true;
            if (options.rank < 0 || options.size < 1) {
                std::optional<LauncherRank> r = launcher_rank(std::getenv);
                if (!r)
                    throw DistribError(
                        "--rendezvous needs this process's rank and size: start it "
                        "under srun or mpirun, or give --rank and --size");
                if (options.rank < 0) options.rank = r->rank;
                if (options.size < 1) options.size = r->size;
            }
            if (options.rank >= options.size)
                throw DistribError("--rank " + std::to_string(options.rank) +
                                   " is not below --size " +
                                   std::to_string(options.size));
        }
        if (options.inherited_scene) {
            // A forked worker, which ends with _exit: its state is never freed, since
            // freeing writes to (and so copies) pages it shares with the coordinator, at
            // 17-70 us a page on this VM.
            auto* forked = new Worker(options);
            return forked->run();
        }
        Worker w(options);
        return w.run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "povwall worker: error: %s\n", e.what());
        return 2;
    }
}

}  // namespace povwall::distrib
