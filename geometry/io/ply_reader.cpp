// PLY reader (ply_reader.h). The file is read into memory whole (freed before cleanup, whose peak
// is far larger), its header parsed into elements and properties, and its body walked record by
// record: binary with memcpy and a byte swap where the file's order is not the machine's, ASCII
// with std::from_chars, one record a line.
//
// Every count the header claims is checked against the bytes after end_header (each record's
// smallest size) and the memory available (mesh_limits.h) before anything is reserved by it; a
// list's count is checked against the bytes or the values left before it is used.
//
// Index
//   [SECTION] Types ...................... Type, typeOf, sizeOf, isInteger, load, loadNumber, loadInteger,
//                                          toFloat
//   [SECTION] Header ..................... Property, Element, Header, HeaderLines, tokenize, parseProperty,
//                                          parseHeaderLine, readHeader
//   [SECTION] Roles ...................... uniqueElement, findProperty, assignRoles
//   [SECTION] Counts ..................... minRecordBytes, checkCounts, facesToReserve, checkListCount
//   [SECTION] Mesh ....................... MeshSink
//   [SECTION] Binary body ................ BinaryBody
//   [SECTION] ASCII body ................. AsciiBody
//   [SECTION] Reading .................... readFile, readBody, read, readPly
#include "geometry/io/ply_reader.h"

#include "geometry/io/mesh_limits.h"
#include "geometry/io/polygon_triangulation.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace geometry::io::detail {

