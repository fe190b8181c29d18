// A self-contained HTML page holding one table (inline CSS, images by relative path, no
// network): the corpus report's page, kept free of what its rows mean.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace povwall::output {

struct HtmlWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// `text` with & < > " ' replaced by entities: safe in element text and quoted attributes.
std::string html_escape(std::string_view text);

struct HtmlCell {
    std::string text;   // shown escaped (below the image when there is one)
    std::string image;  // relative path of an image shown as a thumbnail linking to it
    std::string link;   // relative path the text links to ("" none)
    std::string css_class;  // class of the <td> ("num" right-aligns)
};

struct HtmlRow {
    std::string css_class;  // class of the <tr>
    std::vector<HtmlCell> cells;
};

struct HtmlReport {
    std::string title;
    std::vector<std::string> summary;  // paragraphs above the table, escaped
    std::vector<std::string> columns;
    std::vector<HtmlRow> rows;
    std::string css;  // added to the built-in stylesheet (row classes, ...)
};

// The page. A script at its end records, once the window has loaded, the number of images
// that loaded (complete, naturalWidth > 0) in <body data-images-loaded> and the number of
// table rows in <body data-rows>, so a headless browser can check the page.
std::string html_report_text(const HtmlReport& report);

// Writes the page to `path` through a temporary file in the same folder and a rename: a
// failed write leaves no file. Throws HtmlWriteError.
void write_html_report(const HtmlReport& report, const std::string& path);

}  // namespace povwall::output
