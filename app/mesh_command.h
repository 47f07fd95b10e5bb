#pragma once
// `shadowscope mesh info FILE [--json]` and `shadowscope mesh clean IN OUT`.
#include "geometry/io/model_loader.h"
#include "geometry/io/up_axis.h"

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace app {

struct MeshOptions {
    std::string input, output;
    bool json = false;
    double creaseAngleDeg = 30.0;
    double mergeTolerance = geometry::io::kDefaultMergeTolerance; // model units
    std::optional<double> mergeToleranceOfDiagonal;               // instead: a fraction of the bounds' diagonal
    bool fixOrientation = false;
    std::optional<geometry::io::UpAxis> up; // info: the file's up axis (default: its format's)
};

/// Adds the `mesh` command with its `info` and `clean` subcommands; returns the `mesh` command.
CLI::App* addMeshCommand(CLI::App& cli, MeshOptions& options);
/// Runs whichever subcommand of `mesh` was parsed.
int runMesh(const CLI::App& mesh, const MeshOptions& options);

} // namespace app
