#include "io/gltf_reader.h"

#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <map>

#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp {

namespace {

constexpr double kCmPerMetre = 100.0;

// A float accessor's values, `width` per element, checked against its buffer view.
std::vector<float> readFloatAccessor(const std::string& path, const tinygltf::Model& model, int index, int width,
                                     const std::string& what) {
    auto fail = [&](const std::string& found) {
        throwParseError(path, 0, what + " as a float accessor of " + std::to_string(width) + " component(s)", found);
    };
    if (index < 0 || index >= static_cast<int>(model.accessors.size())) fail("accessor " + std::to_string(index));
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) fail("component type " + std::to_string(a.componentType));
    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != width)
        fail(std::to_string(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type))) + " components");
    if (a.sparse.isSparse) fail("a sparse accessor");
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model.bufferViews.size())) fail("no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) fail("no buffer");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t element = sizeof(float) * static_cast<std::size_t>(width);
    const std::size_t stride = view.byteStride ? view.byteStride : element;
    const std::size_t start = view.byteOffset + a.byteOffset;
    if (a.count > 0 && (stride < element || start + (a.count - 1) * stride + element > data.size() ||
                        a.byteOffset + (a.count - 1) * stride + element > view.byteLength))
        fail(std::to_string(a.count) + " elements that run past their buffer");
    std::vector<float> out(a.count * static_cast<std::size_t>(width));
    for (std::size_t i = 0; i < a.count; ++i)
        std::memcpy(&out[i * static_cast<std::size_t>(width)], &data[start + i * stride], element);
    for (float v : out)
        if (!std::isfinite(v)) fail("a value that is not finite");
    return out;
}

const tinygltf::Value* extraOf(const tinygltf::Value& extras, const char* key) {
    if (!extras.IsObject() || !extras.Has(key)) return nullptr;
    return &extras.Get(key);
}

Eigen::Vector3d vectorOf(const tinygltf::Value& v) {
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    if (!v.IsArray() || v.ArrayLen() != 3) return out;
    for (int i = 0; i < 3; ++i)
        if (v.Get(i).IsNumber()) out[i] = v.Get(i).GetNumberAsDouble();
    return out;
}

tinygltf::Model loadGltfModel(const std::string& path) {
    const std::string bytes = readFileBytes(path, 512u << 20, "a glTF file");
    const std::size_t slash = path.find_last_of('/');
    const std::string baseDir = slash == std::string::npos ? "." : path.substr(0, slash);
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = fileExtension(path) == "glb";
    const auto size = static_cast<unsigned>(bytes.size());
    const bool ok = binary
                        ? loader.LoadBinaryFromMemory(
                              &model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, baseDir)
                        : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, baseDir);
    if (!ok)
        throwParseError(path, 0, binary ? "a binary glTF 2.0 file" : "a glTF 2.0 JSON file",
                        err.empty() ? "an unreadable file" : err);
    return model;
}

// The skin's joints as a tree, in the order they become the skeleton's joints.
struct GltfJointTree {
    std::map<int, int> skinIndexOf;    // node → index in skin.joints
    std::vector<int> parentJointNode;  // per skin joint: the node of its parent joint, -1 for the root
    int rootNode = -1;
    std::vector<int> order;      // nodes, parents before children
    std::map<int, int> jointOf;  // node → skeleton joint
};

// Each joint's parent is its nearest ancestor node that is a joint; exactly one joint has none.
void findGltfJointParents(const std::string& path, const tinygltf::Model& model, const tinygltf::Skin& skin,
                          GltfJointTree& tree) {
    const int nodeCount = static_cast<int>(model.nodes.size());
    std::vector<int> parentNode(static_cast<std::size_t>(nodeCount), -1);
    for (int i = 0; i < nodeCount; ++i)
        for (int c : model.nodes[i].children)
            if (c >= 0 && c < nodeCount) parentNode[c] = i;
    for (int k = 0; k < static_cast<int>(skin.joints.size()); ++k) {
        const int node = skin.joints[k];
        if (node < 0 || node >= nodeCount)
            throwParseError(path, 0, "skin joints that are nodes", "node " + std::to_string(node));
        tree.skinIndexOf[node] = k;
    }
    tree.parentJointNode.assign(skin.joints.size(), -1);
    for (int k = 0; k < static_cast<int>(skin.joints.size()); ++k) {
        int a = parentNode[skin.joints[k]];
        for (int guard = 0; a >= 0 && !tree.skinIndexOf.count(a) && guard < nodeCount; ++guard) a = parentNode[a];
        tree.parentJointNode[k] = a >= 0 && tree.skinIndexOf.count(a) ? a : -1;
        if (tree.parentJointNode[k] < 0) {
            if (tree.rootNode >= 0)
                throwParseError(
                    path, 0, "one root joint",
                    "'" + model.nodes[tree.rootNode].name + "' and '" + model.nodes[skin.joints[k]].name + "'");
            tree.rootNode = skin.joints[k];
        }
    }
    if (tree.rootNode < 0) throwParseError(path, 0, "a root joint", "a skin with no joints or a cycle");
}

