// `motiongp inbetween MODEL --on CLIP --gaps A:B[,A:B…] --out OUT.bvh|.glb|.gltf|.fbx
//  [--method prior|retrieve|interpolate|hold] [--skel ASF] [--json]`:
// the frames strictly between keys A and B of CLIP (1-based, any clip of the model's skeleton) are
// generated from the keys and the frames around them (motion/inbetween.h); the rest of the clip is
// copied and the whole clip is written.
#include <iostream>
#include <sstream>

#include "cli_common.h"
#include "command_registry.h"
#include "ik_cli.h"
#include "io/clip_loader.h"
#include "io/text_reader.h"
#include "motion/inbetween.h"

namespace mgp::app {
namespace {

struct InbetweenOptions {
    std::string model, on, skel, gaps, out, method = "prior";
    bool json = false;
    int iterations = 100;
};

// "A:B[,A:B…]" (1-based keys) → gaps; the first bad item is named.
std::vector<InbetweenGap> parseGaps(const std::string& text) {
    std::vector<InbetweenGap> gaps;
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
        const std::string_view t = trim(item);
        const std::size_t colon = t.find(':');
        long long a = 0, b = 0;
        if (colon == std::string_view::npos || !parseInt(trim(t.substr(0, colon)), a) ||
            !parseInt(trim(t.substr(colon + 1)), b) || a < 1 || b < 1 || a > 100000000 || b > 100000000)
            throw UsageError(
                "expected --gaps as key frames A:B counted from 1, comma-separated (e.g. 40:100,200:260), found '" +
                std::string(t) + "'");
        gaps.push_back({static_cast<int>(a - 1), static_cast<int>(b - 1)});
    }
    if (gaps.empty() || text.back() == ',') throw UsageError("expected --gaps A:B[,A:B…], found '" + text + "'");
    return gaps;
}

InbetweenMethod parseMethod(const std::string& name) {
    for (InbetweenMethod m :
         {InbetweenMethod::kPrior, InbetweenMethod::kRetrieve, InbetweenMethod::kInterpolate, InbetweenMethod::kHold})
        if (name == inbetweenMethodName(m)) return m;
    throw UsageError("expected --method prior, retrieve, interpolate or hold, found '" + name + "'");
}

nlohmann::json secondDifferenceJson(const SecondDifferenceStats& s) { return {{"p95", s.p95Deg}, {"max", s.maxDeg}}; }

int runInbetween(const InbetweenOptions& o) {
    requireExportPath(o.out);
    InbetweenJob job;
    job.method = parseMethod(o.method);
    job.gaps = parseGaps(o.gaps);
    job.maxIterations = o.iterations;
    job.version = loadModelVersion(o.model);
    job.clip = loadClip(o.on, o.skel);
    if (const std::string problem = job.validate(); !problem.empty()) throw UsageError(problem);
    job.run();
    Clip result = job.clip;
    result.frames = job.frames;
    exportFromCli(result, o.out);
    nlohmann::json gaps = nlohmann::json::array();
    for (const InbetweenJob::GapReport& r : job.reports) {
        nlohmann::json g = {{"a", r.gap.a + 1},
                            {"b", r.gap.b + 1},
                            {"frames", r.gap.b - r.gap.a - 1},
                            {"seconds", r.seconds},
                            {"key_error_cm", r.keyErrorCm},
                            {"second_difference_deg", secondDifferenceJson(r.smoothness)},
                            {"clip_second_difference_deg", secondDifferenceJson(r.reference)}};
        if (!r.sourceClip.empty()) {
            g["source"] = {{"clip", r.sourceClip},
                           {"first", r.sourceFirst + 1},
                           {"last", r.sourceLast + 1},
                           {"time_scale", r.timeScale},
                           {"match_cost", r.matchCost}};
            g["variance"] = {{"mean", r.meanVariance}, {"max", r.maxVariance}};
        }
        if (job.method == InbetweenMethod::kPrior)
            g["span"] = {{"stop", spanStopName(r.stop)},
                         {"iterations", r.iterations},
                         {"held_foot_frames", r.heldFootFrames},
                         {"max_held_residual_cm", r.maxHeldResidualCm}};
        gaps.push_back(g);
    }
    if (o.json)
        printJson({{"method", inbetweenMethodName(job.method)}, {"out", o.out}, {"gaps", gaps}});
    else
        for (const InbetweenJob::GapReport& r : job.reports)
            std::cout << "frames " << r.gap.a + 2 << ".." << r.gap.b << ": " << r.gap.b - r.gap.a - 1 << " frames ("
                      << inbetweenMethodName(job.method) << ") in " << r.seconds << " s, second difference p95 "
                      << r.smoothness.p95Deg << "° (the clip's " << r.reference.p95Deg << "°)\n";
    if (!o.json) std::cout << "wrote " << o.out << "\n";
    return 0;
}

const CommandRegistration inbetweenCommand(
    "inbetween", "Generate the frames between key poses of a clip under the learned prior",
    [](CLI::App& sub) -> CommandRunner {
        auto o = std::make_shared<InbetweenOptions>();
        sub.add_option("model", o->model, "Model file (trained on clips of the same skeleton)")->required();
        sub.add_option("--on", o->on,
                       "The clip whose gaps are filled: AMC, BVH or glTF (any clip of the model's skeleton)")
            ->required();
        sub.add_option("--skel", o->skel, "ASF skeleton for an AMC clip (default: SS.asf beside SS_TT.amc)");
        sub.add_option("--gaps", o->gaps, "Keys A:B counted from 1, comma-separated: frames A+1..B−1 are generated")
            ->required();
        sub.add_option(
            "--method", o->method,
            "prior (default: the best training stretch, warped onto the keys and solved under the learned prior with "
            "planted feet held), retrieve (the warped stretch alone), interpolate or hold (the baselines)");
        sub.add_option("--iterations", o->iterations, "prior: iteration cap per gap")->check(CLI::Range(1, 100000));
        sub.add_option("--out", o->out, "Output .bvh, .glb, .gltf or .fbx (every frame of the clip)")->required();
        sub.add_flag("--json", o->json, "Print one JSON object");
        return [o]() { return runInbetween(*o); };
    });

}  // namespace
}  // namespace mgp::app
