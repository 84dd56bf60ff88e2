#include "document_helpers.h"

#include <doctest/doctest.h>

#include <cmath>

namespace mgp::test {

void dragBy(EditorDocument& doc, Effector e, const Eigen::Vector3d& delta) {
    REQUIRE(doc.beginDrag(e) == "");
    const Eigen::Vector3d start = doc.effectorPosition(e);
    const int steps = int(std::ceil(delta.norm()));
    for (int k = 1; k <= steps; ++k) doc.dragTo(start + delta * (double(k) / steps), 50);
    for (int k = 0; k < 5; ++k) doc.refine(50);
    REQUIRE(doc.endDrag().has_value());
}

bool samePose(const Pose& a, const Pose& b) {
    if (a.rootCm != b.rootCm || a.anglesDeg.size() != b.anglesDeg.size()) return false;
    for (std::size_t j = 0; j < a.anglesDeg.size(); ++j)
        if (a.anglesDeg[j] != b.anglesDeg[j]) return false;
    return true;
}

}  // namespace mgp::test
