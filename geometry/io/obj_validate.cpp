// OBJ pre-validation: one pass over the file, line by line, read the way OpenMesh 9's
// _OBJReader_ reads it (each line trimmed of " \t\r\n", empty and '#' lines skipped, the first
// token is the keyword; vertices in a first pass, faces in a second), so that what passes here
// is what OpenMesh will read. Stricter than OpenMesh where that is simpler to keep safe: every
// face corner and index must be well formed, where OpenMesh skips some garbage silently.
//
// Index
//   [SECTION] Tokens and messages ........ isBlank, trim, nextToken, quoted, shownIndex, plural
//   [SECTION] Numbers and face corners ... checkCoordinate, splitCorner
//   [SECTION] The validator .............. Elements, ObjValidator::line, lineTooLong, finish
//   [SECTION] Checks per line ............ checkText, vertex, texcoord, face, checkIndex, materialLibrary
//   [SECTION] Reading the file ........... scanObjFile, validateObjFile, readObjFile
#include "geometry/io/obj_validate.h"
#include "geometry/io/mesh_limits.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace geometry::io::detail {

namespace {

// OpenMesh removed repeated corners from each polygon in O(k²) time, and ear clipping is
// O(k²) too: one polygon, and all of them together, stay well under a second.
constexpr uint64_t kMaxCorners = 32'768;
constexpr uint64_t kMaxCornerPairs = uint64_t(1) << 30;
constexpr size_t kMaxLineBytes = size_t(1) << 20;
constexpr size_t kBlockBytes = size_t(1) << 20;
// OpenMesh reads every file an `mtllib` line names, once per line, whole.
constexpr uint64_t kMaxMaterialLibraries = 64;
constexpr uint64_t kMaxMaterialBytes = uint64_t(64) << 20; // all of them together

// ---- [SECTION] Tokens and messages ----------------------------------------------------------

/// Whitespace as OpenMesh's trimString and operator>> see it in text that passed checkText
/// (the other C whitespace, \v and \f, is refused there as control characters).
constexpr bool isBlank(char c) noexcept { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view s) noexcept {
    while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
    while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
    return s;
}

/// The next whitespace-separated token of `rest`, which moves past it; empty at the end.
std::string_view nextToken(std::string_view& rest) noexcept {
    size_t i = 0;
    while (i < rest.size() && isBlank(rest[i])) ++i;
    size_t j = i;
    while (j < rest.size() && !isBlank(rest[j])) ++j;
    const std::string_view token = rest.substr(i, j - i);
    rest.remove_prefix(j);
    return token;
}

/// A token for a message: quoted, cut short, and ASCII (it holds no control characters by
/// then; other bytes need not be valid UTF-8, which JSON reports could not hold).
std::string quoted(std::string_view token) {
    constexpr size_t kShown = 32;
    std::string shown(token.substr(0, kShown));
    std::replace_if(
        shown.begin(), shown.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; }, '?');
    return "'" + shown + (token.size() > kShown ? "...'" : "'");
}

/// An index that parsed as digits, for a message: as written, unless absurdly long.
std::string shownIndex(std::string_view token) {
    constexpr size_t kShown = 20;
    return std::string(token.substr(0, kShown)) + (token.size() > kShown ? "..." : "");
}

std::string plural(uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// ---- [SECTION] Numbers and face corners -----------------------------------------------------

enum class Number { Ok, NotANumber, NotFinite, OutOfRange };

/// A coordinate that OpenMesh's `stream >> float` reads whole and without failing. from_chars
/// takes the same decimal forms ([+-](d+[.d*] | .d+)[(e|E)[+-]d+], '+' aside) and also NaN and
/// Inf, which that read refuses, as it refuses values beyond float range. OpenMesh then drops
/// the vertex but still counts it for relative indices, so such vertices are refused here
/// rather than left to cleanup.
Number checkCoordinate(std::string_view s) noexcept {
    const bool plus = s.starts_with('+'); // from_chars takes no '+', and no "+-1" must pass either
    if (plus && (s.size() == 1 || s[1] == '-')) return Number::NotANumber;
    const char* first = s.data() + (plus ? 1 : 0);
    const char* last = s.data() + s.size();
    double value = 0;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::invalid_argument || end != last) return Number::NotANumber;
    if (ec == std::errc::result_out_of_range) return Number::OutOfRange;
    if (!std::isfinite(value)) return Number::NotFinite;
    return std::fabs(value) > FLT_MAX ? Number::OutOfRange : Number::Ok;
}

