#pragma once
// Checks shared by the model loaders' tests.
#include "geometry/io/model_loader.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace testutil {

/// loadModel(path) must throw a one-line std::runtime_error "PATH: problem" holding `needle`.
inline void expectLoadRejected(const std::string& path, const std::string& needle) {
    try {
        (void)geometry::io::loadModel(path);
        ADD_FAILURE() << path << " was accepted";
    } catch (const std::runtime_error& e) {
        const std::string msg = e.what();
        EXPECT_TRUE(msg.starts_with(path + ": ")) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        EXPECT_NE(msg.find(needle), std::string::npos) << msg;
    }
}

} // namespace testutil
