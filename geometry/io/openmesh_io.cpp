// OBJ, STL, OFF and PLY: OFF through OpenMesh's reader; OBJ, STL and PLY read here (OBJ by its
// validator, which keeps a polygon's repeated corners; STL by strict parsers; PLY by
// ply_reader.cpp, which follows the format's spec where OpenMesh's reader read a subset of it).
// Saving is mesh_save.cpp's. Polygons are ear-clipped (polygon_triangulation.h).
//
// Reading OFF goes through OpenMesh's IOManager with our own importer that collects flat arrays,
// not through a TriMesh: a halfedge mesh drops non-manifold faces ("complex edge"), which CAD
// exports are full of, and building the connectivity is the slow part of read_mesh anyway.
//
// OpenMesh's readers trust their input (they reserve and loop by header counts and per-face
// valences), so an OFF file is validated here first, against its real size, before the reader
// sees it (OBJ in obj_validate.cpp). Every error is a std::runtime_error "PATH: problem" on one line.
//
// Index
//   [SECTION] Files ...................... fail, checkedFileSize, readAll, readHead
//   [SECTION] Importer ................... FlatImporter
//   [SECTION] Text scanning .............. LineScanner, tokenize, parseInt, checkTextFace, checkCounts
//   [SECTION] STL ........................ validateStl (binary STL is read by stl_binary.cpp)
//   [SECTION] ASCII STL .................. StlTokens, StlParser, readAsciiStl
//   [SECTION] OFF ........................ validateOff
//   [SECTION] Reading .................... QuietOpenMesh, readThroughOpenMesh, readObj, readOpenMeshFile
//                                          (PLY: readPly, ply_reader.cpp)
#include "geometry/io/mesh_limits.h"
#include "geometry/io/model_loader.h"
#include "geometry/io/obj_validate.h"
#include "geometry/io/ply_reader.h"
#include "geometry/io/polygon_triangulation.h"
#include "geometry/io/stl_binary.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace geometry::io::detail {

/// Reads an OBJ/STL/OFF/PLY file (ext: lower case, no dot) into one uncleaned mesh; binary STL
/// reports its progress as "reading".
scene::Mesh readOpenMeshFile(const std::string& path, const std::string& ext, CleanupReport& readerCounts,
                             const Progress& progress);

namespace {

// Beside the caps of mesh_limits.h: one face's corners.
constexpr uint64_t kMaxFaceValence = 1'000'000;

// ---- [SECTION] Files ------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw std::runtime_error(path + ": " + problem);
}

uint64_t checkedFileSize(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) fail(path, "file not found");
    if (!fs::is_regular_file(st)) fail(path, "not a regular file");
    const uint64_t size = fs::file_size(path, ec);
    if (ec) fail(path, "cannot read file size");
    if (size == 0) fail(path, "file is empty");
    std::ifstream probe(path, std::ios::binary);
    if (!probe) fail(path, "cannot open file for reading");
    return size;
}

/// The whole file; the caller has checked that its size is sane (it is the real size on disk).
std::string readAll(const std::string& path, uint64_t size) {
    std::string data(size, '\0');
    std::ifstream in(path, std::ios::binary);
    if (!in.read(data.data(), static_cast<std::streamsize>(size))) fail(path, "cannot read file");
    return data;
}

std::string readHead(const std::string& path, uint64_t size, size_t n) {
    return readAll(path, std::min<uint64_t>(size, n)); // reads the first n bytes only
}

// ---- [SECTION] Importer ---------------------------------------------------------------------

using namespace OpenMesh;

/// Collects vertices and (triangulated) faces into flat arrays. Out-of-range indices are
/// recorded, not trusted: some readers pass them through unchecked.
class FlatImporter final : public IO::BaseImporter {
public:
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    size_t faces = 0;
    size_t badFaces = 0;       // faces with an index out of range
    int64_t firstBadIndex = 0; // for the message
    size_t firstBadFace = 0;
    PolygonStats polygons;

    explicit FlatImporter(uint64_t fileSize) : fileSize_(fileSize) {}

