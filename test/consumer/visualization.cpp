// SPDX-License-Identifier: BSD-3-Clause
// morphreg::visualization: links the visualiser (VTK rendering). Run with --render under an X server to draw a
// tetrahedron offscreen; without arguments it only checks the program starts. Exit 0 on success.
#include <morphreg/visualization/registration_visualizer.h>

#include <iostream>
#include <string>

int
main (int argc, char** argv)
{
  if (argc < 2 || std::string (argv[1]) != "--render") {
    std::cout << "visualization consumer linked\n";
    return 0;
  }
  morphreg::TriangleMesh tetrahedron;
  tetrahedron.vertices = Eigen::Matrix3Xd::Identity (3, 4) * 10.0;
  tetrahedron.triangles.resize (3, 4);
  tetrahedron.triangles << 0, 0, 0, 1, //
      2, 1, 3, 2,                      //
      1, 3, 2, 3;
  morphreg::RegistrationVisualizer viewer (morphreg::RegistrationVisualizer::Display::Offscreen);
  viewer.addModelMesh (tetrahedron);
  viewer.saveScreenshot ("visualization.png", 64, 64);
  std::cout << "rendered visualization.png\n";
  return 0;
}
