#include "io/gltf_writer.h"

#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/text_reader.h"
#include "skeleton/forward_kinematics.h"

namespace mgp {

namespace {

constexpr double kMetresPerCm = 0.01;
// Bones shorter than this get no box in the export's mesh (a zero offset, a missing tail).
constexpr double kMinBoneCm = 0.5;

// One glTF buffer with its views and accessors, appended to as the export goes.
class GltfBuffer {
public:
    explicit GltfBuffer(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

    // A tightly packed accessor of `count` elements of `type` (TINYGLTF_TYPE_*) and
    // `componentType`, from `bytes` (count × element size), in a view of its own aligned to 4.
    int addAccessor(const void* bytes, std::size_t byteLength, std::size_t count, int type, int componentType,
                    int target = 0) {
        std::vector<unsigned char>& data = model_.buffers[0].data;
        data.resize((data.size() + 3) / 4 * 4, 0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = byteLength;
        view.target = target;
        const auto* p = static_cast<const unsigned char*>(bytes);
        data.insert(data.end(), p, p + byteLength);
        model_.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
        accessor.componentType = componentType;
        accessor.count = count;
        accessor.type = type;
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // Floats, `width` per element (1, 3, 4 or 16); with min/max per component when asked (the
    // specification requires them for POSITION and for animation inputs).
    int addFloats(const std::vector<float>& values, int width, bool withBounds, int target = 0) {
        static const std::map<int, int> kTypeOfWidth = {
            {1, TINYGLTF_TYPE_SCALAR}, {3, TINYGLTF_TYPE_VEC3}, {4, TINYGLTF_TYPE_VEC4}, {16, TINYGLTF_TYPE_MAT4}};
        const std::size_t count = values.size() / static_cast<std::size_t>(width);
        const int index = addAccessor(values.data(), values.size() * sizeof(float), count, kTypeOfWidth.at(width),
                                      TINYGLTF_COMPONENT_TYPE_FLOAT, target);
        if (withBounds && count > 0) {
            tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
            a.minValues.assign(static_cast<std::size_t>(width), values[0]);
            a.maxValues.assign(static_cast<std::size_t>(width), values[0]);
            for (std::size_t i = 0; i < values.size(); ++i) {
                const std::size_t c = i % static_cast<std::size_t>(width);
                a.minValues[c] = std::min<double>(a.minValues[c], values[i]);
                a.maxValues[c] = std::max<double>(a.maxValues[c], values[i]);
            }
        }
        return index;
    }

private:
    tinygltf::Model& model_;
};

void appendVector(std::vector<float>& out, const Eigen::Vector3d& v) {
    out.insert(out.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
}

// The export's figure: one pointed box per bone (from `head` to `tail`, world rest, metres),
// skinned wholly to `joint`.
struct FigureMesh {
    std::vector<float> positions;        // xyz per vertex
    std::vector<std::uint16_t> joints;   // 4 per vertex (only the first is weighted)
    std::vector<float> weights;          // 4 per vertex
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside

    void addBone(const Eigen::Vector3d& head, const Eigen::Vector3d& tail, int joint) {
        const Eigen::Vector3d axis = tail - head;
        const double length = axis.norm();
        const Eigen::Vector3d dir = axis / length;
        // Two directions across the bone: any vector not parallel to it, made orthogonal.
        const Eigen::Vector3d helper = std::abs(dir.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
        const Eigen::Vector3d u = dir.cross(helper).normalized();
        const Eigen::Vector3d v = dir.cross(u);
        const double radius = std::clamp(0.12 * length, 0.01, 0.04);
        const Eigen::Vector3d waist = head + 0.2 * axis;
        const auto first = static_cast<std::uint32_t>(positions.size() / 3);
        appendVector(positions, head);
        appendVector(positions, waist + radius * u);
        appendVector(positions, waist + radius * v);
        appendVector(positions, waist - radius * u);
        appendVector(positions, waist - radius * v);
        appendVector(positions, tail);
        for (int k = 0; k < 6; ++k) {
            joints.insert(joints.end(), {static_cast<std::uint16_t>(joint), 0, 0, 0});
            weights.insert(weights.end(), {1.0f, 0.0f, 0.0f, 0.0f});
        }
        // Around the waist (1..4, counter-clockwise about dir): a fan to the head and one to the tail.
        for (std::uint32_t k = 0; k < 4; ++k) {
            const std::uint32_t a = first + 1 + k, b = first + 1 + (k + 1) % 4;
            indices.insert(indices.end(), {first, b, a});
            indices.insert(indices.end(), {first + 5, a, b});
        }
    }
};

tinygltf::Value vectorValue(const Eigen::Vector3d& v) {
    return tinygltf::Value(
        tinygltf::Value::Array{tinygltf::Value(v.x()), tinygltf::Value(v.y()), tinygltf::Value(v.z())});
}

// The joint nodes (parents precede children, as in the skeleton); returns their world rest
// positions in metres.
std::vector<Eigen::Vector3d> addJointNodes(const Skeleton& sk, tinygltf::Model& model) {
    const int n = sk.jointCount();
    std::vector<Eigen::Vector3d> restM(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
        const Joint& joint = sk.joints[j];
        restM[j] = joint.offsetCm * kMetresPerCm + (joint.parent >= 0 ? restM[joint.parent] : Eigen::Vector3d::Zero());
        tinygltf::Node node;
        node.name = joint.name;
        if (!joint.offsetCm.isZero()) {
            const Eigen::Vector3d t = joint.offsetCm * kMetresPerCm;
            node.translation = {t.x(), t.y(), t.z()};
        }
        tinygltf::Value::Object extras;
        if (!joint.bone.empty()) extras["bone"] = tinygltf::Value(joint.bone);
        if (!joint.tailCm.isZero()) extras["tail_m"] = vectorValue(joint.tailCm * kMetresPerCm);
        if (!extras.empty()) node.extras = tinygltf::Value(std::move(extras));
        model.nodes.push_back(node);
        if (joint.parent >= 0) model.nodes[static_cast<std::size_t>(joint.parent)].children.push_back(j);
    }
    return restM;
}

// The skin over every joint and the figure mesh it deforms, on a node of its own at the scene's
// root with no transform (as skinned meshes must be). Returns that node's index.
int addSkinnedFigure(const Clip& clip, const std::vector<Eigen::Vector3d>& restM, GltfBuffer& buffer,
                     tinygltf::Model& model) {
    const Skeleton& sk = clip.skeleton;
    const int n = sk.jointCount();
    FigureMesh figure;
    std::vector<bool> hasChild(static_cast<std::size_t>(n), false);
    for (int j = 1; j < n; ++j) {
        const int p = sk.joints[j].parent;
        hasChild[p] = true;
        if (sk.joints[j].offsetCm.norm() >= kMinBoneCm) figure.addBone(restM[p], restM[j], p);
    }
    for (int j = 0; j < n; ++j)
        if (!hasChild[j] && sk.joints[j].tailCm.norm() >= kMinBoneCm)
            figure.addBone(restM[j], restM[j] + sk.joints[j].tailCm * kMetresPerCm, j);
    if (figure.indices.empty())
        throw std::invalid_argument("glTF export: expected a skeleton with at least one bone of " +
                                    std::to_string(kMinBoneCm) + " cm or more, found none");
    std::vector<float> inverseBind;  // column-major 4×4: a translation by −rest (rest rotations are I)
    for (int j = 0; j < n; ++j) {
        Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
        m.block<3, 1>(0, 3) = (-restM[j]).cast<float>();
        inverseBind.insert(inverseBind.end(), m.data(), m.data() + 16);
    }
    tinygltf::Skin skin;
    skin.name = clip.name;
    skin.skeleton = 0;
    for (int j = 0; j < n; ++j) skin.joints.push_back(j);
    skin.inverseBindMatrices = buffer.addFloats(inverseBind, 16, false);
    model.skins.push_back(skin);

    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = buffer.addFloats(figure.positions, 3, true, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["JOINTS_0"] =
        buffer.addAccessor(figure.joints.data(), figure.joints.size() * sizeof(std::uint16_t), figure.joints.size() / 4,
                           TINYGLTF_TYPE_VEC4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["WEIGHTS_0"] = buffer.addFloats(figure.weights, 4, false, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.indices = buffer.addAccessor(figure.indices.data(), figure.indices.size() * sizeof(std::uint32_t),
                                           figure.indices.size(), TINYGLTF_TYPE_SCALAR,
                                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Mesh mesh;
    mesh.name = clip.name + "_figure";
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node meshNode;
    meshNode.name = clip.name + "_figure";
    meshNode.mesh = static_cast<int>(model.meshes.size()) - 1;
    meshNode.skin = static_cast<int>(model.skins.size()) - 1;
    model.nodes.push_back(meshNode);
    return static_cast<int>(model.nodes.size()) - 1;
}

// The animation: every joint's local rotation G_parentᵀ·G_j from FK (continuous in sign) and the
// root's translation, one LINEAR key per frame.
void addAnimation(const Clip& clip, GltfBuffer& buffer, tinygltf::Model& model) {
    const Skeleton& sk = clip.skeleton;
    const int n = sk.jointCount(), frames = clip.frameCount();
    std::vector<float> times(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) times[f] = static_cast<float>(f / clip.fps);
    std::vector<std::vector<float>> rotations(static_cast<std::size_t>(n));
    std::vector<Eigen::Quaterniond> previous(static_cast<std::size_t>(n));
    std::vector<float> rootTranslation;
    FkState fk;
    for (int f = 0; f < frames; ++f) {
        forwardKinematics(sk, clip.frames[f], fk);
        appendVector(rootTranslation, fk.jointCm[0] * kMetresPerCm);
        for (int j = 0; j < n; ++j) {
            const int p = sk.joints[j].parent;
            const Eigen::Matrix3d local =
                p < 0 ? fk.global[j] : Eigen::Matrix3d(fk.global[p].transpose() * fk.global[j]);
            Eigen::Quaterniond q(local);
            q.normalize();
            if (f > 0 && q.dot(previous[j]) < 0.0) q.coeffs() = -q.coeffs();
            previous[j] = q;
            rotations[j].insert(rotations[j].end(), {static_cast<float>(q.x()), static_cast<float>(q.y()),
                                                     static_cast<float>(q.z()), static_cast<float>(q.w())});
        }
    }
    tinygltf::Animation animation;
    animation.name = clip.name;
    const int input = buffer.addFloats(times, 1, true);
    auto addChannel = [&](int node, const char* path, const std::vector<float>& values, int width) {
        tinygltf::AnimationSampler sampler;
        sampler.input = input;
        sampler.output = buffer.addFloats(values, width, false);
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
        channel.target_node = node;
        channel.target_path = path;
        animation.channels.push_back(channel);
    };
    addChannel(0, "translation", rootTranslation, 3);
    for (int j = 0; j < n; ++j) addChannel(j, "rotation", rotations[j], 4);
    model.animations.push_back(animation);
}

tinygltf::Model gltfModelOf(const Clip& clip) {
    const int n = clip.skeleton.jointCount(), frames = clip.frameCount();
    if (n == 0 || frames == 0)
        throw std::invalid_argument("glTF export: expected a clip with joints and frames, found " + std::to_string(n) +
                                    " joints and " + std::to_string(frames) + " frames");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "MotionGP";
    GltfBuffer buffer(model);
    const std::vector<Eigen::Vector3d> restM = addJointNodes(clip.skeleton, model);
    const int figureNode = addSkinnedFigure(clip, restM, buffer, model);
    addAnimation(clip, buffer, model);

    tinygltf::Value::Object extras;
    extras["tool"] = tinygltf::Value(std::string("MotionGP"));
    extras["source_clip"] = tinygltf::Value(clip.name);
    extras["source_file"] = tinygltf::Value(clip.sourcePath);
    extras["source_format"] = tinygltf::Value(std::string(clipFormatName(clip.format)));
    extras["convention"] = tinygltf::Value(clip.convention);
    extras["fps"] = tinygltf::Value(clip.fps);
    extras["frames"] = tinygltf::Value(frames);
    extras["rest_frame"] = tinygltf::Value(clip.restFrame);  // frame 1 is a converter's T-pose
    model.asset.extras = tinygltf::Value(std::move(extras));

    tinygltf::Scene scene;
    scene.name = clip.name;
    scene.nodes = {0, figureNode};  // the skeleton's root and the figure
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    return model;
}

}  // namespace

bool isGltfPath(const std::string& path) {
    const std::string ext = fileExtension(path);
    return ext == "glb" || ext == "gltf";
}

std::string formatGltf(const Clip& clip, bool binary) {
    const tinygltf::Model model = gltfModelOf(clip);
    tinygltf::TinyGLTF writer;
    std::ostringstream out;
    if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary))
        throw std::runtime_error("glTF export of '" + clip.name + "': tinygltf could not write the model");
    return out.str();
}

void writeGltf(const Clip& clip, const std::string& path) {
    writeFileAtomically(path, formatGltf(clip, fileExtension(path) == "glb"));
}

}  // namespace mgp
