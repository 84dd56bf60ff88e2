#include "ik/balance_region.h"

#include <algorithm>
#include <limits>

namespace mgp {
namespace {

// The point of segment ab nearest p; `atEnd`: it is a or b (not inside the segment).
Eigen::Vector2d nearestOnSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 bool* atEnd) {
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    *atEnd = t <= 0.0 || t >= 1.0;
    return a + t * ab;
}

}  // namespace

double turn(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

bool BalanceRegion::convexCounterClockwise() const {
    const std::size_t n = hull.size();
    if (n < 3) return true;
    for (std::size_t i = 0; i < n; ++i)
        if (!(turn(hull[i], hull[(i + 1) % n], hull[(i + 2) % n]) > 0.0)) return false;
    return true;
}

double BalanceRegion::outsideCm(const Eigen::Vector2d& p, Eigen::Vector2d* direction, double* curvature) const {
    if (direction) direction->setZero();
    if (curvature) *curvature = 0.0;
    if (hull.empty()) return std::numeric_limits<double>::infinity();
    bool inside = hull.size() >= 3;
    Eigen::Vector2d nearest = hull[0];
    bool corner = true;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Eigen::Vector2d& a = hull[i];
        const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
        bool atEnd = true;
        const Eigen::Vector2d q = nearestOnSegment(p, a, b, &atEnd);
        if (const double d = (p - q).norm(); d < best) {
            best = d;
            nearest = q;
            corner = atEnd;
        }
        if (hull.size() >= 3 && turn(a, b, p) < 0.0) inside = false;  // right of a counter-clockwise edge
    }
    if (inside || best <= growCm) return 0.0;
    if (direction) *direction = (p - nearest) / best;
    if (curvature && corner) *curvature = 1.0 / best;
    return best - growCm;
}

}  // namespace mgp
