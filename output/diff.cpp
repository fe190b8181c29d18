#include "output/diff.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "output/image_io.h"

namespace povwall::output {

std::vector<size_t> bad_pixel_indices(const Image& a, const Image& b, double fail) {
    std::vector<size_t> bad;
    if (a.width != b.width || a.height != b.height) return bad;
    const size_t n = size_t(a.width) * size_t(a.height);
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(double(a.rgba[i * 4 + c]) - double(b.rgba[i * 4 + c])) > fail) {
                bad.push_back(i);
                break;
            }
        }
    }
    return bad;
}

DiffResult diff_images(const Image& a, const Image& b, const DiffThresholds& t,
                       const std::vector<uint8_t>* skip) {
    DiffResult r;
    r.width = a.width;
    r.height = a.height;
    if (a.width != b.width || a.height != b.height) {
        r.status = DiffResult::Status::SizeMismatch;
        r.error = "image sizes differ: " + std::to_string(a.width) + "x" +
                  std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                  std::to_string(b.height);
        return r;
    }
    double sum = 0;
    long long n = 0;
    const long long pixels = (long long)a.width * a.height;
    for (long long i = 0; i < pixels; ++i) {
        if (skip && size_t(i) < skip->size() && (*skip)[size_t(i)]) continue;
        ++n;
        bool bad = false, warn = false;
        for (int c = 0; c < 3; ++c) {
            double va = a.rgba[i * 4 + c], vb = b.rgba[i * 4 + c];
            double d = std::fabs(va - vb);
            sum += d * d;
            if (d > r.max_abs) {
                r.max_abs = d;
                r.max_x = int(i % a.width);
                r.max_y = int(i / a.width);
                r.max_channel = c;
                r.max_value_a = va;
                r.max_value_b = vb;
            }
            if (d > t.fail) bad = true;
            if (d > t.warn) warn = true;
        }
        r.bad_pixels += bad;
        r.warn_pixels += warn;
    }
    r.rmse = n ? std::sqrt(sum / double(n * 3)) : 0;
    r.psnr = r.rmse > 0 ? 20 * std::log10(1 / r.rmse)
                        : std::numeric_limits<double>::infinity();
    r.bad_pixel_fraction = n ? double(r.bad_pixels) / double(n) : 0;
    // Fail when either golden threshold is exceeded; warn when some pixels are over the
    // per-channel threshold but few enough to be allowed.
    if (r.rmse > t.max_rmse || r.bad_pixel_fraction > t.max_bad_fraction) {
        r.status = DiffResult::Status::Fail;
    } else if (n && double(r.warn_pixels) / double(n) > t.warn_percent / 100.0) {
        r.status = DiffResult::Status::Warn;
    }
    return r;
}

DiffResult diff_files(const std::string& a, const std::string& b,
                      const DiffThresholds& t) {
    Image ia, ib;
    try {
        ia = read_image(a);
        ib = read_image(b);
    } catch (const ImageIoError& e) {
        DiffResult r;
        r.status = DiffResult::Status::Unreadable;
        r.error = e.what();
        return r;
    }
    return diff_images(ia, ib, t);
}

Image difference_image(const Image& a, const Image& b) {
    Image d(a.width, a.height);
    if (a.width != b.width || a.height != b.height) return d;
    for (size_t i = 0; i < d.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c)
            d.rgba[i + c] = std::fabs(a.rgba[i + c] - b.rgba[i + c]);
        d.rgba[i + 3] = 1.0f;
    }
    return d;
}

Image difference_heatmap(const Image& a, const Image& b, double full_scale) {
    Image heat(a.width, a.height);
    if (a.width != b.width || a.height != b.height) return heat;
    // Equally spaced stops: a difference of a third of full scale is pure blue, two
    // thirds yellow, full scale red.
    static constexpr float kStops[4][3] = {{0, 0, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 0}};
    for (size_t i = 0; i < heat.rgba.size(); i += 4) {
        float largest = 0;
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, std::fabs(a.rgba[i + c] - b.rgba[i + c]));
        const float t = float(std::clamp(largest / full_scale, 0.0, 1.0)) * 3.0f;
        const int stop = std::min(int(t), 2);
        const float f = t - float(stop);
        for (int c = 0; c < 3; ++c)
            heat.rgba[i + c] =
                kStops[stop][c] + f * (kStops[stop + 1][c] - kStops[stop][c]);
        heat.rgba[i + 3] = 1.0f;
    }
    return heat;
}

Image block_means(const Image& image, int block) {
    if (block <= 1) return image;
    const int w = (image.width + block - 1) / block,
              h = (image.height + block - 1) / block;
    Image out(w, h);
    for (int by = 0; by < h; ++by) {
        for (int bx = 0; bx < w; ++bx) {
            double sum[4] = {0, 0, 0, 0};
            int n = 0;
            for (int y = by * block; y < std::min(image.height, (by + 1) * block); ++y) {
                for (int x = bx * block; x < std::min(image.width, (bx + 1) * block);
                     ++x) {
                    const float* p = image.pixel(x, y);
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                    ++n;
                }
            }
            float* o = out.pixel(bx, by);
            for (int c = 0; c < 4; ++c) o[c] = float(sum[c] / n);
        }
    }
    return out;
}

}  // namespace povwall::output
