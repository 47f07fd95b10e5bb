#pragma once
// Running the shadowscope executable from tests (SHADOWSCOPE_EXE is set by tests/CMakeLists.txt).
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

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

/// An empty folder under the system temp folder, named for the test.
inline std::filesystem::path freshDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("shadowscope_test_" + name);
    std::filesystem::remove_all(dir);
    return dir;
}

} // namespace testutil
