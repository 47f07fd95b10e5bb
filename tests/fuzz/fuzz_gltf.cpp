// Fuzzes glTF loading (.gltf JSON or .glb binary: the first byte picks).
#include "fuzz_input.h"
#include "geometry/io/model_loader.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    const std::string path = fuzz::writeTemp(data + 1, size - 1, (data[0] & 1) ? ".glb" : ".gltf");
    try {
        (void)geometry::io::loadModel(path);
    } catch (const std::exception&) {}
    return 0;
}
