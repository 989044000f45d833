// SPDX-License-Identifier: BSD-3-Clause
// morphreg::synthetic: a coarse synthetic head and a simulated laser scan of it. Exit 0 on success.
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <iostream>

int
main ()
{
  const morphreg::synthetic::HeadGenerator generator (24);
  const auto head = generator.sample (7);
  const morphreg::MeshTopology topology (head.mesh);
  const auto scan = morphreg::synthetic::ScanSimulator ().scan (head.mesh, 1);
  std::cout << head.mesh.numVertices () << " vertices, euler " << topology.eulerCharacteristic () << ", "
            << scan.cloud->size () << " scan points\n";
  return topology.eulerCharacteristic () == 2 && scan.cloud->size () > 1000 ? 0 : 1;
}
