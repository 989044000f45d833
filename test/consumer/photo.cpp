// SPDX-License-Identifier: BSD-3-Clause
// morphreg::photo: a small RGB image written as PNG and read back (VTK's image IO inside the component), and the
// closest point of a 2D polyline. Exit 0 on success.
#include <morphreg/photo/polyline_2d.h>
#include <morphreg/io/rgb_image_io.h>

#include <iostream>

int
main ()
{
  morphreg::RgbImage image;
  image.width = 4;
  image.height = 3;
  image.data.assign (3 * 4 * 3, 0);
  image.data[3 * (2 * 4 + 1)] = 200; // red at column 1, row 2
  morphreg::saveRgbImage ("photo.png", image);
  const morphreg::RgbImage read = morphreg::loadRgbImage ("photo.png");

  Eigen::Matrix2Xd points (2, 3);
  points << 0, 10, 10, //
      0, 0, 10;
  const morphreg::Polyline2d polyline (points);
  const Eigen::Vector2d closest = polyline.closestPoint (Eigen::Vector2d (5, 3));
  std::cout << read.width << "x" << read.height << " read back, red " << int (read.pixel (1, 2)[0])
            << ", closest point (" << closest.transpose () << ")\n";
  return read.width == 4 && read.pixel (1, 2)[0] == 200 && closest.isApprox (Eigen::Vector2d (5, 0)) ? 0 : 1;
}
