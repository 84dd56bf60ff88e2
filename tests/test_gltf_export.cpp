// glTF export and import: the file's structure (skin on a mesh, one animation keyed per frame,
// quaternions continuous in sign, metres), the round trip through our reader against FK on every
// frame, the size against BVH, and clear errors for bad input. The real clients (the Khronos
// validator, Blender) check the same exports in tests/gltf/.
#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "io/bvh_writer.h"
#include "io/clip_export.h"
#include "io/clip_loader.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/parse_error.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

namespace {

tinygltf::Model parsedGltf(const std::string& bytes, bool binary) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, static_cast<unsigned>(bytes.size()))
               : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()), "");
    REQUIRE_MESSAGE(ok, err);
    return model;
}

std::vector<float> floatsOf(const tinygltf::Model& m, int accessor) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
    REQUIRE(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const std::size_t n =
        a.count * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)));
    std::vector<float> out(n);
    std::memcpy(out.data(), &m.buffers.at(0).data.at(v.byteOffset + a.byteOffset), n * sizeof(float));
    return out;
}

// The worst distance between two clips' joints (by index) over every frame, cm.
double worstJointGapCm(const Clip& a, const Clip& b) {
    REQUIRE(a.frameCount() == b.frameCount());
    REQUIRE(a.skeleton.jointCount() == b.skeleton.jointCount());
    FkState fa, fb;
    double worst = 0.0;
    for (int t = 0; t < a.frameCount(); ++t) {
        forwardKinematics(a.skeleton, a.frames[t], fa);
        forwardKinematics(b.skeleton, b.frames[t], fb);
        for (int j = 0; j < a.skeleton.jointCount(); ++j)
            worst = std::max(worst, (fa.jointCm[j] - fb.jointCm[j]).norm());
        for (int e = 0; e < kEffectorCount; ++e) {
            const auto eff = static_cast<Effector>(e);
            if (a.skeleton.hasEffector(eff))
                worst = std::max(worst, (effectorCm(a.skeleton, fa, eff) - effectorCm(b.skeleton, fb, eff)).norm());
        }
    }
    return worst;
}

}  // namespace

TEST_CASE("glTF export: a skinned figure, one animation keyed per frame, quaternions continuous in sign") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const int n = clip.skeleton.jointCount();
    const tinygltf::Model m = parsedGltf(formatGltf(clip, true), true);
    CHECK(m.asset.version == "2.0");
    REQUIRE(m.nodes.size() == static_cast<std::size_t>(n) + 1);  // the joints and the figure
    for (int j = 0; j < n; ++j) CHECK(m.nodes[j].name == clip.skeleton.joints[j].name);
    // The lfemur's rest translation is its offset in metres.
    const int femur = clip.skeleton.findBone("lfemur");
    REQUIRE(femur > 0);
    for (int k = 0; k < 3; ++k)
        CHECK(m.nodes[femur].translation.at(k) == doctest::Approx(clip.skeleton.joints[femur].offsetCm[k] / 100.0));
    REQUIRE(m.skins.size() == 1);
    CHECK(m.skins[0].joints.size() == static_cast<std::size_t>(n));
    CHECK(m.nodes[n].skin == 0);
    CHECK(m.nodes[n].mesh == 0);
    CHECK(m.nodes[n].translation.empty());
    REQUIRE(m.scenes.size() == 1);
    CHECK(m.scenes[0].nodes == std::vector<int>{0, n});
    // The inverse bind matrix of a joint undoes its world rest position.
    const std::vector<float> ibm = floatsOf(m, m.skins[0].inverseBindMatrices);
    Eigen::Vector3d restFemur = Eigen::Vector3d::Zero();
    for (int j = femur; j >= 0; j = clip.skeleton.joints[j].parent)
        restFemur += clip.skeleton.joints[j].offsetCm / 100.0;
    for (int k = 0; k < 3; ++k) CHECK(ibm[16 * femur + 12 + k] == doctest::Approx(-restFemur[k]).epsilon(1e-6));

    REQUIRE(m.animations.size() == 1);
    const tinygltf::Animation& anim = m.animations[0];
    CHECK(anim.name == clip.name);
    CHECK(anim.channels.size() == static_cast<std::size_t>(n) + 1);  // every rotation and the root's translation
    const std::vector<float> times = floatsOf(m, anim.samplers[0].input);
    REQUIRE(times.size() == static_cast<std::size_t>(clip.frameCount()));
    CHECK(times[1] - times[0] == doctest::Approx(1.0 / clip.fps).epsilon(1e-5));
    CHECK(times.back() == doctest::Approx((clip.frameCount() - 1) / clip.fps).epsilon(1e-6));
    int rotations = 0;
    for (const tinygltf::AnimationChannel& ch : anim.channels) {
        CHECK(anim.samplers[ch.sampler].interpolation == "LINEAR");
        CHECK(anim.samplers[ch.sampler].input == anim.samplers[0].input);
        if (ch.target_path != "rotation") {
            CHECK(ch.target_path == "translation");
            CHECK(ch.target_node == 0);
            continue;
        }
        ++rotations;
        const std::vector<float> q = floatsOf(m, anim.samplers[ch.sampler].output);
        for (std::size_t f = 0; f < times.size(); ++f) {
            const Eigen::Vector4f now(&q[4 * f]);
            CHECK(now.norm() == doctest::Approx(1.0).epsilon(1e-5));
            if (f > 0) CHECK(now.dot(Eigen::Vector4f(&q[4 * (f - 1)])) >= 0.0f);
        }
    }
    CHECK(rotations == n);
    CHECK(m.asset.extras.Get("source_clip").Get<std::string>() == clip.name);
    CHECK(m.asset.extras.Get("fps").GetNumberAsDouble() == clip.fps);
}