/// The value of a coordinate checkCoordinate() accepted (from_chars rounds as `>> float` does).
float coordinateValue(std::string_view s) noexcept {
    if (s.starts_with('+')) s.remove_prefix(1);
    float value = 0;
    std::from_chars(s.data(), s.data() + s.size(), value);
    return value;
}

/// Splits a face corner of the form "v", "v/vt", "v//vn" or "v/vt/vn"; false for any other.
bool splitCorner(std::string_view token, std::array<std::string_view, 3>& part) noexcept {
    part = {};
    for (size_t k = 0; k < 3; ++k) {
        const size_t slash = token.find('/');
        part[k] = token.substr(0, slash);
        if (slash == std::string_view::npos) return !part[0].empty() && !part[k].empty();
        token.remove_prefix(slash + 1);
    }
    return false; // a fourth component
}

// ---- [SECTION] The validator ----------------------------------------------------------------

/// Vertices, texture coordinates or normals: how many so far, and the largest positive index
/// a face used (checked at the end: OpenMesh reads all vertices before any face).
struct Elements {
    Elements(const char* index_, const char* one_, const char* many_) : index(index_), one(one_), many(many_) {}
    const char* index; // "face vertex index"
    const char* one;   // "vertex"
    const char* many;  // "vertices"
    uint64_t count = 0;
    uint64_t maxRef = 0; // UINT64_MAX: an index too large for int64, written as hugeRef
    uint64_t maxRefLine = 0;
    std::string hugeRef;
};

class ObjValidator {
public:
    /// `out`, when given, receives the vertices and faces as well.
    ObjValidator(const std::string& path, ObjPolygons* out) : path_(path), out_(out) {}

