#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/diff_report.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/parse_args.h"
#include "output/diff.h"
#include "output/image_io.h"

namespace povwall::cli {

nlohmann::json diff_json(const output::DiffResult& r) {
    nlohmann::json j;
    j["rmse"] = r.rmse;
    j["psnr"] = std::isinf(r.psnr) ? nlohmann::json("inf") : nlohmann::json(r.psnr);
    j["max_abs"] = r.max_abs;
    j["bad_pixel_fraction"] = r.bad_pixel_fraction;
    j["width"] = r.width;
    j["height"] = r.height;
    j["bad_pixels"] = r.bad_pixels;
    j["max_at"] = {r.max_x, r.max_y, r.max_channel};
    static const char* kStatus[] = {"pass", "warn", "fail", "size_mismatch",
                                    "unreadable"};
    j["status"] = kStatus[int(r.status)];
    return j;
}

void print_diff(const output::DiffResult& r, const std::string& note) {
    if (r.status == output::DiffResult::Status::Unreadable ||
        r.status == output::DiffResult::Status::SizeMismatch) {
        std::printf("%s\nFAILURE\n", r.error.c_str());
        return;
    }
    std::printf("rmse: %.6f\n", r.rmse);
    if (std::isinf(r.psnr))
        std::printf("psnr: inf\n");
    else
        std::printf("psnr: %.2f dB\n", r.psnr);
    static const char kChan[] = "RGB";
    std::printf("max_abs: %.6f @ (%d, %d, %c) %.6f vs %.6f\n", r.max_abs, r.max_x,
                r.max_y, kChan[r.max_channel], r.max_value_a, r.max_value_b);
    std::printf("bad_pixel_fraction: %.6f (%lld of %lld pixels)\n", r.bad_pixel_fraction,
                r.bad_pixels, (long long)r.width * r.height);
    if (!note.empty()) std::printf("%s\n", note.c_str());
    static const char* kWord[] = {"PASS", "WARNING", "FAILURE", "FAILURE", "FAILURE"};
    std::printf("%s\n", kWord[int(r.status)]);
}

int run_diff(int argc, char** argv) {
    CLI::App app{
        "Compare two images as stored (0..1 scale): RMSE, PSNR, max error, bad pixels",
        "povwall diff"};
    std::string a, b, diff_out;
    bool json = false;
    double fail_percent = -1;
    output::DiffThresholds t;
    app.add_option("A", a, "first image")->required();
    app.add_option("B", b, "second image")->required();
    app.add_flag("--json", json, "print one JSON object");
    app.add_option(
        "-o,--output", diff_out,
        "write the per-channel absolute difference image (same size images only)");
    app.add_option("--fail", t.fail, "per-channel difference making a pixel bad")
        ->capture_default_str();
    app.add_option("--warn", t.warn, "per-channel difference giving a warning")
        ->capture_default_str();
    app.add_option("--failpercent", fail_percent,
                   "% of pixels allowed over --fail (same as --max-bad-fraction x 100)");
    app.add_option("--warnpercent", t.warn_percent, "% of pixels allowed over --warn")
        ->capture_default_str();
    app.add_option("--max-rmse", t.max_rmse, "largest RMSE that passes")
        ->capture_default_str();
    app.add_option("--max-bad-fraction", t.max_bad_fraction,
                   "largest fraction of bad pixels that passes")
        ->capture_default_str();
    if (auto done = parse_args(app, argc, argv)) return *done;
    if (fail_percent >= 0) t.max_bad_fraction = fail_percent / 100.0;
    output::DiffResult r;
    Image ia, ib;
    try {
        ia = output::read_image(a);
        ib = output::read_image(b);
        r = output::diff_images(ia, ib, t);
    } catch (const output::ImageIoError& e) {
        r.status = output::DiffResult::Status::Unreadable;
        r.error = e.what();
    }
    if (!diff_out.empty() && (r.status == output::DiffResult::Status::Pass ||
                              r.status == output::DiffResult::Status::Warn ||
                              r.status == output::DiffResult::Status::Fail)) {
        OutputEncoding raw;  // differences are written as values, not as colours
        raw.gamma_handling = false;
        output::write_image(output::difference_image(ia, ib), diff_out, raw);
    }
    if (json) {
        std::printf("%s\n", diff_json(r).dump().c_str());
    } else {
        print_diff(r, "");
    }
    return exit_code(r.status);
}

}  // namespace povwall::cli