    VertexHandle add_vertex(const Vec3f& p) override {
        positions.emplace_back(p[0], p[1], p[2]);
        return VertexHandle(static_cast<int>(positions.size() - 1));
    }
    VertexHandle add_vertex() override { return add_vertex(Vec3f(0.f, 0.f, 0.f)); }
    FaceHandle add_face(const VHandles& vh) override {
        const size_t face = faces++;
        for (const VertexHandle& h : vh) {
            if (h.idx() < 0 || static_cast<size_t>(h.idx()) >= positions.size()) {
                if (badFaces++ == 0) {
                    firstBadIndex = h.idx();
                    firstBadFace = face;
                }
                return FaceHandle(static_cast<int>(face));
            }
        }
        corners_.clear();
        for (const VertexHandle& h : vh) corners_.push_back(static_cast<uint32_t>(h.idx()));
        if (corners_.size() >= 3) appendPolygon(positions, corners_, indices, polygons);
        return FaceHandle(static_cast<int>(face));
    }
    // Header counts are hints only: never reserve more than the file could hold.
    void reserve(unsigned int nV, unsigned int, unsigned int nF) override {
        positions.reserve(std::min<uint64_t>(nV, fileSize_ / 6));
        indices.reserve(3 * std::min<uint64_t>(nF, fileSize_ / 8));
    }
    size_t n_vertices() const override { return positions.size(); }
    size_t n_faces() const override { return faces; }
    size_t n_edges() const override { return 0; }

    // Halfedge-level input (OpenMesh's own .om format) and attributes we do not keep.
    HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
    FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
    void set_face_texindex(FaceHandle, int) override {}
    void set_point(VertexHandle vh, const Vec3f& p) override {
        if (vh.idx() >= 0 && static_cast<size_t>(vh.idx()) < positions.size()) positions[vh.idx()] = {p[0], p[1], p[2]};
    }
    void set_halfedge(VertexHandle, HalfedgeHandle) override {}
    void set_normal(VertexHandle, const Vec3f&) override {}
    void set_normal(VertexHandle, const Vec3d&) override {}
    void set_color(VertexHandle, const Vec3uc&) override {}
    void set_color(VertexHandle, const Vec4uc&) override {}
    void set_color(VertexHandle, const Vec3f&) override {}
    void set_color(VertexHandle, const Vec4f&) override {}
    void set_texcoord(VertexHandle, const Vec2f&) override {}
    void set_status(VertexHandle, const Attributes::StatusInfo&) override {}
    void set_next(HalfedgeHandle, HalfedgeHandle) override {}
    void set_face(HalfedgeHandle, FaceHandle) override {}
    void request_face_texcoords2D() override {}
    void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
    void set_texcoord(VertexHandle, const Vec3f&) override {}
    void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
    void set_status(HalfedgeHandle, const Attributes::StatusInfo&) override {}
    void set_color(EdgeHandle, const Vec3uc&) override {}
    void set_color(EdgeHandle, const Vec4uc&) override {}
    void set_color(EdgeHandle, const Vec3f&) override {}
    void set_color(EdgeHandle, const Vec4f&) override {}
    void set_status(EdgeHandle, const Attributes::StatusInfo&) override {}
    void set_normal(FaceHandle, const Vec3f&) override {}
    void set_normal(FaceHandle, const Vec3d&) override {}
    void set_color(FaceHandle, const Vec3uc&) override {}
    void set_color(FaceHandle, const Vec4uc&) override {}
    void set_color(FaceHandle, const Vec3f&) override {}
    void set_color(FaceHandle, const Vec4f&) override {}
    void set_status(FaceHandle, const Attributes::StatusInfo&) override {}
    void add_texture_information(int, std::string) override {}

private:
    uint64_t fileSize_;
    std::vector<uint32_t> corners_; // scratch
};

// ---- [SECTION] Text scanning ----------------------------------------------------------------

/// Splits text into lines and lines into whitespace-separated tokens without copying.
struct LineScanner {
    std::string_view text;
    size_t pos = 0;

