// PLY after the format's spec (geometry/io/ply_reader.cpp): lists of every count type before and
// after a face's corner list, scalars among them, other elements, CR and CRLF line ends, both byte
// orders, coordinate types, and hostile headers and bodies. Each fixture is one description
// written here as ASCII and as binary in both byte orders, and the reader's raw mesh (before
// cleanup) is compared with the positions and triangles it must give.
//
// Index
//   [SECTION] Fixture and writer ......... PlyLoading, Prop, Elem, Ply, writePly, twoQuads, expectedQuads
//   [SECTION] Layouts .................... lists around the corners, count types, scalars, other elements
//   [SECTION] Encodings .................. line ends, byte orders, coordinate types
//   [SECTION] Hostile input .............. counts, lists, truncation, indices, header
#include "geometry/io/model_loader.h"
#include "geometry/io/ply_reader.h"
#include "geometry/io/polygon_triangulation.h"

#include "loader_test_util.h"
#include "temp_dir_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>

using namespace geometry;
using namespace geometry::io;
namespace fs = std::filesystem;

namespace {

// ---- [SECTION] Fixture and writer -----------------------------------------------------------

/// A property: a scalar of `type`, or a list of `type` items when `countType` is set.
struct Prop {
    std::string type, name, countType;
};
/// An element and its records: each record holds one value vector per property (a scalar's has one value).
struct Elem {
    std::string name;
    std::vector<Prop> props;
    std::vector<std::vector<std::vector<double>>> records;
};
using Ply = std::vector<Elem>;

size_t typeSize(const std::string& t) {
    static const std::map<std::string, size_t> kSizes = {{"char", 1},  {"int8", 1},    {"uchar", 1},  {"uint8", 1},
                                                         {"short", 2}, {"int16", 2},   {"ushort", 2}, {"uint16", 2},
                                                         {"int", 4},   {"int32", 4},   {"uint", 4},   {"uint32", 4},
                                                         {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    return kSizes.at(t);
}

bool isFloatType(const std::string& t) { return t == "float" || t == "float32" || t == "double" || t == "float64"; }

/// `v` stored as `type` in the given byte order.
std::string encode(double v, const std::string& type, bool bigEndian) {
    char bytes[8];
    const size_t n = typeSize(type);
    if (type == "float" || type == "float32") {
        const float f = static_cast<float>(v);
        std::memcpy(bytes, &f, 4);
    } else if (isFloatType(type)) {
        std::memcpy(bytes, &v, 8);
    } else {
        const auto i = static_cast<uint64_t>(static_cast<int64_t>(v)); // two's complement, low bytes first (x86)
        std::memcpy(bytes, &i, n);
    }
    std::string s(bytes, n);
    if (bigEndian) std::reverse(s.begin(), s.end());
    return s;
}

std::string asciiValue(double v, const std::string& type) {
    if (!isFloatType(type)) return std::to_string(static_cast<int64_t>(v));
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

/// The file: format "ascii", "binary_little_endian" or "binary_big_endian"; `eol` ends every
/// header line (and every ASCII record).
std::string writePly(const Ply& ply, const std::string& format, const std::string& eol = "\n") {
    std::string s = "ply" + eol + "format " + format + " 1.0" + eol + "comment written by test_ply_loading" + eol;
    for (const Elem& e : ply) {
        s += "element " + e.name + " " + std::to_string(e.records.size()) + eol;
        for (const Prop& p : e.props)
            s += "property " + (p.countType.empty() ? p.type : "list " + p.countType + " " + p.type) + " " + p.name +
                 eol;
    }
    s += "obj_info after the elements" + eol + "end_header" + eol;
    const bool ascii = format == "ascii", big = format == "binary_big_endian";
    for (const Elem& e : ply) {
        for (const auto& record : e.records) {
            std::string line;
            for (size_t k = 0; k < e.props.size(); ++k) {
                const Prop& p = e.props[k];
                const std::vector<double>& values = record[k];
                if (!p.countType.empty()) {
                    const auto count = static_cast<double>(values.size());
                    line += ascii ? asciiValue(count, p.countType) + " " : encode(count, p.countType, big);
                }
                for (const double v : values) line += ascii ? asciiValue(v, p.type) + " " : encode(v, p.type, big);
            }
            s += ascii ? line.substr(0, line.size() - 1) + eol : line;
        }
    }
    return s;
}

const char* const kFormats[] = {"ascii", "binary_little_endian", "binary_big_endian"};

/// Two quads, the second off the first's plane and not square.
Elem quadVertices(const std::vector<Prop>& props = {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""}}) {
    const double p[8][3] = {{0, 0, 0}, {1, 0, 0},   {1, 1, 0},      {0, 1, 0},
                            {2, 0, 1}, {3.5, 0, 1}, {3.5, 2.25, 1}, {2, 2.25, 1}};
    Elem e{"vertex", props, {}};
    for (const auto& v : p) {
        std::vector<std::vector<double>> record;
        for (const Prop& prop : props) {
            if (prop.name == "x" || prop.name == "y" || prop.name == "z") record.push_back({v[prop.name[0] - 'x']});
            else if (prop.countType.empty()) record.push_back({7});
            else record.push_back({1, 2, 3});
        }
        e.records.push_back(record);
    }
    return e;
}

/// The face element over quadVertices(): `props` with the corners in `vertex_indices` (or
/// vertex_index), texcoord lists of eight values, any other scalar 5.
Elem quadFaces(const std::vector<Prop>& props) {
    Elem e{"face", props, {}};
    for (const std::vector<double>& corners : {std::vector<double>{0, 1, 2, 3}, std::vector<double>{4, 5, 6, 7}}) {
        std::vector<std::vector<double>> record;
        for (const Prop& p : props) {
            if (p.name.starts_with("vertex_ind")) record.push_back(corners);
            else if (!p.countType.empty()) record.push_back({0, 0, 1, 0, 1, 1, 0, 1});
            else record.push_back({5});
        }
        e.records.push_back(record);
    }
    return e;
}

const Prop kCorners{"int", "vertex_indices", "uchar"};
const Prop kTexcoord{"float", "texcoord", "uchar"};

/// What two quads must give: their positions as written, and the triangles ear clipping makes of them.
scene::Mesh expectedQuads() {
    scene::Mesh m;
    for (const auto& r : quadVertices().records)
        m.positions.emplace_back(float(r[0][0]), float(r[1][0]), float(r[2][0]));
    PolygonStats stats;
    for (const std::vector<uint32_t>& q : {std::vector<uint32_t>{0, 1, 2, 3}, std::vector<uint32_t>{4, 5, 6, 7}})
        appendPolygon(m.positions, q, m.indices, stats);
    return m;
}

class PlyLoading : public testutil::TempDirTest {
protected:
    PlyLoading() : TempDirTest("shadowscope_ply_") {}

    /// The reader's mesh before cleanup.
    scene::Mesh readRaw(const std::string& path, CleanupReport* counts = nullptr) {
        CleanupReport local;
        return detail::readPly(path, fs::file_size(path), counts ? *counts : local);
    }

    /// `ply` in every format gives exactly the two quads' positions and triangles.
    void expectQuadsInEveryFormat(const Ply& ply, const std::string& name) {
        const scene::Mesh want = expectedQuads();
        ASSERT_EQ(want.triangleCount(), 4u);
        for (const char* format : kFormats) {
            SCOPED_TRACE(std::string(name) + " " + format);
            const std::string path = write(name + "_" + format + ".ply", writePly(ply, format));
            CleanupReport counts;
            const scene::Mesh got = readRaw(path, &counts);
            EXPECT_EQ(got.positions, want.positions);
            EXPECT_EQ(got.indices, want.indices);
            EXPECT_EQ(counts.polygonsTriangulated, 2u);
            const LoadedModel m = loadModel(path);
            ASSERT_EQ(m.meshes.size(), 1u);
            EXPECT_EQ(m.meshes[0].triangleCount(), 4u);
            EXPECT_EQ(m.report.polygonsTriangulated, 2u);
        }
    }
};

} // namespace

// ---- [SECTION] Layouts ----------------------------------------------------------------------

TEST_F(PlyLoading, TexcoordListAfterTheCorners) {
    // OpenMesh's reader took the texcoord list for the next face's corners: 1 triangle instead of 4.
    expectQuadsInEveryFormat({quadVertices(), quadFaces({kCorners, kTexcoord})}, "after");
}

TEST_F(PlyLoading, TexcoordListBeforeTheCorners) {
    expectQuadsInEveryFormat({quadVertices(), quadFaces({kTexcoord, kCorners})}, "before");
}

TEST_F(PlyLoading, EveryIntegerCountType) {
    for (const char* count : {"ushort", "uint", "char", "uchar", "short", "int", "int8", "uint16", "int32"}) {
        for (const char* item : {"int", "uint", "ushort", "uchar", "int16"}) {
            const Prop corners{item, "vertex_indices", count};
            const Prop texcoord{"double", "texcoord", count};
            expectQuadsInEveryFormat({quadVertices(), quadFaces({texcoord, corners, texcoord})},
                                     std::string(count) + "_" + item);
        }
    }
}

TEST_F(PlyLoading, ScalarsAmongTheLists) {
    const Prop flags{"uchar", "flags", ""}, quality{"double", "quality", ""}, id{"int", "id", ""};
    expectQuadsInEveryFormat({quadVertices(), quadFaces({flags, kCorners, quality})}, "flags");
    expectQuadsInEveryFormat({quadVertices(), quadFaces({id, kTexcoord, flags, kCorners, quality, kTexcoord})}, "mix");
}

TEST_F(PlyLoading, VertexIndexAlias) {
    expectQuadsInEveryFormat({quadVertices(), quadFaces({{"uint", "vertex_index", "uchar"}})}, "alias");
}

TEST_F(PlyLoading, OtherVertexPropertiesAreSkipped) {
    const Ply ply{quadVertices({{"uchar", "red", ""},
                                {"float", "z", ""},
                                {"short", "extra", "uint"},
                                {"double", "nx", ""},
                                {"float", "x", ""},
                                {"float", "y", ""},
                                {"float", "confidence", ""}}),
                  quadFaces({kCorners})};
    expectQuadsInEveryFormat(ply, "vprops");
}

TEST_F(PlyLoading, OtherElementsAreSkipped) {
    const Elem material{"material",
                        {{"uchar", "name", "uchar"}, {"float", "shininess", ""}, {"int", "ids", "ushort"}},
                        {{{'s', 't', 'e', 'e', 'l'}, {0.5}, {1, 2}}, {{'g', 'l', 'a', 's', 's'}, {0.25}, {}}}};
    const Elem edge{"edge", {{"int", "vertex1", ""}, {"int", "vertex2", ""}}, {{{0}, {1}}, {{1}, {2}}, {{2}, {3}}}};
    expectQuadsInEveryFormat({quadVertices(), material, quadFaces({kCorners, kTexcoord}), edge}, "between");
    expectQuadsInEveryFormat({edge, quadVertices(), quadFaces({kCorners}), material}, "around");
}

TEST_F(PlyLoading, FacesBeforeVertices) {
    expectQuadsInEveryFormat({quadFaces({kTexcoord, kCorners}), quadVertices()}, "facesfirst");
}

TEST_F(PlyLoading, FacesOfFewerThanThreeCornersAreDropped) {
    Elem faces = quadFaces({kCorners});
    faces.records.push_back({{1, 2}});
    faces.records.push_back({std::vector<double>{}});
    faces.records.push_back({{5}});
    for (const char* format : kFormats) {
        SCOPED_TRACE(format);
        const scene::Mesh got =
            readRaw(write(std::string("short_") + format + ".ply", writePly({quadVertices(), faces}, format)));
        EXPECT_EQ(got.indices, expectedQuads().indices);
    }
}

TEST_F(PlyLoading, NonFiniteCoordinatesPassThrough) {
    Elem vertices = quadVertices({{"double", "x", ""}, {"float", "y", ""}, {"float", "z", ""}});
    vertices.records[1][0][0] = std::numeric_limits<double>::quiet_NaN();
    vertices.records[2][1][0] = std::numeric_limits<double>::infinity();
    vertices.records[3][0][0] = 1e300; // beyond float: infinite
    for (const char* format : kFormats) {
        SCOPED_TRACE(format);
        const scene::Mesh got =
            readRaw(write(std::string("nan_") + format + ".ply", writePly({vertices, quadFaces({kCorners})}, format)));
        ASSERT_EQ(got.positions.size(), 8u);
        EXPECT_TRUE(std::isnan(got.positions[1].x));
        EXPECT_EQ(got.positions[2].y, std::numeric_limits<float>::infinity());
        EXPECT_EQ(got.positions[3].x, std::numeric_limits<float>::infinity());
        EXPECT_EQ(got.positions[4], glm::vec3(2, 0, 1));
    }
}

// ---- [SECTION] Encodings --------------------------------------------------------------------

TEST_F(PlyLoading, CrOnlyAndCrlfLineEnds) {
    const Ply ply{quadVertices(), quadFaces({kCorners, kTexcoord})};
    const scene::Mesh want = expectedQuads();
    for (const char* eol : {"\r", "\r\n", "\n"}) {
        for (const char* format : kFormats) {
            SCOPED_TRACE(std::string(format) + (eol[0] == '\n' ? " LF" : eol[1] ? " CRLF" : " CR"));
            const scene::Mesh got = readRaw(write("eol.ply", writePly(ply, format, eol)));
            EXPECT_EQ(got.positions, want.positions);
            EXPECT_EQ(got.indices, want.indices);
        }
    }
}

TEST_F(PlyLoading, BinaryBodyStartingWithALineEndByte) {
    // The body starts right after end_header's line end, even where its first byte is CR or LF.
    for (const char* eol : {"\r", "\r\n", "\n"}) {
        for (const double tag : {10.0, 13.0}) {
            const Ply ply{
                quadVertices({{"uchar", "tag", ""}, {"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""}}),
                quadFaces({kCorners})};
            Ply tagged = ply;
            for (auto& r : tagged[0].records) r[0] = {tag};
            for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
                SCOPED_TRACE(std::string(format) + " tag " + std::to_string(tag));
                const scene::Mesh got = readRaw(write("tag.ply", writePly(tagged, format, eol)));
                EXPECT_EQ(got.positions, expectedQuads().positions);
                EXPECT_EQ(got.indices, expectedQuads().indices);
            }
        }
    }
}

TEST_F(PlyLoading, ByteOrderTwinsAreBitIdentical) {
    const Ply ply{quadVertices({{"float", "x", ""},
                                {"float", "y", ""},
                                {"float", "z", ""},
                                {"double", "nx", ""},
                                {"ushort", "extra", "short"},
                                {"uint", "label", ""}}),
                  quadFaces({{"uchar", "flags", ""},
                             {"uint", "vertex_indices", "ushort"},
                             {"float", "texcoord", "int"},
                             {"double", "quality", ""}})};
    const scene::Mesh ascii = readRaw(write("twin_a.ply", writePly(ply, "ascii")));
    ASSERT_EQ(ascii.triangleCount(), 4u);
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const scene::Mesh binary = readRaw(write(std::string("twin_") + format + ".ply", writePly(ply, format)));
        ASSERT_EQ(binary.positions.size(), ascii.positions.size());
        EXPECT_EQ(std::memcmp(binary.positions.data(), ascii.positions.data(), ascii.positions.size() * 12), 0);
        EXPECT_EQ(binary.indices, ascii.indices);
    }
    EXPECT_EQ(ascii.positions, expectedQuads().positions);
}

TEST_F(PlyLoading, CoordinateTypes) {
    for (const char* type : {"double", "float64", "int16", "short", "int", "uchar", "char", "uint"}) {
        Elem vertices = quadVertices({{type, "x", ""}, {type, "y", ""}, {"float", "z", ""}});
        const bool whole = std::string(type) != "double" && std::string(type) != "float64";
        // The quads scaled: to integers an integer type holds, or (double) to values a float rounds.
        for (auto& r : vertices.records) {
            r[0][0] = whole ? r[0][0] * 2 : r[0][0] * 0.1;
            r[1][0] = whole ? r[1][0] * 4 : r[1][0] * -0.01;
        }
        for (const char* format : kFormats) {
            SCOPED_TRACE(std::string(type) + " " + format);
            const scene::Mesh got = readRaw(write(std::string("coord_") + type + format + ".ply",
                                                  writePly({vertices, quadFaces({kCorners})}, format)));
            ASSERT_EQ(got.positions.size(), 8u);
            for (size_t i = 0; i < 8; ++i) {
                EXPECT_EQ(got.positions[i].x, static_cast<float>(vertices.records[i][0][0]));
                EXPECT_EQ(got.positions[i].y, static_cast<float>(vertices.records[i][1][0]));
            }
            EXPECT_EQ(got.triangleCount(), 4u);
        }
    }
    // int16's range, both ends.
    Elem vertices = quadVertices({{"int16", "x", ""}, {"float", "y", ""}, {"float", "z", ""}});
    vertices.records[0][0] = {-32768};
    vertices.records[1][0] = {32767};
    for (const char* format : kFormats) {
        const scene::Mesh got = readRaw(write("range.ply", writePly({vertices, quadFaces({kCorners})}, format)));
        EXPECT_EQ(got.positions[0].x, -32768.f);
        EXPECT_EQ(got.positions[1].x, 32767.f);
    }
}

TEST_F(PlyLoading, AsciiSeparatorsAndSigns) {
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const scene::Mesh got = readRaw(write("seps.ply", header + "\t0 +0 -0\n\n1\t0  0 \n  0 1e0 0\n\n3 +0 1 2"));
    EXPECT_EQ(got.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(got.indices, (std::vector<uint32_t>{0, 1, 2}));
}

// ---- [SECTION] Hostile input ----------------------------------------------------------------

TEST_F(PlyLoading, HugeCountsAreRefusedBeforeAllocating) {
    for (const char* format : kFormats) {
        SCOPED_TRACE(format);
        std::string s = writePly({quadVertices(), quadFaces({kCorners})}, format);
        // 2^31 faces: 2 GiB of records at least (binary), 4 GiB (ASCII), in a file of a few hundred bytes.
        s.replace(s.find("element face 2"), 14, "element face 2147483648");
        testutil::expectLoadRejected(
            write(std::string("huge_") + format + ".ply", s),
            "PLY element 'face' claims 2147483648 records: with the elements before it at least");
        std::string v = writePly({quadVertices(), quadFaces({kCorners})}, format);
        v.replace(v.find("element vertex 8"), 16, "element vertex 4294967296");
        testutil::expectLoadRejected(write(std::string("over_") + format + ".ply", v), "32-bit indices");
    }
    // A skipped element's count is checked the same way.
    std::string s = writePly({quadVertices(), {"edge", {{"int", "a", ""}}, {{{0}}}}, quadFaces({kCorners})},
                             "binary_little_endian");
    s.replace(s.find("element edge 1"), 14, "element edge 4000000000");
    testutil::expectLoadRejected(write("edges.ply", s), "PLY element 'edge' claims 4000000000 records");
}

TEST_F(PlyLoading, NegativeListCount) {
    for (const char* format : kFormats) {
        for (const char* list : {"vertex_indices", "texcoord"}) {
            SCOPED_TRACE(std::string(format) + " " + list);
            Elem faces = quadFaces({{"int", "vertex_indices", "char"}, {"float", "texcoord", "char"}});
            std::string s = writePly({quadVertices(), faces}, format);
            // The second face's list count, -1: in ASCII its text; in binary the byte before its items.
            const bool corners = std::string(list) == "vertex_indices";
            if (std::string(format) == "ascii") {
                const size_t at = s.rfind(corners ? "\n4 4 5 6 7" : " 8 0 0 1 0 1 1 0 1\n");
                s.replace(at + 1, 1, "-1");
            } else {
                const size_t faceBytes = 1 + 16 + 1 + 32;
                s[s.size() - faceBytes + (corners ? 0 : 17)] = '\xff';
            }
            testutil::expectLoadRejected(write("neg.ply", s),
                                         "PLY element 'face' record 1 has a negative count (-1) for list '" +
                                             std::string(list) + "'");
        }
    }
}

TEST_F(PlyLoading, HugeValence) {
    std::string s = writePly({quadVertices(), quadFaces({{"int", "vertex_indices", "uint"}})}, "binary_little_endian");
    s.replace(s.size() - 20, 4, std::string("\x40\x42\x0f\x00", 4)); // 1'000'000 is allowed: then truncated
    testutil::expectLoadRejected(write("valence_ok.ply", s), "truncated PLY body in element 'face'");
    s.replace(s.size() - 20, 4, std::string("\x41\x42\x0f\x00", 4));
    testutil::expectLoadRejected(write("valence.ply", s), "face 1 lists 1000001 vertex indices, over the 1000000");
}

TEST_F(PlyLoading, TruncatedBody) {
    const Elem material{"material", {{"uchar", "name", "uint"}}, {{{'a', 'b', 'c'}}}};
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const std::string s = writePly({quadVertices(), quadFaces({kCorners, kTexcoord})}, format);
        // Cuts into the faces (records of 1 + 16 + 1 + 32 bytes) down to where the counts check
        // refuses the body instead (under two list counts a face: 4 bytes).
        for (size_t cut = 1; cut <= 2 * 50 - 4; cut += 7)
            testutil::expectLoadRejected(write("cut.ply", s.substr(0, s.size() - cut)),
                                         "truncated PLY body in element 'face'");
        // A skipped element's list running past the end.
        std::string m = writePly({quadVertices(), material}, format);
        testutil::expectLoadRejected(write("cutm.ply", m.substr(0, m.size() - 1)),
                                     "truncated PLY body in element 'material'");
    }
    std::string a = writePly({quadVertices(), quadFaces({kCorners})}, "ascii");
    a.resize(a.rfind("4 4 5 6 7"));
    testutil::expectLoadRejected(write("cut_ascii.ply", a), "truncated PLY body in element 'face' (1 of 2 records)");
    std::string b = writePly({quadVertices(), quadFaces({kCorners})}, "ascii");
    b.resize(b.rfind(" 7"));
    testutil::expectLoadRejected(write("short_ascii.ply", b), "PLY element 'face' record 1 has too few values");
}

TEST_F(PlyLoading, IndexOutOfRange) {
    for (const char* format : kFormats) {
        SCOPED_TRACE(format);
        Elem faces = quadFaces({{"int", "vertex_indices", "uchar"}, kTexcoord});
        faces.records[1][0][2] = 9;
        testutil::expectLoadRejected(write("idx.ply", writePly({quadVertices(), faces}, format)),
                                     "face 1 references vertex 9 but the file has only 8 vertices (1 bad faces)");
        faces.records[0][0][0] = -1;
        testutil::expectLoadRejected(write("neg_idx.ply", writePly({quadVertices(), faces}, format)),
                                     "face 0 references vertex -1 but the file has only 8 vertices (2 bad faces)");
    }
}

TEST_F(PlyLoading, NonNumericAsciiValueNamesTheElement) {
    const std::string good =
        writePly({quadVertices({{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""}, {"uchar", "red", ""}}),
                  {"edge", {{"int", "a", ""}}, {{{0}}}},
                  quadFaces({kCorners})},
                 "ascii");
    struct Case {
        std::string line, bad, message;
    };
    const std::string vertex5 = "\n3.5 0 1 7\n", edge0 = "\n0\n", face1 = "\n4 4 5 6 7\n";
    const Case cases[] = {
        {vertex5, "\nabc 0 1 7\n", "PLY element 'vertex' record 5: 'abc' is not a number"},
        {vertex5, "\n3.5 abc 1 7\n", "PLY element 'vertex' record 5: 'abc' is not a number"},
        {vertex5, "\n3.5 0 1 abc\n", "PLY element 'vertex' record 5: 'abc' is not a number"}, // walked over
        {vertex5, "\n3.5 0 1 7 8\n", "PLY element 'vertex' record 5 has more values than its properties"},
        {edge0, "\nabc\n", "PLY element 'edge' record 0: 'abc' is not a number"},
        {face1, "\n4 4 5 abc 7\n", "PLY element 'face' record 1: 'abc' is not an integer"},
        {face1, "\n4.0 4 5 6 7\n", "PLY element 'face' record 1: '4.0' is not an integer"}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.bad);
        std::string s = good;
        const size_t at = s.find(c.line);
        ASSERT_NE(at, std::string::npos);
        s.replace(at, c.line.size(), c.bad);
        testutil::expectLoadRejected(write("nan.ply", s), c.message);
    }
}

TEST_F(PlyLoading, BadHeaders) {
    const std::string good = writePly({quadVertices(), quadFaces({kCorners})}, "ascii");
    auto edited = [&](const std::string& from, const std::string& to) {
        std::string s = good;
        s.replace(s.find(from), from.size(), to);
        return s;
    };
    const std::pair<std::string, std::string> cases[] = {
        {good.substr(0, good.find("end_header")), "PLY header has no end_header (truncated file)"},
        {edited("ply\n", "plyx\n"), "missing 'ply' magic"},
        {edited("1.0", "2.0"), "bad PLY format line"},
        {edited("format ascii 1.0\n", ""), "PLY header has no format line"},
        {edited("property float x\n", ""), "PLY element 'vertex' has no property 'x'"},
        {edited("property float y", "property list uchar float y"), "'y' of element 'vertex' is a list"},
        {edited("vertex_indices", "corners"), "PLY element 'face' has no 'vertex_indices' list"},
        {edited("list uchar int vertex_indices", "list uchar float vertex_indices"), "not a list of integers"},
        {edited("list uchar int", "list float int"), "bad PLY list count type 'float'"},
        {edited("property float z", "property real z"), "unknown PLY property type 'real'"},
        {edited("element vertex 8", "element vertex -8"), "bad PLY element line"},
        {edited("element vertex 8", "element points 8"), "PLY header has no 'vertex' element"},
        {edited("comment", "remark"), "unexpected line in PLY header starting 'remark'"},
        {edited("comment written", "comment \x01 written"), "PLY header is not plain text"},
        {edited("comment written", "comment \xc3\xa9 written"), "PLY header is not plain text"},
        {"ply\nformat ascii 1.0\ncomment " + std::string(1 << 20, 'x') + "\nend_header\n",
         "no end_header in its first 1 MiB"}};
    for (const auto& [bytes, message] : cases) {
        SCOPED_TRACE(message);
        testutil::expectLoadRejected(write("hdr.ply", bytes), message);
    }
}
