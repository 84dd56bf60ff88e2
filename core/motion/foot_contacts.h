#pragma once
// Foot contacts of a captured clip: the one rule the learned IK (a planted foot is held like a
// pin by default) and span regeneration (every planted foot keeps its captured position) share.
//
// A foot is planted when it is low AND nearly still. Height is measured above the clip's ground
// level, the lowest point either foot habitually reaches (the 5th percentile of each foot's
// height over the clip, the lower of the two), because capture floors are rarely at y = 0 and
// the foot effector sits at the ankle/foot joint, not at the sole. Speed is the central
// difference |p(t+1) − p(t−1)| / 2 in cm per frame. Hysteresis keeps a contact from flickering:
// a foot enters contact under the tight thresholds and leaves only past the loose ones, contacts
// at most `mergeGapFrames` apart are merged, and contacts shorter than `minFrames` are dropped.
//
// Speed thresholds are stated per frame at 120 fps (the CMU capture rate); for another frame
// rate they are scaled by 120 / fps so the rule means the same speed in cm/s.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ik/ik_types.h"
#include "skeleton/clip.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/skeleton.h"

namespace mgp {

struct ContactRule {
    // Defaults chosen on 35_01 (walk), 10_03 (kick), 16_01 (jump) and 09_01 (run): the ankle of
    // a planted foot sits 0.3–2.5 cm above the ground level and moves < 0.2 cm/frame; heel
    // strike and toe-off pass 3.5 cm or 0.4 cm/frame within a few frames.
    double enterHeightCm = 2.5;         // planted when at most this high above ground …
    double enterSpeedCmPerFrame = 0.2;  // … and at most this fast (24 cm/s at 120 fps)
    double exitHeightCm = 3.5;          // a planted foot lifts off above this height …
    double exitSpeedCmPerFrame = 0.4;   // … or above this speed (48 cm/s at 120 fps)
    int mergeGapFrames = 3;             // two contacts this close in time are one (a jitter)
    int minFrames = 6;                  // shorter contacts are noise (50 ms at 120 fps)
    double groundPercentile = 0.05;     // of each foot's height over the clip
};

struct FootContact {
    Effector foot = Effector::kLFoot;
    int first = 0;        // first planted frame (0-based, inclusive)
    int last = 0;         // last planted frame (inclusive)
    bool enabled = true;  // the user can switch a contact off
    bool contains(int frame) const { return frame >= first && frame <= last; }
    int length() const { return last - first + 1; }
};

struct ContactSet {
    double groundCm = 0.0;  // the clip's ground level (world Y, cm)
    // The floor the solves keep hands and feet above (ConstrainedIkRequest::floorCm): the lowest
    // height either foot effector reaches over the clip, so no captured frame is below it. None
    // when the skeleton has no feet.
    std::optional<double> floorCm;
    std::vector<FootContact> contacts;  // sorted by foot, then by first frame
    // The enabled contact of `foot` that holds `frame`, or nullptr.
    const FootContact* at(Effector foot, int frame) const;
    FootContact* at(Effector foot, int frame);
};

// The rule on explicit foot trajectories (cm, one entry per frame; either may be empty when the
// skeleton has no such foot). Throws std::invalid_argument on a bad rule (a loose threshold
// tighter than its tight one, minFrames < 1, percentile outside [0, 1]).
ContactSet detectFootContacts(const std::vector<Eigen::Vector3d>& leftFootCm,
                              const std::vector<Eigen::Vector3d>& rightFootCm, double fps,
                              const ContactRule& rule = {});
// The rule on a clip's own feet (FK of every frame).
ContactSet detectFootContacts(const Clip& clip, const ContactRule& rule = {});

// One effector's world position at every frame of the clip, or of `frames` (cm; empty when the
// skeleton has no such effector).
std::vector<Eigen::Vector3d> effectorTrajectory(const Clip& clip, Effector effector);
std::vector<Eigen::Vector3d> effectorTrajectory(const Skeleton& skeleton, const std::vector<Pose>& frames,
                                                Effector effector);

// The feet a pose solve holds by default on `frame`: each foot in ground contact there
// (`contacts`), not released and not already in `constraints`, as a pin where it stands (`fk` of
// that frame). `released` is indexed by Effector (null: none released).
std::vector<IkConstraint> contactPinsAt(const Clip& clip, const FkState& fk, const ContactSet& contacts, int frame,
                                        const std::vector<IkConstraint>& constraints, const bool* released = nullptr);

}  // namespace mgp
