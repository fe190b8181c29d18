// The image file types POV-Ray 3.7 names before a file (image_map, bump_map,
// height_field), how a file's type follows from its name, and the names POV-Ray tries
// when it looks for the file (3.7:source/backend/support/fileutil.cpp, the extension
// table; backend/scene/scene.cpp, SceneData::FindFile).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace povwall::parser {

struct ImageFileType {
    const char* keyword;
    // The extensions POV-Ray appends when it looks for a file of this type, in its order
    // (empty: none). `sys` has none on Unix (its system format is not defined there).
    const char* extensions[4];
};
inline constexpr ImageFileType kImageFileTypes[] = {
    {"tga", {".tga", ".TGA", "", ""}},
    {"png", {".png", ".PNG", "", ""}},
    {"ppm", {".ppm", ".PPM", "", ""}},
    {"pgm", {".pgm", ".PGM", "", ""}},
    {"gif", {".gif", ".GIF", "", ""}},
    {"iff", {".iff", ".IFF", "", ""}},
    {"jpeg", {".jpg", ".JPG", ".jpeg", ".JPEG"}},
    {"tiff", {".tif", ".TIF", ".tiff", ".TIFF"}},
    {"bmp", {".bmp", ".BMP", "", ""}},
    {"exr", {".exr", ".EXR", "", ""}},
    {"hdr", {".hdr", ".HDR", "", ""}},
    {"sys", {"", "", "", ""}},
    // A GIF holding 16-bit heights (height_field only); POV-Ray looks for it as a GIF.
    {"pot", {".gif", ".GIF", "", ""}}};

// The type a keyword names; null when the word is none.
const ImageFileType* image_type_for_keyword(std::string_view word);

// The type POV-Ray infers from a file name's extension (compared without case; `pot`
// is never inferred); null when the extension names none.
const ImageFileType* image_type_for_extension(std::string_view extension);

// The type of a file named without type keyword and without extension: the output file
// type (POV-Ray's +F letter); null for a letter with no input type.
const ImageFileType* image_type_for_output_letter(char letter);

// The names POV-Ray tries for `name` of `type`, in order: the name itself first when it
// ends in one of the type's extensions (compared with case), then the name with each
// extension appended, then the name itself if not tried first.
std::vector<std::string> image_file_candidates(const std::string& name,
                                               const ImageFileType& type);

// Whether a file OpenImageIO reads as `format` ("png", "targa", "pnm", ...) is one
// POV-Ray's reader for `type` reads (POV-Ray picks the reader by the type, not by the
// file's content).
bool image_format_matches(const ImageFileType& type, std::string_view format);

}  // namespace povwall::parser
