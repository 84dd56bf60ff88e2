// `motiongp export CLIP [--skel ASF] --out FILE.bvh|.glb|.gltf|.fbx [--json]`: the clip as BVH
// (cm, Y up), glTF 2.0 (metres, Y up, a skinned figure and one animation) or FBX (that glTF
// converted by Blender); docs/export.md.
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "io/clip_loader.h"

namespace mgp::app {
namespace {

const CommandRegistration exportCommand(
    "export", "Write a clip as BVH, glTF 2.0 or FBX (.bvh, .glb, .gltf, .fbx)", [](CLI::App& sub) -> CommandRunner {
        auto clipPath = std::make_shared<std::string>();
        auto skel = std::make_shared<std::string>();
        auto out = std::make_shared<std::string>();
        auto json = std::make_shared<bool>(false);
        sub.add_option("clip", *clipPath, "AMC, BVH or glTF file")->required();
        sub.add_option("--skel", *skel, "ASF skeleton for an AMC");
        sub.add_option("--out", *out, "Output .bvh, .glb, .gltf or .fbx (needs Blender) file, written atomically")
            ->required();
        sub.add_flag("--json", *json, "Print one JSON object");
        return [=]() {
            requireExportPath(*out);
            const Clip clip = loadClip(*clipPath, *skel);
            exportFromCli(clip, *out);
            if (*json)
                printJson({{"out", *out}, {"frames", clip.frameCount()}, {"joints", clip.skeleton.jointCount()}});
            else
                std::cout << "wrote " << *out << " (" << clip.frameCount() << " frames)\n";
            return 0;
        };
    });

}  // namespace
}  // namespace mgp::app