TEST_CASE("glTF round trip: our reader gives back every joint where FK puts it, on every frame and every source") {
    const std::string dir = test::scratchDir("gltf_export");
    std::vector<Clip> clips{makeSyntheticWalk()};
    for (const char* shipped : {"asf_amc/35_01.amc", "bvh/02_03.bvh", "bvh/49_04.bvh", "bvh/131_01.bvh"})
        clips.push_back(loadClip(test::mocap(shipped)));
    for (const Clip& clip : clips) {
        for (const std::string ext : {".glb", ".gltf"}) {
            CAPTURE(clip.name);
            CAPTURE(ext);
            const std::string path = dir + "/" + clip.name + ext;
            exportClip(clip, path);
            const Clip back = loadClip(path);
            CHECK(back.format == ClipFormat::kGltf);
            CHECK(back.name == clip.name);
            CHECK(back.fps == clip.fps);
            CHECK(back.frameCount() == clip.frameCount());
            CHECK(back.restFrame == clip.restFrame);
            REQUIRE(back.skeleton.jointCount() == clip.skeleton.jointCount());
            for (int j = 0; j < clip.skeleton.jointCount(); ++j) {
                CHECK(back.skeleton.joints[j].name == clip.skeleton.joints[j].name);
                CHECK(back.skeleton.joints[j].parent == clip.skeleton.joints[j].parent);
                CHECK(back.skeleton.joints[j].bone == clip.skeleton.joints[j].bone);
            }
            for (int e = 0; e < kEffectorCount; ++e)
                CHECK(back.skeleton.hasEffector(static_cast<Effector>(e)) ==
                      clip.skeleton.hasEffector(static_cast<Effector>(e)));
            // Single-precision floats in metres: a few 1e-5 cm over a 2 m body.
            const double gap = worstJointGapCm(clip, back);
            MESSAGE(clip.name << ext << ": worst joint/effector gap " << gap << " cm");
            CHECK(gap < 1e-3);
        }
    }
}

TEST_CASE("glTF export is no larger than twice the BVH of the same motion") {
    for (const std::string shipped : {"asf_amc/35_01.amc", "bvh/131_01.bvh"}) {
        const Clip clip = loadClip(test::mocap(shipped));
        const std::size_t glb = formatGltf(clip, true).size(), bvh = formatBvh(clip).size();
        MESSAGE(shipped << ": .glb " << glb << " bytes, .bvh " << bvh << " bytes");
        CHECK(glb <= 2 * bvh);
    }
}