namespace {
// A unity build may put this file in one translation unit with openmesh_io.cpp, whose helpers
// have the same short names (fail, tokenize, kMaxFaceValence).
namespace ply {

// One face's corners at most (as for OFF).
constexpr uint64_t kMaxFaceValence = 1'000'000;
// Where end_header must have come: a PLY header is a few lines of text.
constexpr size_t kMaxHeaderBytes = 1 << 20;

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw std::runtime_error(path + ": " + problem);
}

/// A name or a token for a message: quoted, cut short, printable ASCII.
std::string shown(std::string_view s) {
    constexpr size_t kShown = 32;
    std::string out(s.substr(0, kShown));
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
    return "'" + out + (s.size() > kShown ? "...'" : "'");
}

// ---- [SECTION] Types ------------------------------------------------------------------------

enum class Type : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// The type a header names (the spec's names and their sized aliases); false for any other word.
bool typeOf(std::string_view name, Type& type) {
    static constexpr std::pair<std::string_view, Type> kNames[] = {
        {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
        {"short", Type::Int16},   {"int16", Type::Int16},     {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
        {"int", Type::Int32},     {"int32", Type::Int32},     {"uint", Type::UInt32},    {"uint32", Type::UInt32},
        {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
    for (const auto& [n, t] : kNames) {
        if (n != name) continue;
        type = t;
        return true;
    }
    return false;
}

constexpr size_t sizeOf(Type t) {
    switch (t) {
    case Type::Int8:
    case Type::UInt8: return 1;
    case Type::Int16:
    case Type::UInt16: return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32: return 4;
    case Type::Float64: return 8;
    }
    return 0;
}

constexpr bool isInteger(Type t) { return t != Type::Float32 && t != Type::Float64; }

/// The T stored at `p` (records are not aligned), byte-swapped when the file's order is not the machine's.
template <class T> T load(const char* p, bool swap) {
    using Bits = std::conditional_t<
        sizeof(T) == 1, uint8_t,
        std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;
    Bits b;
    std::memcpy(&b, p, sizeof b);
    if constexpr (sizeof(T) == 2) b = swap ? __builtin_bswap16(b) : b;
    if constexpr (sizeof(T) == 4) b = swap ? __builtin_bswap32(b) : b;
    if constexpr (sizeof(T) == 8) b = swap ? __builtin_bswap64(b) : b;
    return std::bit_cast<T>(b);
}

double loadNumber(const char* p, Type t, bool swap) {
    switch (t) {
    case Type::Int8: return load<int8_t>(p, swap);
    case Type::UInt8: return load<uint8_t>(p, swap);
    case Type::Int16: return load<int16_t>(p, swap);
    case Type::UInt16: return load<uint16_t>(p, swap);
    case Type::Int32: return load<int32_t>(p, swap);
    case Type::UInt32: return load<uint32_t>(p, swap);
    case Type::Float32: return load<float>(p, swap);
    case Type::Float64: return load<double>(p, swap);
    }
    return 0;
}

/// An integer property's value: list counts (integer types by the header's check) and indices.
/// Every integer type fits a double exactly; float types are refused by the header.
int64_t loadInteger(const char* p, Type t, bool swap) {
    return t == Type::Float32 || t == Type::Float64 ? 0 : static_cast<int64_t>(loadNumber(p, t, swap));
}

/// A coordinate as float: beyond float's range it becomes ±inf, which cleanup drops as it drops NaN.
float toFloat(double d) {
    constexpr double kMax = std::numeric_limits<float>::max();
    if (d > kMax) return std::numeric_limits<float>::infinity();
    if (d < -kMax) return -std::numeric_limits<float>::infinity();
    return static_cast<float>(d); // NaN stays NaN
}

// ---- [SECTION] Header -----------------------------------------------------------------------

/// What a property is to the mesh: a coordinate, the face's corners, or nothing (walked over).
enum class Role : uint8_t { None, X, Y, Z, Indices };
enum class Kind : uint8_t { Other, Vertex, Face };

struct Property {
    std::string name;
    Type type = Type::Float32; // a scalar's type, or a list's item type
    bool list = false;
    Type countType = Type::UInt8; // a list's count
    Role role = Role::None;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> props;
    Kind kind = Kind::Other;
};

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct Header {
    std::optional<Format> format;
    std::vector<Element> elements;
    size_t bodyStart = 0; // right after end_header's line end
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// The header's lines, within its first kMaxHeaderBytes. They end as the magic line does: LF
/// (CRLF's CR is then space) or CR alone (classic Mac OS), so that a binary body starts right
/// after end_header's line end, whatever its first byte.
class HeaderLines {
public:
    HeaderLines(const std::string& path, std::string_view data)
        : path_(path), text_(data.substr(0, kMaxHeaderBytes)), whole_(data.size() <= kMaxHeaderBytes) {
        const size_t first = text_.find_first_of("\r\n");
        if (first != std::string_view::npos && text_[first] == '\r' &&
            (first + 1 == text_.size() || text_[first + 1] != '\n'))
            eol_ = '\r';
    }

    /// The next line, without its end; false after the last.
    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) return false;
        size_t end = text_.find(eol_, pos_);
        if (end == std::string_view::npos) {
            if (!whole_) fail(path_, "PLY header has no end_header in its first 1 MiB (corrupt file)");
            end = text_.size();
        }
        line = text_.substr(pos_, end - pos_);
        pos_ = std::min(end + 1, text_.size());
        for (const char c : line) {
            const auto u = static_cast<unsigned char>(c);
            if ((u < 0x20 && !isSpace(c)) || u > 0x7e) fail(path_, "PLY header is not plain text (corrupt file)");
        }
        return true;
    }
    /// Where the line after the last one read starts.
    [[nodiscard]] size_t position() const { return pos_; }

private:
    const std::string& path_;
    std::string_view text_;
    bool whole_;
    char eol_ = '\n';
    size_t pos_ = 0;
};

void tokenize(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
}

/// "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME".
Property parseProperty(const std::string& path, const std::vector<std::string_view>& tok) {
    Property p;
    p.list = tok.size() >= 2 && tok[1] == "list";
    if (tok.size() != (p.list ? 5u : 3u))
        fail(path,
             "bad PLY property line (expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME')");
    p.name = tok.back();
    const std::string_view type = tok[p.list ? 3 : 1];
    if (!typeOf(type, p.type)) fail(path, "unknown PLY property type " + shown(type));
    if (p.list && (!typeOf(tok[2], p.countType) || !isInteger(p.countType)))
        fail(path, "bad PLY list count type " + shown(tok[2]) + " (expected an integer type)");
    return p;
}

/// A header line other than a comment and end_header: the format, an element, or a property of the last element.
void parseHeaderLine(const std::string& path, const std::vector<std::string_view>& tok, Header& header) {
    if (tok[0] == "format") {
        if (header.format) fail(path, "PLY header has two format lines");
        const std::string_view name = tok.size() == 3 && tok[2] == "1.0" ? tok[1] : "";
        if (name == "ascii") header.format = Format::Ascii;
        else if (name == "binary_little_endian") header.format = Format::BinaryLittleEndian;
        else if (name == "binary_big_endian") header.format = Format::BinaryBigEndian;
        else fail(path, "bad PLY format line (expected 'format ascii|binary_little_endian|binary_big_endian 1.0')");
    } else if (tok[0] == "element") {
        uint64_t n = 0;
        const std::string_view count = tok.size() == 3 ? tok[2] : "";
        const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
        if (count.empty() || ec != std::errc() || end != count.data() + count.size())
            fail(path, "bad PLY element line (expected 'element NAME COUNT')");
        header.elements.push_back({std::string(tok[1]), n, {}, Kind::Other});
    } else if (tok[0] == "property") {
        if (header.elements.empty()) fail(path, "PLY property line before any element line");
        header.elements.back().props.push_back(parseProperty(path, tok));
    } else {
        fail(path, "unexpected line in PLY header starting " + shown(tok[0]) + " (corrupt file)");
    }
}

Header readHeader(const std::string& path, std::string_view data) {
    HeaderLines lines(path, data);
    std::string_view line;
    std::vector<std::string_view> tok;
    if (!data.starts_with("ply") || !lines.next(line) || (tokenize(line, tok), tok.size() != 1 || tok[0] != "ply"))
        fail(path, "missing 'ply' magic (not a PLY file)");
    Header header;
    for (;;) {
        if (!lines.next(line)) fail(path, "PLY header has no end_header (truncated file)");
        tokenize(line, tok);
        if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
        if (tok[0] == "end_header" && tok.size() == 1) break;
        parseHeaderLine(path, tok, header);
    }
    if (!header.format) fail(path, "PLY header has no format line");
    header.bodyStart = lines.position();
    return header;
}

// ---- [SECTION] Roles ------------------------------------------------------------------------

Element* uniqueElement(const std::string& path, Header& header, std::string_view name) {
    Element* found = nullptr;
    for (Element& e : header.elements) {
        if (e.name != name) continue;
        if (found) fail(path, "PLY header has two '" + std::string(name) + "' elements");
        found = &e;
    }
    return found;
}

Property* findProperty(Element& e, std::string_view name) {
    for (Property& p : e.props)
        if (p.name == name) return &p;
    return nullptr;
}

/// Marks what the mesh is read from (the vertex element's x, y, z, the face element's index
/// list); refuses a header without them. A file without a face element is points only, which
/// loadModel refuses as having no triangles.
void assignRoles(const std::string& path, Header& header) {
    Element* vertex = uniqueElement(path, header, "vertex");
    if (!vertex) fail(path, "PLY header has no 'vertex' element");
    vertex->kind = Kind::Vertex;
    for (const auto& [name, role] : {std::pair{"x", Role::X}, std::pair{"y", Role::Y}, std::pair{"z", Role::Z}}) {
        Property* p = findProperty(*vertex, name);
        if (!p) fail(path, std::string("PLY element 'vertex' has no property '") + name + "'");
        if (p->list) fail(path, std::string("PLY property '") + name + "' of element 'vertex' is a list, not a number");
        p->role = role;
    }
    Element* face = uniqueElement(path, header, "face");
    if (!face) return;
    face->kind = Kind::Face;
    Property* corners = findProperty(*face, "vertex_indices");
    if (!corners) corners = findProperty(*face, "vertex_index");
    if (!corners) fail(path, "PLY element 'face' has no 'vertex_indices' list");
    if (!corners->list || !isInteger(corners->type))
        fail(path, "PLY property '" + corners->name + "' of element 'face' is not a list of integers");
    corners->role = Role::Indices;
}

// ---- [SECTION] Counts -----------------------------------------------------------------------

/// The smallest record of `e`: binary, its scalars and list counts (a list may be empty); ASCII,
/// a value and a separator for each property (a list: its count).
uint64_t minRecordBytes(const Element& e, bool ascii) {
    uint64_t n = 0;
    for (const Property& p : e.props) n += ascii ? 2 : sizeOf(p.list ? p.countType : p.type);
    return n;
}

/// Refuses counts over 32-bit indices, records that cannot fit in the `bodyBytes` after
/// end_header, and meshes that cannot fit in memory: before anything is allocated by a count.
void checkCounts(const std::string& path, const Header& header, uint64_t bodyBytes) {
    uint64_t vertices = 0, faces = 0;
    for (const Element& e : header.elements) {
        if (e.count > kMaxIndexed)
            fail(path, "PLY element " + shown(e.name) + " count " + std::to_string(e.count) +
                           " is over the 2^32 - 1 that 32-bit indices reach");
        if (e.kind == Kind::Vertex) vertices = e.count;
        if (e.kind == Kind::Face) faces = e.count;
    }
    const bool ascii = header.format == Format::Ascii;
    const uint64_t slack = ascii ? 1 : 0; // the last ASCII value needs no separator after it
    uint64_t minBytes = 0;
    for (const Element& e : header.elements) {
        // Under 2^32 records of under 2^23 bytes (8 a property line of a 1 MiB header), added to at
        // most bodyBytes: no overflow.
        // A record of no properties counts as one byte, so that no count goes unbounded.
        minBytes += std::max<uint64_t>(minRecordBytes(e, ascii), 1) * e.count;
        if (minBytes > bodyBytes + slack)
            fail(path, "PLY element " + shown(e.name) + " claims " + std::to_string(e.count) +
                           " records: with the elements before it at least " + std::to_string(minBytes - slack) +
                           " bytes, which cannot fit in the " + std::to_string(bodyBytes) +
                           " bytes after end_header (truncated or corrupt file)");
    }
    // Faces may be polygons: at least one triangle each, so the estimate is a floor.
    if (const std::string problem = meshMemoryProblem(vertices, faces, availableMemory()); !problem.empty())
        fail(path, "PLY header claims " + problem);
}

/// The faces to reserve room for: the face element's count, but no more triangles than its
/// bytes could hold (a hostile header may claim empty lists).
uint64_t facesToReserve(const Header& header, uint64_t bodyBytes) {
    const bool ascii = header.format == Format::Ascii;
    for (const Element& e : header.elements) {
        if (e.kind != Kind::Face) continue;
        uint64_t cornerBytes = 0;
        for (const Property& p : e.props)
            if (p.role == Role::Indices) cornerBytes = 3 * (ascii ? 2 : sizeOf(p.type));
        return std::min(e.count, bodyBytes / (minRecordBytes(e, ascii) + cornerBytes));
    }
    return 0;
}

/// A list's count as read: refused when negative, or over kMaxFaceValence for a face's corners.
uint64_t checkListCount(const std::string& path, const Element& e, const Property& p, uint64_t record, int64_t n) {
    if (n < 0)
        fail(path, "PLY element " + shown(e.name) + " record " + std::to_string(record) + " has a negative count (" +
                       std::to_string(n) + ") for list " + shown(p.name) + " (corrupt file)");
    if (p.role == Role::Indices && static_cast<uint64_t>(n) > kMaxFaceValence)
        fail(path, "face " + std::to_string(record) + " lists " + std::to_string(n) + " vertex indices, over the " +
                       std::to_string(kMaxFaceValence) + " a face may have (corrupt file)");
    return static_cast<uint64_t>(n);
}

// ---- [SECTION] Mesh -------------------------------------------------------------------------

/// The mesh as the body is read: positions in order; faces range-checked, then triangulated.
/// A face with an index out of range is counted and skipped, and the read fails at the end
/// naming the first. A face of fewer than three corners is dropped, as it was when OpenMesh read
/// PLY: it has no area, and a reader's counts reach the load report only for polygons.
class MeshSink {
public:
    MeshSink(uint64_t vertices, uint64_t faces) : vertexCount_(vertices) {
        mesh_.positions.reserve(vertices);
        mesh_.indices.reserve(3 * faces);
    }

    void addVertex(const glm::vec3& p) { mesh_.positions.push_back(p); }
    void beginFace() {
        corners_.clear();
        bad_ = false;
    }
    void corner(int64_t v) {
        if (v >= 0 && static_cast<uint64_t>(v) < vertexCount_) {
            corners_.push_back(static_cast<uint32_t>(v));
        } else if (!bad_) {
            bad_ = true;
            badIndex_ = v;
        }
    }
    /// Faces are read after every vertex (readBody), so the polygon sees its corners' positions.
    void endFace(uint64_t face) {
        if (bad_) {
            if (badFaces_++ == 0) {
                firstBadFace_ = face;
                firstBadIndex_ = badIndex_;
            }
            return;
        }
        if (corners_.size() >= 3) appendPolygon(mesh_.positions, corners_, mesh_.indices, stats_);
    }
    scene::Mesh finish(const std::string& path, CleanupReport& counts) {
        if (badFaces_ > 0)
            fail(path, "face " + std::to_string(firstBadFace_) + " references vertex " +
                           std::to_string(firstBadIndex_) + " but the file has only " + std::to_string(vertexCount_) +
                           " vertices (" + std::to_string(badFaces_) + " bad faces)");
        addPolygonCounts(stats_, counts);
        return std::move(mesh_);
    }

private:
    scene::Mesh mesh_;
    uint64_t vertexCount_;
    std::vector<uint32_t> corners_; // the current face's
    bool bad_ = false;
    int64_t badIndex_ = 0, firstBadIndex_ = 0;
    uint64_t badFaces_ = 0, firstBadFace_ = 0;
    PolygonStats stats_;
};

// ---- [SECTION] Binary body ------------------------------------------------------------------

/// The binary body, read in place.
class BinaryBody {
public:
    BinaryBody(const std::string& path, std::string_view body, bool swap)
        : path_(path), begin_(body.data()), p_(body.data()), end_(body.data() + body.size()), swap_(swap) {}

    [[nodiscard]] size_t position() const { return static_cast<size_t>(p_ - begin_); }
    void seek(size_t at) { p_ = begin_ + at; }

    /// Reads the records of `e` into `mesh` where it is the vertex or face element, else walks over them.
    void element(const Element& e, MeshSink* mesh) {
        if (e.props.empty()) return;
        MeshSink* sink = e.kind == Kind::Other ? nullptr : mesh;
        for (uint64_t r = 0; r < e.count; ++r) record(e, r, sink);
    }

private:
    void record(const Element& e, uint64_t r, MeshSink* mesh) {
        glm::vec3 v(0.f);
        if (mesh && e.kind == Kind::Face) mesh->beginFace();
        for (const Property& p : e.props) {
            if (p.list) list(e, p, r, mesh);
            else scalar(e, p, mesh ? &v : nullptr);
        }
        if (!mesh) return;
        if (e.kind == Kind::Vertex) mesh->addVertex(v);
        else mesh->endFace(r);
    }
    void need(const Element& e, uint64_t bytes) const {
        if (static_cast<uint64_t>(end_ - p_) < bytes) fail(path_, "truncated PLY body in element " + shown(e.name));
    }
    void scalar(const Element& e, const Property& p, glm::vec3* v) {
        const size_t n = sizeOf(p.type);
        need(e, n);
        if (v && p.role != Role::None) (*v)[int(p.role) - int(Role::X)] = toFloat(loadNumber(p_, p.type, swap_));
        p_ += n;
    }
    void list(const Element& e, const Property& p, uint64_t r, MeshSink* mesh) {
        need(e, sizeOf(p.countType));
        const int64_t n = loadInteger(p_, p.countType, swap_);
        p_ += sizeOf(p.countType);
        const uint64_t bytes = checkListCount(path_, e, p, r, n) * sizeOf(p.type); // below 2^32 · 8
        need(e, bytes);
        if (mesh && p.role == Role::Indices) corners(p.type, static_cast<uint64_t>(n), *mesh);
        p_ += bytes;
    }
    /// A face's corners: the item type chosen once a list, not once a value.
    template <class T> void cornersOf(uint64_t n, MeshSink& mesh) const {
        for (uint64_t j = 0; j < n; ++j) mesh.corner(static_cast<int64_t>(load<T>(p_ + j * sizeof(T), swap_)));
    }
    void corners(Type t, uint64_t n, MeshSink& mesh) const {
        switch (t) {
        case Type::Int8: return cornersOf<int8_t>(n, mesh);
        case Type::UInt8: return cornersOf<uint8_t>(n, mesh);
        case Type::Int16: return cornersOf<int16_t>(n, mesh);
        case Type::UInt16: return cornersOf<uint16_t>(n, mesh);
        case Type::Int32: return cornersOf<int32_t>(n, mesh);
        case Type::UInt32: return cornersOf<uint32_t>(n, mesh);
        default: return; // float types: refused by assignRoles
        }
    }

    const std::string& path_;
    const char* begin_;
    const char* p_;
    const char* end_;
    bool swap_;
};

// ---- [SECTION] ASCII body -------------------------------------------------------------------

/// The ASCII body: a record a line (LF, CRLF or CR alone; blank lines skipped), values separated
/// by spaces or tabs. Holding records to lines catches a stray or missing value where it is,
/// instead of shifting every later record by it.
class AsciiBody {
public:
    AsciiBody(const std::string& path, std::string_view body) : path_(path), text_(body) {}

    [[nodiscard]] size_t position() const { return pos_; }
    void seek(size_t at) { pos_ = at; }

    /// Reads the records of `e` into `mesh` where it is the vertex or face element, else walks over them.
    void element(const Element& e, MeshSink* mesh) {
        if (e.props.empty()) return; // nothing on its lines, if it has any
        MeshSink* sink = e.kind == Kind::Other ? nullptr : mesh;
        for (uint64_t r = 0; r < e.count; ++r) {
            if (!nextLine())
                fail(path_, "truncated PLY body in element " + shown(e.name) + " (" + std::to_string(r) + " of " +
                                std::to_string(e.count) + " records)");
            record(e, r, sink);
        }
    }

private:
    bool nextLine() {
        while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
        if (pos_ >= text_.size()) return false;
        size_t end = pos_;
        while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
        line_ = text_.substr(pos_, end - pos_);
        at_ = 0;
        pos_ = end;
        return true;
    }
    std::string_view token() {
        while (at_ < line_.size() && (line_[at_] == ' ' || line_[at_] == '\t')) ++at_;
        const size_t start = at_;
        while (at_ < line_.size() && line_[at_] != ' ' && line_[at_] != '\t') ++at_;
        return line_.substr(start, at_ - start);
    }
    [[nodiscard]] std::string where(const Element& e, uint64_t r) const {
        return "PLY element " + shown(e.name) + " record " + std::to_string(r);
    }
    /// The next value of record `r`, without a leading '+' (which from_chars refuses).
    std::string_view value(const Element& e, uint64_t r) {
        std::string_view t = token();
        if (t.empty()) fail(path_, where(e, r) + " has too few values (corrupt file)");
        if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
        return t;
    }

    void record(const Element& e, uint64_t r, MeshSink* mesh) {
        glm::vec3 v(0.f);
        if (mesh && e.kind == Kind::Face) mesh->beginFace();
        for (const Property& p : e.props) {
            if (p.list) list(e, p, r, mesh);
            else if (mesh && p.role != Role::None) v[int(p.role) - int(Role::X)] = coordinate(e, r, p.type);
            else (void)number(e, r);
        }
        if (!token().empty()) fail(path_, where(e, r) + " has more values than its properties (corrupt file)");
        if (!mesh) return;
        if (e.kind == Kind::Vertex) mesh->addVertex(v);
        else mesh->endFace(r);
    }
    void list(const Element& e, const Property& p, uint64_t r, MeshSink* mesh) {
        const uint64_t n = checkListCount(path_, e, p, r, integer(e, r));
        const bool corners = mesh && p.role == Role::Indices;
        for (uint64_t j = 0; j < n; ++j) { // a count beyond the line's values fails at the line's end
            if (corners) mesh->corner(integer(e, r));
            else (void)number(e, r);
        }
    }

    int64_t integer(const Element& e, uint64_t r) {
        const std::string_view t = value(e, r);
        int64_t v = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (ec != std::errc() || end != t.data() + t.size())
            fail(path_, where(e, r) + ": " + shown(t) + " is not an integer");
        return v;
    }
    /// A value walked over: any number will do, however large.
    double number(const Element& e, uint64_t r) {
        const std::string_view t = value(e, r);
        double d = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), d);
        if (ec == std::errc::invalid_argument || end != t.data() + t.size())
            fail(path_, where(e, r) + ": " + shown(t) + " is not a number");
        return d;
    }
    /// A float property read as float (no double rounding); a float's underflow or overflow, and
    /// every other type, through double.
    float coordinate(const Element& e, uint64_t r, Type type) {
        const std::string_view t = value(e, r);
        if (type == Type::Float32) {
            float f = 0;
            const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), f);
            if (ec == std::errc() && end == t.data() + t.size()) return f;
        }
        double d = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), d);
        if (ec == std::errc::invalid_argument || end != t.data() + t.size())
            fail(path_, where(e, r) + ": " + shown(t) + " is not a number");
        if (ec != std::errc()) fail(path_, where(e, r) + ": " + shown(t) + " is out of range");
        return toFloat(d);
    }

    const std::string& path_;
    std::string_view text_;
    size_t pos_ = 0;
    std::string_view line_; // the current record's
    size_t at_ = 0;         // in line_
};

