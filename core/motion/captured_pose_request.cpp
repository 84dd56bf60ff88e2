#include "motion/captured_pose_request.h"

#include "ik/learned_ik.h"
#include "motion/support_polygon.h"

namespace mgp {

ConstrainedIkRequest capturedPoseRequest(const gp::ModelVersion& version, int frame,
                                         std::vector<IkConstraint> constraints, const ContactSet& contacts,
                                         int maxIterations) {
    const Clip& clip = version.model->clip;
    ConstrainedIkRequest req;
    req.start = clip.frames[frame];
    req.startX = latentStartForFrame(version, frame);
    FkState fk;
    forwardKinematics(clip.skeleton, req.start, fk);
    req.constraints = std::move(constraints);
    for (const IkConstraint& pin : contactPinsAt(clip, fk, contacts, frame, req.constraints))
        req.constraints.push_back(pin);
    req.maxIterations = maxIterations;
    req.floorCm = contacts.floorCm;
    req.balance = balanceRegion(clip.skeleton, clip.frames[frame], fk, contacts, frame, req.constraints);
    return req;
}

}  // namespace mgp
