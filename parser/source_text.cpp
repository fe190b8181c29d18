// SourceText: a source file's bytes, owned or mapped from the page cache.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

#include "parser/source.h"

namespace povwall::parser {

namespace {

// Files from this size on are mapped. Smaller ones are copied: a copy costs little, and
// a copy cannot change under the parser.
constexpr size_t kMapFromBytes = size_t(16) << 20;

}  // namespace

SourceText& SourceText::operator=(SourceText&& other) noexcept {
    if (this == &other) return *this;
    if (mapped_) munmap(const_cast<char*>(mapped_), mapped_size_);
    owned_ = std::move(other.owned_);
    mapped_ = other.mapped_;
    mapped_size_ = other.mapped_size_;
    other.mapped_ = nullptr;
    other.mapped_size_ = 0;
    return *this;
}

SourceText::~SourceText() {
    if (mapped_) munmap(const_cast<char*>(mapped_), mapped_size_);
}

bool SourceText::read_file(const std::string& path) {
    *this = SourceText();
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    struct stat st {};
    if (fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
        close(fd);
        return false;
    }
    if (S_ISREG(st.st_mode) && size_t(st.st_size) >= kMapFromBytes) {
        // MAP_POPULATE maps the cached pages in one call instead of a fault per page.
        void* p = mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE,
                       fd, 0);
        if (p != MAP_FAILED) {
            close(fd);
            mapped_ = static_cast<const char*>(p);
            mapped_size_ = size_t(st.st_size);
            return true;
        }
    }
    close(fd);
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    if (S_ISREG(st.st_mode)) {
        // Sized once and read in one go: a stringstream grows by doubling and copies
        // again.
        owned_.resize(size_t(st.st_size));
        in.read(owned_.data(), st.st_size);
        owned_.resize(size_t(in.gcount()));
        return !in.bad();
    }
    // Not a regular file (a pipe): read it as it comes.
    owned_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

}  // namespace povwall::parser
