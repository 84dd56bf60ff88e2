#pragma once
// A linked GLSL program (vertex + fragment) with uniform setters cached by name.
// Compile/link errors throw RenderError with the GL log (at setup, never in the frame loop).
#include <glm/glm.hpp>
#include <string>
#include <unordered_map>

namespace mgp::render {

class ShaderProgram {
public:
    ShaderProgram() = default;
    ShaderProgram(const char* name, const char* vertexSource, const char* fragmentSource);
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const;
    void set(const char* name, int v);
    void set(const char* name, float v);
    void set(const char* name, const glm::vec2& v);
    void set(const char* name, const glm::vec3& v);
    void set(const char* name, const glm::vec4& v);
    void set(const char* name, const glm::mat3& v);
    void set(const char* name, const glm::mat4& v);
    void setArray(const char* name, const glm::vec4* v, int count);

private:
    int location(const char* name);
    unsigned program_ = 0;
    std::unordered_map<std::string, int> locations_;
};

}  // namespace mgp::render
