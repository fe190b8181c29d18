// Error against run time as an SVG scatter plot: one point per render setting, the Pareto
// front (no other point is both faster and more accurate) joined by a line, reference
// renderers' points drawn apart. Written for `povwall sweep`.
#pragma once

#include <string>
#include <vector>

namespace povwall::output {

struct PlotPoint {
    std::string label;
    double seconds = 0;
    double rmse = 0;
    bool reference_renderer = false;  // POV-Ray's own point: a red square, not a dot
};

// Indices of the points on the Pareto front of (seconds, rmse), fastest first.
std::vector<size_t> pareto_front(const std::vector<PlotPoint>& points);

// The SVG document. rmse is drawn on a log scale; values below `rmse_floor` sit on the
// floor line (an exact match has rmse 0).
std::string error_time_svg(const std::vector<PlotPoint>& points, const std::string& title,
                           double rmse_floor = 1e-5);

}  // namespace povwall::output
