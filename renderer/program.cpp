#include "program.h"

#include "shader_sources.h"

#include <stdexcept>

namespace renderer {

namespace {

/// The shader's source with each `#include "NAME"` line replaced by that built-in source (one level:
/// included sources include nothing).
std::string expandIncludes(std::string_view name) {
    const std::string_view src = shaderSource(name);
    std::string out;
    size_t pos = 0;
    while (pos < src.size()) {
        size_t eol = src.find('\n', pos);
        if (eol == std::string_view::npos) eol = src.size();
        const std::string_view line = src.substr(pos, eol - pos);
        constexpr std::string_view directive = "#include \"";
        if (line.starts_with(directive) && line.ends_with('"'))
            out += shaderSource(line.substr(directive.size(), line.size() - directive.size() - 1));
        else out += line;
        out += '\n';
        pos = eol + 1;
    }
    return out;
}

} // namespace

static GLuint compile(GLenum stage, std::string_view name, std::string_view defines) {
    std::string src = expandIncludes(name);
    if (!defines.empty()) {
        const size_t eol = src.find('\n');
        src.insert(eol == std::string::npos ? src.size() : eol + 1, defines);
    }
    const GLuint s = glCreateShader(stage);
    const GLchar* text = src.data();
    const GLint len = static_cast<GLint>(src.size());
    glShaderSource(s, 1, &text, &len);
    glCompileShader(s);
    GLint ok = GL_FALSE;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw std::runtime_error("shader " + std::string(name) + " does not compile: " + log);
    }
    return s;
}

Program::Program(std::string_view vertexName, std::string_view fragmentName, std::string_view defines) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexName, defines);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragmentName, defines);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    link(std::string(vertexName) + "+" + std::string(fragmentName));
}

Program::Program(Compute, std::string_view computeName, std::string_view defines) {
    const GLuint cs = compile(GL_COMPUTE_SHADER, computeName, defines);
    id_ = glCreateProgram();
    glAttachShader(id_, cs);
    glLinkProgram(id_);
    glDeleteShader(cs);
    link(computeName);
}

/// Throws with the log when the program just linked did not.
void Program::link(std::string_view what) {
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(id_, sizeof log, nullptr, log);
        glDeleteProgram(id_);
        throw std::runtime_error("program " + std::string(what) + " does not link: " + log);
    }
}

Program::~Program() { glDeleteProgram(id_); }

GLint Program::location(const char* name) {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    const GLint loc = glGetUniformLocation(id_, name);
    locations_.emplace(name, loc);
    return loc;
}

} // namespace renderer