    bool nextLine(std::string_view& line) {
        if (pos >= text.size()) return false;
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        line = text.substr(pos, end - pos);
        pos = std::min(end + 1, text.size()); // never past the end: callers use size - pos
        return true;
    }
    /// Next line with at least one token, skipping blank lines and '#' comments when asked.
    bool nextDataLine(std::string_view& line, bool skipComments) {
        while (nextLine(line)) {
            const size_t first = line.find_first_not_of(" \t\r");
            if (first == std::string_view::npos) continue;
            if (skipComments && line[first] == '#') continue;
            return true;
        }
        return false;
    }
};

void tokenize(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
}

bool parseInt(std::string_view s, int64_t& value) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && p == s.data() + s.size();
}

/// Checks one text face record "k i0 … ik-1 [colour…]" against the vertex count. OpenMesh
/// reads faces token by token, so where it does not skip the rest of the line (`trailing`
/// false) an extra value would be read as the next face's vertex count: refused.
void checkTextFace(const std::string& path, const std::vector<std::string_view>& tok, uint64_t face,
                   uint64_t vertexCount, bool trailing) {
    int64_t k = 0;
    if (tok.empty() || !parseInt(tok[0], k) || k < 0)
        fail(path, "face " + std::to_string(face) + " has no valid vertex count (corrupt file)");
    if (static_cast<uint64_t>(k) > kMaxFaceValence || static_cast<uint64_t>(k) + 1 > tok.size())
        fail(path, "face " + std::to_string(face) + " claims " + std::to_string(k) +
                       " vertices but lists fewer (corrupt or truncated file)");
    if (!trailing && static_cast<uint64_t>(k) + 1 != tok.size())
        fail(path, "face " + std::to_string(face) + " has values after its " + std::to_string(k) +
                       " vertex indices (face colours need a COFF header)");
    for (int64_t j = 1; j <= k; ++j) {
        int64_t idx = 0;
        if (!parseInt(tok[j], idx)) fail(path, "face " + std::to_string(face) + " has a non-integer vertex index");
        if (idx < 0 || static_cast<uint64_t>(idx) >= vertexCount)
            fail(path, "face " + std::to_string(face) + " references vertex " + std::to_string(idx) +
                           " but the file has only " + std::to_string(vertexCount) + " vertices");
    }
}

void checkCounts(const std::string& path, uint64_t vertices, uint64_t faces, uint64_t minBytes, uint64_t available) {
    // Faces of a text format may be polygons: at least one triangle each, so the estimate is a floor.
    if (const std::string problem = meshMemoryProblem(vertices, faces, availableMemory()); !problem.empty())
        fail(path, "header claims " + problem);
    if (minBytes > available)
        fail(path, "header claims " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                       " faces, which cannot fit in " + std::to_string(available) +
                       " bytes (truncated or corrupt file)");
}

// ---- [SECTION] STL --------------------------------------------------------------------------

enum class StlKind { Ascii, Binary };

uint32_t readLe32(const char* p) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
    return v;
}

/// Same rule as OpenMesh (size = 84 + 50·n means binary), but a file that is neither a
/// consistent binary STL nor text starting with "solid" is refused instead of parsed as text.
StlKind validateStl(const std::string& path, uint64_t size) {
    const std::string head = readHead(path, size, 512);
    if (size >= 84) {
        const uint64_t n = readLe32(head.data() + 80);
        if (84 + 50 * n == size) {
            // Three vertices per facet until cleanup merges them.
            if (const std::string problem = meshMemoryProblem(3 * n, n, availableMemory()); !problem.empty())
                fail(path, "binary STL header claims " + problem);
            return StlKind::Binary;
        }
    }
    const size_t first = head.find_first_not_of(" \t\r\n");
    const bool solid =
        first != std::string::npos && head.size() - first >= 5 && strncasecmp(head.c_str() + first, "solid", 5) == 0;
    const bool text = head.find('\0') == std::string::npos;
    if (solid && text) return StlKind::Ascii;
    if (size < 84) fail(path, "too small for a binary STL (" + std::to_string(size) + " bytes) and not ASCII STL");
    const uint64_t n = readLe32(head.data() + 80);
    fail(path, "binary STL header claims " + std::to_string(n) + " triangles (" + std::to_string(84 + 50 * n) +
                   " bytes) but the file has " + std::to_string(size) + " bytes (truncated or corrupt)");
}

// ---- [SECTION] ASCII STL --------------------------------------------------------------------

