// `motiongp fk CLIP [--skel ASF] --frame T [--json]`: effector positions (cm, Y up) of frame T.
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::app {
namespace {

const CommandRegistration fkCommand(
    "fk", "Forward kinematics: root and effector positions of one frame", [](CLI::App& sub) -> CommandRunner {
        auto clipPath = std::make_shared<std::string>();
        auto skel = std::make_shared<std::string>();
        auto frame = std::make_shared<long long>(1);
        auto json = std::make_shared<bool>(false);
        sub.add_option("clip", *clipPath, "AMC or BVH file")->required();
        sub.add_option("--skel", *skel, "ASF skeleton for an AMC");
        sub.add_option("--frame", *frame, "Frame, counted from 1 (whatever the file's own labels)")->required();
        sub.add_flag("--json", *json, "Print one JSON object");
        return [=]() {
            const Clip clip = loadClip(*clipPath, *skel);
            const int index = frameIndexFromCli(clip, *frame);
            nlohmann::json j;
            j["frame"] = *frame;
            j["positions_cm"] = effectorPositionsJson(clip, index);
            // Every joint's position by its file name (a BVH importer's bone heads; tests compare them).
            FkState fk;
            forwardKinematics(clip.skeleton, clip.frames[index], fk);
            nlohmann::json joints = nlohmann::json::object();
            for (int k = 0; k < clip.skeleton.jointCount(); ++k)
                joints[clip.skeleton.joints[k].name] = vec3Json(fk.jointCm[k]);
            j["joints_cm"] = joints;
            if (*json) {
                printJson(j);
            } else {
                std::cout << clip.name << " frame " << *frame << " (cm, Y up):\n";
                for (auto& [k, v] : j["positions_cm"].items()) std::cout << "  " << k << " " << v.dump() << "\n";
            }
            return 0;
        };
    });

}  // namespace
}  // namespace mgp::app
