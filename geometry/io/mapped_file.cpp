#include "geometry/io/mapped_file.h"

#include "geometry/scene/scratch_pages.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace geometry::io {

MappedFile::MappedFile(const std::string& path, uint64_t size, bool writable) : size_(size_t(size)) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error(path + ": cannot open file for reading: " + std::strerror(errno));
    if (size_ == 0) {
        ::close(fd);
        return;
    }
    void* p = ::mmap(nullptr, size_, PROT_READ | (writable ? PROT_WRITE : 0), MAP_PRIVATE, fd, 0);
    const int mapError = errno;
    ::close(fd);
    if (p == MAP_FAILED) throw std::runtime_error(path + ": cannot map the file: " + std::strerror(mapError));
    data_ = static_cast<unsigned char*>(p);
    ::madvise(p, size_, MADV_SEQUENTIAL);
}

MappedFile::~MappedFile() {
    if (data_ != nullptr) ::munmap(data_, size_);
}

void MappedFile::release(const void* from, const void* to) noexcept {
    if (to <= from) return;
    scene::scratch::dropPages(from, size_t(static_cast<const char*>(to) - static_cast<const char*>(from)));
}

} // namespace geometry::io
