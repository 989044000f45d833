// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/model/morphable_model.h>

#include <pcl/type_traits.h>

namespace morphreg
{
template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
MorphableModel::generateCloud (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  const TriangleMesh mesh = generateMesh (coefficients, selection);
  typename pcl::PointCloud<PointT>::Ptr cloud (new pcl::PointCloud<PointT>);
  cloud->resize (mesh.numVertices ());
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i)
    (*cloud)[i].getVector3fMap () = mesh.vertices.col (i).cast<float> ();
  if constexpr (pcl::traits::has_normal_v<PointT>) {
    const Eigen::Matrix3Xd normals = vertexNormals (mesh);
    for (Eigen::Index i = 0; i < mesh.numVertices (); ++i)
      (*cloud)[i].getNormalVector3fMap () = normals.col (i).cast<float> ();
  }
  return cloud;
}

} // namespace morphreg
