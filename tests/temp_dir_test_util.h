#pragma once
// A test fixture with its own temporary folder (removed after the test) and a way to write files into it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace testutil {

class TempDirTest : public ::testing::Test {
protected:
    /// The folder is PREFIX + pid + the test's name under the system's temporary folder.
    explicit TempDirTest(std::string prefix) : prefix_(std::move(prefix)) {}

    std::filesystem::path dir;

    void SetUp() override {
        dir =
            std::filesystem::temp_directory_path() / (prefix_ + std::to_string(::getpid()) + "_" +
                                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir);
    }
    void TearDown() override {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    /// Writes `bytes` to dir/name; returns the path.
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::filesystem::path p = dir / name;
        std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return p.string();
    }

private:
    std::string prefix_;
};

} // namespace testutil