/// Whitespace-separated tokens of an ASCII STL with their line numbers. Control bytes other
/// than whitespace are refused where they stand (OpenMesh's reader left such numbers unread).
class StlTokens {
public:
    StlTokens(const std::string& path, std::string_view text) : path_(path), text_(text) {}

    /// The next token, empty at the end of the file.
    std::string_view next() {
        while (pos_ < text_.size() && isSpace(text_[pos_])) {
            if (endsLine(pos_)) ++line_;
            ++pos_;
        }
        if (pos_ < text_.size()) tokenLine_ = line_; // at the end, messages name the last token's line
        const size_t start = pos_;
        while (pos_ < text_.size() && !isSpace(text_[pos_])) checkByte(text_[pos_++]);
        return text_.substr(start, pos_ - start);
    }
    /// Skips the rest of the current line (a solid's name, which may hold tabs), still refusing
    /// other control bytes. A line ends in LF, CRLF or CR alone (old Mac exporters).
    void skipLine() {
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') {
            if (text_[pos_] != '\t') checkByte(text_[pos_]);
            ++pos_;
        }
    }
    [[noreturn]] void failHere(const std::string& problem) const {
        fail(path_, "line " + std::to_string(tokenLine_) + ": " + problem);
    }

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
    /// LF, or a CR not followed by LF: one line end each, whichever convention the file uses.
    [[nodiscard]] bool endsLine(size_t i) const {
        return text_[i] == '\n' || (text_[i] == '\r' && (i + 1 == text_.size() || text_[i + 1] != '\n'));
    }
    void checkByte(char c) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u != 0x7f) return;
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", u);
        tokenLine_ = line_;
        failHere(std::string("control character ") + hex + " (not ASCII STL text)");
    }

    const std::string& path_;
    std::string_view text_;
    size_t pos_ = 0;
    uint64_t line_ = 1, tokenLine_ = 1;
};

/// A token for a message: quoted, cut short, plain ASCII.
std::string shownToken(std::string_view token) {
    if (token.empty()) return "end of file";
    constexpr size_t kShown = 32;
    std::string shown(token.substr(0, kShown));
    std::replace_if(
        shown.begin(), shown.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; }, '?');
    return "'" + shown + (token.size() > kShown ? "...'" : "'");
}

bool keywordIs(std::string_view token, std::string_view keyword) {
    return token.size() == keyword.size() && strncasecmp(token.data(), keyword.data(), keyword.size()) == 0;
}

/// solid name / (facet normal n n n / outer loop / vertex x y z ×3 / endloop / endfacet)* /
/// endsolid name, possibly several solids; keywords in any case, as exporters vary.
class StlParser {
public:
    StlParser(const std::string& path, std::string_view text) : tokens_(path, text) {}

