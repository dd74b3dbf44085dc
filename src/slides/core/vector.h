// Vector types: three-component vectors and tensors from Eigen, SI units throughout.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace slides {

using Vec3 = Eigen::Vector3d;
/// Velocity gradient: gradient(i, j) = dU_i / dx_j.
using Mat3 = Eigen::Matrix3d;

} // namespace slides
