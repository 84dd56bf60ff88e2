#pragma once
// The central difference every gradient test checks an analytic derivative against.
#include <Eigen/Core>

namespace mgp::test {

// (f(z + h·e_i) − f(z − h·e_i)) / 2h: f's derivative along coordinate i at z.
template <class F>
double centralDifference(const F& f, const Eigen::VectorXd& z, Eigen::Index i, double h = 1e-6) {
    Eigen::VectorXd zp = z, zm = z;
    zp[i] += h;
    zm[i] -= h;
    return (f(zp) - f(zm)) / (2 * h);
}

}  // namespace mgp::test