GltfJointTree gltfJointTree(const std::string& path, const tinygltf::Model& model, const tinygltf::Skin& skin) {
    GltfJointTree tree;
    findGltfJointParents(path, model, skin, tree);
    // Parents before children, otherwise in the skin's order (our exports' order is kept).
    for (bool grew = true; grew;) {
        grew = false;
        for (int k = 0; k < static_cast<int>(skin.joints.size()); ++k) {
            const int node = skin.joints[k];
            if (tree.jointOf.count(node) ||
                (tree.parentJointNode[k] >= 0 && !tree.jointOf.count(tree.parentJointNode[k])))
                continue;
            tree.jointOf[node] = static_cast<int>(tree.order.size());
            tree.order.push_back(node);
            grew = true;
        }
    }
    return tree;
}

// The skeleton's joints from the nodes; returns each joint's rest rotation (the pose of a joint
// no channel animates).
std::vector<Eigen::Quaterniond> addGltfJoints(const std::string& path, const tinygltf::Model& model,
                                              const GltfJointTree& tree, Clip& clip) {
    std::vector<Eigen::Quaterniond> restRotation;
    for (int node : tree.order) {
        const tinygltf::Node& nd = model.nodes[node];
        Joint joint;
        joint.name = nd.name.empty() ? "node" + std::to_string(node) : nd.name;
        joint.parent = node == tree.rootNode ? -1 : tree.jointOf.at(tree.parentJointNode[tree.skinIndexOf.at(node)]);
        if (!nd.matrix.empty())
            throwParseError(path, 0, "joint transforms as translation/rotation", "a matrix on '" + joint.name + "'");
        for (double s : nd.scale)
            if (std::abs(s - 1.0) > 1e-6)
                throwParseError(path, 0, "joints with scale 1",
                                "scale " + std::to_string(s) + " on '" + joint.name + "'");
        if (nd.translation.size() == 3)
            joint.offsetCm = Eigen::Vector3d(nd.translation[0], nd.translation[1], nd.translation[2]) * kCmPerMetre;
        restRotation.push_back(
            nd.rotation.size() == 4
                ? Eigen::Quaterniond(nd.rotation[3], nd.rotation[0], nd.rotation[1], nd.rotation[2]).normalized()
                : Eigen::Quaterniond::Identity());
        if (const tinygltf::Value* bone = extraOf(nd.extras, "bone"); bone && bone->IsString())
            joint.bone = bone->Get<std::string>();
        if (const tinygltf::Value* tail = extraOf(nd.extras, "tail_m")) joint.tailCm = vectorOf(*tail) * kCmPerMetre;
        if (joint.bone.empty()) clip.unmappedJoints.push_back(joint.name);
        clip.skeleton.joints.push_back(joint);
    }
    return restRotation;
}

// The animation's channels: one shared time line, rotations per joint, translation of the root.
struct GltfChannels {
    std::vector<float> times;
    std::vector<std::vector<float>> rotation, rootTranslation;
};

GltfChannels readGltfChannels(const std::string& path, const tinygltf::Model& model,
                              const tinygltf::Animation& animation, const GltfJointTree& tree, const Skeleton& sk) {
    GltfChannels ch;
    std::vector<float>& times = ch.times;
    ch.rotation.resize(static_cast<std::size_t>(sk.jointCount()));
    ch.rootTranslation.resize(1);
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
        if (!tree.jointOf.count(channel.target_node) || channel.target_path == "weights") continue;
        const int j = tree.jointOf.at(channel.target_node);
        const std::string& name = sk.joints[j].name;
        if (channel.sampler < 0 || channel.sampler >= static_cast<int>(animation.samplers.size()))
            throwParseError(path, 0, "a channel with a sampler",
                            "sampler " + std::to_string(channel.sampler) + " on '" + name + "'");
        const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(channel.sampler)];
        if (sampler.interpolation != "LINEAR" && sampler.interpolation != "STEP")
            throwParseError(path, 0, "LINEAR or STEP keys", sampler.interpolation + " on '" + name + "'");
        const std::vector<float> t = readFloatAccessor(path, model, sampler.input, 1, "key times");
        if (times.empty()) times = t;
        bool same = t.size() == times.size();
        for (std::size_t i = 0; same && i < t.size(); ++i) same = std::abs(t[i] - times[i]) <= 1e-5f;
        if (!same) throwParseError(path, 0, "every channel keyed at the same times", "other times on '" + name + "'");
        if (channel.target_path == "rotation") {
            ch.rotation[j] = readFloatAccessor(path, model, sampler.output, 4, "rotations of '" + name + "'");
            if (ch.rotation[j].size() != 4 * times.size())
                throwParseError(path, 0, "one rotation per key", "another count on '" + name + "'");
        } else if (channel.target_path == "translation") {
            if (j != 0) throwParseError(path, 0, "translation animated on the root joint only", "on '" + name + "'");
            ch.rootTranslation[0] = readFloatAccessor(path, model, sampler.output, 3, "translations of '" + name + "'");
            if (ch.rootTranslation[0].size() != 3 * times.size())
                throwParseError(path, 0, "one translation per key", "another count on '" + name + "'");
        } else if (channel.target_path == "scale") {
            for (float s : readFloatAccessor(path, model, sampler.output, 3, "scales of '" + name + "'"))
                if (std::abs(s - 1.0f) > 1e-5f)
                    throwParseError(path, 0, "joints with scale 1", "animated scale on '" + name + "'");
        }
    }
    if (times.empty()) throwParseError(path, 0, "an animation that keys the skeleton's joints", "none");
    return ch;
}