    void line(std::string_view raw) {
        ++line_;
        if (raw.size() > kMaxLineBytes) fail("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
        if (line_ == 1 && raw.starts_with("\xEF\xBB\xBF"))
            fail("starts with a UTF-8 byte order mark, which OpenMesh cannot read (save without BOM)");
        const std::string_view s = trim(raw);
        checkText(s);
        if (s.empty() || s[0] == '#') return;
        std::string_view rest = s;
        const std::string_view key = nextToken(rest);
        if (key == "v") vertex(rest);
        else if (key == "vt") texcoord(rest);
        else if (key == "vn") ++normals_.count; // OpenMesh counts every vn line for relative indices
        else if (key == "f") face(rest);
        else if (key == "mtllib") materialLibrary(trim(rest));
        // Everything else (vn data, g, o, s, usemtl, l, p, curves...) OpenMesh ignores.
    }

    /// Called when the current line grows past the limit before its end is even read.
    [[noreturn]] void lineTooLong() {
        ++line_;
        fail("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
    }

    void finish() const {
        for (const Elements* e : {&vertices_, &texcoords_, &normals_})
            if (e->maxRef > e->count)
                failAt(e->maxRefLine, std::string(e->index) + " " +
                                          (e->maxRef == UINT64_MAX ? e->hugeRef : std::to_string(e->maxRef)) +
                                          " out of range (" + plural(e->count, e->one, e->many) + ")");
    }

private:
    [[noreturn]] void failAt(uint64_t line, const std::string& problem) const {
        throw std::runtime_error(path_ + ": line " + std::to_string(line) + ": " + problem);
    }
    [[noreturn]] void fail(const std::string& problem) const { failAt(line_, problem); }

    /// The memory the vertices and triangles so far need (mesh_limits.h), checked every 2^20 of either:
    /// a text file has no header to check first.
    void checkMemory() const {
        if (const std::string problem = meshMemoryProblem(vertices_.count, triangles_, available_); !problem.empty())
            fail(problem + " (and the file goes on)");
    }

    // ---- [SECTION] Checks per line ----------------------------------------------------------

    /// No control characters but tab: NUL bytes or binary data would reach OpenMesh's string
    /// handling (a NUL cuts an `mtllib` name short), and a lone CR is no line ending it knows.
    void checkText(std::string_view s) const {
        unsigned bad = 0; // one branch-free (vectorizable) pass first: nearly every line is clean
        for (const char c : s) {
            const unsigned u = static_cast<unsigned char>(c);
            bad |=
                (static_cast<unsigned>(u < 0x20) & static_cast<unsigned>(u != '\t')) | static_cast<unsigned>(u == 0x7f);
        }
        if (bad == 0) return;
        for (const char c : s) {
            const auto u = static_cast<unsigned char>(c);
            if ((u >= 0x20 && u != 0x7f) || c == '\t') continue;
            if (c == '\0') fail("NUL byte (binary data, not OBJ text)");
            if (c == '\r') fail("carriage return inside a line (only LF or CRLF line endings are supported)");
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02x", u);
            fail(std::string("control character ") + hex + " (not OBJ text)");
        }
    }

    /// `what` names the line ("vertex"), `item` one of its numbers ("coordinate").
    void checkCoordinates(std::string_view rest, int needed, const char* what, const char* item) const {
        for (int k = 0; k < needed; ++k) {
            const std::string_view token = nextToken(rest);
            if (token.empty())
                fail(std::string(what) + " has " + plural(k, "number", "numbers") + ", needs " +
                     std::to_string(needed));
            switch (checkCoordinate(token)) {
            case Number::Ok: break;
            case Number::NotANumber: fail(std::string(what) + " " + item + " " + quoted(token) + " is not a number");
            case Number::NotFinite:
                fail(std::string(what) + " " + item + " " + quoted(token) +
                     " is not finite (OpenMesh cannot read NaN or Inf)");
            case Number::OutOfRange:
                fail(std::string(what) + " " + item + " " + quoted(token) + " is out of float range");
            }
        }
    }

    void vertex(std::string_view rest) {
        checkCoordinates(rest, 3, "vertex", "coordinate"); // a w or colour after x y z is ignored, as OpenMesh does
        if ((++vertices_.count & 0xfffff) == 0) checkMemory();
        if (!out_) return;
        glm::vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = coordinateValue(nextToken(rest));
        out_->positions.push_back(p);
    }

    /// OpenMesh fails the whole file on a vt line without two numbers (1D coordinates included).
    void texcoord(std::string_view rest) {
        checkCoordinates(rest, 2, "texture coordinate", "value");
        ++texcoords_.count;
    }

    void face(std::string_view rest) {
        uint64_t corners = 0;
        std::array<std::string_view, 3> part;
        for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest)) {
            if (++corners > kMaxCorners)
                fail("face has more than " + std::to_string(kMaxCorners) + " vertices, over the limit");
            if (token == "\\") fail("line continuation '\\' is not supported (join the face onto one line)");
            if (!splitCorner(token, part))
                fail("bad face vertex " + quoted(token) + " (expected v, v/vt, v//vn or v/vt/vn)");
            const int64_t v = checkIndex(part[0], vertices_);
            if (out_) out_->corners.push_back(static_cast<uint32_t>(v)); // in range: checked here or in finish()
            if (!part[1].empty()) checkIndex(part[1], texcoords_);
            if (!part[2].empty()) checkIndex(part[2], normals_);
        }
        if (corners < 3) fail("face has " + plural(corners, "vertex", "vertices") + ", needs at least 3");
        if (out_) out_->faceStarts.push_back(static_cast<uint32_t>(out_->corners.size()));
        const uint64_t before = triangles_;
        triangles_ += corners - 2;
        if ((before >> 20) != (triangles_ >> 20)) checkMemory();
        cornerPairs_ += corners * (corners - 1) / 2;
        if (cornerPairs_ > kMaxCornerPairs)
            fail("too many large polygons for OpenMesh's OBJ reader (its cost grows with the square of "
                 "polygon size); triangulate on export");
    }

