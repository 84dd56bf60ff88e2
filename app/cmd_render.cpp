// `motiongp render (CLIP [--skel ASF] | MODEL [--clip NAME]) --frame T --out FILE.png [--size WxH]
//  [--camera front|side|three-quarter] [--ghost-captured] [--path EFFECTOR]... [--select EFFECTOR]
//  [--no-handles] [--onion BEFORE:AFTER:SPACING] [--trail PART]... [--trail-frames N] [--json]`:
//  draws one frame offscreen (EGL surfaceless, no display) and writes a PNG.
// The MODEL form (a trained model file) draws one of the model's source clips (--clip NAME, its
// file stem; default the first; --frame counts within it) with the model's own
// reconstruction of frame T — the mean pose f(x_t) at the frame's latent point — so that
// --ghost-captured shows the captured pose beside what the model makes of it.
#include <filesystem>
#include <iostream>
#include <regex>

#include "cli_common.h"
#include "command_registry.h"
#include "gp/model_version.h"
#include "ik/learned_ik.h"
#include "ik_cli.h"
#include "io/clip_loader.h"
#include "render/scene_builder.h"
#include "render/snapshot.h"

namespace mgp::app {
namespace {

Effector effectorFromCli(const std::string& option, const std::string& name) {
    Effector e{};
    if (!parseEffector(name, e))
        throw UsageError("expected " + option + " among {lhand, rhand, lfoot, rfoot, head}, found '" + name + "'");
    return e;
}

// "BEFORE:AFTER:SPACING" (e.g. 2:2:5): ghosts before and after the frame, frames apart.
render::OnionSkin onionFromCli(const std::string& text) {
    std::smatch m;
    const std::string expected = "expected --onion BEFORE:AFTER:SPACING with BEFORE and AFTER in 0.." +
                                 std::to_string(render::kMaxOnionGhosts) + " and SPACING in 1.." +
                                 std::to_string(render::kMaxOnionSpacing) + " (e.g. 2:2:5), found '" + text + "'";
    if (!std::regex_match(text, m, std::regex(R"((\d{1,2}):(\d{1,2}):(\d{1,3}))"))) throw UsageError(expected);
    const render::OnionSkin o{std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3])};
    if (o.before > render::kMaxOnionGhosts || o.after > render::kMaxOnionGhosts || o.spacing < 1 ||
        o.spacing > render::kMaxOnionSpacing)
        throw UsageError(expected);
    return o;
}

render::TrailPart trailFromCli(const std::string& name) {
    render::TrailPart part{};
    if (!render::parseTrailPart(name, part))
        throw UsageError("expected --trail among {lhand, rhand, lfoot, rfoot, head, root}, found '" + name + "'");
    return part;
}

