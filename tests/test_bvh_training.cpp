// Training on BVH clips (skeleton/pose_layout.h, gp/train/training_clips.h): a BVH trains on its own
// rotation channels, the latent dimension follows eq. 4 on the channels that move, the rest frame
// is never a row, learned IK reaches targets on such a model, and an edit exported to BVH keeps
// the source hierarchy and comes back through our reader at the same joint positions. Small
// models only (CI budget).
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "central_difference.h"
#include "gp/model_file.h"
#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "gp/train/training_clips.h"
#include "ik/constrained_ik.h"
#include "ik/learned_ik.h"
#include "io/bvh_reader.h"
#include "io/bvh_writer.h"
#include "io/clip_loader.h"
#include "skeleton/clip_match.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"

using namespace mgp;

namespace {

// The channels of a BVH file that move over `frames`, counted from the clip's own angles (not the
// pose vector): the D the model must come out with.
int movingChannels(const Clip& clip, const std::vector<int>& frames) {
    int count = 0;
    for (int j = 0; j < clip.skeleton.jointCount(); ++j)
        for (int a = 0; a < 3; ++a) {
            if (j > 0 && !clip.skeleton.joints[j].dof[a]) continue;
            double lo = 1e300, hi = -1e300;
            for (int f : frames) {
                lo = std::min(lo, clip.frames[f].anglesDeg[j][a]);
                hi = std::max(hi, clip.frames[f].anglesDeg[j][a]);
            }
            count += hi - lo > 1e-6 ? 1 : 0;
        }
    return count;
}

// Trains MODEL on CLIP with the CLI (every 4th frame, M = 40, T = 1).
nlohmann::json trainCli(const std::string& clips, const std::string& model) {
    const test::CliResult t =
        test::runCli("train " + clips + " --step 4 --active 40 --iters 1 --scg-iters 10 --json --out " + model);
    REQUIRE_MESSAGE(t.exitCode == 0, t.err);
    return nlohmann::json::parse(t.out);
}

// Largest distance between the two clips' joints over every frame (same skeleton order).
double largestJointGapCm(const Clip& a, const Clip& b) {
    double worst = 0.0;
    FkState fa, fb;
    for (int f = 0; f < a.frameCount(); ++f) {
        forwardKinematics(a.skeleton, a.frames[f], fa);
        forwardKinematics(b.skeleton, b.frames[f], fb);
        for (int j = 0; j < a.skeleton.jointCount(); ++j)
            worst = std::max(worst, (fa.jointCm[j] - fb.jointCm[j]).norm());
    }
    return worst;
}

}  // namespace

TEST_CASE("BVH pose vector: the root's three rotations, then every joint's own rotation channels") {
    const Clip clip = readBvh(test::mocap("bvh/02_03.bvh"));
    REQUIRE(clip.skeleton.poseVector == PoseVectorKind::kChannels);
    const PoseLayout layout(clip.skeleton);
    int channels = 3;
    for (int j = 1; j < clip.skeleton.jointCount(); ++j)
        for (bool on : clip.skeleton.joints[j].dof) channels += on ? 1 : 0;
    CHECK(layout.size() == channels);
    for (int a = 0; a < 3; ++a) {
        CHECK(layout.joint(a) == 0);
        CHECK(layout.axis(a) == a);
    }
    for (int k = 3; k < layout.size(); ++k) {
        REQUIRE(layout.joint(k) > 0);
        CHECK(clip.skeleton.joints[layout.joint(k)].dof[layout.axis(k)]);
        if (k > 3) CHECK(layout.joint(k) >= layout.joint(k - 1));  // joint order
    }
    CHECK(layout.dofName(clip.skeleton, 3) ==
          clip.skeleton.joints[layout.joint(3)].name + " r" + "xyz"[layout.axis(3)]);
    // Every animated angle is in the vector: extract then apply on a blank pose gives the frame back.
    const Pose& source = clip.frames[30];
    Pose back;
    back.anglesDeg.assign(clip.skeleton.jointCount(), Eigen::Vector3d::Zero());
    layout.apply(layout.extract(source).data(), back);
    for (int j = 0; j < clip.skeleton.jointCount(); ++j)
        for (int a = 0; a < 3; ++a)
            if (j == 0 || clip.skeleton.joints[j].dof[a]) CHECK(back.anglesDeg[j][a] == source.anglesDeg[j][a]);
    // An ASF clip keeps the paper's 47.
    CHECK(PoseLayout(loadClip(test::mocap("asf_amc/35_01.amc")).skeleton).size() == kAsfPoseDofs);
}

