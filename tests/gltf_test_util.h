#pragma once
// Fixture helpers shared by the glTF loader tests: aligned binary buffers, base64 data URIs, GLB
// containers, and a fixture that writes bytes, text and JSON documents into its temporary folder.
#include "geometry/io/gltf_loader.h"
#include "temp_dir_test_util.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace gltftest {

/// glTF accessor componentType codes.
inline constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;

using Bytes = std::vector<unsigned char>;

/// A binary buffer assembled piece by piece, each piece 4-byte aligned as glTF requires.
struct Bin {
    Bytes bytes;
    template <typename T> size_t add(const std::vector<T>& values) {
        while (bytes.size() % 4) bytes.push_back(0);
        const size_t offset = bytes.size();
        bytes.resize(offset + values.size() * sizeof(T));
        std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
        return offset;
    }
};

inline std::string base64(const Bytes& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        const uint32_t n = uint32_t(data[i]) << 16 | (i + 1 < data.size() ? uint32_t(data[i + 1]) << 8 : 0) |
                           (i + 2 < data.size() ? uint32_t(data[i + 2]) : 0);
        out += table[n >> 18 & 63];
        out += table[n >> 12 & 63];
        out += i + 1 < data.size() ? table[n >> 6 & 63] : '=';
        out += i + 2 < data.size() ? table[n & 63] : '=';
    }
    return out;
}

inline std::string dataUri(const Bytes& bin) { return "data:application/octet-stream;base64," + base64(bin); }

inline void putU32(Bytes& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

/// GLB 2.0 container: 12-byte header, JSON chunk, optional BIN chunk, both padded to 4 bytes.
inline Bytes makeGlb(std::string text, Bytes bin) {
    while (text.size() % 4) text += ' ';
    while (bin.size() % 4) bin.push_back(0);
    const size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    Bytes out;
    putU32(out, 0x46546C67); // "glTF"
    putU32(out, 2);
    putU32(out, uint32_t(total));
    putU32(out, uint32_t(text.size()));
    putU32(out, 0x4E4F534A); // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    if (!bin.empty()) {
        putU32(out, uint32_t(bin.size()));
        putU32(out, 0x004E4942); // "BIN\0"
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

/// Whether any of the load report's notes contains `text`.
inline bool hasNote(const geometry::io::LoadedModel& model, const std::string& text) {
    for (const auto& note : model.report.notes)
        if (note.find(text) != std::string::npos) return true;
    return false;
}

/// Loads `path` expecting loadGltf to throw (a failure is recorded if it loads); returns the message.
inline std::string loadFailure(const std::string& path) {
    try {
        (void)geometry::io::loadGltf(path);
        ADD_FAILURE() << path << " loaded without error";
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return {};
}

/// A test with its own temporary folder (PREFIX + pid + the test's name) to write glTF files into.
class GltfFileTest : public testutil::TempDirTest {
protected:
    using TempDirTest::TempDirTest;

    std::string writeBytes(const std::string& name, const Bytes& bytes) const {
        return write(name, std::string(bytes.begin(), bytes.end()));
    }
    std::string writeText(const std::string& name, const std::string& text) const { return write(name, text); }
    std::string writeDoc(const std::string& name, const nlohmann::json& doc) const { return write(name, doc.dump()); }
};

} // namespace gltftest
