// FkMemo (core/skeleton/fk_memo.h): the same FK as computed afresh, computed again only when the
// slot's pose changes bit for bit.
#include "io/clip_loader.h"
#include "skeleton/fk_memo.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("FK memo: a slot is computed once per pose, and equals forward kinematics") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    FkMemo memo;
    FkState fresh;
    for (int pass = 0; pass < 2; ++pass)
        for (int f = 10; f < 20; ++f) {
            const FkState& remembered = memo.of(clip.skeleton, clip.frames[f], f);
            forwardKinematics(clip.skeleton, clip.frames[f], fresh);
            REQUIRE(remembered.jointCm.size() == fresh.jointCm.size());
            for (std::size_t j = 0; j < fresh.jointCm.size(); ++j) CHECK(remembered.jointCm[j] == fresh.jointCm[j]);
        }
    CHECK(memo.computed() == 10);  // the second pass found every pose unchanged
    // The root turned by 10°: that slot, and only it, is computed again, and every joint moved.
    Pose edited = clip.frames[12];
    edited.anglesDeg[0].y() += 10.0;
    FkState old;
    forwardKinematics(clip.skeleton, clip.frames[12], old);
    const FkState& changed = memo.of(clip.skeleton, edited, 12);
    forwardKinematics(clip.skeleton, edited, fresh);
    CHECK(changed.jointCm.back() == fresh.jointCm.back());
    CHECK((changed.jointCm.back() - old.jointCm.back()).norm() > 1.0);
    CHECK(memo.computed() == 11);
    // One angle changed by its last bit is another pose too (identical means bit for bit).
    Pose nudged = clip.frames[14];
    nudged.anglesDeg[3].x() = std::nextafter(nudged.anglesDeg[3].x(), 1e9);
    memo.of(clip.skeleton, nudged, 14);
    CHECK(memo.computed() == 12);
    memo.of(clip.skeleton, clip.frames[13], 13);
    CHECK(memo.computed() == 12);
    memo.forget();
    memo.of(clip.skeleton, clip.frames[13], 13);
    CHECK(memo.computed() == 13);
}
