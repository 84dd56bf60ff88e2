#include "cli_common.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "io/clip_export.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::app {

void printJson(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

int frameIndexFromCli(const Clip& clip, long long frame) {
    if (frame < 1 || frame > clip.frameCount())
        throw UsageError("expected --frame in 1.." + std::to_string(clip.frameCount()) +
                         " (clip frames counted from 1), found " + std::to_string(frame));
    return static_cast<int>(frame - 1);
}

nlohmann::json vec3Json(const Eigen::Vector3d& v) {
    // Round to 1e-9 cm so the printed numbers are short but still exact for any test.
    auto r = [](double x) { return std::round(x * 1e9) / 1e9; };
    return nlohmann::json::array({r(v.x()), r(v.y()), r(v.z())});
}

nlohmann::json effectorPositionsJson(const Clip& clip, int frameIndex) {
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[frameIndex], fk);
    nlohmann::json out;
    out["root"] = vec3Json(fk.jointCm[0]);
    for (int e = 0; e < kEffectorCount; ++e) {
        const auto eff = static_cast<Effector>(e);
        out[effectorName(eff)] =
            clip.skeleton.hasEffector(eff) ? vec3Json(effectorCm(clip.skeleton, fk, eff)) : nlohmann::json(nullptr);
    }
    return out;
}

void requireExportPath(const std::string& out) {
    if (!isExportPath(out))
        throw UsageError("expected --out to end in " + std::string(exportExtensions()) + ", found '" + out + "'");
}

void exportFromCli(const Clip& clip, const std::string& out) {
    exportClip(clip, out, [](const std::string& stage) { std::cerr << stage << "\n"; });
}

void printClaims(const nlohmann::json& claims) {
    for (const auto& c : claims) {
        const auto& p = c["pooled"];
        std::printf("claim: %s\n  %s: %d of %d pairs favour it, %d against, %d ties; p = %.3g -> %s\n",
                    c["claim"].get<std::string>().c_str(), c["test"].get<std::string>().c_str(),
                    p["positive"].get<int>(), p["pairs"].get<int>(), p["negative"].get<int>(), p["zero"].get<int>(),
                    p["p"].get<double>(), c["verdict"].get<std::string>().c_str());
    }
}

}  // namespace mgp::app
