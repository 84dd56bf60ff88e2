#pragma once
// Mesh generation (CPU, no GL) and GPU upload. Vertices are position + normal; a tube's
// position is (cos θ, t, sin θ) with t ∈ {0, 1} along the axis, and the shader places it
// between two points with a radius per end (bones, path segments, pins).
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace mgp::render {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;  // triangles
};

MeshData makeSphere(int slices, int stacks);  // unit sphere at the origin
MeshData makeTube(int slices);                // open tube, unit radius, t ∈ [0, 1] along +Y
MeshData makeQuadXZ();                        // [-1,1]² in XZ at y = 0, normal +Y

// Owns a VAO with attribute 0 = position, 1 = normal (needs a current GL context).
class GpuMesh {
public:
    GpuMesh() = default;
    explicit GpuMesh(const MeshData& data);
    ~GpuMesh();
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    void draw() const;
    // Per-instance data: `count` vec4 attributes starting at `firstAttribute`, read from `buffer`
    // (tightly packed, advancing once per instance).
    void attachInstanceBuffer(unsigned buffer, int firstAttribute, int count) const;
    void drawInstanced(int instances) const;

private:
    void release();
    unsigned vao_ = 0, vbo_ = 0, ebo_ = 0;
    int indexCount_ = 0;
};

}  // namespace mgp::render
