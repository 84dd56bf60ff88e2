#pragma once
// Helpers for tests that drive an EditorDocument (core tests and the GUI tests).
#include <Eigen/Core>

#include "edit/editor_document.h"

namespace mgp::test {

// A drag made of 1 cm steps (as mouse moves would be), a few idle refinements, then release.
void dragBy(EditorDocument& doc, Effector e, const Eigen::Vector3d& delta);

}  // namespace mgp::test
