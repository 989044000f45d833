// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file iteration_progress.h
 *  \brief Progress of a running MorphableICP fit, one call per iteration with its correspondences and their RMS
 *  distance: for progress bars, logs and Python callbacks.
 */
#include <morphreg/registration/morphable_icp.h>

#include <pcl/point_types.h>

#include <cstddef>
#include <functional>

namespace morphreg
{
/** \brief Called once per iteration: its number (from 1), the correspondences kept and their RMS distance (mm). */
using IterationCallback = std::function<void (int iteration, std::size_t correspondences, double rms)>;

/** \brief Calls \a callback after every iteration of \a icp's align() (through PCL's
 *  registerVisualizationCallback, which it replaces). An exception thrown by \a callback stops the fit and leaves
 *  align() with it.
 *  \param[in,out] icp the registration to watch
 *  \param[in] callback the function to call
 */
void
watchIterations (MorphableICP<pcl::PointNormal>& icp, IterationCallback callback);

} // namespace morphreg