TEST_CASE("BVH training: D = the channels that move, d by eq. 4, no rest-frame row, the file round-trips") {
    const std::string dir = test::scratchDir("bvh_training");
    std::filesystem::create_directories(dir);
    struct Case {
        const char* file;
        int latentDim;  // eq. 4 on the measured D
    };
    // Daz-friendly (D < 60) and 3dsMax-friendly (D ≥ 60: a 3-D latent space).
    for (const Case& c : {Case{"bvh/02_03.bvh", 2}, Case{"bvh/131_01.bvh", 3}}) {
        CAPTURE(c.file);
        const std::string path = test::mocap(c.file),
                          model = dir + "/" + std::filesystem::path(c.file).stem().string() + ".model";
        const nlohmann::json j = trainCli(path, model);
        const gp::GpModel m = gp::loadModel(model);
        const Clip source = readBvh(path);
        std::vector<int> frames;
        for (int t = source.restFrame ? 4 : 0; t < source.frameCount(); t += 4) frames.push_back(t);
        CHECK(m.trainingFrames == frames);  // frames 1, 5, 9, ... less a rest frame 1
        CHECK(m.D() == movingChannels(source, frames));
        CHECK(j["D"] == m.D());
        CHECK(j["pose_dofs"] == PoseLayout(source.skeleton).size());
        CHECK(m.latentDim() == gp::latentDimensionFor(m.D()));
        CHECK(m.latentDim() == c.latentDim);
        CHECK(j["latent_dim"] == c.latentDim);
        // The model's clip is the source's (joints, every frame's angles modulo 360°).
        std::string why;
        CHECK_MESSAGE(sameCapture(m.clip, source, &why), why);
        CHECK(m.clip.skeleton.poseVector == PoseVectorKind::kChannels);
        // Saving and loading again gives the same model file.
        gp::saveModel(dir + "/again.model", m);
        CHECK(test::readText(dir + "/again.model") == test::readText(model));
    }
}

TEST_CASE(
    "BVH model: learned IK reaches a 20 cm hand target with the feet pinned, and the edit exports in the source "
    "hierarchy") {
    const std::string dir = test::scratchDir("bvh_ik");
    std::filesystem::create_directories(dir);
    const std::string path = test::mocap("bvh/02_03.bvh"), model = dir + "/daz.model";
    trainCli(path, model);

    const test::CliResult p = test::runCli("pose " + model +
                                           " --frame 60 --target rhand=0,20,0 --pin lfoot --pin rfoot "
                                           "--iterations 50 --json");
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const auto jp = nlohmann::json::parse(p.out);
    CHECK(jp["reached"] == true);
    CHECK(jp["converged"] == true);
    CHECK(jp["targets"][0]["residual_cm"].get<double>() <= 0.05);
    for (const auto& pin : jp["pins"]) CHECK(pin["residual_cm"].get<double>() <= 0.05);
    CHECK(jp["nearest"]["clip"] == "02_03");
    CHECK(jp["pose_deg"].size() == static_cast<std::size_t>(PoseLayout(readBvh(path).skeleton).size()));

    // The same solve through the library, written into the model's clip and exported: the file
    // keeps the source's joints, names, offsets and channel orders, and reads back at the same
    // joint positions on every frame.
    const gp::GpModel m = gp::loadModel(model);
    ConstrainedIkSolver solver(gp::ModelVersion::make(m));
    ConstrainedIkRequest request;
    request.start = m.clip.frames[59];
    request.startX = m.X.row(14).transpose();  // training row 14 is frame 60 (frames 5, 9, ...)
    REQUIRE(m.trainingFrames[14] == 60);
    FkState fk;
    forwardKinematics(m.clip.skeleton, request.start, fk);
    IkConstraint target;
    target.effector = Effector::kRHand;
    target.targetCm = effectorCm(m.clip.skeleton, fk, Effector::kRHand) + Eigen::Vector3d(0, 20, 0);
    request.constraints.push_back(target);
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot}) {
        IkConstraint pin;
        pin.effector = foot;
        pin.pin = true;
        pin.targetCm = effectorCm(m.clip.skeleton, fk, foot);
        request.constraints.push_back(pin);
    }
    const ConstrainedIkResult r = solver.solve(request);
    CHECK(r.reached);
    Clip edited = m.clip;
    edited.frames[59] = r.pose;
    const Clip back = parseBvh("edit.bvh", formatBvh(edited));
    const Clip source = readBvh(path);
    std::string why;
    CHECK_MESSAGE(sameSkeleton(back.skeleton, source.skeleton, &why),
                  why);  // names, parents, offsets, orders, channels
    CHECK(back.convention == source.convention);
    CHECK(back.restFrame == source.restFrame);
    REQUIRE(back.frameCount() == edited.frameCount());
    CHECK(largestJointGapCm(back, edited) < 1e-5);
    FkState fe;
    forwardKinematics(back.skeleton, back.frames[59], fe);
    CHECK((effectorCm(back.skeleton, fe, Effector::kRHand) - target.targetCm).norm() <= 0.05);
}

