// density_file df3 "name": POV-Ray 3.7's voxel files (its Read_Density_File). A 6-byte
// header of three big-endian 16-bit sizes, then the voxels, x fastest, as big-endian
// 8, 16 or 32 bit values; the width is the one whose size makes up the rest of the file
// exactly (32 bit tried first, as POV-Ray does). The file is found like an image: the
// name, then with ".df3" and ".DF3", in the scene's and the library folders.
#include "parser/density_files.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "parser/image_file_types.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

namespace fs = std::filesystem;

constexpr ImageFileType kDf3{"df3", {".df3", ".DF3", "", ""}};

uint32_t big_endian(const unsigned char* p, int bytes) {
    uint32_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
    return v;
}

}  // namespace

DensityFile decode_df3(std::string_view bytes) {
    if (bytes.size() < 6) throw std::runtime_error("Error reading density_file");
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    DensityFile f;
    f.size_x = big_endian(data, 2);
    f.size_y = big_endian(data + 2, 2);
    f.size_z = big_endian(data + 4, 2);
    const uint64_t count = uint64_t(f.size_x) * f.size_y * f.size_z;
    const uint64_t length = bytes.size() - 6;
    if (count * 4 == length)
        f.bytes_per_voxel = 4;
    else if (count * 2 == length)
        f.bytes_per_voxel = 2;
    else if (count == length)
        f.bytes_per_voxel = 1;
    else
        throw std::runtime_error("Invalid density file size");
    f.voxels.resize(count);
    for (uint64_t i = 0; i < count; ++i)
        f.voxels[i] =
            big_endian(data + 6 + i * uint64_t(f.bytes_per_voxel), f.bytes_per_voxel);
    return f;
}

std::shared_ptr<const DensityFile> Interpreter::parse_density_file() {
    const Token df3 = next();
    if (!is_word(df3, "df3")) expected("df3", df3);
    const Token name_token = peek();
    const std::string name = parse_string();
    std::string path;
    for (const std::string& candidate : image_file_candidates(name, kDf3)) {
        path = resolve_include(candidate, frames_.back().file, false);
        if (!path.empty()) break;
    }
    if (path.empty())
        error(name_token, "Cannot read media density file \"" + name + "\" (not found)");
    // One read per file and version: a scene may #write the file before naming it.
    std::error_code ec;
    const auto written = fs::last_write_time(path, ec).time_since_epoch().count();
    const std::string key = path + '\n' + std::to_string(written);
    if (auto it = density_files_.find(key); it != density_files_.end()) return it->second;
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)),
                      std::istreambuf_iterator<char>());
    if (!in && !in.eof())
        error(name_token, "Cannot read media density file \"" + path + "\"");
    std::shared_ptr<DensityFile> file;
    try {
        file = std::make_shared<DensityFile>(decode_df3(bytes));
    } catch (const std::runtime_error& e) {
        error(name_token, std::string(e.what()) + " \"" + path + "\"");
    }
    file->path = path;
    image_files_.push_back(path);
    density_files_.emplace(key, file);
    return file;
}

}  // namespace povwall::parser
