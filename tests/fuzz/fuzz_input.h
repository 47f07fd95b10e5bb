#pragma once
// libFuzzer targets hand the loaders a real file: the loaders take paths, as the tool does.
#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace fuzz {

/// Writes data to a per-process temporary file with the given extension; returns its path.
inline std::string writeTemp(const uint8_t* data, size_t size, const std::string& extension) {
    const std::string path = "/tmp/shadowscope_fuzz_" + std::to_string(getpid()) + extension;
    if (FILE* f = std::fopen(path.c_str(), "wb")) {
        if (size) std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
    return path;
}

} // namespace fuzz