const CommandRegistration renderCommand(
    "render", "Draw one frame offscreen to a PNG (no display needed)", [](CLI::App& sub) -> CommandRunner {
        auto input = std::make_shared<std::string>();
        auto skel = std::make_shared<std::string>();
        auto frame = std::make_shared<long long>(1);
        auto out = std::make_shared<std::string>();
        auto size = std::make_shared<std::string>("1280x720");
        auto camera = std::make_shared<std::string>("three-quarter");
        auto ghost = std::make_shared<bool>(false);
        auto paths = std::make_shared<std::vector<std::string>>();
        auto select = std::make_shared<std::string>();
        auto clipName = std::make_shared<std::string>();
        auto noHandles = std::make_shared<bool>(false);
        auto onion = std::make_shared<std::string>();
        auto trails = std::make_shared<std::vector<std::string>>();
        auto trailFrames = std::make_shared<int>(30);
        auto json = std::make_shared<bool>(false);
        sub.add_option("input", *input, "CLIP (AMC or BVH file) or MODEL (a file written by `motiongp train`)")
            ->required();
        sub.add_option("--skel", *skel, "ASF skeleton for an AMC (default: SS.asf beside SS_TT.amc)");
        sub.add_option("--clip", *clipName, "NAME: with a MODEL, which of its clips (file stem; default: the first)");
        sub.add_option("--frame", *frame, "Frame, counted from 1")->required();
        sub.add_option("--out", *out, "PNG file to write (atomically)")->required();
        sub.add_option("--size", *size, "Image size WxH (default 1280x720)");
        sub.add_option("--camera", *camera, "front | side | three-quarter (relative to where the character faces)");
        sub.add_flag("--ghost-captured", *ghost, "Also draw the captured pose as a ghost beside the shown one");
        sub.add_option("--path", *paths, "Draw this effector's trajectory (±60 frames, keys every 20)");
        sub.add_option("--select", *select, "Show this effector's handle as selected");
        sub.add_flag("--no-handles", *noHandles, "Hide the effector handles");
        sub.add_option("--onion", *onion,
                       "BEFORE:AFTER:SPACING: onion skins, e.g. 2:2:5 (two ghosts each side, 5 frames apart)");
        sub.add_option("--trail", *trails,
                       "Draw this point's motion trail, a tick per frame (lhand rhand lfoot rfoot head root)");
        sub.add_option("--trail-frames", *trailFrames, "Frames each side the trails span (default 30)");
        sub.add_flag("--json", *json, "Print one JSON object");
        return [=]() {
            std::smatch m;
            if (!std::regex_match(*size, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
                throw UsageError("expected --size WxH (e.g. 1280x720), found '" + *size + "'");
            const int width = std::stoi(m[1]), height = std::stoi(m[2]);
            if (width < 16 || height < 16 || width > 8192 || height > 8192)
                throw UsageError("expected --size between 16x16 and 8192x8192, found '" + *size + "'");
            render::CameraPreset preset{};
            if (!render::parseCameraPreset(camera->c_str(), preset))
                throw UsageError("expected --camera among {front, side, three-quarter}, found '" + *camera + "'");

            const std::filesystem::path outDir = std::filesystem::path(*out).parent_path();
            if (!outDir.empty() && !std::filesystem::is_directory(outDir))
                throw UsageError("expected --out in an existing folder, found '" + *out + "'");
            render::ClipSceneOptions opt;
            gp::ModelVersionPtr model;
            if (!isClipPath(*input))
                model = loadModelVersion(*input, *clipName);  // a clear error if it is not a model file
            else if (!clipName->empty())
                throw UsageError("expected --clip only with a MODEL, found it with the clip '" + *input + "'");
            const Clip clip = model ? model->model->clip : loadClip(*input, *skel);
            opt.frameIndex = frameIndexFromCli(clip, *frame);
            if (model) {
                const gp::GpModel& m = *model->model;
                Eigen::VectorXd mean;
                double variance = 0.0;
                model->posterior->predict(latentStartForFrame(*model, opt.frameIndex), mean, variance);
                Pose reconstructed = clip.frames[opt.frameIndex];
                const Eigen::VectorXd full = m.fullPose(mean);
                PoseLayout(clip.skeleton).apply(full.data(), reconstructed);
                opt.editedPose = reconstructed;
            }
            opt.ghostCaptured = *ghost;
            opt.handles = !*noHandles;
            for (const std::string& p : *paths) opt.paths.push_back(effectorFromCli("--path", p));
            if (!select->empty()) opt.selected = effectorFromCli("--select", *select);
            if (!onion->empty()) opt.onion = onionFromCli(*onion);
            for (const std::string& t : *trails) {
                opt.trails.push_back(trailFromCli(t));
                if (!render::hasTrailPart(clip.skeleton, opt.trails.back()))
                    throw UsageError("expected --trail a point this skeleton has, found '" + t +
                                     "' (no such joint in " + clip.name + ")");
            }
            if (*trailFrames < 1)
                throw UsageError("expected --trail-frames of at least 1, found " + std::to_string(*trailFrames));
            opt.trailHalfSpan = *trailFrames;
            const render::Scene scene = render::buildClipScene(clip, opt);

            FkState fk;
            forwardKinematics(clip.skeleton, clip.frames[opt.frameIndex], fk);
            render::OffscreenContext context(width, height);
            render::SceneRenderer renderer;
            const render::OrbitCamera cam =
                render::framedPresetCamera(preset, scene, render::characterForward(clip.skeleton, fk), width, height);
            render::writePng(render::snapshot(context, renderer, scene, cam), *out);
            if (*json) {
                printJson({{"out", *out},
                           {"width", width},
                           {"height", height},
                           {"clip", clip.name},
                           {"frame", *frame},
                           {"camera", render::cameraPresetName(preset)},
                           {"model", model != nullptr}});
            } else {
                std::cout << "wrote " << *out << " (" << width << "x" << height << ", " << clip.name << " frame "
                          << *frame << ", " << render::cameraPresetName(preset) << " camera)\n";
            }
            return 0;
        };
    });

}  // namespace
}  // namespace mgp::app
