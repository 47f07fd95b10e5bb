#pragma once
// Running the shadowscope executable from tests (SHADOWSCOPE_EXE is set by tests/CMakeLists.txt).
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace testutil {

struct CommandResult {
    int exitCode = -1;
    std::string output; // stdout and stderr
};

inline CommandResult runShadowscope(const std::string& args) {
    CommandResult r;
    const std::string cmd = std::string(SHADOWSCOPE_EXE) + " " + args + " 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// One run's exit code, stdout and stderr apart.
struct SplitResult {
    int exitCode = -1;
    std::string out, err;
};

/// runShadowscope() with stderr kept apart from stdout (through a file in the temp folder).
inline SplitResult runShadowscopeSplit(const std::string& args) {
    SplitResult r;
    std::string errPath = (std::filesystem::temp_directory_path() / "shadowscope_stderr_XXXXXX").string();
    const int fd = mkstemp(errPath.data());
    if (fd < 0) return r;
    close(fd);
    const std::string cmd = std::string(SHADOWSCOPE_EXE) + " " + args + " 2>" + errPath;
    if (FILE* pipe = popen(cmd.c_str(), "r")) {
        std::array<char, 4096> buf{};
        while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.out.append(buf.data(), n);
        const int status = pclose(pipe);
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::ifstream in(errPath, std::ios::binary);
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::filesystem::remove(errPath);
    return r;
}

/// An empty folder under the system temp folder, named for the test and this process, so two test
/// runs at once (two checkouts, CI next to a developer's run) never write into one folder; removed
/// when the process ends.
inline std::filesystem::path freshDir(const std::string& name) {
    struct Cleanup {
        std::vector<std::filesystem::path> dirs;
        ~Cleanup() {
            for (const auto& d : dirs) {
                std::error_code ec;
                std::filesystem::remove_all(d, ec);
            }
        }
    };
    static Cleanup cleanup;
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("shadowscope_test_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    cleanup.dirs.push_back(dir);
    return dir;
}

} // namespace testutil
