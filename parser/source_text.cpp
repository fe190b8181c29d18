// SourceText: a source file's bytes, owned or mapped from the page cache.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

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
    const bool regular = S_ISREG(st.st_mode);
    if (regular && size_t(st.st_size) >= kMapFromBytes) {
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
    // Sized once from the file's size, one byte over so that the read meeting the end
    // needs no growth (a pipe's buffer doubles as it comes).
    const size_t first = regular ? size_t(st.st_size) + 1 : 65536;
    owned_.reserve(first);
    advise_huge_pages(owned_.data(), first);
    owned_.resize(first);
    size_t used = 0;
    bool ok = true;
    for (;;) {
        if (used == owned_.size()) owned_.resize(2 * owned_.size());
        const ssize_t got = ::read(fd, owned_.data() + used, owned_.size() - used);
        if (got > 0) {
            used += size_t(got);
            continue;
        }
        if (got < 0 && errno == EINTR) continue;
        ok = got == 0;
        break;
    }
    close(fd);
    owned_.resize(used);
    return ok;
}

}  // namespace povwall::parser
