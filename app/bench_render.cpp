// bench section "render": one 1280×720 frame of the editor scene (35_01 frame 1, three-quarter
// camera, handles and a path) drawn offscreen (EGL pbuffer, 4x MSAA, llvmpipe), and the PNG
// capture: read back, encode, and read back + encode + atomic write.
#include <GL/gl.h>

#include <unistd.h>

#include <filesystem>

#include "bench_registry.h"
#include "io/clip_loader.h"
#include "render/scene_builder.h"
#include "render/snapshot.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::app {
namespace {

const BenchRegistration renderBench(
    "render", "Offscreen frame time at 1280x720 and PNG capture time", [](const BenchContext& ctx) {
        const Clip clip = ctx.mocapDir.empty() ? makeSyntheticWalk() : loadClip(ctx.mocapDir + "/asf_amc/35_01.amc");
        render::ClipSceneOptions opt;
        opt.paths = {Effector::kRFoot};
        const render::Scene scene = render::buildClipScene(clip, opt);
        FkState fk;
        forwardKinematics(clip.skeleton, clip.frames[0], fk);
        const int width = 1280, height = 720;
        render::OffscreenContext context(width, height);
        const render::GlInfo info = render::currentGlInfo();
        render::SceneRenderer renderer;
        const render::OrbitCamera cam = render::framedPresetCamera(
            render::CameraPreset::kThreeQuarter, scene, render::characterForward(clip.skeleton, fk), width, height);
        for (int i = 0; i < 3; ++i) renderer.draw(scene, cam, width, height, 0);  // warm-up (shader JIT)
        glFinish();
        const int frames = ctx.quick ? 5 : 30;
        std::vector<double> frameSamples, readSamples, encodeSamples, writeSamples;
        for (int r = 0; r < ctx.repeats; ++r)
            for (int i = 0; i < frames; ++i)
                frameSamples.push_back(secondsOf([&] {
                    renderer.draw(scene, cam, width, height, 0);
                    glFinish();
                }));
        // The same frame with nothing in it (clear, background, MSAA resolve): llvmpipe's floor on this
        // machine, so the scene's own cost can be read off (and the effect of a concurrent load seen).
        const render::Scene empty;
        std::vector<double> emptySamples;
        for (int r = 0; r < ctx.repeats; ++r)
            for (int i = 0; i < frames; ++i)
                emptySamples.push_back(secondsOf([&] {
                    renderer.draw(empty, cam, width, height, 0);
                    glFinish();
                }));
        // The same scene without antialiasing (what a UI could choose on a slow software rasteriser).
        std::vector<double> noMsaaSamples;
        {
            render::SceneRenderer plain(1);
            for (int i = 0; i < 3; ++i) plain.draw(scene, cam, width, height, 0);
            for (int r = 0; r < ctx.repeats; ++r)
                for (int i = 0; i < frames; ++i)
                    noMsaaSamples.push_back(secondsOf([&] {
                        plain.draw(scene, cam, width, height, 0);
                        glFinish();
                    }));
        }
        renderer.draw(scene, cam, width, height, 0);  // the capture below reads the scene's frame
        glFinish();
        const std::string path =
            (std::filesystem::temp_directory_path() / ("motiongp_bench_render_" + std::to_string(::getpid()) + ".png"))
                .string();
        render::Image img;
        std::vector<std::uint8_t> png;
        for (int r = 0; r < ctx.repeats; ++r) {
            readSamples.push_back(secondsOf([&] { img = render::readFramebuffer(width, height); }));
            encodeSamples.push_back(secondsOf([&] { png = render::encodePng(img); }));
            writeSamples.push_back(secondsOf([&] { render::writePng(render::readFramebuffer(width, height), path); }));
        }
        std::filesystem::remove(path);
        return nlohmann::json{{"clip", clip.name},
                              {"size", {width, height}},
                              {"renderer", info.renderer},
                              {"msaa_samples", renderer.msaaSamples()},
                              {"frame_seconds", summarizeSeconds(frameSamples)},
                              {"empty_frame_seconds", summarizeSeconds(emptySamples)},
                              {"frame_no_msaa_seconds", summarizeSeconds(noMsaaSamples)},
                              {"readback_seconds", summarizeSeconds(readSamples)},
                              {"png_encode_seconds", summarizeSeconds(encodeSamples)},
                              {"png_capture_seconds", summarizeSeconds(writeSamples)},
                              {"png_bytes", png.size()}};
    });

}  // namespace
}  // namespace mgp::app
