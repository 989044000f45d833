// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Internal: where the features sit on the mean synthetic head (mm; +Y up, +Z out of the face, +X to the
// subject's left). Right-side points are given; the left side is their mirror image.
#include <Eigen/Core>

namespace morphreg
{
namespace synthetic
{
namespace anatomy
{
inline const Eigen::Vector3d kRightEye (-31.5, 33.0, 80.0);
inline const Eigen::Vector3d kRightBrow (-30.0, 50.0, 86.0);
inline const Eigen::Vector3d kRightCheek (-46.0, 4.0, 74.0);
inline const Eigen::Vector3d kNoseTip (0.0, -2.0, 95.0);
inline const Eigen::Vector3d kNoseRidge (0.0, 16.0, 93.0);
inline const Eigen::Vector3d kNasion (0.0, 38.0, 90.0);
inline const Eigen::Vector3d kRightNoseWing (-14.0, -8.0, 90.0);
inline const Eigen::Vector3d kRightNostril (-6.0, -12.0, 97.0);
inline const Eigen::Vector3d kUpperLip (0.0, -35.0, 95.0);
inline const Eigen::Vector3d kMouth (0.0, -42.0, 96.0);
inline const Eigen::Vector3d kLowerLip (0.0, -50.0, 93.0);
inline const Eigen::Vector3d kChin (0.0, -84.0, 82.0);
inline const Eigen::Vector3d kRightEar (-75.0, 12.0, -8.0);
inline const Eigen::Vector3d kRightConcha (-75.0, 8.0, -3.0);
inline const Eigen::Vector3d kNoseCentre (0.0, 8.0, 95.0);
} // namespace anatomy
} // namespace synthetic
} // namespace morphreg
