// Writes the model and session seed corpora for the fuzz targets (run by run_fuzz.sh):
//   motiongp_fuzz_seeds OUTDIR [ASF AMC]
// OUTDIR/model/tiny.json: a FASGPLVM trained on frames 1–40 of the AMC (M = 20, T = 1), or on a
// 40-frame synthetic walk without a clip; OUTDIR/session/*.json: a synthetic-clip session with
// an edit, pins and a path, and one that carries the model. Mocap files are only read.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "io/amc_reader.h"
#include "io/asf_reader.h"
#include "session/session_file.h"
#include "skeleton/synthetic_clip.h"

namespace {
void write(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error(path + ": expected a writable file, found an error");
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::cerr << "usage: motiongp_fuzz_seeds OUTDIR [ASF AMC]\n";
        return 2;
    }
    try {
        const std::string out = argv[1];
        mgp::Clip clip;
        if (argc == 4) {
            const mgp::Clip full = mgp::readAmc(argv[3], mgp::readAsf(argv[2]));
            mgp::appendFrames(clip, full, 0, std::min(40, full.frameCount()));
        } else {
            clip = mgp::makeSyntheticWalk(40);
        }
        mgp::unwrapClip(clip);
        std::vector<int> frames;
        for (int f = 0; f < clip.frameCount(); ++f) frames.push_back(f);
        mgp::gp::TrainOptions opt;
        opt.activeSize = 20;
        opt.outerIterations = 1;
        opt.scgIterations = 5;
        opt.pointIterations = 5;
        opt.threads = 1;
        mgp::gp::TrainResult res = mgp::gp::train(mgp::gp::trainingDataFromClip(clip, frames), opt);
        res.model.clip = clip;
        res.model.sourceFile = clip.name + ".amc";
        res.model.settings.frameFirst = 1;
        res.model.settings.frameLast = clip.frameCount();
        write(out + "/model/tiny.json", mgp::gp::modelToJsonText(res.model));

        mgp::SessionData s;
        s.syntheticClip = true;
        s.syntheticFrames = 40;
        const mgp::Clip walk = mgp::makeSyntheticWalk(40);
        mgp::EditRecord edit;
        edit.pose = walk.frames[5];
        s.edits[5] = edit;
        s.frame = 5;
        s.pins[static_cast<int>(mgp::Effector::kLFoot)] = true;
        s.selectedEffector = static_cast<int>(mgp::Effector::kRHand);
        s.path.present = true;
        s.path.effector = mgp::Effector::kRFoot;
        s.path.keyFrames = {2, 10, 20};
        s.path.keyOffsetsCm = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, 0)};
        s.ui = {{"panel", "model"}, {"zoom", 1.5}};
        write(out + "/session/synthetic.json", mgp::sessionToJsonText(s, out + "/session/synthetic.json"));

        mgp::SessionData m;
        m.model = res.model;
        m.modelVersion = 1;
        m.frame = 3;
        mgp::EditRecord me;
        me.pose = res.model.clip.frames[3];
        me.x = res.model.X.row(3).transpose();
        m.edits[3] = me;
        write(out + "/session/with_model.json", mgp::sessionToJsonText(m, out + "/session/with_model.json"));
    } catch (const std::exception& e) {
        std::cerr << "motiongp_fuzz_seeds: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
