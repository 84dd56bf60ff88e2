#include "skeleton/rotation.h"

#include <algorithm>
#include <cmath>

namespace mgp {

Eigen::Matrix3d axisRotation(int axis, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    Eigen::Matrix3d r;
    switch (axis) {
        case kAxisX: r << 1, 0, 0, 0, c, -s, 0, s, c; break;
        case kAxisY: r << c, 0, s, 0, 1, 0, -s, 0, c; break;
        default: r << c, -s, 0, s, c, 0, 0, 0, 1; break;
    }
    return r;
}

Eigen::Matrix3d eulerMatrix(const Eigen::Vector3d& anglesDeg, const RotationOrder& order) {
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    for (int a : order)
        if (anglesDeg[a] != 0.0) r = r * axisRotation(a, anglesDeg[a] * kDegToRad);
    return r;
}

Eigen::Vector3d eulerZYXFromMatrix(const Eigen::Matrix3d& r) {
    // r = Rz(z) Ry(y) Rx(x): r(2,0) = -sin y.
    const double sy = std::max(-1.0, std::min(1.0, -r(2, 0)));
    const double y = std::asin(sy);
    double x, z;
    if (std::abs(sy) < 1.0 - 1e-12) {
        x = std::atan2(r(2, 1), r(2, 2));
        z = std::atan2(r(1, 0), r(0, 0));
    } else {  // gimbal lock: put everything into z
        x = 0.0;
        z = std::atan2(-r(0, 1), r(1, 1));
    }
    return Eigen::Vector3d(x, y, z) * kRadToDeg;
}

Eigen::Vector3d eulerFromMatrix(const Eigen::Matrix3d& r, const RotationOrder& order) {
    // r = R_i(α) R_j(β) R_k(γ); s = +1 when (i, j, k) is cyclic (xyz, yzx, zxy), else −1.
    const int i = order[0], j = order[1], k = order[2];
    const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
    const double sb = std::max(-1.0, std::min(1.0, s * r(i, k)));
    const double beta = std::asin(sb);
    double alpha, gamma;
    if (std::abs(sb) < 1.0 - 1e-12) {
        alpha = std::atan2(-s * r(j, k), r(k, k));
        gamma = std::atan2(-s * r(i, j), r(i, i));
    } else {  // gimbal lock: r = R_i(α) R_j(±90°) up to γ, which is set to 0
        gamma = 0.0;
        alpha = std::atan2(s * r(k, j), r(j, j));
    }
    Eigen::Vector3d out;
    out[i] = alpha * kRadToDeg;
    out[j] = beta * kRadToDeg;
    out[k] = gamma * kRadToDeg;
    return out;
}

Eigen::Vector3d eulerAlternative(const Eigen::Vector3d& anglesDeg, const RotationOrder& order) {
    Eigen::Vector3d out = anglesDeg;
    out[order[0]] += 180.0;
    out[order[1]] = 180.0 - anglesDeg[order[1]];
    out[order[2]] += 180.0;
    return out;
}

double wrapNear(double angleDeg, double referenceDeg) {
    return angleDeg - 360.0 * std::round((angleDeg - referenceDeg) / 360.0);
}

}  // namespace mgp
