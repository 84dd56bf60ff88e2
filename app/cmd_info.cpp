// `motiongp info CLIP [--skel ASF] [--json]`: what a clip holds, in the model's terms.
#include <iostream>

#include <cstdlib>

#include "cli_common.h"
#include "command_registry.h"
#include "gui_run.h"
#include "io/clip_loader.h"
#include "io/data_paths.h"
#include "skeleton/pose_layout.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::app {

namespace {

nlohmann::json clipInfoJson(const Clip& clip) {
    const auto missing = missingModelBones(clip.skeleton);
    const Eigen::MatrixXd y = poseMatrix(clip);
    nlohmann::json j;
    j["clip"] = clip.name;
    j["format"] = clipFormatName(clip.format);
    j["convention"] = clip.convention;
    j["frames"] = clip.frameCount();
    j["joints"] = clip.skeleton.jointCount();
    j["fps"] = clip.fps;
    j["bones"] = kModelBones - static_cast<int>(missing.size());
    const int rotationDofs = PoseLayout(clip.skeleton).size();
    j["dof"] = rotationDofs + 3;  // + root translation
    j["rot_dof"] = rotationDofs;
    j["constant_dofs"] = constantColumns(y);
    j["unmapped"] = clip.unmappedJoints;
    j["missing_bones"] = missing;
    j["rest_frame"] = clip.restFrame;
    j["cm_per_file_unit"] = clip.cmPerFileUnit;
    j["first_frame_label"] = clip.firstFrameLabel;
    return j;
}

void printHuman(const nlohmann::json& j) {
    std::cout << j["clip"].get<std::string>() << ": " << j["format"].get<std::string>() << " ("
              << j["convention"].get<std::string>() << "), " << j["frames"] << " frames at " << j["fps"] << " fps, "
              << j["joints"] << " joints, " << j["bones"] << " of 22 bones, constant DOFs " << j["constant_dofs"].dump()
              << ", rest frame " << (j["rest_frame"].get<bool>() ? "yes" : "no") << "\n";
    if (!j["unmapped"].empty()) std::cout << "  unmapped joints: " << j["unmapped"].dump() << "\n";
    if (!j["missing_bones"].empty())
        std::cout << "  bones missing from the file (held at 0): " << j["missing_bones"].dump() << "\n";
}

const CommandRegistration infoCommand(
    "info", "Summarise a clip (frames, fps, DOFs, constant columns)", [](CLI::App& sub) -> CommandRunner {
        auto clipPath = std::make_shared<std::string>();
        auto skel = std::make_shared<std::string>();
        auto json = std::make_shared<bool>(false);
        sub.add_option("clip", *clipPath, "AMC, BVH or glTF (.glb, .gltf) file")->required();
        sub.add_option("--skel", *skel, "ASF skeleton for an AMC (default: SS.asf beside SS_TT.amc)");
        sub.add_flag("--json", *json, "Print one JSON object");
        return [=]() {
            const Clip clip = loadClip(*clipPath, *skel);
            const nlohmann::json j = clipInfoJson(clip);
            if (*json)
                printJson(j);
            else
                printHuman(j);
            return 0;
        };
    });

}  // namespace

int runDefault() {
    // `motiongp` with no verb opens the editor on the default clip (the 10_02 kick, else the
    // synthetic demo clip) when a display is available; otherwise it says how to run it.
    const auto dir = findEditorMocapFolder(globalOptions().dataDir, globalOptions().exeDir);
    if (!globalOptions().dataDir.empty() && !dir)
        throw UsageError("expected --data to name a folder holding asf_amc/ or bvh/, found '" +
                         globalOptions().dataDir + "'");
    const char* display = std::getenv("DISPLAY");
    if (display && *display) return runGui(GuiArgs{});
    const auto clipPath = dir ? defaultClipIn(*dir) : std::nullopt;
    if (clipPath) {
        printHuman(clipInfoJson(loadClip(*clipPath)));
    } else {
        std::cout << "No mocap folder found: the editor opens the built-in synthetic demo clip.\n";
        printHuman(clipInfoJson(makeSyntheticWalk()));
    }
    std::cout << "motiongp: no display: run `xvfb-run -a -s '-screen 0 1280x800x24' motiongp` for the editor, or "
                 "`motiongp gui --offscreen --frames 3 --screenshot out.png` (default clip: "
              << (clipPath ? *clipPath : std::string("synthetic demo, no mocap folder found")) << ")\n";
    return 0;
}

}  // namespace mgp::app
