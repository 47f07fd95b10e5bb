#include "gl_api.h"

#define SSGL_FN(type, name) type ssgl_##name = nullptr;
#include "gl_functions.inc"
#undef SSGL_FN

namespace renderer::gl {

const char* loadFunctions(ProcAddressFn getProc) noexcept {
    const char* missing = nullptr;
#define SSGL_FN(type, name)                                                                                            \
    ssgl_##name = reinterpret_cast<type>(getProc(#name));                                                              \
    if (!ssgl_##name && !missing) missing = #name;
#include "gl_functions.inc"
#undef SSGL_FN
    return missing;
}

} // namespace renderer::gl