// The asset's fps and rest_frame extras; without fps, the key spacing.
void readGltfTiming(const tinygltf::Model& model, const std::vector<float>& times, Clip& clip) {
    clip.fps = 0.0;
    if (const tinygltf::Value* fps = extraOf(model.asset.extras, "fps"); fps && fps->IsNumber())
        clip.fps = fps->GetNumberAsDouble();
    if (!(clip.fps > 0.0) && times.size() > 1 && times.back() > times.front())
        clip.fps = static_cast<double>(times.size() - 1) / (times.back() - times.front());
    if (!(clip.fps > 0.0)) clip.fps = 30.0;  // a single key has no rate; any will do
    if (const tinygltf::Value* rest = extraOf(model.asset.extras, "rest_frame"); rest && rest->IsBool())
        clip.restFrame = rest->Get<bool>();
}

// One pose per key: animated rotations, else the rest rotation; the root's translation if keyed.
void addGltfFrames(const GltfChannels& ch, const std::vector<Eigen::Quaterniond>& restRotation, Clip& clip) {
    Skeleton& sk = clip.skeleton;
    const int n = sk.jointCount();
    for (int j = 0; j < n; ++j)
        if (!ch.rotation[j].empty()) sk.joints[j].dof = {true, true, true};
    for (std::size_t f = 0; f < ch.times.size(); ++f) {
        Pose pose;
        pose.anglesDeg.resize(static_cast<std::size_t>(n));
        for (int j = 0; j < n; ++j) {
            Eigen::Quaterniond q = restRotation[j];
            if (!ch.rotation[j].empty()) {
                const float* r = &ch.rotation[j][4 * f];
                q = Eigen::Quaterniond(r[3], r[0], r[1], r[2]).normalized();
            }
            pose.anglesDeg[j] = eulerZYXFromMatrix(q.toRotationMatrix());
        }
        if (!ch.rootTranslation[0].empty()) {
            const float* t = &ch.rootTranslation[0][3 * f];
            pose.rootCm = Eigen::Vector3d(t[0], t[1], t[2]) * kCmPerMetre - sk.joints[0].offsetCm;
        }
        clip.frames.push_back(std::move(pose));
    }
}

}  // namespace

Clip readGltfClip(const std::string& path) {
    const tinygltf::Model model = loadGltfModel(path);
    if (model.skins.empty()) throwParseError(path, 0, "a skin (the skeleton's joints)", "no skin");
    if (model.animations.empty()) throwParseError(path, 0, "an animation", "no animation");
    const GltfJointTree tree = gltfJointTree(path, model, model.skins[0]);

    Clip clip;
    clip.sourcePath = path;
    clip.format = ClipFormat::kGltf;
    clip.convention = "gltf";
    clip.cmPerFileUnit = kCmPerMetre;
    const tinygltf::Animation& animation = model.animations[0];
    clip.name = animation.name.empty() ? fileStem(path) : animation.name;
    clip.skeleton.poseVector = PoseVectorKind::kChannels;
    const std::vector<Eigen::Quaterniond> restRotation = addGltfJoints(path, model, tree, clip);
    const GltfChannels channels = readGltfChannels(path, model, animation, tree, clip.skeleton);
    readGltfTiming(model, channels.times, clip);
    addGltfFrames(channels, restRotation, clip);
    clip.skeleton.resolveEffectors();
    clip.skeleton.validate();
    return clip;
}

}  // namespace mgp
