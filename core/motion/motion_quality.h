#pragma once
// How keepable an edited span is, next to the same numbers for the captured span.
//
// All angles are the 47 pose DOFs (skeleton/pose_layout.h) in degrees; every difference is
// wrapped to (−180°, 180°] so a 359° → 1° step counts as 2°.
//   second difference at frame s: max over DOFs |wrap(y_{s+1} − y_s) − wrap(y_s − y_{s−1})|,
//     taken at every s in first..last that has both neighbours in the clip (so the joins to the
//     captured frames count); p95 (nearest rank on the sorted values) and max over those s.
//   pose change at frame t: max over DOFs |wrap(y_t − ŷ_t)| (ŷ the capture); worst over the span.
//   contact travel: the largest horizontal (XZ) distance between the effector's positions on two
//     frames of the contact interval, clipped to the clip.
#include <Eigen/Core>
#include <vector>

#include "skeleton/clip.h"

namespace mgp {

struct SecondDifferenceStats {
    double p95Deg = 0.0;
    double maxDeg = 0.0;
    int maxFrame = -1;                // centre frame of the largest one
    std::vector<double> perFrameDeg;  // one per counted centre frame
};

// Largest joint-angle second difference per frame over centres first..last of `frames`.
SecondDifferenceStats secondDifferences(const std::vector<Pose>& frames, const Skeleton& skeleton, int first, int last);

// Nearest-rank percentile (q in [0, 1]) of `values`; 0 for an empty list.
double percentile(std::vector<double> values, double q);

// Largest |wrap(a_k − b_k)| over the 47 DOFs (degrees).
double largestAngleChangeDeg(const Pose& a, const Pose& b, const Skeleton& skeleton);

struct ContactTravel {
    Effector foot = Effector::kLFoot;
    int first = 0, last = 0;  // the interval (0-based, inclusive)
    double editedCm = 0.0;
    double capturedCm = 0.0;
};

// Largest horizontal distance between two frames of first..last of `trajectoryCm`.
double horizontalTravelCm(const std::vector<Eigen::Vector3d>& trajectoryCm, int first, int last);

struct SpanQuality {
    int first = 0, last = 0;  // the span's captured end frames
    SecondDifferenceStats edited, captured;
    double worstKeyErrorCm = 0.0;     // over the keys strictly inside the span
    double worstPathErrorCm = 0.0;    // over every inner frame's path target
    double worstPoseChangeDeg = 0.0;  // largest per-frame change from the capture
    int worstPoseChangeFrame = -1;
    std::vector<ContactTravel> contacts;  // held feet overlapping the span
};

struct ContactInterval {
    Effector foot = Effector::kLFoot;
    int first = 0, last = 0;
};

// The report for an edited motion (`edited`, every clip frame) against `captured` (same length).
// pathCm: the target at frames first..last; keyFrames: the path's keys; contacts: intervals whose
// travel to report (an interval is reported whole, not clipped to the span).
SpanQuality measureSpan(const Clip& captured, const std::vector<Pose>& edited, int first, int last, Effector effector,
                        const std::vector<Eigen::Vector3d>& pathCm, const std::vector<int>& keyFrames,
                        const std::vector<ContactInterval>& contacts);

}  // namespace mgp
