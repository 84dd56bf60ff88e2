// Numerical faults: training on degenerate data, and learned IK and the editor
// document on unreachable, far-away, zero-length and non-finite targets. Each case ends with a
// clear message or a valid result — a saved model whose every number is finite when read back,
// a finite pose with `reached: false` where the target cannot be met — never NaN, never a crash.
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "edit/editor_document.h"
#include "gp/model_file.h"
#include "gp/model_version.h"
#include "gp/train/trainer.h"
#include "ik/learned_ik.h"
#include "io/parse_error.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

namespace {

gp::TrainOptions smallOptions() {
    gp::TrainOptions opt;
    opt.activeSize = 20;
    opt.outerIterations = 3;
    opt.scgIterations = 20;
    opt.pointIterations = 20;
    opt.threads = 1;
    return opt;
}

// Every number in a model document is finite, and nothing numeric was written as null (which
// is how nlohmann-json writes NaN and Inf); only params.eta is null, and only for SGPLVM.
void checkAllFinite(const nlohmann::json& j, const std::string& where, int& numbers) {
    if (j.is_number()) {
        ++numbers;
        CHECK_MESSAGE(std::isfinite(j.get<double>()), where << " = " << j.dump());
    } else if (j.is_null()) {
        CHECK_MESSAGE(where == "/params/eta", "null (NaN or Inf written) at " << where);
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) checkAllFinite(j[i], where + "/" + std::to_string(i), numbers);
    } else if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) checkAllFinite(it.value(), where + "/" + it.key(), numbers);
    }
}

// Saves, reloads (the loader's own checks) and walks the file.
void checkSavedModelFinite(const gp::GpModel& model, const std::string& path) {
    gp::saveModel(path, model);
    const gp::GpModel back = gp::loadModel(path);
    CHECK(back.N() == model.N());
    int numbers = 0;
    checkAllFinite(nlohmann::json::parse(test::readText(path)), "", numbers);
    CHECK(numbers > 100);
    // The model is usable: the precomputation factors K.
    CHECK_NOTHROW(gp::ModelVersion::make(back));
}

