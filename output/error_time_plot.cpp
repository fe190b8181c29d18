#include "output/error_time_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "output/html_report.h"

namespace povwall::output {
namespace {

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

}  // namespace

std::vector<size_t> pareto_front(const std::vector<PlotPoint>& points) {
    std::vector<size_t> order(points.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].seconds != points[b].seconds)
            return points[a].seconds < points[b].seconds;
        return points[a].rmse < points[b].rmse;
    });
    // Scanning by time: a point is on the front when it is more accurate than every
    // faster one.
    std::vector<size_t> front;
    double best = INFINITY;
    for (size_t i : order) {
        if (points[i].rmse < best) {
            front.push_back(i);
            best = points[i].rmse;
        }
    }
    return front;
}

std::string error_time_svg(const std::vector<PlotPoint>& points, const std::string& title,
                           double rmse_floor) {
    const double W = 760, H = 480, left = 70, right = 230, top = 40, bottom = 50;
    const double pw = W - left - right, ph = H - top - bottom;
    double tmax = 0;
    for (const auto& p : points) tmax = std::max(tmax, p.seconds);
    tmax = tmax > 0 ? tmax * 1.08 : 1;
    double lo = std::log10(rmse_floor), hi = lo + 1;
    for (const auto& p : points)
        hi = std::max(hi, std::log10(std::max(p.rmse, rmse_floor)));
    hi = std::ceil(hi + 0.05);
    auto X = [&](double s) { return left + pw * s / tmax; };
    auto Y = [&](double e) {
        return top + ph * (1 - (std::log10(std::max(e, rmse_floor)) - lo) / (hi - lo));
    };
    std::ostringstream o;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"22\" font-size=\"14\">" << html_escape(title)
      << "</text>\n";
    // Axes, decades of rmse, five time ticks.
    o << "<g stroke=\"#888\" fill=\"none\"><rect x=\"" << left << "\" y=\"" << top
      << "\" width=\"" << pw << "\" height=\"" << ph << "\"/></g>\n";
    for (int d = int(lo); d <= int(hi); ++d) {
        const double y = Y(std::pow(10.0, d));
        o << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << y
          << "\" y2=\"" << y << "\" stroke=\"#eee\"/><text x=\"" << left - 6 << "\" y=\""
          << y + 4 << "\" text-anchor=\"end\">" << (d == int(lo) ? "\u2264" : "") << "1e"
          << d << "</text>\n";
    }
    for (int i = 0; i <= 5; ++i) {
        const double s = tmax * i / 5, x = X(s);
        o << "<text x=\"" << x << "\" y=\"" << top + ph + 16
          << "\" text-anchor=\"middle\">" << fmt("%.2f", s) << "</text>\n";
    }
    o << "<text x=\"" << left + pw / 2 << "\" y=\"" << H - 12
      << "\" text-anchor=\"middle\">wall seconds (median)</text>\n"
      << "<text transform=\"translate(16," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">rmse against the reference</text>\n";
    const std::vector<size_t> front = pareto_front(points);
    o << "<polyline class=\"pareto\" fill=\"none\" stroke=\"#2a7\" stroke-width=\"1.5\" "
         "points=\"";
    for (size_t i : front) o << X(points[i].seconds) << "," << Y(points[i].rmse) << " ";
    o << "\"/>\n";
    // Each point carries its number; the key on the right names the settings (names
    // beside the points would overlap where settings have nearly equal time and error).
    // A number moves right while it would overlap one already placed.
    std::vector<std::pair<double, double>> placed;
    auto number_x = [&](double x, double y) {
        double nx = x + 6;
        for (int tries = 0; tries < 6; ++tries) {
            const bool hit =
                std::any_of(placed.begin(), placed.end(), [&](const auto& q) {
                    return std::fabs(q.first - nx) < 13 && std::fabs(q.second - y) < 11;
                });
            if (!hit) break;
            nx += 13;
        }
        placed.emplace_back(nx, y);
        return nx;
    };
    for (size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& p = points[i];
        const double x = X(p.seconds), y = Y(p.rmse);
        const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
        if (p.reference_renderer) {
            o << "<rect class=\"povray\" x=\"" << x - 5 << "\" y=\"" << y - 5
              << "\" width=\"10\" height=\"10\" fill=\"#d33\"/>\n";
        } else {
            o << "<circle class=\"povwall" << (on_front ? " pareto-point" : "")
              << "\" cx=\"" << x << "\" cy=\"" << y << "\" r=\"4\" fill=\""
              << (on_front ? "#2a7" : "#36c") << "\"/>\n";
        }
        o << "<text x=\"" << number_x(x, y) << "\" y=\"" << y - 4
          << "\" font-size=\"10\" fill=\"#444\">" << i + 1 << "</text>\n";
    }
    // Legend.
    const double lx = left + pw + 16;
    o << "<circle cx=\"" << lx << "\" cy=\"" << top + 10
      << "\" r=\"4\" fill=\"#36c\"/><text x=\"" << lx + 10 << "\" y=\"" << top + 14
      << "\">povwall setting</text>\n"
      << "<circle cx=\"" << lx << "\" cy=\"" << top + 28
      << "\" r=\"4\" fill=\"#2a7\"/><text x=\"" << lx + 10 << "\" y=\"" << top + 32
      << "\">on the Pareto front</text>\n"
      << "<rect x=\"" << lx - 5 << "\" y=\"" << top + 41
      << "\" width=\"10\" height=\"10\" fill=\"#d33\"/><text x=\"" << lx + 10 << "\" y=\""
      << top + 50 << "\">POV-Ray 3.7</text>\n";
    for (size_t i = 0; i < points.size(); ++i) {
        o << "<text x=\"" << lx - 5 << "\" y=\"" << top + 80 + 14 * double(i) << "\">"
          << i + 1 << "  " << html_escape(points[i].label) << "</text>\n";
    }
    o << "</svg>\n";
    return o.str();
}

}  // namespace povwall::output
