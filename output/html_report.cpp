#include "output/html_report.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace povwall::output {
namespace {

namespace fs = std::filesystem;

const char* kStyle = R"(body { font: 14px sans-serif; margin: 1em; color: #222; }
h1 { font-size: 1.4em; }
table { border-collapse: collapse; }
th, td { border: 1px solid #ccc; padding: 3px 6px; vertical-align: middle; }
th { background: #eee; position: sticky; top: 0; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td img { display: block; width: 160px; image-rendering: pixelated; }
.summary p { margin: 0.2em 0; }
)";

// Counts what loaded once everything has had its chance to (the load event fires after
// every image has loaded or failed).
const char* kCheckScript = R"(<script>
window.addEventListener('load', function () {
  var loaded = 0;
  for (var i = 0; i < document.images.length; ++i) {
    var img = document.images[i];
    if (img.complete && img.naturalWidth > 0) ++loaded;
  }
  document.body.dataset.imagesLoaded = String(loaded);
  document.body.dataset.rows = String(document.querySelectorAll('tbody tr').length);
});
</script>
)";

void write_cell(std::ostringstream& out, const HtmlCell& cell) {
    out << "<td";
    if (!cell.css_class.empty())
        out << " class=\"" << html_escape(cell.css_class) << "\"";
    out << ">";
    if (!cell.image.empty()) {
        const std::string src = html_escape(cell.image);
        out << "<a href=\"" << src << "\"><img src=\"" << src << "\" alt=\""
            << html_escape(cell.text) << "\"></a>";
    }
    if (!cell.text.empty() && cell.image.empty()) {
        if (!cell.link.empty())
            out << "<a href=\"" << html_escape(cell.link) << "\">"
                << html_escape(cell.text) << "</a>";
        else
            out << html_escape(cell.text);
    }
    out << "</td>";
}

}  // namespace

std::string html_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string html_report_text(const HtmlReport& report) {
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta "
           "charset=\"utf-8\">\n<title>"
        << html_escape(report.title) << "</title>\n<style>\n"
        << kStyle << report.css << "</style>\n</head>\n<body>\n<h1>"
        << html_escape(report.title) << "</h1>\n<div class=\"summary\">\n";
    for (const std::string& line : report.summary)
        out << "<p>" << html_escape(line) << "</p>\n";
    out << "</div>\n<table>\n<thead><tr>";
    for (const std::string& c : report.columns)
        out << "<th>" << html_escape(c) << "</th>";
    out << "</tr></thead>\n<tbody>\n";
    for (const HtmlRow& row : report.rows) {
        out << "<tr";
        if (!row.css_class.empty())
            out << " class=\"" << html_escape(row.css_class) << "\"";
        out << ">";
        for (const HtmlCell& cell : row.cells) write_cell(out, cell);
        out << "</tr>\n";
    }
    out << "</tbody>\n</table>\n" << kCheckScript << "</body>\n</html>\n";
    return out.str();
}

void write_html_report(const HtmlReport& report, const std::string& path) {
    const fs::path target(path);
    const fs::path tmp = target.parent_path() / ("." + target.filename().string() +
                                                 ".tmp" + std::to_string(getpid()));
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << html_report_text(report);
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(tmp, ignored);
            throw HtmlWriteError("cannot write '" + tmp.string() + "'");
        }
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw HtmlWriteError("cannot write '" + path + "': " + ec.message());
    }
}

}  // namespace povwall::output
