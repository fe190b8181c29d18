// image_map pigments and bump_map normals, as POV-Ray 3.7 maps a 2-D image onto 3-D
// pattern space (planar, spherical, cylindrical, torus), samples it (none, bilinear,
// bicubic, normalised distance) and turns three samples into a bumped normal.
#include <algorithm>
#include <cmath>

#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

constexpr Real kPi = 3.14159265358979323846;
constexpr Real kTinyOffset = 1.0e-10;  // POV-Ray's EPSILON, added before wrapping

// v modulo `limit`, in [0, limit).
Real wrap(Real v, Real limit) {
    Real r = std::fmod(v, limit);
    if (r < 0) r += limit;
    return r >= limit ? 0.0 : r;
}

// Angle of (x, z) from +x towards +z, as a fraction of a turn in [0, 1).
Real turn_fraction(Real x, Real z) {
    Real theta;
    if (z == 0.0) {
        theta = x > 0 ? 0.0 : kPi;
    } else {
        theta = std::acos(x / std::sqrt(x * x + z * z));
        if (z < 0.0) theta = 2 * kPi - theta;
    }
    return theta / (2 * kPi);
}

// Pattern-space point -> image coordinates in pixels (x right, y down), or false when
// the point is off the image (once, or no direction to map).
bool image_coordinates(const ImageMapping& m, const Point3& p, Real& u, Real& v) {
    const int iw = m.pixels->width, ih = m.pixels->height;
    u = 0;
    v = 0;
    switch (m.map_type) {
        case 1: {  // spherical: longitude -> u, latitude -> v
            Real len = length(p);
            if (len == 0.0) return false;
            Point3 q = p / len;
            Real phi = 0.5 + std::asin(q.y) / kPi;
            Real ring = std::sqrt(q.x * q.x + q.z * q.z);
            Real theta = ring == 0.0 ? 0.0 : turn_fraction(q.x, q.z);
            u = theta * m.width;
            v = phi * m.height;
            break;
        }
        case 2: {  // cylindrical around y: angle -> u, height -> v
            if (m.once && (p.y < 0.0 || p.y > 1.0)) return false;
            v = std::fmod(p.y * m.height, m.height);
            Real len = length(p);
            if (len == 0.0) return false;
            Real x = p.x / len, z = p.z / len;
            if (std::sqrt(x * x + z * z) == 0.0) return false;
            u = turn_fraction(x, z) * m.width;
            break;
        }
        case 5: {  // torus (major radius 1) round y: angle round y -> u, round the tube
                   // -> v
            Real ring = std::sqrt(p.x * p.x + p.z * p.z);
            if (ring == 0.0) return false;
            Real theta = -turn_fraction(p.x, p.z) * 2 * kPi;
            Real x = ring - 1.0;
            Real phi = std::acos(-x / std::sqrt(x * x + p.y * p.y));
            if (p.y > 0.0) phi = 2 * kPi - phi;
            u = -theta / (2 * kPi) * m.width;
            v = phi / (2 * kPi) * m.height;
            break;
        }
        default:  // planar: the unit square of the xy plane
            if (m.once && (p.x < 0.0 || p.x > 1.0)) return false;
            u = std::fmod(p.x * m.width, m.width);
            if (m.once && (p.y < 0.0 || p.y > 1.0)) return false;
            v = std::fmod(p.y * m.height, m.height);
            break;
    }
    u += m.offset_u + kTinyOffset;
    v += m.offset_v + kTinyOffset;
    if (m.once && (u >= iw || v >= ih || u < 0.0 || v < 0.0)) return false;
    u = wrap(u, Real(iw));
    v = wrap(-v, Real(ih));  // image rows run top to bottom
    return true;
}

// The pixel at image coordinates (x, y), wrapping or clamping them.
void pixel_at(const ImageMapping& m, Real x, Real y, int& ix, int& iy) {
    const ImagePixels& img = *m.pixels;
    if (m.once) {
        ix = x < 0.0 ? 0 : (x >= img.width ? img.width - 1 : int(x));
        iy = y < 0.0 ? 0 : (y >= img.height ? img.height - 1 : int(y));
    } else {
        ix = std::min(int(wrap(x, Real(img.width))), img.width - 1);
        iy = std::min(int(wrap(y, Real(img.height))), img.height - 1);
    }
}

