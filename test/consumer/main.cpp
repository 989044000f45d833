// Uses the installed morphreg: generate a head, check its topology, scan it. Exit 0 on success.
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <iostream>

int
main ()
{
  const morphreg::synthetic::HeadGenerator generator (24);
  const auto head = generator.sample (1);
  const morphreg::MeshTopology topology (head.mesh);
  const auto scan = morphreg::synthetic::ScanSimulator ().scan (head.mesh, 1);
  std::cout << "vertices " << head.mesh.numVertices () << ", euler " << topology.eulerCharacteristic ()
            << ", scan points " << scan.cloud->size () << '\n';
  return topology.eulerCharacteristic () == 2 && !scan.cloud->empty () ? 0 : 1;
}
