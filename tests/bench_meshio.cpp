// Mesh loading cost against OpenMesh's own read_mesh, on one ~1M-triangle binary STL written
// once into a temporary folder (the platform scene, flattened into one mesh).
// Goal (issue "CAD meshes in"): loadModel (read + cleanup + chunking) ≤ 2 × bare read_mesh.
#include "geometry/io/model_loader.h"
#include "geometry/scene/builtin_scenes.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// The platform scene as one mesh, transforms applied (an STL has no hierarchy).
geometry::scene::Mesh flattenedPlatform() {
    const geometry::scene::Scene scene = geometry::scene::makePlatformScene({1'000'000});
    geometry::scene::Mesh all;
    for (const geometry::scene::Mesh& m : scene.meshes) {
        const uint32_t base = static_cast<uint32_t>(all.positions.size());
        for (const glm::vec3& p : m.positions) all.positions.emplace_back(m.transform * glm::vec4(p, 1.f));
        for (uint32_t i : m.indices) all.indices.push_back(base + i);
    }
    return all;
}

struct Fixture {
    fs::path dir = fs::temp_directory_path() / ("shadowscope_bench_meshio_" + std::to_string(::getpid()));
    std::string stl = (dir / "platform_1m.stl").string();
    size_t triangles = 0;
    Fixture() {
        fs::create_directories(dir);
        const geometry::scene::Mesh mesh = flattenedPlatform();
        triangles = mesh.triangleCount();
        geometry::io::saveMesh(stl, mesh);
        std::printf("fixture: %s, %zu triangles, %.1f MB\n", stl.c_str(), triangles, fs::file_size(stl) / 1e6);
    }
    ~Fixture() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

Fixture& fixture() {
    static Fixture f;
    return f;
}

std::map<std::string, double>& meanMs() {
    static std::map<std::string, double> m;
    return m;
}

/// Runs `body` per iteration and records its mean wall time under `name` for the ratio.
template <typename Body> void timed(benchmark::State& state, const std::string& name, Body&& body) {
    double total = 0;
    int64_t n = 0;
    for (auto _ : state) {
        const auto t0 = Clock::now();
        body();
        total += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        ++n;
    }
    meanMs()[name] = total / static_cast<double>(n);
    state.counters["triangles"] = static_cast<double>(fixture().triangles);
}

void BM_OpenMeshReadMesh(benchmark::State& state) {
    const std::string& path = fixture().stl;
    timed(state, "read_mesh", [&] {
        OpenMesh::TriMesh_ArrayKernelT<> mesh;
        if (!OpenMesh::IO::read_mesh(mesh, path)) state.SkipWithError("read_mesh failed");
        benchmark::DoNotOptimize(mesh.n_faces());
        state.counters["faces_kept"] = static_cast<double>(mesh.n_faces());
    });
}

void BM_LoadModel(benchmark::State& state) {
    const std::string& path = fixture().stl;
    timed(state, "loadModel", [&] {
        const geometry::io::LoadedModel model = geometry::io::loadModel(path);
        benchmark::DoNotOptimize(model.meshes.front().triangleCount());
    });
}

void BM_CleanMeshAlone(benchmark::State& state) {
    const geometry::scene::Mesh source = flattenedPlatform();
    for (auto _ : state) {
        state.PauseTiming();
        geometry::scene::Mesh m = source;
        state.ResumeTiming();
        benchmark::DoNotOptimize(geometry::io::cleanMesh(m).outputFaces);
    }
}

/// Absurd files are refused before they cost anything: a binary STL claiming 2³²−1 triangles, an
/// OBJ with a 3 MiB line, a 40 000-corner face and three 30 000-corner polygons (the unit tests check
/// the messages; this, the time, goal ≤ 1 s for all of them).
void BM_RejectAbsurdFiles(benchmark::State& state) {
    const fs::path dir = fixture().dir;
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    std::string stl(80, ' ');
    const uint32_t count = 0xFFFFFFFFu;
    stl.append(reinterpret_cast<const char*>(&count), 4);
    stl.append(50, '\0');
    std::string face = triangle + "f", polygon = "f";
    for (int i = 0; i < 40000; ++i) face += " 1";
    for (int i = 0; i < 30000; ++i) polygon += " " + std::to_string(i % 3 + 1);
    const std::vector<std::pair<std::string, std::string>> files{
        {"huge.stl", stl},
        {"longline.obj", triangle + "# " + std::string(3 << 20, 'x') + "\nf 1 2 3\n"},
        {"bigface.obj", face + "\n"},
        {"polygons.obj", triangle + polygon + "\n" + polygon + "\n" + polygon + "\n"}};
    for (const auto& [name, text] : files) {
        std::FILE* f = std::fopen((dir / name).string().c_str(), "wb");
        std::fwrite(text.data(), 1, text.size(), f);
        std::fclose(f);
    }
    for (auto _ : state)
        for (const auto& [name, text] : files) {
            try {
                (void)geometry::io::loadModel((dir / name).string());
                state.SkipWithError(("accepted " + name).c_str());
            } catch (const std::exception&) {}
        }
}

BENCHMARK(BM_OpenMeshReadMesh)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_RejectAbsurdFiles)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_LoadModel)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_CleanMeshAlone)->Unit(benchmark::kMillisecond)->Iterations(5);

} // namespace

int main(int argc, char** argv) {
    // read_mesh reports every face its halfedge mesh refuses (non-manifold CAD input) on omerr;
    // printing hundreds of thousands of lines would be timed as part of its read.
    omerr().disable();
    omlog().disable();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    const auto& ms = meanMs();
    if (ms.count("read_mesh") && ms.count("loadModel"))
        std::printf("bare read_mesh %.1f ms, loadModel (read + cleanup + chunking) %.1f ms, ratio %.2f (goal <= 2)\n",
                    ms.at("read_mesh"), ms.at("loadModel"), ms.at("loadModel") / ms.at("read_mesh"));
    return 0;
}
