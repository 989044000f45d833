// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/visualization/registration_visualizer.h>

#include <pcl/common/io.h>

namespace morphreg
{
namespace detail
{
/** The x, y, z of any PCL point type, as the cloud the visualiser draws. */
template <typename PointT>
pcl::PointCloud<pcl::PointXYZ>::Ptr
positionsOf (const pcl::PointCloud<PointT>& cloud)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr positions (new pcl::PointCloud<pcl::PointXYZ>);
  pcl::copyPointCloud (cloud, *positions);
  return positions;
}
} // namespace detail

template <typename PointT>
void
RegistrationVisualizer::addTargetCloud (const pcl::PointCloud<PointT>& cloud, const std::string& id, int viewport,
                                        double point_size)
{
  addTargetPositions (detail::positionsOf (cloud), id, viewport, point_size);
}

template <typename PointT>
void
RegistrationVisualizer::addScanOverlay (const pcl::PointCloud<PointT>& cloud, std::size_t max_points,
                                        const std::string& id, int viewport)
{
  addOverlayPositions (detail::positionsOf (cloud), max_points, id, viewport);
}

template <typename PointSource, typename PointTarget>
void
RegistrationVisualizer::addCorrespondences (const pcl::PointCloud<PointSource>& source,
                                            const pcl::PointCloud<PointTarget>& target,
                                            const pcl::Correspondences& correspondences, std::size_t max_lines,
                                            const std::string& id, int viewport)
{
  addCorrespondenceLines (detail::positionsOf (source), detail::positionsOf (target), correspondences, max_lines, id,
                          viewport);
}

template <typename PointSource, typename PointTarget>
RegistrationVisualizer::RegistrationCallback<PointSource, PointTarget>
RegistrationVisualizer::makeRegistrationCallback (int viewport, std::size_t max_lines)
{
  // The target only changes between align() calls: remember which one was drawn and redraw it when it changes.
  auto drawn_target = std::make_shared<const pcl::PointCloud<PointTarget>*> (nullptr);
  return [this, viewport, max_lines,
          drawn_target] (const pcl::PointCloud<PointSource>& source, const pcl::Indices& source_indices,
                         const pcl::PointCloud<PointTarget>& target, const pcl::Indices& target_indices) {
    const bool target_changed = *drawn_target != &target;
    *drawn_target = &target;
    showRegistrationState (detail::positionsOf (source), source_indices, detail::positionsOf (target), target_changed,
                           target_indices, viewport, max_lines);
  };
}

} // namespace morphreg