TEST_CASE("BVH multi-clip: one hierarchy trains one model, another hierarchy fails with exit 2 and one line") {
    const std::string dir = test::scratchDir("bvh_multi");
    std::filesystem::create_directories(dir);
    const std::string copy = dir + "/02_03b.bvh";
    std::filesystem::copy_file(test::mocap("bvh/02_03.bvh"), copy, std::filesystem::copy_options::overwrite_existing);
    const nlohmann::json j = trainCli(test::mocap("bvh/02_03.bvh") + " " + copy, dir + "/two.model");
    REQUIRE(j["clips"].size() == 2u);
    CHECK(j["clips"][1]["name"] == "02_03b");
    CHECK(j["N"] == 2 * j["clips"][0]["frames"].get<int>());

    const test::CliResult x =
        test::runCli("train " + test::mocap("bvh/02_03.bvh") + " " + test::mocap("bvh/49_04.bvh") +
                     " --step 4 --active 10 --iters 1 --out " + dir + "/x.model");
    CHECK(x.exitCode == 2);
    CHECK(std::count(x.err.begin(), x.err.end(), '\n') == 1);
    CHECK(x.err.find("49_04.bvh against") != std::string::npos);
    CHECK(x.err.find("joint ") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir + "/x.model"));

    const test::CliResult y =
        test::runCli("train " + test::mocap("bvh/02_03.bvh") + " " + test::mocap("asf_amc/02_03.amc") +
                     " --step 4 --active 10 --iters 1 --out " + dir + "/y.model");
    CHECK(y.exitCode == 2);
    CHECK(std::count(y.err.begin(), y.err.end(), '\n') == 1);
}

TEST_CASE("BVH model with a 3-D latent space: the constrained IK's ∇F matches central differences") {
    // 131_01 (3dsMax-friendly, mixed rotation orders): D ≥ 60, so d = 3. Every 20th frame, M = 20, T = 1.
    const std::string path = test::mocap("bvh/131_01.bvh");
    gp::FrameSelection every20;
    every20.step = 20;
    std::vector<gp::TrainingClip> clips = gp::prepareTrainingClips({loadClip(path)}, {path}, every20);
    gp::TrainOptions o;
    o.activeSize = 20;
    o.outerIterations = 1;
    o.scgIterations = 10;
    o.pointIterations = 10;
    gp::TrainResult trained = gp::train(gp::trainingDataOf(clips), o);
    gp::attachTrainingClips(trained.model, std::move(clips), every20);
    const gp::ModelVersionPtr version = gp::ModelVersion::make(std::move(trained.model));
    const gp::GpModel& m = *version->model;
    REQUIRE(m.latentDim() == 3);
    const Skeleton& sk = m.clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req;
    req.start = m.clip.frames[200];
    req.startX = latentStartForFrame(*version, 200);
    req.constraints = {
        {Effector::kRHand, effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(-5, 12, 3), false, 1.0},
        {Effector::kLHand, effectorCm(sk, req.start, Effector::kLHand) + Eigen::Vector3d(2, -3, 1), false, 0.9},
        {Effector::kLFoot, effectorCm(sk, req.start, Effector::kLFoot), true}};
    Eigen::VectorXd z = solver.startPoint(req);
    z.head(3).array() += 0.05;
    for (int k = 3; k < z.size(); ++k) z[k] += 0.3 * std::sin(k);
    Eigen::VectorXd g;
    solver.objective(req, z, &g);
    double worst = 0.0;
    for (int i = 0; i < z.size(); ++i) {
        const double numeric =
            test::centralDifference([&](const Eigen::VectorXd& v) { return solver.objective(req, v, nullptr); }, z, i);
        worst = std::max(worst, std::abs(numeric - g[i]));
    }
    MESSAGE("∇F (BVH, d = 3): max abs error " << worst << " against |g|∞ " << g.cwiseAbs().maxCoeff());
    CHECK(worst < 1e-6 * g.cwiseAbs().maxCoeff());
}
