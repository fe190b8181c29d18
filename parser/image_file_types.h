// The image file types POV-Ray 3.7 names before a file (image_map, bump_map,
// height_field), and the extension each appends to a name that has none.
#pragma once

namespace povwall::parser {

struct ImageFileType {
    const char* keyword;
    const char* extension;
};
inline constexpr ImageFileType kImageFileTypes[] = {
    {"png", ".png"},  {"tga", ".tga"},  {"ppm", ".ppm"}, {"pgm", ".pgm"}, {"gif", ".gif"},
    {"jpeg", ".jpg"}, {"tiff", ".tif"}, {"bmp", ".bmp"}, {"exr", ".exr"}, {"hdr", ".hdr"},
    {"iff", ".iff"},  {"sys", ""},      {"pot", ".pot"}};

}  // namespace povwall::parser
