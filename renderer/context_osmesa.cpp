#include "context.h"
#include "osmesa_api.h"

#include <stdexcept>
#include <vector>

namespace renderer {

namespace {
class OSMesaGlContext final : public GlContext {
public:
    OSMesaGlContext() : buffer_(osmesa::kBufferSide * osmesa::kBufferSide * 4) {
        std::string error;
        ctx_ = osmesa::create(error);
        if (!ctx_) throw std::runtime_error(error);
        try {
            makeCurrent();
            initialiseGl(osmesa::procAddress);
        } catch (...) {
            osmesa::destroy(ctx_);
            throw;
        }
    }
    ~OSMesaGlContext() override { osmesa::destroy(ctx_); }
    void makeCurrent() override {
        if (!osmesa::makeCurrent(ctx_, buffer_.data()))
            throw std::runtime_error("OSMesa could not make its context current");
    }
    [[nodiscard]] Backend backend() const noexcept override { return Backend::OSMesa; }

private:
    void* ctx_ = nullptr;
    std::vector<unsigned char> buffer_;
};
} // namespace

std::unique_ptr<GlContext> createOSMesaContext() { return std::make_unique<OSMesaGlContext>(); }

} // namespace renderer