TEST_CASE("glTF: bad input gets one clear error") {
    const std::string dir = test::scratchDir("gltf_bad");
    const Clip clip = makeSyntheticWalk();
    auto messageOf = [](auto&& f) -> std::string {
        try {
            f();
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    CHECK(messageOf([&] { exportClip(clip, dir + "/motion.fbx.txt"); }) ==
          dir + "/motion.fbx.txt: expected an output file ending in .bvh, .glb, .gltf or .fbx, found '.txt'");
    Clip empty = clip;
    empty.frames.clear();
    CHECK(messageOf([&] { formatGltf(empty, true); }).find("expected a clip with joints and frames") !=
          std::string::npos);

    // A truncated binary file and a glTF with no skin: ParseErrors naming the file, never a crash.
    const std::string glb = formatGltf(clip, true);
    test::writeText(dir + "/cut.glb", glb.substr(0, glb.size() / 2));
    std::string why = messageOf([&] { readGltfClip(dir + "/cut.glb"); });
    CHECK(why.rfind(dir + "/cut.glb: expected a binary glTF 2.0 file, found ", 0) == 0);
    test::writeText(dir + "/noskin.gltf",
                    R"({"asset": {"version": "2.0"}, "nodes": [{"name": "a"}], "scenes": [{"nodes": [0]}]})");
    CHECK(messageOf([&] { readGltfClip(dir + "/noskin.gltf"); }) ==
          dir + "/noskin.gltf: expected a skin (the skeleton's joints), found no skin");
    test::writeText(dir + "/text.gltf", "not json");
    why = messageOf([&] { readGltfClip(dir + "/text.gltf"); });
    CHECK(why.rfind(dir + "/text.gltf: expected a glTF 2.0 JSON file, found ", 0) == 0);
}

TEST_CASE("glTF reader: a damaged file of ours is refused with what was expected, never read past its buffer") {
    const std::string dir = test::scratchDir("gltf_damaged");
    const nlohmann::json good = nlohmann::json::parse(formatGltf(makeSyntheticWalk(30), false));
    struct Damage {
        const char* what;
        std::function<void(nlohmann::json&)> apply;
        const char* expected;  // the message's "expected ..." part
    };
    const std::vector<Damage> damages{
        {"a rotation accessor longer than its buffer view",
         [](nlohmann::json& j) {
             const int a = j["animations"][0]["samplers"][1]["output"];
             j["accessors"][a]["count"] = 100000;
         },
         "expected rotations of 'root' as a float accessor of 4 component(s), found 100000 elements that run past "
         "their buffer"},
        {"a key time accessor of integers",
         [](nlohmann::json& j) {
             j["accessors"][j["animations"][0]["samplers"][0]["input"].get<int>()]["componentType"] = 5125;
         },
         "expected key times as a float accessor of 1 component(s), found component type 5125"},
        {"a channel on a missing sampler", [](nlohmann::json& j) { j["animations"][0]["channels"][1]["sampler"] = 99; },
         "expected a channel with a sampler, found sampler 99"},
        {"cubic spline keys",
         [](nlohmann::json& j) { j["animations"][0]["samplers"][1]["interpolation"] = "CUBICSPLINE"; },
         "expected LINEAR or STEP keys, found CUBICSPLINE"},
        {"a scaled joint",
         [](nlohmann::json& j) {
             j["nodes"][1]["scale"] = {2.0, 2.0, 2.0};
         },
         "expected joints with scale 1"},
        {"a second root",
         [](nlohmann::json& j) {
             for (auto& n : j["nodes"]) {
                 auto& c = n["children"];
                 if (c.is_array()) c.erase(std::remove(c.begin(), c.end(), 1), c.end());
             }
         },
         "expected one root joint"},
        {"translation on a child joint",
         [](nlohmann::json& j) { j["animations"][0]["channels"][0]["target"]["node"] = 1; },
         "expected translation animated on the root joint only"},
    };
    for (const Damage& d : damages) {
        CAPTURE(std::string(d.what));
        nlohmann::json j = good;
        d.apply(j);
        const std::string path = dir + "/damaged.gltf";
        test::writeText(path, j.dump());
        std::string why;
        try {
            readGltfClip(path);
        } catch (const ParseError& e) {
            why = e.what();
        }
        INFO(why);
        CHECK(why.rfind(path + ": ", 0) == 0);
        CHECK(why.find(d.expected) != std::string::npos);
    }
}

TEST_CASE("FBX export without Blender, or with a Blender that fails, says so and leaves no file behind") {
    const std::string dir = test::scratchDir("fbx_export");
    const std::string clip = test::mocap("bvh/02_03.bvh"), out = dir + "/motion.fbx";
    auto exportWith = [&](const std::string& blender) {
        test::CliLimits limits;
        limits.env = {{"MOTIONGP_BLENDER", blender}};
        return test::runCliArgs({"export", clip, "--out", out}, limits);
    };
    test::CliResult r = exportWith(dir + "/no-such-blender");
    CHECK(r.exitCode == 1);
    CHECK(r.err == "motiongp: error: " + out +
                       ": FBX export needs Blender (apt-get install blender, or set MOTIONGP_BLENDER), "
                       "found MOTIONGP_BLENDER=" +
                       dir +
                       "/no-such-blender, which is not an executable file; glTF (.glb) needs "
                       "nothing else\n");
    CHECK_FALSE(std::filesystem::exists(out));

    // A "Blender" that prints and fails: its last lines reach the user, and the temporary glTF and
    // log beside the target are gone.
    const std::string fake = dir + "/fake-blender";
    test::writeText(
        fake,
        "#!/bin/sh\necho 'Error: Python: Traceback (most recent call last):'\necho 'ImportError: no glTF'\nexit 1\n");
    std::filesystem::permissions(fake, std::filesystem::perms::owner_all | std::filesystem::perms::group_read |
                                           std::filesystem::perms::group_exec | std::filesystem::perms::others_read |
                                           std::filesystem::perms::others_exec);
    r = exportWith(fake);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find(out + ": expected Blender to write the FBX, found exit status 1; Blender's last lines:") !=
          std::string::npos);
    CHECK(r.err.find("ImportError: no glTF") != std::string::npos);
    std::vector<std::string> left;
    for (const auto& e : std::filesystem::directory_iterator(dir)) left.push_back(e.path().filename().string());
    std::sort(left.begin(), left.end());
    CHECK(left == std::vector<std::string>{"fake-blender"});
}
