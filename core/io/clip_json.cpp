#include "io/clip_json.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/parse_error.h"
#include "skeleton/pose_layout.h"

namespace mgp {

namespace {

// Above the readers' 1e6 per value: unwrapping over time (skeleton/clip.h) can carry an angle
// past 1e6 in a saved clip (a model's clip is unwrapped). FK stays finite far beyond this.
constexpr double kMaxAbsPoseDeg = 1e10;
constexpr double kMaxAbsRootCm = 1e9;

nlohmann::json vec3(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& file,
                            const std::string& where) {
    if (!j.is_object() || !j.contains(key))
        throwParseError(file, 0, "field '" + std::string(key) + "' in " + where, "none");
    return j.at(key);
}

Eigen::Vector3d readVec3(const nlohmann::json& j, const std::string& file, const std::string& what) {
    if (!j.is_array() || j.size() != 3) throwParseError(file, 0, "3 numbers for " + what, j.dump());
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
        if (!j[i].is_number()) throwParseError(file, 0, "a number in " + what, j[i].dump());
        v[i] = j[i].get<double>();
    }
    return v;
}

// An integer in [lo, hi]: nlohmann's get<int>() casts a float such as 1e300 with undefined
// behaviour, so check the type and range first.
long long integerOf(const nlohmann::json& v, long long lo, long long hi, const std::string& file,
                    const std::string& what) {
    bool ok = false;
    if (v.is_number_unsigned())  // every non-negative integer; may exceed long long
        ok = v.get<unsigned long long>() <= static_cast<unsigned long long>(hi) && v.get<long long>() >= lo;
    else if (v.is_number_integer())
        ok = v.get<long long>() >= lo && v.get<long long>() <= hi;
    if (!ok) throwParseError(file, 0, "an integer for " + what, v.dump());
    return v.get<long long>();
}

ClipFormat formatFromName(const std::string& s, const std::string& file) {
    if (s == "amc") return ClipFormat::kAmc;
    if (s == "bvh") return ClipFormat::kBvh;
    if (s == "synthetic") return ClipFormat::kSynthetic;
    if (s == "gltf") return ClipFormat::kGltf;
    throwParseError(file, 0, "clip format amc, bvh, gltf or synthetic", "'" + s + "'");
}

}  // namespace

nlohmann::json clipToJson(const Clip& clip) {
    nlohmann::json j;
    j["name"] = clip.name;
    j["format"] = clipFormatName(clip.format);
    j["convention"] = clip.convention;
    j["fps"] = clip.fps;
    j["cm_per_file_unit"] = clip.cmPerFileUnit;
    j["first_frame_label"] = clip.firstFrameLabel;
    j["rest_frame"] = clip.restFrame;
    nlohmann::json joints = nlohmann::json::array();
    for (const Joint& jt : clip.skeleton.joints) {
        nlohmann::json a = nlohmann::json::array();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) a.push_back(jt.axis(r, c));
        joints.push_back({{"name", jt.name},
                          {"bone", jt.bone},
                          {"parent", jt.parent},
                          {"offset_cm", vec3(jt.offsetCm)},
                          {"tail_cm", vec3(jt.tailCm)},
                          {"axis", a},
                          {"order", {jt.order[0], jt.order[1], jt.order[2]}},
                          {"dof", {jt.dof[0], jt.dof[1], jt.dof[2]}}});
    }
    j["joints"] = joints;
    const Eigen::MatrixXd y = poseMatrix(clip);
    nlohmann::json poses = nlohmann::json::array(), roots = nlohmann::json::array();
    for (int t = 0; t < clip.frameCount(); ++t) {
        nlohmann::json row = nlohmann::json::array();
        for (Eigen::Index k = 0; k < y.cols(); ++k) row.push_back(y(t, k));
        poses.push_back(row);
        roots.push_back(vec3(clip.frames[t].rootCm));
    }
    j["poses_deg"] = poses;
    j["root_cm"] = roots;
    return j;
}

