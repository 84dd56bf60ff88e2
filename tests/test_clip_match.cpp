// sameCapture (skeleton/clip_match.h): a model's clip is recognised as the open clip after
// unwrapping and the model file's JSON, and every kind of difference is named.
#include <doctest/doctest.h>

#include <limits>

#include "io/clip_loader.h"
#include "skeleton/clip_match.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("sameCapture: the fixture model's clip is the shipped 35_01, not 10_03") {
    const Clip walk = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Clip kick = loadClip(test::mocap("asf_amc/10_03.amc"));
    const gp::ModelVersionPtr model = test::walkModel35();
    std::string why;
    CHECK(sameCapture(walk, model->model->clip, &why));
    CHECK_MESSAGE(why.empty(), why);
    CHECK(sameCapture(walk, walk));
    CHECK_FALSE(sameCapture(kick, model->model->clip, &why));
    CHECK_FALSE(why.empty());
}

TEST_CASE("sameCapture: each difference is found and named") {
    const Clip walk = loadClip(test::mocap("asf_amc/35_01.amc"));
    std::string why;

    Clip shifted = walk;  // a whole turn is the same orientation
    shifted.frames[5].anglesDeg[3].x() += 360.0;
    CHECK(sameCapture(walk, shifted, &why));

    // One DOF of the pose vector moved by 1e-3°: found, named by bone and axis.
    const PoseLayout layout(walk.skeleton);
    const int dof = 10;
    Clip moved = walk;
    moved.frames[11].anglesDeg[layout.joint(dof)][layout.axis(dof)] += 1e-3;
    CHECK_FALSE(sameCapture(walk, moved, &why));
    CHECK(why ==
          std::string("frame 12, ") + asfPoseDofTable()[dof].bone + " r" + "xyz"[layout.axis(dof)] + ": 0.001° apart");

    // A bone outside the pose vector (toes, fingers) does not count: the model keeps none.
    const int toes = walk.skeleton.findJoint("ltoes");
    REQUIRE(toes >= 0);
    Clip toesMoved = walk;
    toesMoved.frames[3].anglesDeg[toes].x() += 20.0;
    CHECK(sameCapture(walk, toesMoved, &why));

    Clip translated = walk;
    translated.frames[0].rootCm.y() += 0.5;
    CHECK_FALSE(sameCapture(walk, translated, &why));
    CHECK(why == "frame 1, root position: 0.5 cm apart");

    Clip shorter = walk;
    shorter.frames.pop_back();
    CHECK_FALSE(sameCapture(walk, shorter, &why));
    CHECK(why == "358 frames against 357");

    Clip renamed = walk;
    renamed.skeleton.joints[2].name = "elsewhere";
    CHECK_FALSE(sameCapture(walk, renamed, &why));
    CHECK(why == "joint 3 is " + walk.skeleton.joints[2].name + " against elsewhere");

    Clip nan = walk;
    nan.frames[7].anglesDeg[layout.joint(dof)][layout.axis(dof)] = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(sameCapture(walk, nan, &why));
    CHECK(why.find("frame 8") == 0);
}
