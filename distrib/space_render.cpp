#include "distrib/space_render.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>

#include "distrib/parent_table.h"
#include "trace/camera.h"
#include "trace/shading.h"

namespace povwall::distrib {
namespace {

using Clock = std::chrono::steady_clock;
using trace::TraceResult;

// A ray travelling between boxes. Its origin is never re-based at a wall: searches resume
// at `t_from` along the original ray, so POV-Ray's absolute minimum distances still hold.
struct RayItem {
    trace::TraceRay trace;
    bool shadow = false;
    bool counted = false;
    Real t_from = 0;
    Real light_distance = kInfinity;
    trace::ShadowState shadow_state;
    // Where the result goes: a waiting parent (parent tracking) or the pixel.
    uint64_t parent = 0;
    int32_t parent_box = -1;
    uint16_t slot = 0;
    int32_t pixel = 0;
    // Forward contributions: factors from this ray's colour / transmit to the pixel.
    Rgb contribution{1.0f};
    float transmit_contribution = 1;
};

struct ResultItem {
    uint64_t parent = 0;
    uint16_t slot = 0;
    TraceResult result;
};

struct Item {
    bool is_result = false;
    RayItem ray;
    ResultItem result;
};

struct WaitingParent {
    trace::ShadingRecord record;
    std::vector<TraceResult> results;
    RayItem origin;
};

struct Box {
    Box(QueuePolicy policy) : queue(policy) {}
    int index = 0;
    std::unique_ptr<trace::PreparedScene> scene;
    trace::RayContext ctx;
    std::mutex inbox_mutex;
    std::vector<Item> inbox;
    std::atomic<size_t> pending{0};
    std::atomic<bool> busy{false};
    WorkQueue<Item> queue;
    ParentTable<WaitingParent> parents;
    trace::ShadingRecord record;  // scratch for spawn_children
    uint64_t next_id = 0;
    BoxStats stats;
};

class SpaceRenderer {
public:
    SpaceRenderer(const Scene& scene, const trace::RenderSettings& settings,
                  const SpaceOptions& options)
        : scene_(scene), settings_(settings), options_(options) {
        parents_ = options.results == SpaceOptions::Results::Parents ||
                   (options.results == SpaceOptions::Results::Auto && !shading_is_linear(scene));
    }

    Image run(SpaceStats* stats);

private:
    void setup();
    void worker(int thread);
    void emit_camera_rays(int thread);
    void process(Box& box, Item& item, int thread);
    void process_ray(Box& box, RayItem& ray, int thread);
    void deliver(Box& box, const RayItem& ray, const TraceResult& result, int thread);
    void push(Box* current, int dest, Item&& item);
    int first_box(const Ray& ray, Real t_from, VirtualWalls::Segment& seg, int& next) const;
    void add_pixel(int thread, int pixel, const Rgb& c, float transmit);

