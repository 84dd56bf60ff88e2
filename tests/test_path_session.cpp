// The document's path session (core/edit/path_session.h) on the synthetic walk, without GL.
#include <doctest/doctest.h>

#include "edit/path_session.h"
#include "motion/foot_contacts.h"
#include "skeleton/synthetic_clip.h"

using namespace mgp;

TEST_CASE("path session: keys, offsets and positions against the captured path, each change counted") {
    const Clip clip = makeSyntheticWalk();
    int changes = 0;
    PathSession paths(clip, [&] { ++changes; });
    CHECK(paths.setKeyOffset(0, Eigen::Vector3d::Zero()) == "no path is being edited");
    CHECK(paths.targets().empty());

    REQUIRE(paths.begin(Effector::kRFoot, 100) == "");
    CHECK(changes == 1);
    const PathEdit& p = *paths.edit();
    CHECK(p.keyFrames == defaultPathKeys(100, clip.frameCount()));
    const std::vector<Eigen::Vector3d> captured = effectorTrajectory(clip, Effector::kRFoot);
    const int k1 = p.keyFrames[1];
    CHECK(paths.keyPosition(1).isApprox(captured[k1]));
    CHECK(paths.captured().size() == std::size_t(p.keyFrames.back() - p.keyFrames.front() + 1));
    CHECK(paths.captured().front().isApprox(captured[p.keyFrames.front()]));

    // A key moved to a world position: its offset is position − captured position.
    REQUIRE(paths.setKeyPosition(1, captured[k1] + Eigen::Vector3d(0, 4, 0)) == "");
    CHECK(paths.edit()->keyOffsetsCm[1].isApprox(Eigen::Vector3d(0, 4, 0)));
    CHECK(changes == 2);
    const std::vector<Eigen::Vector3d> targets = paths.targets();
    REQUIRE(targets.size() == paths.captured().size());
    CHECK(targets[std::size_t(k1 - p.keyFrames.front())].isApprox(captured[k1] + Eigen::Vector3d(0, 4, 0)));

    // New key frames keep the offsets of frames that stay keys.
    std::vector<int> keys = paths.edit()->keyFrames;
    keys.insert(keys.begin() + 2, (keys[1] + keys[2]) / 2);
    REQUIRE(paths.setKeyFrames(keys) == "");
    CHECK(paths.edit()->keyOffsetsCm[1].isApprox(Eigen::Vector3d(0, 4, 0)));
    CHECK(paths.edit()->keyOffsetsCm[2].isZero());

    paths.setMode(PathMode::kDisplacement);
    CHECK(paths.edit()->mode == PathMode::kDisplacement);
    const int before = changes;
    paths.setMode(PathMode::kDisplacement);  // no change, not counted
    CHECK(changes == before);
    paths.end();
    CHECK(!paths.edit());
    CHECK(changes == before + 1);
}

TEST_CASE("path session: bad keys and offsets are refused and leave the path as it was") {
    const Clip clip = makeSyntheticWalk();
    PathSession paths(clip);
    REQUIRE(paths.begin(Effector::kLHand, 50) == "");
    const PathEdit kept = *paths.edit();
    CHECK(paths.setKeyOffset(99, Eigen::Vector3d::Zero()) ==
          "expected a key in 1.." + std::to_string(kept.keyFrames.size()) + ", found 100");
    CHECK(paths.setKeyOffset(0, Eigen::Vector3d(NAN, 0, 0)) == "expected a finite offset, found NaN or Inf");
    CHECK(!paths.setKeyFrames({5, 5, 9}).empty());
    PathEdit wrong = kept;
    wrong.keyOffsetsCm.pop_back();
    CHECK(paths.set(wrong).find("expected one offset per key") == 0);
    CHECK(paths.edit()->keyFrames == kept.keyFrames);
    CHECK(paths.edit()->keyOffsetsCm == kept.keyOffsetsCm);
    paths.reset();
    CHECK(!paths.edit());

    const Clip none;
    PathSession empty(none);
    CHECK(empty.begin(Effector::kRFoot, 0) == "no clip is open");
}
