// Image comparison in the manner of OpenImageIO's idiff.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace povwall::output {

struct DiffThresholds {
    double fail = 0.1;  // a channel differing by more than this makes a pixel "bad"
    double warn =
        0.1;  // pixels over this (but within the allowed fraction) give a warning
    double warn_percent = 0.0;  // % of pixels allowed over `warn` before warning (idiff)
    // Failure: rmse above max_rmse or a bad-pixel fraction above max_bad_fraction
    // (povwall's golden thresholds by default).
    double max_rmse = 0.01;
    double max_bad_fraction = 0.002;  // idiff's -failpercent, as a fraction
};

struct DiffResult {
    int width = 0, height = 0;
    double rmse = 0, psnr = 0, max_abs = 0;
    int max_x = 0, max_y = 0, max_channel = 0;
    double max_value_a = 0, max_value_b = 0;
    long long bad_pixels = 0, warn_pixels = 0;
    double bad_pixel_fraction = 0;
    enum class Status {
        Pass = 0,
        Warn = 1,
        Fail = 2,
        SizeMismatch = 3,
        Unreadable = 4
    } status = Status::Pass;
    std::string error;  // for Unreadable / SizeMismatch
};

// Compares RGB channels of two images as stored (0..1 scale). `skip` (one entry per
// pixel, row-major): pixels left out of every statistic and of the decision (the rmse
// and fractions are then over the other pixels).
DiffResult diff_images(const Image& a, const Image& b, const DiffThresholds& t = {},
                       const std::vector<uint8_t>* skip = nullptr);
// The pixels (row-major indices) with a channel differing by more than `fail`: the bad
// pixels of diff_images.
std::vector<size_t> bad_pixel_indices(const Image& a, const Image& b, double fail);
DiffResult diff_files(const std::string& a, const std::string& b,
                      const DiffThresholds& t = {});

// The means of `block` x `block` pixel squares (the last row and column of squares may
// be narrower): stochastic renders (crand, jitter) are compared by these, where POV-Ray's
// own random numbers make no two renders alike pixel for pixel.
Image block_means(const Image& image, int block);

// |a - b| per RGB channel (alpha 1), for looking at where two same-sized images differ.
Image difference_image(const Image& a, const Image& b);

// A heatmap of where two same-sized images differ: each pixel's largest RGB channel
// difference on a colour ramp black (equal) -> blue -> yellow -> red (at `full_scale` and
// above; with the default, every bad pixel of DiffThresholds{} is red). Values are meant
// to be written raw (OutputEncoding::gamma_handling off).
Image difference_heatmap(const Image& a, const Image& b, double full_scale = 0.1);

}  // namespace povwall::output
