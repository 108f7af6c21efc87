#pragma once
// Fixed-size vector and tensor types used everywhere (Eigen, no heavy modules).
#include <Eigen/Core>

namespace tephra {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using IntVec3 = Eigen::Vector3i;

}  // namespace tephra