Clip clipFromJson(const nlohmann::json& j, const std::string& file) {
    try {
        Clip clip;
        clip.name = field(j, "name", file, "clip").get<std::string>();
        clip.format = formatFromName(field(j, "format", file, "clip").get<std::string>(), file);
        clip.convention = field(j, "convention", file, "clip").get<std::string>();
        clip.fps = field(j, "fps", file, "clip").get<double>();
        clip.cmPerFileUnit = field(j, "cm_per_file_unit", file, "clip").get<double>();
        clip.firstFrameLabel =
            integerOf(field(j, "first_frame_label", file, "clip"), std::numeric_limits<long long>::min(),
                      std::numeric_limits<long long>::max(), file, "first_frame_label");
        clip.restFrame = field(j, "rest_frame", file, "clip").get<bool>();
        clip.sourcePath = "";
        const auto& joints = field(j, "joints", file, "clip");
        if (!joints.is_array() || joints.empty()) throwParseError(file, 0, "a non-empty joint list", joints.dump());
        for (const auto& jj : joints) {
            Joint jt;
            jt.name = field(jj, "name", file, "joint").get<std::string>();
            jt.bone = field(jj, "bone", file, "joint").get<std::string>();
            jt.parent = static_cast<int>(integerOf(field(jj, "parent", file, "joint"), std::numeric_limits<int>::min(),
                                                   std::numeric_limits<int>::max(), file, "parent"));
            jt.offsetCm = readVec3(field(jj, "offset_cm", file, "joint"), file, "offset_cm");
            jt.tailCm = readVec3(field(jj, "tail_cm", file, "joint"), file, "tail_cm");
            const auto& a = field(jj, "axis", file, "joint");
            if (!a.is_array() || a.size() != 9) throwParseError(file, 0, "9 numbers for axis", a.dump());
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) jt.axis(r, c) = a[3 * r + c].get<double>();
            const auto& o = field(jj, "order", file, "joint");
            if (!o.is_array() || o.size() != 3) throwParseError(file, 0, "3 axes for order", o.dump());
            for (int i = 0; i < 3; ++i) {
                const int ax = static_cast<int>(integerOf(o[i], 0, 2, file, "an axis 0..2 in order"));
                if (ax < 0 || ax > 2) throwParseError(file, 0, "an axis 0..2", std::to_string(ax));
                jt.order[i] = ax;
            }
            const auto& dof = field(jj, "dof", file, "joint");
            if (!dof.is_array() || dof.size() != 3) throwParseError(file, 0, "3 flags for dof", dof.dump());
            for (int i = 0; i < 3; ++i) jt.dof[i] = dof[i].get<bool>();
            const int idx = static_cast<int>(clip.skeleton.joints.size());
            if ((idx == 0) != (jt.parent < 0) || jt.parent >= idx)
                throwParseError(file, 0, "parents listed before their children", "joint '" + jt.name + "'");
            clip.skeleton.joints.push_back(jt);
        }
        if (clip.format == ClipFormat::kBvh || clip.format == ClipFormat::kGltf)
            clip.skeleton.poseVector = PoseVectorKind::kChannels;
        clip.skeleton.validate();
        clip.skeleton.resolveEffectors();
        const auto& poses = field(j, "poses_deg", file, "clip");
        const auto& roots = field(j, "root_cm", file, "clip");
        if (!poses.is_array() || !roots.is_array() || poses.size() != roots.size() || poses.empty())
            throwParseError(file, 0, "as many root translations as poses (at least one)",
                            std::to_string(roots.size()) + " and " + std::to_string(poses.size()));
        const PoseLayout layout(clip.skeleton);
        Eigen::VectorXd y(layout.size());
        for (std::size_t t = 0; t < poses.size(); ++t) {
            if (!poses[t].is_array() || poses[t].size() != static_cast<std::size_t>(layout.size()))
                throwParseError(file, 0, std::to_string(layout.size()) + " pose DOFs in frame " + std::to_string(t + 1),
                                poses[t].dump());
            for (int k = 0; k < layout.size(); ++k) {
                y[k] = poses[t][k].get<double>();
                // Beyond this a value is corruption (FK of 1e308 degrees is NaN).
                if (!(std::abs(y[k]) <= kMaxAbsPoseDeg))
                    throwParseError(file, 0, "angles within ±1e10 degrees in clip frame " + std::to_string(t + 1),
                                    poses[t][k].dump());
            }
            Pose p;
            p.rootCm = readVec3(roots[t], file, "root_cm");
            if (!(p.rootCm.cwiseAbs().maxCoeff() <= kMaxAbsRootCm))
                throwParseError(file, 0, "root translations within ±1e9 cm in clip frame " + std::to_string(t + 1),
                                roots[t].dump());
            p.anglesDeg.assign(clip.skeleton.joints.size(), Eigen::Vector3d::Zero());
            layout.apply(y.data(), p);
            clip.frames.push_back(std::move(p));
        }
        return clip;
    } catch (const nlohmann::json::exception& e) {
        throwParseError(file, 0, "a valid clip section", e.what());
    } catch (const std::logic_error& e) {
        throwParseError(file, 0, "a valid skeleton", e.what());
    }
}

}  // namespace mgp