    scene::Mesh parse() {
        expect("solid", "at the start of the file");
        tokens_.skipLine();
        for (;;) {
            const std::string_view t = tokens_.next();
            if (keywordIs(t, "facet")) {
                facet();
                continue;
            }
            if (!keywordIs(t, "endsolid")) tokens_.failHere("expected 'facet' or 'endsolid', got " + shownToken(t));
            tokens_.skipLine();
            const std::string_view after = tokens_.next();
            if (after.empty()) break;
            if (!keywordIs(after, "solid"))
                tokens_.failHere("expected 'solid' or the end of the file after 'endsolid', got " + shownToken(after));
            tokens_.skipLine();
        }
        return std::move(mesh_);
    }

private:
    void expect(std::string_view keyword, const std::string& where) {
        const std::string_view t = tokens_.next();
        if (!keywordIs(t, keyword))
            tokens_.failHere("expected '" + std::string(keyword) + "' " + where + ", got " + shownToken(t));
    }
    /// Exactly three numbers; NaN and Inf parse (cleanup drops them), anything else is an error.
    glm::vec3 numbers(const char* after) {
        glm::vec3 v;
        for (int k = 0; k < 3; ++k) {
            std::string_view t = tokens_.next();
            const std::string_view original = t;
            if (t.starts_with('+') && !(t.size() > 1 && t[1] == '-')) t.remove_prefix(1);
            const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v[k]);
            if (t.empty() || ec == std::errc::invalid_argument || end != t.data() + t.size())
                tokens_.failHere(std::string("expected a number after '") + after + "', got " + shownToken(original));
            if (ec == std::errc::result_out_of_range)
                tokens_.failHere("number " + shownToken(original) + " after '" + after + "' is out of float range");
        }
        return v;
    }
    void facet() {
        // The memory a file of this many facets needs, checked every 2^20 facets as they come.
        if (const uint64_t n = mesh_.triangleCount() + 1; (n & 0xfffff) == 0)
            if (const std::string problem = meshMemoryProblem(3 * n, n, available_); !problem.empty())
                tokens_.failHere(problem + " (and the file goes on)");
        expect("normal", "after 'facet'");
        (void)numbers("normal"); // recomputed from the vertices
        expect("outer", "after the facet normal");
        expect("loop", "after 'outer'");
        for (int k = 0; k < 3; ++k) {
            const std::string_view t = tokens_.next();
            if (!keywordIs(t, "vertex"))
                tokens_.failHere("expected 'vertex' (a facet has 3), got " + shownToken(t) + " after " +
                                 std::to_string(k) + (k == 1 ? " vertex" : " vertices"));
            mesh_.indices.push_back(static_cast<uint32_t>(mesh_.positions.size()));
            mesh_.positions.push_back(numbers("vertex"));
        }
        const std::string_view t = tokens_.next();
        if (keywordIs(t, "vertex")) tokens_.failHere("facet has more than 3 vertices (expected 'endloop')");
        if (!keywordIs(t, "endloop")) tokens_.failHere("expected 'endloop' after 3 vertices, got " + shownToken(t));
        expect("endfacet", "after 'endloop'");
    }

    StlTokens tokens_;
    scene::Mesh mesh_;
    uint64_t available_ = availableMemory(); // once per file: the facets are checked against it
};

/// The whole file parsed here, three vertices per facet (no OpenMesh: its ASCII reader read
/// garbage as 0 and left numbers with control bytes uninitialised). Cleanup merges and counts.
scene::Mesh readAsciiStl(const std::string& path, const std::string& data) { return StlParser(path, data).parse(); }

// ---- [SECTION] OFF --------------------------------------------------------------------------

void validateOff(const std::string& path, uint64_t size) {
    const std::string data = readAll(path, size);
    LineScanner lines{data};
    std::string_view line;
    std::vector<std::string_view> tok;
    // OpenMesh reads the header line, then the counts with operator>> (no comments in between).
    if (!lines.nextLine(line)) fail(path, "empty OFF file");
    tokenize(line, tok);
    if (tok.empty() || tok[0].size() < 3 || tok[0].substr(tok[0].size() - 3) != "OFF")
        fail(path, "missing OFF header (corrupt file)");
    const std::string_view kind = tok[0].substr(0, tok[0].size() - 3);
    if (kind.find_first_not_of("STCN") != std::string_view::npos)
        fail(path, "unsupported OFF variant '" + std::string(tok[0]) + "' (only 3D OFF, COFF, NOFF, STOFF)");
    if (tok.size() > 1 && tok[1] == "BINARY") fail(path, "binary OFF is not supported; save it as ASCII OFF");
    if (tok.size() > 1) fail(path, "counts on the OFF header line are not supported; put them on the next line");
    // OpenMesh reads the counts and every value with operator>> across lines, then skips the
    // rest of a vertex line (and of a face line in COFF only). Lines are held to exactly that
    // layout, so what is checked here is what OpenMesh will read.
    if (!lines.nextDataLine(line, false)) fail(path, "OFF header has no vertex/face counts (truncated file)");
    tokenize(line, tok);
    int64_t nv = -1, nf = -1, ne = -1;
    if (tok.size() != 3 || !parseInt(tok[0], nv) || !parseInt(tok[1], nf) || !parseInt(tok[2], ne) || nv < 0 || nf < 0)
        fail(path, "OFF counts line is not 'vertices faces edges' (corrupt file)");
    // A vertex needs at least "0 0 0\n", a face at least "3 0 1 2\n".
    checkCounts(path, nv, nf, 6 * uint64_t(nv) + 8 * uint64_t(nf), size - lines.pos);
    const size_t vertexValues = kind.find('N') != std::string_view::npos ? 6 : 3;
    for (int64_t v = 0; v < nv; ++v) {
        if (!lines.nextDataLine(line, false))
            fail(path, "has " + std::to_string(v) + " of " + std::to_string(nv) + " vertices (truncated file)");
        tokenize(line, tok);
        if (tok.size() < vertexValues)
            fail(path, "vertex " + std::to_string(v) + " has fewer than " + std::to_string(vertexValues) + " values");
    }
    const bool faceColours = kind.find('C') != std::string_view::npos;
    for (int64_t f = 0; f < nf; ++f) {
        if (!lines.nextDataLine(line, false))
            fail(path, "has " + std::to_string(f) + " of " + std::to_string(nf) + " faces (truncated file)");
        tokenize(line, tok);
        checkTextFace(path, tok, f, nv, faceColours);
    }
}

