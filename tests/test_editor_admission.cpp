// The editor feeds the model only poses the admission rule admits (core/gp/training_range.h): an
// unreachable drag stays an edit, is not posted, and the update table and status say why; feet in
// ground contact are held like pins unless released.
#include <doctest/doctest.h>

#include "edit/editor_document.h"
#include "skeleton/forward_kinematics.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("editor: an unreachable drag is kept as an edit, refused by the model, and the feet in contact stay") {
    EditorDocument doc;
    const gp::ModelVersionPtr v0 = test::walkModel35();
    doc.setModel(v0, true);
    doc.setFrame(100);
    REQUIRE((doc.inContact(Effector::kLFoot) || doc.inContact(Effector::kRFoot)));
    const Eigen::Vector3d lf = doc.effectorPosition(Effector::kLFoot), rf = doc.effectorPosition(Effector::kRFoot);
    const bool lIn = doc.inContact(Effector::kLFoot), rIn = doc.inContact(Effector::kRFoot);
    REQUIRE(doc.beginDrag(Effector::kRHand) == "");
    const Eigen::Vector3d hand = doc.effectorPosition(Effector::kRHand);
    for (int k = 1; k <= 30; ++k) doc.dragTo(hand + Eigen::Vector3d(0, 6.0 * k, 4.0 * k));  // 216 cm: out of reach
    CHECK_FALSE(doc.readout().reached);
    REQUIRE(doc.endDrag().has_value());
    CHECK(doc.isEdited(100));
    if (lIn) CHECK((doc.effectorPosition(Effector::kLFoot) - lf).norm() <= 0.05);
    if (rIn) CHECK((doc.effectorPosition(Effector::kRFoot) - rf).norm() <= 0.05);
    doc.waitIdle();
    CHECK(doc.model() == v0);  // not taught
    const auto history = doc.models().history();
    REQUIRE(history.size() == 1);
    CHECK_FALSE(history.back().accepted);
    CHECK(history.back().diagnostic == "refused: a target or pin was not reached");
    CHECK(doc.models().status() == "pose kept as an edit, not added to the model: a target or pin was not reached");

    // Released, a foot in contact is free to move.
    const Effector planted = lIn ? Effector::kLFoot : Effector::kRFoot;
    doc.setContactReleased(planted, true);
    CHECK(doc.contactReleased(planted));
    doc.setFrame(100);
    REQUIRE(doc.beginDrag(Effector::kRHand) == "");
    doc.dragTo(doc.effectorPosition(Effector::kRHand) + Eigen::Vector3d(0, 5, 0));
    bool held = false;
    for (const auto& c : doc.readout().constraints) held |= c.pin && c.effector == planted;
    CHECK_FALSE(held);
    doc.cancelDrag();
}