    /// An index is an optional '-' and digits (what from_chars takes for an integer), never 0;
    /// a negative one counts back from the elements read so far, as in OpenMesh (its int
    /// arithmetic stays in range under our caps). Returns the 0-based index (a positive one
    /// past the current count is checked in finish()).
    int64_t checkIndex(std::string_view token, Elements& e) {
        int64_t value = 0;
        const char* last = token.data() + token.size();
        const auto [end, ec] = std::from_chars(token.data(), last, value);
        if (ec == std::errc::invalid_argument || end != last)
            fail(std::string("bad ") + e.index + " " + quoted(token) + " (not an integer)");
        const bool negative = token[0] == '-';
        const bool huge = ec == std::errc::result_out_of_range;
        if (value == 0 && !huge) fail(std::string(e.index) + " 0 (OBJ indices start at 1)");
        if (negative) {
            if (huge || value < -static_cast<int64_t>(e.count))
                fail(std::string(e.index) + " " + shownIndex(token) + " out of range (" +
                     plural(e.count, e.one, e.many) + " before this line)");
        } else if (huge ? e.maxRef != UINT64_MAX : static_cast<uint64_t>(value) > e.maxRef) {
            e.maxRef = huge ? UINT64_MAX : static_cast<uint64_t>(value);
            e.maxRefLine = line_;
            if (huge) e.hugeRef = shownIndex(token);
        }
        return negative ? static_cast<int64_t>(e.count) + value : value - 1;
    }

    /// OpenMesh opens "<folder of the OBJ>/<rest of the line>" and reads it whole, line by line,
    /// once per mtllib line. A missing file it skips; anything but a small regular file (a
    /// folder, /dev/zero, a FIFO, a procfs file, which reports size 0) could hang or exhaust it.
    void materialLibrary(std::string_view name) {
        if (name.empty()) fail("mtllib without a file name");
        if (++materialLibraries_ > kMaxMaterialLibraries)
            fail("more than " + std::to_string(kMaxMaterialLibraries) + " mtllib lines");
        const size_t slash = path_.rfind('/');
        const std::string folder = slash == std::string::npos ? "./" : path_.substr(0, slash + 1);
        const std::filesystem::path file = folder + std::string(name);
        std::error_code ec;
        const std::filesystem::file_status st = std::filesystem::status(file, ec);
        if (ec || !std::filesystem::exists(st)) return; // OpenMesh cannot open it either: no materials
        if (!std::filesystem::is_regular_file(st)) fail("material library " + quoted(name) + " is not a regular file");
        const uint64_t size = std::filesystem::file_size(file, ec);
        if (ec || size == 0) fail("material library " + quoted(name) + " is empty or not a plain file");
        materialBytes_ += size;
        if (materialBytes_ > kMaxMaterialBytes)
            fail("material libraries over " + std::to_string(kMaxMaterialBytes >> 20) + " MiB in total");
    }

    std::string path_;
    ObjPolygons* out_ = nullptr;
    uint64_t line_ = 0;
    Elements vertices_{"face vertex index", "vertex", "vertices"};
    Elements texcoords_{"face texture index", "texture coordinate", "texture coordinates"};
    Elements normals_{"face normal index", "normal", "normals"};
    uint64_t triangles_ = 0, cornerPairs_ = 0;
    uint64_t available_ = availableMemory(); // once per file
    uint64_t materialLibraries_ = 0, materialBytes_ = 0;
};

} // namespace

// ---- [SECTION] Reading the file -------------------------------------------------------------

namespace {

void scanObjFile(const std::string& path, ObjPolygons* out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open file for reading");
    ObjValidator validator(path, out);
    std::vector<char> block(kBlockBytes);
    std::string pending; // the start of a line that continues into the next block
    while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0) {
        std::string_view chunk(block.data(), static_cast<size_t>(in.gcount()));
        while (!chunk.empty()) {
            const size_t nl = chunk.find('\n');
            const size_t take = nl == std::string_view::npos ? chunk.size() : nl;
            if (pending.size() + take > kMaxLineBytes) validator.lineTooLong();
            if (nl == std::string_view::npos) {
                pending.append(chunk);
                break;
            }
            if (pending.empty()) {
                validator.line(chunk.substr(0, nl));
            } else {
                pending.append(chunk.substr(0, nl));
                validator.line(pending);
                pending.clear();
            }
            chunk.remove_prefix(nl + 1);
        }
    }
    if (in.bad()) throw std::runtime_error(path + ": cannot read file");
    if (!pending.empty()) validator.line(pending); // a last line without '\n'
    validator.finish();
}

} // namespace

void validateObjFile(const std::string& path) { scanObjFile(path, nullptr); }

ObjPolygons readObjFile(const std::string& path) {
    ObjPolygons obj;
    scanObjFile(path, &obj);
    return obj;
}

} // namespace geometry::io::detail
