// tinygltf's implementation, compiled here rather than taken from Debian's libtinygltf.so: that
// build lacks KHR_draco_mesh_compression, which needs TINYGLTF_ENABLE_DRACO (set, with the
// other TINYGLTF_* options, for the whole target in CMakeLists.txt so every includer agrees).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