// One pixel (rgbft, with filter/transmit all added); `index`, when asked for: its
// palette index, -1 for an image without (POV-Ray's).
void pixel(const ImageMapping& m, Real x, Real y, double out[5], int* index = nullptr) {
    const ImagePixels& img = *m.pixels;
    int ix, iy;
    pixel_at(m, x, y, ix, iy);
    float c[5];
    img.fetch(ix, iy, c);
    for (int i = 0; i < 5; ++i) out[i] = c[i];
    out[3] += m.all_filter;
    out[4] += m.all_transmit;
    if (index)
        *index = img.indices.empty()
                     ? -1
                     : int(img.indices[size_t(iy) * size_t(img.width) + size_t(ix)]);
}

// Catmull-Rom weights of the four pixels around fraction p.
void cubic_weights(Real x, Real w[4]) {
    Real p = x - Real(int(x)), q = 1 - p;
    w[0] = -0.5 * p * q * q;
    w[1] = 0.5 * q * (q * (3 * p + 1) + 1);
    w[2] = 0.5 * p * (p * (3 * q + 1) + 1);
    w[3] = -0.5 * q * p * p;
}

// The image's colour at (x, y) in pixels, interpolated as `interpolate` asks. With
// `index_sum`: the pixels' palette indices (-1 without a palette) weighted as their
// colours, which POV-Ray's material_map truncates to the texture's number.
Colour sample(const ImageMapping& m, Real x, Real y, double* index_sum = nullptr) {
    double acc[5] = {0, 0, 0, 0, 0};
    int index = -1;
    int* want_index = index_sum ? &index : nullptr;
    if (index_sum) *index_sum = 0;
    if (m.interpolate != 2 && m.interpolate != 3 && m.interpolate != 4) {
        pixel(m, x, y, acc, want_index);
        if (index_sum) *index_sum = index;
    } else if (m.interpolate == 3) {
        x += 0.5;
        y += 0.5;
        int ix = int(x), iy = int(y);
        Real wx[4], wy[4];
        cubic_weights(x, wx);
        cubic_weights(y, wy);
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                double c[5];
                pixel(m, Real(ix + i - 2), Real(iy + j - 2), c, want_index);
                for (int k = 0; k < 5; ++k) acc[k] += c[k] * wx[i] * wy[j];
                if (index_sum) *index_sum += index * (wx[i] * wy[j]);
            }
        }
    } else {
        // The four pixels whose centres surround the point, weighted bilinearly (2) or by
        // inverse squared distance to each centre (4).
        x += 0.5;
        y += 0.5;
        int ix = int(x), iy = int(y);
        Real p = x - ix, q = y - iy;
        Real w[4];
        if (m.interpolate == 2) {
            w[0] = p * q;
            w[1] = (1 - p) * q;
            w[2] = p * (1 - q);
            w[3] = (1 - p) * (1 - q);
        } else {
            Real d[4] = {(1 - p) * (1 - p) + (1 - q) * (1 - q), p * p + (1 - q) * (1 - q),
                         (1 - p) * (1 - p) + q * q, p * p + q * q};
            Real sum = 0;
            for (int i = 0; i < 4; ++i) {
                w[i] = d[i] == 0.0 ? 1e300 : 1.0 / d[i];
                sum += w[i];
            }
            for (Real& wi : w) wi /= sum;
        }
        const Real corners[4][2] = {{Real(ix), Real(iy)},
                                    {Real(ix) - 1, Real(iy)},
                                    {Real(ix), Real(iy) - 1},
                                    {Real(ix) - 1, Real(iy) - 1}};
        for (int i = 0; i < 4; ++i) {
            double c[5];
            pixel(m, corners[i][0], corners[i][1], c, want_index);
            for (int k = 0; k < 5; ++k) acc[k] += c[k] * w[i];
            if (index_sum) *index_sum += index * w[i];
        }
    }
    return Colour{Rgb{float(acc[0]), float(acc[1]), float(acc[2])}, float(acc[3]),
                  float(acc[4])};
}

}  // namespace

