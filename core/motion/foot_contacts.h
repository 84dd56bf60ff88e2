#pragma once
// Foot contacts of a captured clip: the one rule the learned IK (a planted foot is held like a
// pin by default) and span regeneration (every planted foot keeps its captured position) share.
//
// A foot touches the ground at two points, each with its own phase (docs/maths.md §13): the heel (the ankle joint, the
// start of the foot bone) from heel strike, and the toe (the foot effector at the ball of the foot) until toe-off. A
// point is down when it is low AND slow. Height is measured above that point's ground level, the lowest height it
// habitually reaches (the 5th percentile of its height over the clip, the lower of the two feet), because capture
// floors are rarely at y = 0 and neither point is the sole. Speed is the central difference |p(t+1) − p(t−1)| / 2 in cm
// per frame. Hysteresis keeps a phase from flickering: a point enters contact under the tight thresholds and leaves
// only past the loose ones, phases at most `mergeGapFrames` apart are merged, and phases shorter than `minFrames` are
// dropped. A foot's contact (its stance) is the union of its heel and toe phases: from heel strike to toe-off, the
// frames it is held.
//
// The heel's speed thresholds are looser than the toe's: while the foot rolls about the heel
// after heel strike, the ankle, 5–8 cm above it, moves by that distance times the roll's angular
// speed (0.5–0.8 cm/frame on CMU runs and walks), though the heel itself is down.
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

// One point's thresholds (heights above that point's ground level).
struct ContactThresholds {
    double enterHeightCm = 2.5;         // down when at most this high above its ground …
    double enterSpeedCmPerFrame = 0.2;  // … and at most this fast (24 cm/s at 120 fps)
    double exitHeightCm = 3.5;          // a point that is down lifts off above this height …
    double exitSpeedCmPerFrame = 0.8;   // … or above this speed (96 cm/s at 120 fps)
};

struct ContactRule {
    // Chosen on 35_01 (walk), 10_03 (kick), 16_01 (jump) and the runs 09_01, 16_35 and 02_03
    // (docs/maths.md §13). The ball of a flat foot sits 0.3–2.5 cm above its
    // ground level and moves < 0.2 cm/frame; as the heel lifts, the foot pivots about the toes
    // and the ball moves 0.3–0.6 cm/frame until toe-off, so its exit speed is 0.8.
    ContactThresholds toe{2.5, 0.2, 3.5, 0.8};
    // The ankle comes down at heel strike at 0.5–0.8 cm/frame while the foot rolls onto its sole.
    ContactThresholds heel{2.5, 0.8, 3.5, 1.2};
    int mergeGapFrames = 3;          // two phases this close in time are one (a jitter)
    int minFrames = 6;               // shorter phases are noise (50 ms at 120 fps)
    double groundPercentile = 0.05;  // of each point's height over the clip
};

// A closed range of frames (0-based, inclusive); empty when first > last.
struct FrameRange {
    int first = 0, last = -1;
    bool empty() const { return first > last; }
    bool contains(int frame) const { return frame >= first && frame <= last; }
};

// One stance of one foot.
struct FootContact {
    Effector foot = Effector::kLFoot;
    int first = 0;        // heel strike or the first frame the toe is down (0-based, inclusive)
    int last = 0;         // toe-off: the last frame either point is down (inclusive)
    FrameRange heel;      // the frames the heel is down within first..last (empty: the foot stood on its toes)
    FrameRange toe;       // the frames the toe is down (empty: the foot stood on its heel)
    bool enabled = true;  // the user can switch a contact off
    bool contains(int frame) const { return frame >= first && frame <= last; }
    int length() const { return last - first + 1; }
    // The ball of the foot is down and still: the toe is down and so is the heel, if the stance
    // has a heel phase at all (not while the foot rolls onto its sole or pivots at toe-off).
    bool flatAt(int frame) const { return toe.contains(frame) && (heel.empty() || heel.contains(frame)); }
};

struct ContactSet {
    double groundCm = 0.0;      // the toe points' ground level (world Y, cm)
    double heelGroundCm = 0.0;  // the heel points' (the ankles') ground level; 0 when no heel was tracked
    // The floor the solves keep hands and feet above (ConstrainedIkRequest::floorCm): the lowest
    // height either foot effector reaches over the clip, so no captured frame is below it. None
    // when the skeleton has no feet.
    std::optional<double> floorCm;
    std::vector<FootContact> contacts;  // sorted by foot, then by first frame
    // The enabled contact of `foot` that holds `frame`, or nullptr.
    const FootContact* at(Effector foot, int frame) const;
    FootContact* at(Effector foot, int frame);
};

// One foot's two points over the clip (cm, one entry per frame). `heelCm` may be empty: the foot's
// contacts are then its toe phases alone.
struct FootTrack {
    std::vector<Eigen::Vector3d> toeCm, heelCm;
};

// The rule on explicit foot trajectories (either foot's track may be empty when the skeleton has
// no such foot). Throws std::invalid_argument on a bad rule (a loose threshold tighter than its
// tight one, minFrames < 1, percentile outside [0, 1]) or a heel track whose length is not the toe's.
ContactSet detectFootContacts(const FootTrack& left, const FootTrack& right, double fps, const ContactRule& rule = {});
// The toe points alone (the heel tracks empty).
ContactSet detectFootContacts(const std::vector<Eigen::Vector3d>& leftFootCm,
                              const std::vector<Eigen::Vector3d>& rightFootCm, double fps,
                              const ContactRule& rule = {});
// The rule on a clip's own feet (FK of every frame). A rest frame (Clip::restFrame) counts as the
// first captured frame: it sets neither the floor nor the ground.
ContactSet detectFootContacts(const Clip& clip, const ContactRule& rule = {});

// A foot's toe (its effector) and heel (the start of the bone the effector ends) at every frame
// (empty when the skeleton has no such foot).
FootTrack footTrack(const Clip& clip, Effector foot);

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