// Trains on `clip` (every frame); returns the error's words, or "" after checking the model.
std::string trainOutcome(Clip clip, const std::string& path, const gp::TrainOptions& opt = smallOptions()) {
    try {
        gp::TrainResult res = gp::trainOnClip(std::move(clip), opt);
        INFO("trained: L_init " << res.lInit << ", " << res.log.size() << " iterations");
        checkSavedModelFinite(res.model, path);
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

Clip walk(int frames) { return makeSyntheticWalk(frames); }

// A clear error: "expected …, found …", naming the problem.
void checkClear(const std::string& message, const std::string& distinctive) {
    CAPTURE(message);
    CHECK(std::regex_search(message, std::regex("expected .+, found .+")));
    CHECK(message.find(distinctive) != std::string::npos);
}

}  // namespace

TEST_CASE("training on degenerate clips: a clear error or a finite model, never NaN") {
    const std::string dir = test::scratchDir("numerical_training");
    SUBCASE("all frames identical") {
        Clip c = walk(30);
        for (Pose& p : c.frames) p = c.frames[0];
        checkClear(trainOutcome(c, dir + "/same.json"), "every pose DOF constant");
    }
    SUBCASE("constant columns only (every DOF constant, the root still moves)") {
        Clip c = walk(30);
        for (std::size_t t = 0; t < c.frames.size(); ++t) {
            const Eigen::Vector3d root = c.frames[t].rootCm;
            c.frames[t] = c.frames[0];
            c.frames[t].rootCm = root;
        }
        checkClear(trainOutcome(c, dir + "/const.json"), "every pose DOF constant");
    }
    SUBCASE("two frames") {
        Clip c = walk(2);
        checkClear(trainOutcome(c, dir + "/two.json"), "expected at least 3 training frames, found 2");
    }
    SUBCASE("three frames") { CHECK(trainOutcome(walk(3), dir + "/three.json") == ""); }
    SUBCASE("three frames, SGPLVM") {
        gp::TrainOptions opt = smallOptions();
        opt.kind = gp::KernelKind::kSgplvm;
        CHECK(trainOutcome(walk(3), dir + "/three_sgplvm.json", opt) == "");
    }
    SUBCASE("huge angles (±1e6 degrees in some DOFs)") {
        Clip c = walk(30);
        const PoseLayout layout(c.skeleton);
        for (std::size_t t = 0; t < c.frames.size(); ++t) {
            Eigen::VectorXd y = layout.extract(c.frames[t]);
            y[3] = (t % 2 ? 1e6 : -1e6);
            y[10] = 1e6 - 7.0 * static_cast<double>(t);
            layout.apply(y.data(), c.frames[t]);
        }
        CHECK(trainOutcome(c, dir + "/huge.json") == "");
    }
    SUBCASE("a NaN angle") {
        Clip c = walk(30);
        const PoseLayout layout(c.skeleton);
        Eigen::VectorXd y = layout.extract(c.frames[7]);
        y[5] = std::numeric_limits<double>::quiet_NaN();
        layout.apply(y.data(), c.frames[7]);
        checkClear(trainOutcome(c, dir + "/nan.json"), "found NaN at clip frame 8, pose DOF 5");
    }
    SUBCASE("an Inf angle") {
        Clip c = walk(30);
        const PoseLayout layout(c.skeleton);
        Eigen::VectorXd y = layout.extract(c.frames[9]);
        y[12] = std::numeric_limits<double>::infinity();
        layout.apply(y.data(), c.frames[9]);
        // (unwrapping over time may turn Inf into NaN; either way it is named and refused)
        checkClear(trainOutcome(c, dir + "/inf.json"), "at clip frame 10, pose DOF 12");
    }
}

namespace {

// An AMC (with the real subject-35 skeleton) built from the first `frames` frames of 35_01,
// each frame's bone lines passed through `edit(frameIndex, line)`.
std::string amcFrom35(int frames, const std::function<std::string(int, const std::string&)>& edit) {
    std::istringstream in(test::readText(test::mocap("asf_amc/35_01.amc")));
    std::string header, line;
    std::vector<std::vector<std::string>> blocks;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const bool number = !line.empty() && line.find_first_not_of("0123456789") == std::string::npos;
        if (number) {
            if (static_cast<int>(blocks.size()) == frames) break;
            blocks.emplace_back();
        } else if (blocks.empty()) {
            header += line + "\n";
        } else {
            blocks.back().push_back(line);
        }
    }
    REQUIRE(static_cast<int>(blocks.size()) == frames);
    std::string out = header;
    for (int t = 0; t < frames; ++t) {
        out += std::to_string(t + 1) + "\n";
        for (const std::string& l : blocks[static_cast<std::size_t>(t)]) out += edit(t, l) + "\n";
    }
    return out;
}

struct TrainRun {
    test::CliResult r;
    std::string model;
};

TrainRun cliTrain(const std::string& dir, const std::string& name, const std::string& amc) {
    const std::string clip = dir + "/35_" + name + ".amc", model = dir + "/" + name + ".json";
    test::writeText(clip, amc);
    TrainRun run;
    run.model = model;
    run.r = test::runCliArgs({"train", clip, "--skel", test::mocap("asf_amc/35.asf"), "--active", "20", "--iters", "3",
                              "--scg-iters", "20", "--threads", "1", "--out", model},
                             test::hostileLimits());
    return run;
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

}  // namespace

TEST_CASE("`motiongp train` on degenerate clips: clear error (exit 2, no model) or a finite model") {
    const std::string dir = test::scratchDir("numerical_cli");
    const std::string asf = test::mocap("asf_amc/35.asf");
    auto same = [](int, const std::string& l) { return l; };
    SUBCASE("all frames identical") {
        const std::string first = amcFrom35(1, same);
        const std::string body = first.substr(first.find("\n1\n") + 3);
        std::string amc = first.substr(0, first.find("\n1\n") + 1);
        for (int t = 1; t <= 25; ++t) amc += std::to_string(t) + "\n" + body;
        const TrainRun run = cliTrain(dir, "same", amc);
        INFO(test::describe(run.r) << "\n" << run.r.err);
        CHECK(run.r.exitCode == 2);
        CHECK(run.r.err ==
              "motiongp: error: " + dir +
                  "/35_same.amc: expected at least one pose DOF that varies over the training frames, found every "
                  "pose DOF constant (the same pose in every frame)\n");
        CHECK_FALSE(exists(run.model));
    }
    SUBCASE("three frames") {
        const TrainRun run = cliTrain(dir, "three", amcFrom35(3, same));
        INFO(test::describe(run.r) << "\n" << run.r.err);
        REQUIRE(run.r.exitCode == 0);
        checkSavedModelFinite(gp::loadModel(run.model), dir + "/three_again.json");
    }
    SUBCASE("huge angles (±999999 degrees in lfemur rx, rhumerus rz)") {
        const TrainRun run = cliTrain(dir, "huge", amcFrom35(30, [](int t, const std::string& l) {
                                          std::istringstream s(l);
                                          std::string bone;
                                          s >> bone;
                                          if (bone == "lfemur")
                                              return "lfemur " + std::string(t % 2 ? "999999" : "-999999") + " 0 0";
                                          if (bone == "rhumerus")
                                              return "rhumerus 0 0 " + std::to_string(999999 - 13 * t);
                                          return l;
                                      }));
        INFO(test::describe(run.r) << "\n" << run.r.err);
        REQUIRE(run.r.exitCode == 0);
        const gp::GpModel m = gp::loadModel(run.model);
        checkSavedModelFinite(m, dir + "/huge_again.json");
    }
    SUBCASE("a NaN angle") {
        const TrainRun run =
            cliTrain(dir, "nan", amcFrom35(10, [](int t, const std::string& l) {
                         return t == 4 && l.rfind("lfemur ", 0) == 0 ? std::string("lfemur 1 nan 2") : l;
                     }));
        CHECK(run.r.exitCode == 2);
        CHECK(std::regex_match(run.r.err,
                               std::regex("motiongp: error: .*/35_nan\\.amc:[0-9]+: expected a finite number for bone "
                                          "'lfemur', found 'nan'\n")));
        CHECK_FALSE(exists(run.model));
    }
}

// ---- learned IK and the editor document on bad targets ------------------------------------

namespace {

gp::ModelVersionPtr smallModelVersion() {
    static const gp::ModelVersionPtr v = [] {
        gp::TrainResult res = gp::trainOnClip(walk(60), smallOptions());
        return gp::ModelVersion::make(std::move(res.model));
    }();
    return v;
}

Eigen::Vector3d effectorOf(const Skeleton& sk, const Pose& p, Effector e) {
    FkState fk;
    forwardKinematics(sk, p, fk);
    return effectorCm(sk, fk, e);
}

}  // namespace

TEST_CASE("learned IK: unreachable, far-away, zero-length and non-finite targets") {
    const gp::ModelVersionPtr v = smallModelVersion();
    const Clip& clip = v->model->clip;
    const int frame = 20;
    LearnedIkSolver solver(v);
    LearnedIkRequest req;
    req.start = clip.frames[frame];
    req.startX = latentStartForFrame(*v, frame);
    req.maxIterations = 200;
    const Eigen::Vector3d hand = effectorOf(clip.skeleton, req.start, Effector::kRHand);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();

    struct Target {
        const char* name;
        Eigen::Vector3d offset;
        bool reachable;
    };
    for (const Target& t : {Target{"10 m away", {1000, 0, 0}, false}, Target{"1 km away", {0, 1e5, 0}, false},
                            Target{"1e150 cm away", {1e150, 0, 0}, false},
                            Target{"1e308 cm away", {0, 0, 1e308}, false}, Target{"zero-length", {0, 0, 0}, true}}) {
        CAPTURE(t.name);
        req.constraints = {{Effector::kRHand, hand + t.offset, false},
                           {Effector::kLFoot, effectorOf(clip.skeleton, req.start, Effector::kLFoot), true}};
        if (!req.constraints[0].targetCm.allFinite()) {  // 1e308 + hand can round to Inf
            CHECK(solver.validate(req) != "");
            continue;
        }
        REQUIRE(solver.validate(req) == "");
        const LearnedIkResult r = solver.solve(req);
        INFO("diagnostic: " << r.diagnostic);
        REQUIRE(r.constraints.size() == 2);  // every target and pin is reported, whatever happened
        INFO("residual " << r.constraints[0].residualCm);
        CHECK(allFinite(r.pose));
        CHECK(r.x.allFinite());
        CHECK(r.y.allFinite());
        if (t.offset.norm() < 1e154)
            CHECK(std::isfinite(r.objective));
        else
            CHECK(r.diagnostic.find("no finite objective") != std::string::npos);  // F = residual² overflows: said so
        CHECK(std::isfinite(r.sigma2));
        CHECK(std::isfinite(r.constraints[0].residualCm));
        CHECK(r.reached == t.reachable);
        CHECK(r.constraints[0].reached == t.reachable);
        if (!t.reachable) {
            // The best pose reaches towards the target: the residual is at most the distance.
            CHECK(r.constraints[0].residualCm <= t.offset.norm() * (1 + 1e-9));
            CHECK(r.constraints[0].residualCm > kReachedToleranceCm);
        } else {
            CHECK(r.constraints[0].residualCm <= kReachedToleranceCm);
        }
    }
    for (const Eigen::Vector3d& bad :
         {Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d(0, inf, 0), Eigen::Vector3d(0, 0, -inf)}) {
        req.constraints = {{Effector::kRHand, bad, false}};
        CHECK(solver.validate(req) == "expected a finite target for rhand, found NaN or Inf");
        // solve() itself must not throw or return NaN even if the caller skipped validate().
        const LearnedIkResult r = solver.solve(req);
        CHECK(allFinite(r.pose));
        CHECK_FALSE(r.reached);
    }
}

TEST_CASE("`motiongp pose`: a target 1e308 cm away is a finite NOT-reached result, NaN offsets are refused") {
    const std::string dir = test::scratchDir("numerical_pose");
    const std::string model = dir + "/m.json";
    gp::saveModel(model, *smallModelVersion()->model);
    for (const char* offset : {"rhand=1000,0,0", "rhand=0,1e300,0", "rhand=0,0,1e308"}) {
        CAPTURE(offset);
        const test::CliResult r =
            test::runCliArgs({"pose", model, "--frame", "21", "--target", offset, "--json"}, test::hostileLimits());
        INFO(test::describe(r) << "\n" << r.err);
        REQUIRE(r.exitCode == 0);
        const nlohmann::json j = nlohmann::json::parse(r.out);
        CHECK(j["reached"] == false);
        REQUIRE(j["targets"].size() == 1);
        CHECK(j["targets"][0]["residual_cm"].is_number());
        for (const auto& a : j["pose_deg"]) CHECK(a.is_number());  // NaN would be written as null
        for (const auto& item : j["positions_cm"].items()) {
            // A named copy: clang before 16 cannot capture a structured binding in CHECK's lambda.
            const std::string name = item.key();
            if (!item.value().is_null())
                for (const auto& c : item.value()) CHECK_MESSAGE(c.is_number(), name);
        }
    }
    for (const char* offset : {"rhand=nan,0,0", "rhand=0,inf,0", "rhand=0,0,1e999"}) {
        CAPTURE(offset);
        const test::CliResult r =
            test::runCliArgs({"pose", model, "--frame", "21", "--target", offset}, test::hostileLimits());
        CHECK(r.exitCode == 2);
        CHECK(r.err == std::string("motiongp: error: expected --target as dx,dy,dz in cm, found '") +
                           (std::string(offset).substr(6)) + "'\n");
    }
}

TEST_CASE("editor document: unreachable, zero-length and non-finite drags keep a finite pose") {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const bool learned : {true, false}) {
        CAPTURE(learned);
        // A fresh document on frame 20 (learned: the small model; else plain IK on the walk).
        auto makeDoc = [&] {
            auto doc = std::make_unique<EditorDocument>();
            if (learned)
                doc->setModel(smallModelVersion(), true);
            else
                doc->setClip(walk(60), true);
            REQUIRE(doc->hasModel() == learned);
            doc->setFrame(20);
            return doc;
        };
        {
            INFO("a target 10 m away, reached for in 1 m steps");
            auto doc = makeDoc();
            const Eigen::Vector3d start = doc->effectorPosition(Effector::kRHand);
            REQUIRE(doc->beginDrag(Effector::kRHand) == "");
            for (int k = 1; k <= 10; ++k) doc->dragTo(start + Eigen::Vector3d(100.0 * k, 0, 0));
            for (int k = 0; k < 5; ++k) doc->refine();
            CHECK(doc->readout().valid);
            CHECK(doc->readout().learned == learned);
            CHECK_FALSE(doc->readout().reached);
            REQUIRE(doc->readout().constraints.size() >= 1);
            CHECK(std::isfinite(doc->readout().constraints[0].residualCm));
            CHECK(doc->readout().constraints[0].residualCm > 100.0);
            CHECK_FALSE(doc->readout().constraints[0].reached);
            CHECK(allFinite(doc->currentPose()));
            const auto rec = doc->endDrag();
            REQUIRE(rec.has_value());
            CHECK(allFinite(rec->after.pose));
            CHECK(allFinite(doc->currentPose()));
            CHECK(doc->effectorPosition(Effector::kRHand).x() > start.x());  // it reached towards it
            doc->waitIdle();
        }
        {
            INFO("a far-away target (1e6 km) in one jump");
            auto doc = makeDoc();
            const Eigen::Vector3d start = doc->effectorPosition(Effector::kRHand);
            REQUIRE(doc->beginDrag(Effector::kRHand) == "");
            doc->dragTo(start + Eigen::Vector3d(0, 1e11, 0));
            CHECK_FALSE(doc->readout().reached);
            CHECK(allFinite(doc->currentPose()));
            REQUIRE(doc->endDrag().has_value());
            CHECK(allFinite(doc->currentPose()));
            doc->waitIdle();
        }
        {
            INFO("a zero-length drag (dragTo the start position)");
            auto doc = makeDoc();
            const Eigen::Vector3d start = doc->effectorPosition(Effector::kRHand);
            const Eigen::Vector3d root = doc->currentPose().rootCm;
            REQUIRE(doc->beginDrag(Effector::kRHand) == "");
            doc->dragTo(start);
            for (int k = 0; k < 3; ++k) doc->refine();
            CHECK(doc->readout().reached);
            REQUIRE(doc->endDrag().has_value());
            CHECK((doc->effectorPosition(Effector::kRHand) - start).norm() <= kReachedToleranceCm);
            CHECK(allFinite(doc->currentPose()));
            CHECK(doc->currentPose().rootCm == root);
            doc->waitIdle();
        }
        {
            INFO("NaN and Inf targets are ignored; the drag goes on from the last good pose");
            auto doc = makeDoc();
            const Eigen::Vector3d start = doc->effectorPosition(Effector::kRHand);
            REQUIRE(doc->beginDrag(Effector::kRHand) == "");
            doc->dragTo(start + Eigen::Vector3d(0, 5, 0));
            const Pose good = doc->currentPose();
            doc->dragTo({nan, 0, 0});
            doc->dragTo({0, inf, 0});
            doc->dragTo({-inf, nan, inf});
            CHECK(allFinite(doc->currentPose()));
            CHECK(doc->dragTarget().allFinite());
            CHECK(doc->currentPose().anglesDeg == good.anglesDeg);
            const auto rec = doc->endDrag();
            REQUIRE(rec.has_value());
            CHECK(allFinite(rec->after.pose));
            doc->waitIdle();
        }
    }
}
