#include "motion/support_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skeleton/centre_of_mass.h"

namespace mgp {

namespace {

Eigen::Vector2d ground(const Eigen::Vector3d& p) { return {p.x(), p.z()}; }

}  // namespace

std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> pts) {
    std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return pts;
    std::vector<Eigen::Vector2d> hull(2 * pts.size());
    std::size_t k = 0;
    for (const Eigen::Vector2d& p : pts) {  // lower hull
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
        hull[k++] = p;
    }
    for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
        while (k >= lower && turn(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);  // the last point is the first
    return hull;
}

std::vector<Eigen::Vector2d> SupportPolygon::grownOutline(int samples) const {
    std::vector<Eigen::Vector2d> points;
    for (const Eigen::Vector2d& p : hull)
        for (int k = 0; k < samples; ++k) {
            const double a = 2.0 * M_PI * k / samples;
            points.push_back(p + kFootHalfWidthCm * Eigen::Vector2d(std::cos(a), std::sin(a)));
        }
    return convexHull(std::move(points));
}

std::optional<SupportPolygon> supportPolygon(const Skeleton& skeleton, const FkState& fk, const ContactSet& contacts,
                                             int frame) {
    SupportPolygon out;
    std::vector<Eigen::Vector2d> points;
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot}) {
        const FootContact* contact = skeleton.hasEffector(foot) ? contacts.at(foot, frame) : nullptr;
        if (!contact) continue;
        const int j = skeleton.effectorSite(foot).joint;
        out.feet.push_back(foot);
        // The points that are down: the ankle while the heel is, the ball and the toe tips while the
        // toe is (all three between two phases of one stance).
        const bool heel = contact->heel.contains(frame), toe = contact->toe.contains(frame);
        if (heel || !toe) points.push_back(ground(fk.jointCm[j]));
        if (toe || !heel) {
            points.push_back(ground(effectorCm(skeleton, fk, foot)));
            for (int c = j + 1; c < skeleton.jointCount(); ++c)
                if (skeleton.joints[c].parent == j) points.push_back(ground(boneEndCm(skeleton, fk, c)));
        }
    }
    if (out.feet.empty()) return std::nullopt;
    out.hull = convexHull(std::move(points));
    return out;
}

std::optional<BalanceRegion> balanceRegion(const Skeleton& skeleton, const Pose& captured, const FkState& startFk,
                                           const ContactSet& contacts, int frame,
                                           const std::vector<IkConstraint>& constraints) {
    FkState fk;
    forwardKinematics(skeleton, captured, fk);
    const std::optional<SupportPolygon> own = supportPolygon(skeleton, fk, contacts, frame);
    const std::optional<Eigen::Vector3d> com = centreOfMass(skeleton, fk);
    if (!own || !com || own->outsideCm(ground(*com)) > kBalanceToleranceCm) return std::nullopt;
    const std::optional<SupportPolygon> support = supportPolygon(skeleton, startFk, contacts, frame);
    if (!support) return std::nullopt;
    for (Effector foot : support->feet)
        if (std::none_of(constraints.begin(), constraints.end(),
                         [foot](const IkConstraint& c) { return c.pin && c.effector == foot; }))
            return std::nullopt;
    return support->region();
}

Balance judgeBalance(const Skeleton& skeleton, const Pose& captured, const Pose& edited, const ContactSet& contacts,
                     int frame) {
    Balance out;
    FkState fk;
    forwardKinematics(skeleton, captured, fk);
    const std::optional<SupportPolygon> before = supportPolygon(skeleton, fk, contacts, frame);
    const std::optional<Eigen::Vector3d> comBefore = centreOfMass(skeleton, fk);
    if (!before || !comBefore || before->outsideCm(ground(*comBefore)) > kBalanceToleranceCm) return out;
    forwardKinematics(skeleton, edited, fk);
    const std::optional<SupportPolygon> after = supportPolygon(skeleton, fk, contacts, frame);
    const std::optional<Eigen::Vector3d> comAfter = centreOfMass(skeleton, fk);
    if (!after || !comAfter) return out;
    out.judged = true;
    out.outsideCm = after->outsideCm(ground(*comAfter));
    out.offBalance = out.outsideCm > kBalanceToleranceCm;
    return out;
}

}  // namespace mgp
