// Fuzzes the JSON entry points: presets and scene files (the first byte picks).
#include "fuzz_input.h"
#include "geometry/io/preset.h"
#include "geometry/io/scene_file.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    const std::string path = fuzz::writeTemp(data + 1, size - 1, ".json");
    try {
        if (data[0] & 1) (void)geometry::io::loadPreset(path);
        else (void)geometry::io::loadSceneFile(path);
    } catch (const std::exception&) {}
    return 0;
}
