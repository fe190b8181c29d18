#include "parser/image_file_types.h"

#include <cctype>

namespace povwall::parser {
namespace {

bool equal_without_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    }
    return true;
}

}  // namespace

const ImageFileType* image_type_for_keyword(std::string_view word) {
    for (const ImageFileType& t : kImageFileTypes) {
        if (word == t.keyword) return &t;
    }
    return nullptr;
}

const ImageFileType* image_type_for_extension(std::string_view extension) {
    for (const ImageFileType& t : kImageFileTypes) {
        if (std::string_view(t.keyword) == "pot") continue;
        for (const char* e : t.extensions) {
            if (*e && equal_without_case(e, extension)) return &t;
        }
    }
    return nullptr;
}

const ImageFileType* image_type_for_output_letter(char letter) {
    switch (std::toupper(static_cast<unsigned char>(letter))) {
        case 'T':
        case 'C':
            return image_type_for_keyword("tga");
        case 'N':
            return image_type_for_keyword("png");
        case 'J':
            return image_type_for_keyword("jpeg");
        case 'P':
            return image_type_for_keyword("ppm");
        case 'B':
            return image_type_for_keyword("bmp");
        case 'E':
            return image_type_for_keyword("exr");
        case 'H':
            return image_type_for_keyword("hdr");
        case 'S':
            return image_type_for_keyword("sys");
        default:
            return nullptr;
    }
}

bool image_format_matches(const ImageFileType& type, std::string_view format) {
    const std::string_view k = type.keyword;
    if (k == "tga") return format == "targa";
    if (k == "ppm" || k == "pgm") return format == "pnm";
    if (k == "pot") return format == "gif";
    if (k == "exr") return format == "openexr";
    return format == k;
}

std::vector<std::string> image_file_candidates(const std::string& name,
                                               const ImageFileType& type) {
    bool exact_first = false;
    if (const size_t dot = name.find_last_of('.'); dot != std::string::npos) {
        for (const char* e : type.extensions)
            exact_first =
                exact_first || (*e && name.compare(dot, std::string::npos, e) == 0);
    }
    std::vector<std::string> names;
    if (exact_first) names.push_back(name);
    for (const char* e : type.extensions) {
        if (*e) names.push_back(name + e);
    }
    if (!exact_first) names.push_back(name);
    return names;
}

}  // namespace povwall::parser
