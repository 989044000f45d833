// SPDX-License-Identifier: BSD-3-Clause
// Renders a few heads of the built-in synthetic population, front and side views, into one PNG.
// Usage (headless): xvfb-run -a ./sample_population_gallery heads.png [count] [seed]
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <Eigen/Geometry>

#include <iostream>
#include <string>

int
main (int argc, char** argv)
{
  const std::string png = argc > 1 ? argv[1] : "heads.png";
  const int count = argc > 2 ? std::stoi (argv[2]) : 5;
  const std::uint64_t seed = argc > 3 ? std::stoull (argv[3]) : 1;

  const morphreg::synthetic::HeadGenerator generator;
  morphreg::RegistrationVisualizer viewer (morphreg::RegistrationVisualizer::Display::Offscreen);
  const Eigen::Matrix3d profile = Eigen::AngleAxisd (-M_PI / 2.0, Eigen::Vector3d::UnitY ()).toRotationMatrix ();
  for (int i = 0; i < count; ++i) {
    morphreg::TriangleMesh head = generator.sample (seed + static_cast<std::uint64_t> (i)).mesh;
    const Eigen::Vector3d column (240.0 * i, 0.0, 0.0);
    morphreg::TriangleMesh side = head;
    side.vertices = (profile * head.vertices).colwise () + (column + Eigen::Vector3d (0.0, -360.0, 0.0));
    head.vertices.colwise () += column;
    viewer.addModelMesh (head, 1.0, "front_" + std::to_string (i));
    viewer.addModelMesh (side, 1.0, "side_" + std::to_string (i));
  }
  viewer.resetCamera ();
  viewer.saveScreenshot (png, 300 * count, 760);
  std::cout << "wrote " << png << '\n';
  return 0;
}