// ---- [SECTION] Reading ----------------------------------------------------------------------

} // namespace

/// Silences OpenMesh's log and error streams for one call: our exceptions say what went wrong,
/// and a CAD file can make it print one line per non-manifold face. (The streams are global;
/// loading is not meant to run on several threads at once.)
class QuietOpenMesh {
public:
    QuietOpenMesh() : err_(omerr().is_enabled()), log_(omlog().is_enabled()) {
        omerr().disable();
        omlog().disable();
    }
    ~QuietOpenMesh() {
        if (err_) omerr().enable();
        if (log_) omlog().enable();
    }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

private:
    bool err_, log_;
};

namespace {

scene::Mesh readThroughOpenMesh(const std::string& path, uint64_t size, CleanupReport& counts) {
    FlatImporter importer(size);
    IO::Options options; // positions and faces only
    const QuietOpenMesh quiet;
    if (!IO::IOManager().read(path, importer, options))
        fail(path, "OpenMesh could not parse the file (corrupt or truncated)");
    if (importer.badFaces > 0)
        fail(path, "face " + std::to_string(importer.firstBadFace) + " references vertex " +
                       std::to_string(importer.firstBadIndex) + " but the file has only " +
                       std::to_string(importer.positions.size()) + " vertices (" + std::to_string(importer.badFaces) +
                       " bad faces)");
    addPolygonCounts(importer.polygons, counts);
    scene::Mesh mesh;
    mesh.positions = std::move(importer.positions);
    mesh.indices = std::move(importer.indices);
    return mesh;
}

/// OBJ through its validator, which keeps each polygon's corners as written (OpenMesh's OBJ
/// reader removes repeated corners, which breaks a ring face's bridge).
scene::Mesh readObj(const std::string& path, CleanupReport& counts) {
    ObjPolygons obj = readObjFile(path);
    PolygonStats stats;
    scene::Mesh mesh;
    mesh.indices.reserve(obj.corners.size());
    for (size_t f = 0; f + 1 < obj.faceStarts.size(); ++f) {
        const std::span<const uint32_t> corners(obj.corners.data() + obj.faceStarts[f],
                                                obj.faceStarts[f + 1] - obj.faceStarts[f]);
        appendPolygon(obj.positions, corners, mesh.indices, stats);
    }
    addPolygonCounts(stats, counts);
    mesh.positions = std::move(obj.positions);
    return mesh;
}

} // namespace

scene::Mesh readOpenMeshFile(const std::string& path, const std::string& ext, CleanupReport& readerCounts,
                             const Progress& progress) {
    const uint64_t size = checkedFileSize(path);
    if (ext == "stl") {
        // Binary STL never goes through OpenMesh: its reader merges vertices through a std::map
        // whose comparator breaks on NaN, and drops degenerate facets silently.
        if (validateStl(path, size) == StlKind::Binary) return readBinaryStl(path, size, readerCounts, 0, progress);
        return readAsciiStl(path, readAll(path, size));
    }
    if (ext == "obj") return readObj(path, readerCounts);
    if (ext == "ply") return readPly(path, size, readerCounts);
    if (ext != "off") fail(path, "unsupported mesh extension '" + ext + "'");
    validateOff(path, size);
    return readThroughOpenMesh(path, size, readerCounts);
}

} // namespace geometry::io::detail
