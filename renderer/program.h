#pragma once
// A linked GL program with cached uniform locations.
#include "gl/gl_api.h"

#include <glm/glm.hpp>
#include <string>
#include <unordered_map>

namespace renderer {

class Program {
public:
    /// Compiles built-in shaders by file name, with `defines` ("#define X\n" lines) inserted after
    /// each #version line; throws std::runtime_error with the GL log.
    Program(std::string_view vertexName, std::string_view fragmentName, std::string_view defines = "");
    /// A compute program from one built-in shader.
    struct Compute {};
    Program(Compute, std::string_view computeName, std::string_view defines = "");
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const noexcept { glUseProgram(id_); }
    [[nodiscard]] GLuint id() const noexcept { return id_; }
    [[nodiscard]] GLint location(const char* name);
    void set(const char* name, int v) { glUniform1i(location(name), v); }
    void set(const char* name, float v) { glUniform1f(location(name), v); }
    void set(const char* name, const glm::vec2& v) { glUniform2f(location(name), v.x, v.y); }
    void set(const char* name, const glm::ivec2& v) { glUniform2i(location(name), v.x, v.y); }
    void set(const char* name, const glm::vec3& v) { glUniform3f(location(name), v.x, v.y, v.z); }
    void set(const char* name, const glm::mat4& m) { glUniformMatrix4fv(location(name), 1, GL_FALSE, &m[0][0]); }
    void set(const char* name, const glm::vec3* v, int count) { glUniform3fv(location(name), count, &v[0][0]); }
    void set(const char* name, const glm::vec4& v) { glUniform4f(location(name), v.x, v.y, v.z, v.w); }
    void set(const char* name, const glm::vec4* v, int count) { glUniform4fv(location(name), count, &v[0][0]); }

private:
    void link(std::string_view what);
    GLuint id_ = 0;
    std::unordered_map<std::string, GLint> locations_;
};

} // namespace renderer
