#pragma once
// The pose solve that starts from a captured frame, as `motiongp pose`, a drag from the captured
// pose and the IK and falloff benches set it up: the frame's pose and latent start, the given
// constraints, then each foot in ground contact on that frame as a pin where it stands (the rule of
// foot_contacts.h, contactPinsAt), the clip's floor under hands and feet, the default locality, and
// the balance term where the frame stands balanced on those pinned feet (support_polygon.h).
#include <vector>

#include "gp/model_version.h"
#include "ik/constrained_ik.h"
#include "motion/foot_contacts.h"

namespace mgp {

// `frame` is 0-based; `contacts` is detectFootContacts of the version's clip.
ConstrainedIkRequest capturedPoseRequest(const gp::ModelVersion& version, int frame,
                                         std::vector<IkConstraint> constraints, const ContactSet& contacts,
                                         int maxIterations);

}  // namespace mgp