// ---- [SECTION] Reading ----------------------------------------------------------------------

/// The whole file; `size` is its real size on disk.
std::string readFile(const std::string& path, uint64_t size) {
    std::string data(size, '\0');
    std::ifstream in(path, std::ios::binary);
    if (!in.read(data.data(), static_cast<std::streamsize>(size))) fail(path, "cannot read file");
    return data;
}

/// The elements in file order. A face element before the vertex element is walked over first
/// and read once the positions are in, as its polygons are triangulated on them.
template <class Body> void readBody(const Header& header, Body& body, MeshSink& mesh) {
    bool haveVertices = false;
    const Element* deferred = nullptr;
    size_t deferredAt = 0;
    for (const Element& e : header.elements) {
        if (e.kind == Kind::Face && !haveVertices) {
            deferred = &e;
            deferredAt = body.position();
            body.element(e, nullptr);
            continue;
        }
        body.element(e, &mesh);
        haveVertices = haveVertices || e.kind == Kind::Vertex;
    }
    if (!deferred) return;
    body.seek(deferredAt);
    body.element(*deferred, &mesh);
}

scene::Mesh read(const std::string& path, uint64_t size, CleanupReport& counts) {
    const std::string data = readFile(path, size);
    Header header = readHeader(path, data);
    assignRoles(path, header);
    const std::string_view body = std::string_view(data).substr(header.bodyStart);
    checkCounts(path, header, body.size());
    uint64_t vertices = 0;
    for (const Element& e : header.elements)
        if (e.kind == Kind::Vertex) vertices = e.count;
    MeshSink mesh(vertices, facesToReserve(header, body.size()));
    if (header.format == Format::Ascii) {
        AsciiBody ascii(path, body);
        readBody(header, ascii, mesh);
    } else {
        const bool big = header.format == Format::BinaryBigEndian;
        BinaryBody binary(path, body, big != (std::endian::native == std::endian::big));
        readBody(header, binary, mesh);
    }
    return mesh.finish(path, counts);
}

} // namespace ply
} // namespace

scene::Mesh readPly(const std::string& path, uint64_t size, CleanupReport& counts) {
    return ply::read(path, size, counts);
}

} // namespace geometry::io::detail
