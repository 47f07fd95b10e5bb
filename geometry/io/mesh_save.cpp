// saveMesh(): OBJ, OFF and PLY written here, STL binary. Every number is written so that reading
// it back gives the same float bit for bit: the shortest decimal that round-trips (std::to_chars)
// in OBJ and OFF, raw little-endian floats in PLY and STL. Every triangle is kept as it is,
// non-manifold ones too (CAD's daily bread), with no halfedge structure on the way.
#include "geometry/io/model_loader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace geometry::io {

namespace {

constexpr size_t kFlushBytes = 1 << 20; // written in blocks of about this size

/// Appends the shortest decimal text that reads back as exactly `value`.
void appendFloat(std::string& out, float value) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, ec == std::errc() ? end : buf); // 32 bytes always fit a float
}

void appendUint(std::string& out, uint64_t value) {
    char buf[24];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, ec == std::errc() ? end : buf);
}

/// An output file written in blocks, failing with the path named.
class BlockWriter {
public:
    explicit BlockWriter(const std::string& path) : path_(path), out_(path, std::ios::binary) {
        if (!out_) throw std::runtime_error(path + ": cannot write file");
        block_.reserve(kFlushBytes + 256);
    }
    std::string& block() noexcept { return block_; }
    /// Writes the block once it is full (or always, when `force`).
    void flush(bool force = false) {
        if (!force && block_.size() < kFlushBytes) return;
        out_.write(block_.data(), static_cast<std::streamsize>(block_.size()));
        block_.clear();
        if (!out_) throw std::runtime_error(path_ + ": cannot write file (disk full?)");
    }
    void finish() {
        flush(true);
        if (!out_.flush()) throw std::runtime_error(path_ + ": cannot write file (disk full?)");
    }

private:
    const std::string& path_;
    std::ofstream out_;
    std::string block_;
};

template <class T> void appendRaw(std::string& out, const T& value) { // little-endian, as x86-64 stores it
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// Text lines "PREFIX x y z", one per position.
void writePositionLines(BlockWriter& w, const scene::Mesh& mesh, const char* prefix) {
    std::string& b = w.block();
    for (const glm::vec3& p : mesh.positions) {
        b += prefix;
        appendFloat(b, p.x);
        b += ' ';
        appendFloat(b, p.y);
        b += ' ';
        appendFloat(b, p.z);
        b += '\n';
        w.flush();
    }
}

/// Text lines "PREFIX a b c", one per triangle, its indices counted from `first`.
void writeTriangleLines(BlockWriter& w, const scene::Mesh& mesh, const char* prefix, uint64_t first) {
    std::string& b = w.block();
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        b += prefix;
        for (int k = 0; k < 3; ++k) {
            b += ' ';
            appendUint(b, first + mesh.indices[3 * t + k]);
        }
        b += '\n';
        w.flush();
    }
}

void saveObj(const std::string& path, const scene::Mesh& mesh) {
    BlockWriter w(path);
    std::string& b = w.block();
    b += "# shadowscope mesh: ";
    appendUint(b, mesh.positions.size());
    b += " vertices, ";
    appendUint(b, mesh.triangleCount());
    b += " triangles\n";
    writePositionLines(w, mesh, "v ");
    writeTriangleLines(w, mesh, "f", 1); // OBJ counts from 1
    w.finish();
}

void saveOff(const std::string& path, const scene::Mesh& mesh) {
    BlockWriter w(path);
    std::string& b = w.block();
    b += "OFF\n";
    appendUint(b, mesh.positions.size());
    b += ' ';
    appendUint(b, mesh.triangleCount());
    b += " 0\n";
    writePositionLines(w, mesh, "");
    writeTriangleLines(w, mesh, "3", 0);
    w.finish();
}

/// Binary little-endian PLY: exact and a third of the text's size.
void savePly(const std::string& path, const scene::Mesh& mesh) {
    BlockWriter w(path);
    std::string& b = w.block();
    b += "ply\nformat binary_little_endian 1.0\ncomment shadowscope mesh\nelement vertex ";
    appendUint(b, mesh.positions.size());
    b += "\nproperty float x\nproperty float y\nproperty float z\nelement face ";
    appendUint(b, mesh.triangleCount());
    b += "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const glm::vec3& p : mesh.positions) {
        appendRaw(b, p);
        w.flush();
    }
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        b += char(3);
        for (int k = 0; k < 3; ++k) appendRaw(b, mesh.indices[3 * t + k]);
        w.flush();
    }
    w.finish();
}

/// Binary STL (compact, and what CAD tools exchange): every triangle with its corners, 50 bytes
/// each (50 M-triangle test files are written this way).
void saveBinaryStl(const std::string& path, const scene::Mesh& mesh) {
    const size_t tris = mesh.triangleCount();
    if (tris > UINT32_MAX) throw std::runtime_error(path + ": more than 2^32 - 1 triangles do not fit a binary STL");
    BlockWriter w(path);
    std::string& b = w.block();
    std::string header(80, ' ');
    header.replace(0, 22, "shadowscope binary STL");
    b += header;
    appendRaw(b, static_cast<uint32_t>(tris));
    for (size_t t = 0; t < tris; ++t) {
        const uint32_t* v = &mesh.indices[3 * t];
        const glm::vec3 &a = mesh.positions[v[0]], &p1 = mesh.positions[v[1]], &p2 = mesh.positions[v[2]];
        const glm::vec3 cross = glm::cross(p1 - a, p2 - a);
        const float len = glm::length(cross);
        appendRaw(b, len > 0.f && std::isfinite(len) ? cross / len : glm::vec3(0.f));
        appendRaw(b, a);
        appendRaw(b, p1);
        appendRaw(b, p2);
        appendRaw(b, uint16_t(0)); // attribute byte count
        w.flush();
    }
    w.finish();
}

} // namespace

void saveMesh(const std::string& path, const scene::Mesh& mesh) {
    const std::string ext = modelFormat(path);
    if (ext != "obj" && ext != "stl" && ext != "off" && ext != "ply")
        throw std::runtime_error(path + ": cannot save '." + ext + "' (supported: .obj, .stl, .off, .ply)");
    for (uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) throw std::runtime_error(path + ": mesh has an index out of range");
    if (ext == "stl") return saveBinaryStl(path, mesh);
    if (ext == "obj") return saveObj(path, mesh);
    if (ext == "off") return saveOff(path, mesh);
    savePly(path, mesh);
}

} // namespace geometry::io
