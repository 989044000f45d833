// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/registration/iteration_progress.h>

#include <cmath>
#include <memory>

namespace morphreg
{
void
watchIterations (MorphableICP<pcl::PointNormal>& icp, IterationCallback callback)
{
  using Cloud = pcl::PointCloud<pcl::PointNormal>;
  auto iteration = std::make_shared<int> (0);
  std::function<MorphableICP<pcl::PointNormal>::UpdateVisualizerCallbackSignature> watcher =
      [callback = std::move (callback), iteration] (const Cloud& source, const pcl::Indices& source_indices,
                                                    const Cloud& target, const pcl::Indices& target_indices) {
        if (source_indices.empty ())
          return; // PCL's registerVisualizationCallback calls once at registration, before any iteration
        double squares = 0.0;
        for (std::size_t k = 0; k < source_indices.size (); ++k)
          squares += (source[source_indices[k]].getVector3fMap () - target[target_indices[k]].getVector3fMap ())
                         .squaredNorm ();
        callback (++*iteration, source_indices.size (), std::sqrt (squares / source_indices.size ()));
      };
  icp.registerVisualizationCallback (watcher);
}

} // namespace morphreg
