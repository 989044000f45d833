// SPDX-License-Identifier: BSD-3-Clause
// The all-in-one package (find_package(morphreg), morphreg::morphreg): generate heads, build a global model, scan an
// unseen head and register the scan behind a PCL rejector, as the README shows. Exit 0 on success.
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <pcl/registration/correspondence_rejection_median_distance.h>

#include <iostream>

int
main ()
{
  const morphreg::synthetic::HeadGenerator generator (24);
  std::vector<morphreg::TriangleMesh> meshes;
  for (auto& head : generator.population (12, 1))
    meshes.push_back (std::move (head.mesh));
  const auto model = morphreg::ModelBuilder ().buildGlobal (meshes);

  const auto subject = generator.sample (100);
  const morphreg::MeshTopology topology (subject.mesh);
  const auto scan = morphreg::synthetic::ScanSimulator ().scan (subject.mesh, 1);

  morphreg::MorphableICP<pcl::PointNormal> icp;
  icp.setModel (model);
  icp.setInputTarget (scan.cloud);
  auto median = std::make_shared<pcl::registration::CorrespondenceRejectorMedianDistance> ();
  median->setMedianFactor (3.0);
  icp.addCorrespondenceRejector (median);
  pcl::PointCloud<pcl::PointNormal> fitted;
  icp.align (fitted);
  const double rms = icp.getRegistrationReport ().fitness_rms;
  std::cout << "vertices " << subject.mesh.numVertices () << ", euler " << topology.eulerCharacteristic ()
            << ", scan points " << scan.cloud->size () << ", fitness RMS " << rms << " mm\n";
  const bool every_vertex_fitted = static_cast<Eigen::Index> (fitted.size ()) == meshes[0].vertices.cols ();
  return topology.eulerCharacteristic () == 2 && every_vertex_fitted && rms < 3.0 ? 0 : 1;
}
