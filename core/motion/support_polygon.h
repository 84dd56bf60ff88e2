#pragma once
// Balance on a frame: the support polygon of the feet in ground contact and where the centre of
// mass (skeleton/centre_of_mass.h) falls against it, on the ground plane (world x, z; cm).
//
// Each planted foot (motion/foot_contacts.h) stands on the points that are down: its ankle (the
// foot bone's start) while the heel is, the ball (the foot effector) and, where the skeleton has
// them, the toe tips while the toe is; the polygon is the convex hull of those points grown by
// kFootHalfWidthCm (a foot is a sole, not a line), so one flat foot gives a sole-shaped region, a
// heel or a toe alone a disc, and two feet the area between them. A frame without a planted foot
// has no polygon (in the air: balance is not judged).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ik/balance_region.h"
#include "motion/foot_contacts.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/skeleton.h"

namespace mgp {

// How far outside its support a centre of mass may fall before the pose is "off balance" (cm).
constexpr double kBalanceToleranceCm = 2.0;

struct SupportPolygon {
    std::vector<Eigen::Vector2d> hull;  // (x, z), counter-clockwise seen from above; 1 or 2 points when degenerate
    std::vector<Effector> feet;         // the planted feet it stands on
    // How far (cm) the ground point p = (x, z) lies outside the grown polygon (0 inside).
    double outsideCm(const Eigen::Vector2d& p) const { return region().outsideCm(p); }
    BalanceRegion region() const { return {hull, kFootHalfWidthCm}; }
    // The grown polygon's outline (what outsideCm measures from), each hull point's half-sole disc
    // sampled at `samples` angles: counter-clockwise, for drawing.
    std::vector<Eigen::Vector2d> grownOutline(int samples = 12) const;
};

// The convex hull of points on a plane (Andrew's monotone chain), counter-clockwise, collinear
// points dropped; 1 or 2 points when the input is degenerate.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points);

// The support polygon of clip frame `frame` for the pose whose FK is `fk` (the feet where this
// pose puts them), or none when no foot is planted on that frame.
std::optional<SupportPolygon> supportPolygon(const Skeleton& skeleton, const FkState& fk, const ContactSet& contacts,
                                             int frame);

struct Balance {
    bool judged = false;      // a planted foot on the frame and the captured pose balanced on it
    double outsideCm = 0.0;   // the edited pose's centre of mass outside its support (cm)
    bool offBalance = false;  // judged and outsideCm > kBalanceToleranceCm
};

// The balance term's region for a pose solve on clip frame `frame` (ConstrainedIkRequest::balance):
// the support of the planted feet where the start pose (`startFk`) has them, when the captured pose
// stands balanced on them (its centre of mass within kBalanceToleranceCm of its own support) and
// every one of those feet is pinned in `constraints` (a free foot would move the support). None
// otherwise: balance is then not asked for.
std::optional<BalanceRegion> balanceRegion(const Skeleton& skeleton, const Pose& captured, const FkState& startFk,
                                           const ContactSet& contacts, int frame,
                                           const std::vector<IkConstraint>& constraints);

// Judges `edited` on clip frame `frame`: only where the captured pose's centre of mass lies over its
// support (within the tolerance) is the edited one required to stay over it too.
Balance judgeBalance(const Skeleton& skeleton, const Pose& captured, const Pose& edited, const ContactSet& contacts,
                     int frame);

}  // namespace mgp
