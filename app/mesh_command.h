#pragma once
// `shadowscope mesh info FILE [--json]` and `shadowscope mesh clean IN OUT`.
#include <string>

namespace CLI {
class App;
}

namespace app {

struct MeshOptions {
    std::string input, output;
    bool json = false;
    double creaseAngleDeg = 30.0;
    double mergeTolerance = 1e-6;
    bool fixOrientation = false;
};

/// Adds the `mesh` command with its `info` and `clean` subcommands; returns the `mesh` command.
CLI::App* addMeshCommand(CLI::App& cli, MeshOptions& options);
/// Runs whichever subcommand of `mesh` was parsed.
int runMesh(const CLI::App& mesh, const MeshOptions& options);

} // namespace app
