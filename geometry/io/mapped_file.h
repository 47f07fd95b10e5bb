// A file's bytes mapped into memory for a reader's lifetime: the binary STL and glTF readers take
// what they need from the page cache in place, where reading the file into an array would copy it
// and fault in as many fresh pages (on this project's 2-core machine about 2.5 µs each).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace geometry::io {

class MappedFile {
public:
    /// Maps the first `size` bytes of `path` privately; with `writable`, writes change this
    /// process's copy only (the pages written become its own). Throws std::runtime_error naming the
    /// file where it cannot be opened or mapped. A size of 0 maps nothing.
    MappedFile(const std::string& path, uint64_t size, bool writable = false);
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile();
    [[nodiscard]] const unsigned char* data() const noexcept { return data_; }
    [[nodiscard]] unsigned char* writableData() noexcept { return data_; } // only when mapped writable
    [[nodiscard]] size_t size() const noexcept { return size_; }
    [[nodiscard]] std::span<const unsigned char> bytes() const noexcept { return {data_, size_}; }
    /// Drops the whole pages within [from, to) from memory: read once, they would otherwise count
    /// as resident until the file is unmapped (the size of the file on top of a load's peak).
    static void release(const void* from, const void* to) noexcept;

private:
    unsigned char* data_ = nullptr;
    size_t size_ = 0;
};

} // namespace geometry::io
