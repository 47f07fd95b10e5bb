// Fuzzes OBJ / STL / OFF / PLY loading and cleanup: the first byte picks the format.
#include "fuzz_input.h"
#include "geometry/io/model_loader.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    static const char* const kExtensions[] = {".obj", ".stl", ".off", ".ply"};
    const std::string path = fuzz::writeTemp(data + 1, size - 1, kExtensions[data[0] % 4]);
    try {
        (void)geometry::io::loadModel(path);
    } catch (const std::exception&) {
        // A clear error is the expected outcome for bad input; crashes and hangs are the bugs.
    }
    return 0;
}
