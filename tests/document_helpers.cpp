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

}  // namespace mgp::test