    const Scene& scene_;
    const trace::RenderSettings& settings_;
    const SpaceOptions& options_;
    bool parents_ = false;
    VirtualWalls walls_;
    std::vector<std::unique_ptr<Box>> boxes_;
    std::atomic<int64_t> in_flight_{0};
    std::atomic<int> next_pixel_{0};
    int total_pixels_ = 0;
    // Per thread: r, g, b, transmit per pixel, in double so that the order in which
    // contributions arrive does not show in the image.
    std::vector<std::vector<double>> accum_;
    Image image_;
};

// The first box along the ray from t_from that holds any object (empty boxes cannot stop or
// shade a ray, so rays skip them without a message), and the next such box (-1: none).
int SpaceRenderer::first_box(const Ray& ray, Real t_from, VirtualWalls::Segment& seg,
                             int& next) const {
    int count = 0;
    next = -1;
    bool found = false;
    walls_.walk(ray, t_from, kInfinity, [&](const VirtualWalls::Segment& s) {
        if (!found && boxes_[s.box]->scene->primitive_count() == 0) {
            seg = s;  // remembered in case no box along the ray has objects
            ++count;
            return false;
        }
        if (!found) {
            seg = s;
            found = true;
            ++count;
            return false;
        }
        if (boxes_[s.box]->scene->primitive_count() == 0) {
            seg.t_exit = s.t_exit;  // empty boxes extend the current segment's reach
            return false;
        }
        next = s.box;
        return true;
    });
    if (count == 0) {  // NaN ray: stays where it is and misses
        seg = {0, t_from, kInfinity};
    }
    if (next < 0) seg.t_exit = kInfinity;
    return seg.box;
}

void SpaceRenderer::setup() {
    Bounds3 world;
    std::vector<Bounds3> bounds;
    for (const Object& o : scene_.objects) {
        bounds.push_back(trace::object_world_bounds(o));
        if (!bounds.back().infinite()) world.extend(bounds.back());
    }
    const auto& n = options_.boxes;
    if (options_.balanced) {
        std::vector<Bounds3> finite;
        for (const auto& b : bounds) {
            if (!b.infinite()) finite.push_back(b);
        }
        walls_ = VirtualWalls::balanced(finite, n[0], n[1], n[2]);
    } else {
        walls_ = VirtualWalls::uniform(world, n[0], n[1], n[2]);
    }
    std::vector<std::vector<uint32_t>> local(walls_.box_count());
    for (uint32_t i = 0; i < bounds.size(); ++i) {
        for (int b : walls_.boxes_overlapping(bounds[i])) local[b].push_back(i);
    }
    for (int b = 0; b < walls_.box_count(); ++b) {
        auto box = std::make_unique<Box>(options_.queue);
        box->index = b;
        box->scene = std::make_unique<trace::PreparedScene>(scene_, local[b]);
        box->scene->init_context(box->ctx);
        box->next_id = (uint64_t(b) + 1) << 40;
        box->stats.region = walls_.box_bounds(b);
        box->stats.objects = local[b].size();
        box->stats.resident_bytes =
            box->scene->primitive_count() * 96 + box->scene->tree().stats().nodes * 64;
        boxes_.push_back(std::move(box));
    }
}

void SpaceRenderer::push(Box* current, int dest, Item&& item) {
    in_flight_.fetch_add(1, std::memory_order_relaxed);
    Box& d = *boxes_[dest];
    if (current == &d) {
        const bool is_result = item.is_result;
        const int depth = is_result ? 255 : item.ray.trace.depth;
        d.queue.push(std::move(item), is_result, depth);
        d.stats.peak_queue = std::max(d.stats.peak_queue, d.queue.size());
        d.pending.fetch_add(1, std::memory_order_release);
        return;
    }
    if (current) ++current->stats.messages_sent;
    {
        std::lock_guard<std::mutex> lock(d.inbox_mutex);
        d.inbox.push_back(std::move(item));
    }
    d.pending.fetch_add(1, std::memory_order_release);
}

void SpaceRenderer::add_pixel(int thread, int pixel, const Rgb& c, float transmit) {
    double* a = &accum_[thread][size_t(pixel) * 4];
    a[0] += c.r;
    a[1] += c.g;
    a[2] += c.b;
    a[3] += transmit;
}

void SpaceRenderer::deliver(Box& box, const RayItem& ray, const TraceResult& result,
                            int thread) {
    if (!parents_) {
        // Forward contributions: the result lands on the pixel with the factor it carries.
        add_pixel(thread, ray.pixel, ray.contribution * result.colour,
                  ray.shadow ? 0.0f : ray.transmit_contribution * result.transmit);
        return;
    }
    if (ray.parent == 0) {
        float* p = image_.pixel(ray.pixel % image_.width, ray.pixel / image_.width);
        p[0] = result.colour.r;
        p[1] = result.colour.g;
        p[2] = result.colour.b;
        p[3] = result.transmit;
        return;
    }
    Item item;
    item.is_result = true;
    item.result = {ray.parent, ray.slot, result};
    push(&box, ray.parent_box, std::move(item));
}

void SpaceRenderer::process_ray(Box& box, RayItem& ray, int thread) {
    const GlobalSettings& g = scene_.settings;
    VirtualWalls::Segment seg;
    int next;
    first_box(ray.trace.ray, ray.t_from, seg, next);
    if (seg.box != box.index) {  // a tie on a wall sent it here: pass it on unchanged
        Item item;
        item.ray = ray;
        push(&box, seg.box, std::move(item));
        return;
    }
    if (ray.shadow) {
        bool blocked = trace::shadow_segment(*box.scene, ray.trace.ray, seg.t_exit,
                                             ray.light_distance, ray.shadow_state, box.ctx);
        if (blocked || next < 0 || seg.t_exit >= ray.light_distance - 1e-3) {
            deliver(box, ray, {ray.shadow_state.filter, 0}, thread);
            return;
        }
        ray.t_from = seg.t_exit;
        Item item;
        item.ray = ray;
        push(&box, next, std::move(item));
        return;
    }
    // A refused ray is black and opaque (max_trace_level, adc_bailout).
    if (ray.trace.depth > g.max_trace_level || ray.trace.weight < g.adc_bailout) {
        deliver(box, ray, {}, thread);
        return;
    }
    if (!ray.counted) {
        ray.counted = true;
        switch (ray.trace.use) {
            case trace::RayUse::Camera: ++box.stats.camera; break;
            case trace::RayUse::Reflection: ++box.stats.reflected; break;
            case trace::RayUse::Refraction: ++box.stats.refracted; break;
            case trace::RayUse::Shadow: break;
        }
    }
    trace::Hit hit;
    if (!box.scene->closest_hit(ray.trace.ray, ray.t_from, seg.t_exit, ray.trace.use, hit,
                                box.ctx)) {
        if (next < 0) {
            deliver(box, ray, trace::miss_colour(*box.scene, ray.trace.ray), thread);
        } else {
            ray.t_from = seg.t_exit;
            Item item;
            item.ray = ray;
            push(&box, next, std::move(item));
        }
        return;
    }
    trace::ShadingRecord& rec = box.record;
    trace::spawn_children(*box.scene, ray.trace, hit, rec);
    const size_t n = rec.children.size();
    uint64_t id = 0;
    if (parents_) {
        if (n == 0) {
            deliver(box, ray, trace::combine_children(rec, nullptr), thread);
            return;
        }
        id = ++box.next_id;
        WaitingParent w;
        w.record = rec;
        w.results.resize(n);
        w.origin = ray;
        box.parents.park(id, std::move(w), int(n));
        box.stats.peak_parents = std::max(box.stats.peak_parents, box.parents.size());
    } else {
        add_pixel(thread, ray.pixel, ray.contribution * rec.local, 0);
    }
    for (size_t i = 0; i < n; ++i) {
        const trace::ChildRay& c = rec.children[i];
        Item item;
        RayItem& child = item.ray;
        child.trace = c.trace;
        child.shadow = c.kind == trace::ChildRay::Kind::Shadow;
        child.light_distance = c.t_max;
        child.pixel = ray.pixel;
        if (parents_) {
            child.parent = id;
            child.parent_box = box.index;
            child.slot = uint16_t(i);
        } else {
            child.contribution = ray.contribution * c.coeff;
            child.transmit_contribution =
                c.kind == trace::ChildRay::Kind::Transmission
                    ? ray.transmit_contribution * c.transmit_factor
                    : 0.0f;
        }
        if (child.shadow) ++box.stats.shadow;
        VirtualWalls::Segment s;
        int nx;
        push(&box, first_box(child.trace.ray, 0, s, nx), std::move(item));
    }
}

void SpaceRenderer::process(Box& box, Item& item, int thread) {
    if (!item.is_result) {
        ++box.stats.rays_received;
        process_ray(box, item.ray, thread);
        return;
    }
    ++box.stats.results_received;
    const ResultItem& r = item.result;
    auto done = box.parents.deliver(r.parent, [&](WaitingParent& w) { w.results[r.slot] = r.result; });
    if (done) deliver(box, done->origin, trace::combine_children(done->record, done->results.data()), thread);
}

void SpaceRenderer::emit_camera_rays(int thread) {
    constexpr int kBatch = 256;
    while (in_flight_.load(std::memory_order_relaxed) < int64_t(options_.max_rays_in_flight)) {
        int start = next_pixel_.fetch_add(kBatch);
        if (start >= total_pixels_) return;
        int end = std::min(total_pixels_, start + kBatch);
        for (int p = start; p < end; ++p) {
            Item item;
            RayItem& r = item.ray;
            int x = p % settings_.width, y = p / settings_.width;
            r.trace.ray = trace::camera_ray(scene_.camera, x + 0.5, y + 0.5, settings_.width,
                                            settings_.height);
            r.pixel = p;
            VirtualWalls::Segment s;
            int nx;
            push(nullptr, first_box(r.trace.ray, 0, s, nx), std::move(item));
        }
    }
}

void SpaceRenderer::worker(int thread) {
    const size_t n = boxes_.size();
    size_t start = size_t(thread) * 7919 % std::max<size_t>(1, n);
    for (;;) {
        emit_camera_rays(thread);
        bool worked = false;
        for (size_t k = 0; k < n; ++k) {
            Box& box = *boxes_[(start + k) % n];
            if (box.pending.load(std::memory_order_acquire) == 0) continue;
            if (box.busy.exchange(true, std::memory_order_acquire)) continue;
            auto t0 = Clock::now();
            {
                std::vector<Item> incoming;
                {
                    std::lock_guard<std::mutex> lock(box.inbox_mutex);
                    incoming.swap(box.inbox);
                }
                for (Item& it : incoming) {
                    const bool is_result = it.is_result;
                    const int depth = is_result ? 255 : it.ray.trace.depth;
                    box.queue.push(std::move(it), is_result, depth);
                }
                box.stats.peak_queue = std::max(box.stats.peak_queue, box.queue.size());
            }
            for (int budget = 0; budget < 4096 && !box.queue.empty(); ++budget) {
                Item it = box.queue.pop();
                process(box, it, thread);
                box.pending.fetch_sub(1, std::memory_order_release);
                in_flight_.fetch_sub(1, std::memory_order_acq_rel);
            }
            box.stats.busy_seconds += std::chrono::duration<double>(Clock::now() - t0).count();
            box.busy.store(false, std::memory_order_release);
            worked = true;
            start = (start + k + 1) % n;
            break;
        }
        if (!worked) {
            if (next_pixel_.load() >= total_pixels_ && in_flight_.load() == 0) return;
            std::this_thread::yield();
        }
    }
}

Image SpaceRenderer::run(SpaceStats* stats) {
    auto t0 = Clock::now();
    setup();
    const int W = settings_.width, H = settings_.height;
    image_ = Image(W, H);
    total_pixels_ = W * H;
    int threads = settings_.threads > 0
                      ? settings_.threads
                      : int(std::max(1u, std::thread::hardware_concurrency()));
    accum_.assign(threads, parents_ ? std::vector<double>() : std::vector<double>(size_t(W) * H * 4));
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(&SpaceRenderer::worker, this, i);
    worker(0);
    for (auto& t : pool) t.join();
    if (!parents_) {
        for (size_t p = 0; p < size_t(W) * H; ++p) {
            double sum[4] = {0, 0, 0, 0};
            for (int t = 0; t < threads; ++t) {
                for (int c = 0; c < 4; ++c) sum[c] += accum_[t][p * 4 + c];
            }
            for (int c = 0; c < 4; ++c) image_.rgba[p * 4 + c] = float(sum[c]);
        }
    }
    for (size_t p = 0; p < size_t(W) * H; ++p) {
        float& a = image_.rgba[p * 4 + 3];
        a = settings_.alpha ? 1.0f - std::min(1.0f, std::max(0.0f, a)) : 1.0f;
    }
    if (stats) {
        stats->parent_tracking = parents_;
        stats->boxes.clear();
        for (auto& b : boxes_) stats->boxes.push_back(b->stats);
        stats->seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    return std::move(image_);
}

}  // namespace

bool shading_is_linear(const Scene& scene) {
    bool linear = true;
    auto check_layers = [&](const LayeredTexture& layers, auto& self) -> void {
        for (const Texture& t : layers) {
            if (t.finish.reflection_exponent != 1) linear = false;
            for (const auto& m : t.map) self(m, self);
        }
    };
    auto check = [&](const Object& o, auto& self) -> void {
        check_layers(o.texture, check_layers);
        if (auto c = std::get_if<Csg>(&o.shape)) {
            for (const Object& ch : c->children) self(ch, self);
        }
        if (auto m = std::get_if<Mesh>(&o.shape)) {
            for (const auto& t : m->textures) check_layers(t, check_layers);
        }
    };
    for (const Object& o : scene.objects) check(o, check);
    for (const Light& l : scene.lights) {
        for (const Object& o : l.looks_like) check(o, check);
    }
    return linear;
}

Image render_space(const Scene& scene, const trace::RenderSettings& settings,
                   const SpaceOptions& options, SpaceStats* stats) {
    SpaceRenderer r(scene, settings, options);
    return r.run(stats);
}

}  // namespace povwall::distrib
