// ClipEdits (core/edit/clip_edits.h): the clip, its per-frame edits and its foot contacts.
#include <doctest/doctest.h>

#include "edit/clip_edits.h"
#include "io/clip_loader.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

namespace {
EditRecord editWithRoot(double y) {
    EditRecord r;
    r.pose = makeSyntheticWalk().frames[0];
    r.pose.rootCm.y() = y;
    return r;
}
}  // namespace

TEST_CASE("clip edits: a frame shows its edit, else the captured pose, and a step's frame map applies in one call") {
    ClipEdits store;
    CHECK(store.empty());
    store.reset(makeSyntheticWalk(), true);
    CHECK(store.synthetic());
    REQUIRE(store.frameCount() > 10);
    CHECK(store.pose(3).rootCm == store.clip().frames[3].rootCm);
    CHECK_FALSE(store.editAt(3));

    FrameEdits change;
    change[3] = editWithRoot(123.0);
    change[5] = editWithRoot(456.0);
    const FrameEdits before = store.current(change);
    REQUIRE(before.size() == 2);
    CHECK_FALSE(before.at(3));
    CHECK_FALSE(before.at(5));
    store.apply(change);
    CHECK(store.isEdited(3));
    CHECK(store.pose(3).rootCm.y() == 123.0);
    CHECK(store.pose(5).rootCm.y() == 456.0);
    CHECK(store.edits().size() == 2);

    // Undoing is applying the `before` map: frame 3 back to the capture, frame 5 too.
    const FrameEdits now = store.current(change);
    CHECK(now.at(3)->pose.rootCm.y() == 123.0);
    store.apply(before);
    CHECK(store.edits().empty());
    CHECK(store.pose(3).rootCm == store.clip().frames[3].rootCm);

    store.set(7, editWithRoot(7.0));
    store.reset(makeSyntheticWalk(), false);  // a new clip drops every edit
    CHECK(store.edits().empty());
    CHECK_FALSE(store.synthetic());
}

TEST_CASE("clip edits: contacts are detected on reset and switched one by one") {
    ClipEdits store;
    store.reset(loadClip(test::mocap("asf_amc/35_01.amc")), false);
    REQUIRE_FALSE(store.contacts().contacts.empty());
    CHECK(store.contacts().contacts[0].enabled);
    CHECK(store.setContactEnabled(0, false));
    CHECK_FALSE(store.contacts().contacts[0].enabled);
    CHECK_FALSE(store.setContactEnabled(0, false));                                // no change
    CHECK_FALSE(store.setContactEnabled(store.contacts().contacts.size(), true));  // no such contact
    store.reset(loadClip(test::mocap("asf_amc/35_01.amc")), false);
    CHECK(store.contacts().contacts[0].enabled);
}
