#include "render/shader_program.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <glm/gtc/type_ptr.hpp>
#include <utility>
#include <vector>

#include "render/gl_context.h"

namespace mgp::render {

namespace {

GLuint compile(const char* name, GLenum type, const char* source) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
        std::vector<char> log(static_cast<std::size_t>(len) + 1, '\0');
        glGetShaderInfoLog(shader, len, nullptr, log.data());
        glDeleteShader(shader);
        throw RenderError(std::string("shader '") + name + "' (" + (type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                          ") failed to compile:\n" + log.data());
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const char* name, const char* vs, const char* fs) {
    const GLuint v = compile(name, GL_VERTEX_SHADER, vs);
    GLuint f = 0;
    try {
        f = compile(name, GL_FRAGMENT_SHADER, fs);
    } catch (...) {
        glDeleteShader(v);
        throw;
    }
    program_ = glCreateProgram();
    glAttachShader(program_, v);
    glAttachShader(program_, f);
    glBindAttribLocation(program_, 0, "aPosition");
    glBindAttribLocation(program_, 1, "aNormal");
    glLinkProgram(program_);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &len);
        std::vector<char> log(static_cast<std::size_t>(len) + 1, '\0');
        glGetProgramInfoLog(program_, len, nullptr, log.data());
        glDeleteProgram(program_);
        program_ = 0;
        throw RenderError(std::string("shader '") + name + "' failed to link:\n" + log.data());
    }
}

ShaderProgram::~ShaderProgram() {
    if (program_) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& o) noexcept
    : program_(std::exchange(o.program_, 0)), locations_(std::move(o.locations_)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
    if (this != &o) {
        if (program_) glDeleteProgram(program_);
        program_ = std::exchange(o.program_, 0);
        locations_ = std::move(o.locations_);
    }
    return *this;
}

void ShaderProgram::use() const { glUseProgram(program_); }

int ShaderProgram::location(const char* name) {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    const int loc = glGetUniformLocation(program_, name);
    locations_.emplace(name, loc);
    return loc;
}

void ShaderProgram::set(const char* n, int v) { glUniform1i(location(n), v); }
void ShaderProgram::set(const char* n, float v) { glUniform1f(location(n), v); }
void ShaderProgram::set(const char* n, const glm::vec2& v) { glUniform2fv(location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::vec3& v) { glUniform3fv(location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::vec4& v) { glUniform4fv(location(n), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* n, const glm::mat3& v) {
    glUniformMatrix3fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const char* n, const glm::mat4& v) {
    glUniformMatrix4fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::setArray(const char* n, const glm::vec4* v, int count) {
    glUniform4fv(location(n), count, glm::value_ptr(v[0]));
}

}  // namespace mgp::render
