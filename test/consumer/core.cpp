// SPDX-License-Identifier: BSD-3-Clause
// morphreg::core alone: a tetrahedron's topology, a thin plate spline through its corners, a cloud written and read
// back, and a MorphableICP (PCL registration) ready to take a model. Exit 0 on success.
#include <morphreg/io/cloud_io.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <iostream>

int
main ()
{
  morphreg::TriangleMesh tetrahedron;
  tetrahedron.vertices.resize (3, 4);
  tetrahedron.vertices << 0, 10, 0, 0, //
      0, 0, 10, 0,                     //
      0, 0, 0, 10;
  tetrahedron.triangles.resize (3, 4);
  tetrahedron.triangles << 0, 0, 0, 1, //
      2, 1, 3, 2,                      //
      1, 3, 2, 3;
  const morphreg::MeshTopology topology (tetrahedron);

  morphreg::ThinPlateSpline<double, 3> tps;
  const Eigen::Matrix3Xd moved = (tetrahedron.vertices.array () + 1.0).matrix ();
  tps.fit (tetrahedron.vertices, moved);
  const double miss = (tps.evaluate (tetrahedron.vertices) - moved).norm ();

  pcl::PointCloud<pcl::PointNormal> cloud;
  for (Eigen::Index i = 0; i < moved.cols (); ++i) {
    pcl::PointNormal point;
    point.getVector3fMap () = moved.col (i).cast<float> ();
    point.getNormalVector3fMap () = Eigen::Vector3f::UnitZ ();
    cloud.push_back (point);
  }
  morphreg::saveCloud ("core_cloud.pcd", cloud);
  const auto loaded = morphreg::loadCloud<pcl::PointNormal> ("core_cloud.pcd");

  morphreg::MorphableICP<pcl::PointNormal> icp;
  icp.setMaximumIterations (5);
  std::cout << "euler " << topology.eulerCharacteristic () << ", TPS landmark miss " << miss << " mm, "
            << loaded->size () << " points read back, ICP " << icp.getClassName () << "\n";
  return topology.eulerCharacteristic () == 2 && miss < 1e-6 && loaded->size () == 4 ? 0 : 1;
}
