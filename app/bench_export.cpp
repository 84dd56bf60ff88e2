// bench section "export": writing a 4 000-frame clip as glTF (.glb, .gltf) and BVH, with the
// files' sizes (docs/export.md: at most 1 s, and a .glb at most twice the BVH).
#include <cstdio>
#include <filesystem>

#include "bench_registry.h"
#include "io/bvh_writer.h"
#include "io/clip_loader.h"
#include "io/gltf_writer.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::app {
namespace {

const BenchRegistration exportBench(
    "export", "glTF and BVH export of a 4000-frame clip (seconds, bytes)", [](const BenchContext& ctx) {
        const int frames = ctx.quick ? 1000 : 4000;
        const std::string source = ctx.mocapDir + "/bvh/131_01.bvh";
        const Clip one =
            !ctx.mocapDir.empty() && std::filesystem::exists(source) ? loadClip(source) : makeSyntheticWalk();
        Clip clip;
        while (clip.frameCount() < frames)
            appendFrames(clip, one, 0, std::min(one.frameCount(), frames - clip.frameCount()));
        const std::string glbPath = (std::filesystem::temp_directory_path() / "motiongp_bench_export.glb").string();
        std::vector<double> glb, gltf, glbFile, bvh;
        std::size_t glbBytes = 0, gltfBytes = 0, bvhBytes = 0;
        for (int r = 0; r < ctx.repeats; ++r) {
            glb.push_back(secondsOf([&] { glbBytes = formatGltf(clip, true).size(); }));
            gltf.push_back(secondsOf([&] { gltfBytes = formatGltf(clip, false).size(); }));
            glbFile.push_back(secondsOf([&] { writeGltf(clip, glbPath); }));  // with the atomic write's fsync
            bvh.push_back(secondsOf([&] { bvhBytes = formatBvh(clip).size(); }));
        }
        std::remove(glbPath.c_str());
        return nlohmann::json{{"clip", one.name},
                              {"frames", clip.frameCount()},
                              {"joints", clip.skeleton.jointCount()},
                              {"glb_seconds", summarizeSeconds(glb)},
                              {"gltf_seconds", summarizeSeconds(gltf)},
                              {"glb_file_seconds", summarizeSeconds(glbFile)},
                              {"bvh_seconds", summarizeSeconds(bvh)},
                              {"glb_bytes", glbBytes},
                              {"gltf_bytes", gltfBytes},
                              {"bvh_bytes", bvhBytes},
                              {"glb_over_bvh", static_cast<double>(glbBytes) / static_cast<double>(bvhBytes)}};
    });

}  // namespace
}  // namespace mgp::app