Colour image_map_colour(const ImageMapping& m, const Point3& p, bool* on_image) {
    Real x, y;
    // Off the image: clear (white, fully transmitting), as POV-Ray returns.
    if (!m.pixels || !image_coordinates(m, p, x, y)) {
        if (on_image) *on_image = false;
        return Colour{Rgb{1.0f}, 0.0f, 1.0f};
    }
    Colour c = sample(m, x, y);
    if (m.premultiplied) {
        const float alpha = 1.0f - c.transmit;
        if (alpha > 1e-10f)
            c.rgb = Rgb{c.rgb.r / alpha, c.rgb.g / alpha, c.rgb.b / alpha};
    }
    return c;
}

void bump_map_normal(const ImageMapping& m, Real amount, const Point3& p, Vector3& n) {
    Real x, y;
    if (!m.pixels || !image_coordinates(m, p, x, y)) return;
    const Real iw = m.pixels->width, ih = m.pixels->height;
    auto rewrap = [](Real v, Real limit) {
        return v < 0.0 ? v + limit : (v >= limit ? v - limit : v);
    };
    // A palette image's index itself is the height with use_index (not scaled to 0..1:
    // POV-Ray's bump_map); otherwise the colour's grey.
    const bool indices = m.use_index && !m.pixels->indices.empty();
    auto height = [&](Real hx, Real hy) -> Real {
        if (!indices) return sample(m, hx, hy).rgb.grey();
        int ix, iy;
        pixel_at(m, hx, hy, ix, iy);
        return m.pixels->indices[size_t(iy) * size_t(m.pixels->width) + size_t(ix)];
    };
    // Heights here, one pixel left-down and one right-down (image rows grow downwards).
    Real h1 = height(x, y);
    x = rewrap(x - 1, iw);
    y = rewrap(y + 1, ih);
    Real h2 = height(x, y);
    x = rewrap(x + 2, iw);
    Real h3 = height(x, y);
    // The normal of the triangle through the three height samples...
    Vector3 p1{0, amount * h1, 0}, p2{-1, amount * h2, 1}, p3{1, amount * h3, 1};
    Vector3 bump = normalize(cross(p3 - p2, p1 - p2));
    // ...expressed in a frame whose y is the surface normal.
    Vector3 yprime = n;
    Vector3 xprime = cross(yprime, Vector3{0, 1, 0});
    Real len = length(xprime);
    if (len < kTinyOffset) {
        yprime =
            std::fabs(n.y - 1.0) < kTinyOffset ? Vector3{0, 1, 0} : Vector3{0, -1, 0};
        xprime = Vector3{1, 0, 0};
        len = 1.0;
    }
    xprime = xprime / len;
    Vector3 zprime = normalize(cross(xprime, yprime));
    n = xprime * bump.x + yprime * bump.y - zprime * bump.z;
}

}  // namespace povwall::trace::detail

namespace povwall::trace::detail {

Real image_pattern_value(const ImageMapping& m, const Point3& p) {
    Real x, y;
    if (!m.pixels || !image_coordinates(m, p, x, y)) return 0;
    const Colour c = sample(m, x, y);
    const Real v = m.image_value == 1   ? c.transmit
                   : m.image_value == 2 ? c.rgb.r
                                        : c.rgb.grey();
    return std::clamp(v, 0.0, 1.0);
}

int material_map_index(const ImageMapping& m, const Point3& p, int count) {
    Real x, y;
    if (count <= 0 || !m.pixels || !image_coordinates(m, p, x, y)) return 0;
    // The (interpolated) palette index, truncated; none (-1: an image without a palette,
    // or corners' weights that sum to exactly 1) takes red * 255. Interpolated weights
    // that sum to a hair under 1 give 0, as POV-Ray's.
    double index_sum;
    const Colour c = sample(m, x, y, &index_sum);
    const int index = int(index_sum);
    int n = index == -1 ? int(double(c.rgb.r) * 255.0) : index;
    // POV-Ray wraps only numbers above the count; the count itself (and anything the
    // list runs out before) takes the last texture.
    if (n > count) n %= count;
    return std::clamp(n, 0, count - 1);
}

}  // namespace povwall::trace::detail
