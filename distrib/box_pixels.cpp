// The pixels of a black-box render: camera rays of pixels and samples into their first
// boxes, contributions added to the pixel sums (in this process or shared with others),
// and the image or sample colours made from the sums (BoxHost's output;
// distrib/box_host.h).
#include <algorithm>
#include <atomic>
#include <thread>

#include "distrib/box_host.h"
#include "distrib/shared_pixel_sums.h"
#include "trace/camera.h"
#include "trace/forward_sum.h"

namespace povwall::distrib {

void BoxHost::add_pixel(int thread, int pixel, const Rgb& c, float transmit) {
    // Forward contributions go on the sum's grid (trace/forward_sum.h), so the sums are
    // exact whatever the order they arrive in, and equal the single-process tracer's.
    // With parents a slot gets one value: its camera ray's colour, as it is.
    const double v[4] = {parents_ ? double(c.r) : trace::on_sum_grid(c.r),
                         parents_ ? double(c.g) : trace::on_sum_grid(c.g),
                         parents_ ? double(c.b) : trace::on_sum_grid(c.b),
                         parents_ ? double(transmit) : trace::on_sum_grid(transmit)};
    if (shared_sums_) {
        // Other processes add to the same pixels.
        const size_t log =
            size_t(thread) * SharedPixelSums::kStripes + size_t(pixel) / stripe_pixels_;
        std::vector<PixelAdd>& adds = sum_logs_[log];
        adds.push_back({uint32_t(pixel), {v[0], v[1], v[2], v[3]}});
        if (adds.size() >= kSumLogAdd) add_sum_log(log, adds.size() >= kSumLogWait);
        return;
    }
    PixelSums& sums = accum_[size_t(thread)];
    sums.written[size_t(pixel) >> kSumRunShift] = 1;
    double* a = &sums.values[size_t(pixel) * size_t(sum_channels_)];
    for (int k = 0; k < sum_channels_; ++k) a[k] += v[k];
}

void BoxHost::add_sum_log(size_t log, bool wait) {
    std::vector<PixelAdd>& adds = sum_logs_[log];
    std::atomic_ref<uint32_t> lock(
        stripe_locks_[log % SharedPixelSums::kStripes * SharedPixelSums::kLockStride]);
    for (uint32_t free = 0;
         !lock.compare_exchange_strong(free, 1, std::memory_order_acquire); free = 0) {
        if (!wait) return;          // logged on; added at a later contribution
        std::this_thread::yield();  // the holder may be a process waiting for a core
    }
    const size_t channels = size_t(sum_channels_), n = adds.size();
    // The sums miss the cache: fetched a few entries ahead, so the misses overlap.
    constexpr size_t kAhead = 16;
    for (size_t i = 0; i < std::min(n, kAhead); ++i)
        __builtin_prefetch(shared_sums_ + adds[i].pixel * channels, 1);
    for (size_t i = 0; i < n; ++i) {
        if (i + kAhead < n)
            __builtin_prefetch(shared_sums_ + adds[i + kAhead].pixel * channels, 1);
        const PixelAdd& a = adds[i];
        double* sum = shared_sums_ + a.pixel * channels;
        sum[0] += a.value[0];
        sum[1] += a.value[1];
        sum[2] += a.value[2];
        if (channels == 4) sum[3] += a.value[3];
    }
    lock.store(0, std::memory_order_release);
    adds.clear();
}

void BoxHost::set_samples(std::vector<trace::SamplePosition> samples) {
    samples_ = std::move(samples);
    total_pixels_ =
        samples_.empty() ? settings_.width * settings_.height : int(samples_.size());
}

bool BoxHost::has_camera_ray(int slot) const {
    if (!samples_.empty())
        return trace::sample_camera_ray(scene_.camera, blur_.get(),
                                        samples_[size_t(slot)], settings_.width,
                                        settings_.height)
            .has_value();
    const int x = slot % settings_.width, y = slot / settings_.width;
    return trace::camera_ray(scene_.camera, x + 0.5, y + 0.5, settings_.width,
                             settings_.height)
        .has_value();
}

int BoxHost::camera_item(int pixel, Item& item) const {
    RayItem& r = item.ray;
    std::optional<Ray> ray;
    if (!samples_.empty()) {
        ray =
            trace::sample_camera_ray(scene_.camera, blur_.get(), samples_[size_t(pixel)],
                                     settings_.width, settings_.height);
    } else {
        const int x = pixel % settings_.width, y = pixel / settings_.width;
        ray = trace::camera_ray(scene_.camera, x + 0.5, y + 0.5, settings_.width,
                                settings_.height);
    }
    if (!ray) return -1;  // nothing seen there (fisheye corners): the pixel stays black
    r.trace.ray = *ray;
    camera_interiors_.seed(r.trace.ray.origin, r.trace.interiors);
    r.pixel = pixel;
    const int box = enter(r.trace.ray, 0, r.route_walk);
    r.route_box = box;
    return std::max(box, 0);
}

void BoxHost::emit_pixels(int begin, int end) {
    uint64_t made = 0;
    for (int p = begin; p < end; ++p) {
        Item item;
        const int box = camera_item(p, item);
        if (box < 0) continue;
        ++made;
        Box& d = *boxes_[size_t(box)];
        if (!d.scene) {
            remote(box, std::move(item));
            continue;
        }
        {
            std::lock_guard<std::mutex> lock(d.inbox_mutex);
            d.inbox.push_back(std::move(item));
            d.inbox_bytes += sizeof(Item);
        }
        d.pending.fetch_add(1);
    }
    // Created before the range is finished: a status never shows the items missing.
    created_.fetch_add(made);
    pixels_emitted_.fetch_add(uint64_t(end - begin));
    finished_.fetch_add(1);
    wake_idle();
    if (flush) flush();
}

namespace {
// Pixel p of the image from its r, g, b and background-transmit sums.
void set_pixel(Image& image, size_t p, const double* s, bool alpha) {
    for (int c = 0; c < 3; ++c) image.rgba[p * 4 + size_t(c)] = float(s[c]);
    const float t = float(s[3]);
    image.rgba[p * 4 + 3] = alpha ? 1.0f - std::min(1.0f, std::max(0.0f, t)) : 1.0f;
}
}  // namespace

Image image_from_sums(std::span<const double> sums, int width, int height, bool alpha) {
    Image image(width, height);
    const size_t channels = alpha ? 4 : 3;
    for (size_t p = 0; p < size_t(width) * height; ++p) {
        double s[4] = {0, 0, 0, 0};
        for (size_t c = 0; c < channels; ++c) s[c] = sums[p * channels + c];
        set_pixel(image, p, s, alpha);
    }
    return image;
}

void sample_colour(const double* sums, bool alpha, bool camera_ray, float* rgbt) {
    if (!camera_ray) {
        rgbt[0] = rgbt[1] = rgbt[2] = 0;
        rgbt[3] = 1;
        return;
    }
    for (int c = 0; c < 3; ++c) rgbt[c] = float(sums[c]);
    rgbt[3] = alpha ? std::clamp(float(sums[3]), 0.0f, 1.0f) : 0.0f;
}

void BoxHost::sample_colours(std::vector<float>& rgbt) const {
    rgbt.assign(size_t(total_pixels_) * 4, 0.0f);
    for (size_t p = 0; p < size_t(total_pixels_); ++p) {
        double s[4] = {0, 0, 0, 0};
        for (const PixelSums& a : accum_) {
            if (!a.written[p >> kSumRunShift]) continue;
            for (int c = 0; c < sum_channels_; ++c)
                s[c] += a.values[p * size_t(sum_channels_) + size_t(c)];
        }
        sample_colour(s, settings_.alpha, has_camera_ray(int(p)), &rgbt[p * 4]);
    }
}

Image BoxHost::image(int width, int height, bool alpha) const {
    // As image_from_sums(pixel_sums()), summing the threads' runs in the same order,
    // without an 11.5 MB sum array in between.
    Image image(width, height);
    const size_t n = std::min(size_t(width) * size_t(height), size_t(total_pixels_));
    for (size_t p = 0; p < n; ++p) {
        double s[4] = {0, 0, 0, 0};
        for (const PixelSums& a : accum_) {
            if (!a.written[p >> kSumRunShift]) continue;
            for (int c = 0; c < sum_channels_; ++c)
                s[c] += a.values[p * size_t(sum_channels_) + size_t(c)];
        }
        set_pixel(image, p, s, alpha);
    }
    return image;
}

}  // namespace povwall::distrib
