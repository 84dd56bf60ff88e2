// `motiongp export CLIP [--skel ASF] --out FILE.bvh [--json]`: the clip as a cm, Y-up BVH.
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "io/bvh_writer.h"
#include "io/clip_loader.h"

namespace mgp::app {
namespace {

const CommandRegistration exportCommand("export", "Write a clip as BVH (cm, Y up, ASF bone names)",
                              [](CLI::App& sub) -> CommandRunner {
    auto clipPath = std::make_shared<std::string>();
    auto skel = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    sub.add_option("clip", *clipPath, "AMC or BVH file")->required();
    sub.add_option("--skel", *skel, "ASF skeleton for an AMC");
    sub.add_option("--out", *out, "Output .bvh file (written atomically)")->required();
    sub.add_flag("--json", *json, "Print one JSON object");
    return [=]() {
        const Clip clip = loadClip(*clipPath, *skel);
        writeBvh(clip, *out);
        if (*json) printJson({{"out", *out}, {"frames", clip.frameCount()}});
        else std::cout << "wrote " << *out << " (" << clip.frameCount() << " frames)\n";
        return 0;
    };
});

}  // namespace
}  // namespace mgp::app
