// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/synthetic/scan_simulator.h>
#include <morphreg/synthetic/scanner_options.h>

#include "mesh_slicer.h"

#include <pcl/conversions.h>

#include <cmath>
#include <random>
#include <string>

namespace morphreg
{
namespace synthetic
{
namespace
{
/** A ray's return before noise and pose: where on the head it landed and which way the ray went. */
struct RangeSample
{
  int triangle;
  Eigen::Vector3d barycentric;
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
  Eigen::Vector3d ray;
};

/** The range image: rows x angles, each cell the index of its sample or -1 where nothing came back. */
struct RangeImage
{
  std::vector<RangeSample> samples;
  Eigen::MatrixXi cells;
};

/** Casts every row's rays at the head and keeps the returns the incidence limit lets through. */
RangeImage
castRays (const TriangleMesh& head, const ScanSimulator::Parameters& parameters)
{
  const Eigen::Vector3d low = head.vertices.rowwise ().minCoeff ();
  const Eigen::Vector3d high = head.vertices.rowwise ().maxCoeff ();
  const Eigen::Vector2d axis (0.5 * (low.x () + high.x ()), 0.5 * (low.z () + high.z ()));
  const double radius = (high - low).norm (); // every ray starts outside the head
  const int rows = std::max (1, static_cast<int> ((high.y () - low.y ()) / parameters.row_spacing));
  const int angles = parameters.angular_samples;
  const double min_cosine = std::cos (parameters.max_incidence_deg * M_PI / 180.0);
  const Eigen::Matrix3Xd normals = vertexNormals (head);
  // The triangulating camera sits above the laser plane and looks down at it.
  const double elevation = parameters.camera_elevation_deg * M_PI / 180.0;
  const auto camera = [elevation] (const Eigen::Vector2d& outward) {
    return Eigen::Vector3d (std::cos (elevation) * outward.x (), std::sin (elevation),
                            std::cos (elevation) * outward.y ());
  };

  std::vector<std::vector<RangeSample>> row_samples (rows);
  std::vector<std::vector<int>> row_angles (rows);
#pragma omp parallel for schedule(dynamic)
  for (int row = 0; row < rows; ++row) {
    const double height = low.y () + (row + 0.5) * parameters.row_spacing;
    const std::vector<SliceSegment> slice = sliceAtHeight (head, height);
    for (int a = 0; a < angles; ++a) {
      const double theta = 2.0 * M_PI * a / angles;
      const Eigen::Vector2d outward (std::cos (theta), std::sin (theta));
      const SliceHit hit = firstHit (slice, axis + radius * outward, -outward);
      if (hit.segment < 0)
        continue;
      const SliceSegment& segment = slice[hit.segment];
      RangeSample sample;
      sample.triangle = segment.triangle;
      sample.barycentric = (1.0 - hit.along) * segment.start_barycentric + hit.along * segment.end_barycentric;
      sample.position.setZero ();
      sample.normal.setZero ();
      for (int k = 0; k < 3; ++k) {
        const int vertex = head.triangles (k, segment.triangle);
        sample.position += sample.barycentric[k] * head.vertices.col (vertex);
        sample.normal += sample.barycentric[k] * normals.col (vertex);
      }
      sample.normal.normalize ();
      sample.ray = Eigen::Vector3d (-outward.x (), 0.0, -outward.y ());
      if (-sample.normal.dot (sample.ray) < min_cosine || sample.normal.dot (camera (outward)) < min_cosine)
        continue; // too oblique for the laser or its camera (or the back of a surface): no return
      row_samples[row].push_back (sample);
      row_angles[row].push_back (a);
    }
  }

  RangeImage image;
  image.cells = Eigen::MatrixXi::Constant (rows, angles, -1);
  for (int row = 0; row < rows; ++row)
    for (std::size_t k = 0; k < row_samples[row].size (); ++k) {
      image.cells (row, row_angles[row][k]) = static_cast<int> (image.samples.size ());
      image.samples.push_back (row_samples[row][k]);
    }
  return image;
}

/** A random rotation (about a uniform axis, angle up to the limit), scale and translation. */
Eigen::Affine3d
randomSimilarity (const ScanSimulator::Parameters& parameters, std::mt19937_64& rng, double& scale)
{
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> uniform;
  const Eigen::Vector3d axis = Eigen::Vector3d (gaussian (rng), gaussian (rng), gaussian (rng)).normalized ();
  const double angle = uniform (rng) * parameters.max_rotation_deg * M_PI / 180.0;
  scale = 1.0 + (2.0 * uniform (rng) - 1.0) * parameters.max_scale_deviation;
  const Eigen::Vector3d direction = Eigen::Vector3d (gaussian (rng), gaussian (rng), gaussian (rng)).normalized ();
  const Eigen::Vector3d translation = direction * parameters.max_translation * std::cbrt (uniform (rng));
  Eigen::Affine3d transform = Eigen::Affine3d::Identity ();
  transform.linear () = scale * Eigen::AngleAxisd (angle, axis).toRotationMatrix ();
  transform.translation () = translation;
  return transform;
}

pcl::PointNormal
makePoint (const Eigen::Vector3d& position, const Eigen::Vector3d& normal)
{
  pcl::PointNormal point;
  point.getVector3fMap () = position.cast<float> ();
  point.getNormalVector3fMap () = normal.cast<float> ();
  point.curvature = 0.0f;
  return point;
}

/** Adds outliers spread uniformly over the inliers' bounding box grown by 20%, with random normals. */
void
addOutliers (SimulatedScan& scan, double fraction, std::mt19937_64& rng)
{
  const std::size_t inliers = scan.cloud->size ();
  scan.num_outliers = static_cast<int> (std::lround (fraction / (1.0 - fraction) * inliers));
  if (scan.num_outliers == 0)
    return;
  Eigen::Vector3f low = Eigen::Vector3f::Constant (std::numeric_limits<float>::max ());
  Eigen::Vector3f high = -low;
  for (const auto& point : *scan.cloud) {
    low = low.cwiseMin (point.getVector3fMap ());
    high = high.cwiseMax (point.getVector3fMap ());
  }
  const Eigen::Vector3d margin = 0.1 * (high - low).cast<double> ();
  const Eigen::Vector3d box_low = low.cast<double> () - margin, box_size = (high - low).cast<double> () + 2 * margin;
  std::uniform_real_distribution<double> uniform;
  std::normal_distribution<double> gaussian;
  for (int k = 0; k < scan.num_outliers; ++k) {
    const Eigen::Vector3d position =
        box_low + box_size.cwiseProduct (Eigen::Vector3d (uniform (rng), uniform (rng), uniform (rng)));
    const Eigen::Vector3d normal = Eigen::Vector3d (gaussian (rng), gaussian (rng), gaussian (rng)).normalized ();
    scan.cloud->push_back (makePoint (position, normal));
    scan.source_triangle.push_back (-1);
  }
  scan.barycentric.conservativeResize (3, scan.cloud->size ());
  scan.barycentric.rightCols (scan.num_outliers).setZero ();
}

/** Connects neighbouring cells of the range image (angles wrap around) whose points are close enough. */
std::vector<pcl::Vertices>
triangulateRangeImage (const RangeImage& image, double max_edge_length)
{
  std::vector<pcl::Vertices> polygons;
  const auto close_enough = [&] (int a, int b) {
    return (image.samples[a].position - image.samples[b].position).norm () <= max_edge_length;
  };
  const auto add_triangle = [&] (int a, int b, int c) {
    if (a < 0 || b < 0 || c < 0 || !close_enough (a, b) || !close_enough (b, c) || !close_enough (c, a))
      return;
    pcl::Vertices triangle;
    triangle.vertices = {a, b, c}; // counter-clockwise seen from outside: up, then round
    polygons.push_back (triangle);
  };
  const Eigen::Index angles = image.cells.cols ();
  for (Eigen::Index row = 0; row + 1 < image.cells.rows (); ++row)
    for (Eigen::Index a = 0; a < angles; ++a) {
      const Eigen::Index next = (a + 1) % angles;
      add_triangle (image.cells (row, a), image.cells (row + 1, a), image.cells (row, next));
      add_triangle (image.cells (row + 1, a), image.cells (row + 1, next), image.cells (row, next));
    }
  return polygons;
}
} // namespace

ScanSimulator::ScanSimulator (const Parameters& parameters) : parameters_ (parameters)
{
  requireValidScannerParameters (parameters);
}

SimulatedScan
ScanSimulator::scan (const TriangleMesh& head, std::uint64_t seed) const
{
  validateMesh (head, "head mesh to scan");
  const RangeImage image = castRays (head, parameters_);
  if (image.samples.empty ())
    throw InvalidInputError ("ScanSimulator: the scanner sees nothing of the head mesh (is it degenerate?)");

  std::mt19937_64 rng (seed);
  SimulatedScan scan;
  scan.head_to_scan = randomSimilarity (parameters_, rng, scan.scale);
  const Eigen::Matrix3d rotation = scan.head_to_scan.linear () / scan.scale;

  std::normal_distribution<double> noise (0.0, parameters_.noise_sigma);
  scan.cloud.reset (new pcl::PointCloud<pcl::PointNormal>);
  scan.cloud->reserve (image.samples.size ());
  scan.barycentric.resize (3, static_cast<Eigen::Index> (image.samples.size ()));
  for (std::size_t k = 0; k < image.samples.size (); ++k) {
    const RangeSample& sample = image.samples[k];
    const double range_error = parameters_.noise_sigma > 0.0 ? noise (rng) : 0.0;
    const Eigen::Vector3d measured = sample.position + range_error * sample.ray;
    scan.cloud->push_back (makePoint (scan.head_to_scan * measured, rotation * sample.normal));
    scan.source_triangle.push_back (sample.triangle);
    scan.barycentric.col (static_cast<Eigen::Index> (k)) = sample.barycentric;
  }
  addOutliers (scan, parameters_.outlier_fraction, rng);
  scan.cloud->width = static_cast<std::uint32_t> (scan.cloud->size ());
  scan.cloud->height = 1;

  if (parameters_.range_mesh) {
    pcl::toPCLPointCloud2 (*scan.cloud, scan.range_mesh.cloud);
    scan.range_mesh.polygons = triangulateRangeImage (image, parameters_.max_edge_length);
  }
  return scan;
}

} // namespace synthetic
} // namespace morphreg
