// Fixed-size vectors of the simulation's space dimension.
#pragma once

#include <Eigen/Core>

namespace sph {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

}  // namespace sph
