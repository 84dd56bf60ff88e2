#pragma once
// Where a centre of mass may fall on the ground: a convex polygon (x, z; cm) grown by a radius,
// and how far a point lies outside it with the direction that distance grows in. The balance term
// of the constrained IK (docs/maths-ik.md §1) and the support polygon's judgement
// (motion/support_polygon.h) measure the same way.
#include <Eigen/Core>
#include <vector>

namespace mgp {

// Half the width of a sole (cm): how far the support reaches beside the line of the foot bones.
constexpr double kFootHalfWidthCm = 5.0;

// The cross product (a − o) × (b − o): > 0 when o, a, b turn counter-clockwise.
double turn(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

struct BalanceRegion {
    std::vector<Eigen::Vector2d> hull;  // counter-clockwise seen from above; 1 or 2 points when degenerate
    double growCm = kFootHalfWidthCm;
    // What outsideCm assumes of `hull` (1 or 2 points pass): every corner turns counter-clockwise.
    bool convexCounterClockwise() const;
    // How far (cm) p lies outside the grown polygon (0 inside, +∞ with no hull). `direction`, when
    // given and p is outside, is the unit vector from the nearest hull point to p: the gradient of
    // the distance (continuous outside a convex set); zero inside.
    // `curvature`, when given: k with ∇²(distance) = k (I − n nᵀ) there (1 / the distance to the hull
    // where its nearest point is a corner, 0 along an edge or inside).
    double outsideCm(const Eigen::Vector2d& p, Eigen::Vector2d* direction = nullptr, double* curvature = nullptr) const;
};

}  // namespace mgp
