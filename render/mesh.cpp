#include "render/mesh.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <utility>

namespace mgp::render {

namespace {
constexpr float kPi = 3.14159265358979f;
}

MeshData makeSphere(int slices, int stacks) {
    MeshData m;
    for (int i = 0; i <= stacks; ++i) {
        const float phi = kPi * static_cast<float>(i) / static_cast<float>(stacks);
        for (int j = 0; j <= slices; ++j) {
            const float theta = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(slices);
            const glm::vec3 p(std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta));
            m.positions.push_back(p);
            m.normals.push_back(p);
        }
    }
    const auto row = static_cast<std::uint32_t>(slices + 1);
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = static_cast<std::uint32_t>(i) * row + static_cast<std::uint32_t>(j);
            const std::uint32_t b = a + row;
            // Counter-clockwise seen from outside.
            m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    return m;
}

MeshData makeTube(int slices) {
    MeshData m;
    for (int j = 0; j <= slices; ++j) {
        const float theta = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(slices);
        const glm::vec3 radial(std::cos(theta), 0.0f, std::sin(theta));
        for (int end = 0; end < 2; ++end) {
            m.positions.emplace_back(radial.x, static_cast<float>(end), radial.z);
            m.normals.push_back(radial);
        }
    }
    for (int j = 0; j < slices; ++j) {
        const auto a = static_cast<std::uint32_t>(2 * j);
        m.indices.insert(m.indices.end(), {a, a + 1, a + 2, a + 1, a + 3, a + 2});
    }
    return m;
}

MeshData makeQuadXZ() {
    MeshData m;
    m.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.indices = {0, 2, 1, 0, 3, 2};
    return m;
}

GpuMesh::GpuMesh(const MeshData& data) : indexCount_(static_cast<int>(data.indices.size())) {
    std::vector<float> interleaved;
    interleaved.reserve(data.positions.size() * 6);
    for (std::size_t i = 0; i < data.positions.size(); ++i) {
        const glm::vec3& p = data.positions[i];
        const glm::vec3& n = data.normals[i];
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(),
                 GL_STATIC_DRAW);
    glGenBuffers(1, &ebo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
                 data.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);
}

GpuMesh::~GpuMesh() { release(); }

GpuMesh::GpuMesh(GpuMesh&& o) noexcept
    : vao_(std::exchange(o.vao_, 0)),
      vbo_(std::exchange(o.vbo_, 0)),
      ebo_(std::exchange(o.ebo_, 0)),
      indexCount_(std::exchange(o.indexCount_, 0)) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& o) noexcept {
    if (this != &o) {
        release();
        vao_ = std::exchange(o.vao_, 0);
        vbo_ = std::exchange(o.vbo_, 0);
        ebo_ = std::exchange(o.ebo_, 0);
        indexCount_ = std::exchange(o.indexCount_, 0);
    }
    return *this;
}

void GpuMesh::release() {
    if (ebo_) glDeleteBuffers(1, &ebo_);
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    vao_ = vbo_ = ebo_ = 0;
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::attachInstanceBuffer(unsigned buffer, int firstAttribute, int count) const {
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    const GLsizei stride = static_cast<GLsizei>(count * 4 * sizeof(float));
    for (int i = 0; i < count; ++i) {
        const auto attr = static_cast<GLuint>(firstAttribute + i);
        glEnableVertexAttribArray(attr);
        glVertexAttribPointer(attr, 4, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<void*>(static_cast<std::size_t>(i) * 4 * sizeof(float)));
        glVertexAttribDivisor(attr, 1);
    }
    glBindVertexArray(0);
}

void GpuMesh::drawInstanced(int instances) const {
    glBindVertexArray(vao_);
    glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, instances);
}

}  // namespace mgp::render
