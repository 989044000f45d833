// SPDX-License-Identifier: BSD-3-Clause
// ScanResampler: an 11618-vertex reference (HeadGenerator resolution 44, smoothly offset from the truth by up to
// 1.5 mm) resampled onto a ScanSimulator scan of about 80k points, as a point cloud (weighted local planes) and as its
// triangulated range image (ray casting through Intel Embree); the search structures' build timed apart; and the same
// ray queries (both directions from every reference vertex, first hit, one thread) through Embree and through VTK's
// vtkOBBTree, vtkStaticCellLocator and vtkModifiedBSPTree; and the point cloud's 24-nearest-neighbour queries through
// the resampler's grid and through PCL's KdTreeFLANN. setInputScan and resample() have no external baseline (PCL and
// VTK have no resampler: their labels say so); the ray and neighbour queries run on one thread on both sides, the
// builds on the threads in the counter "threads" (Embree's own pool and VTK's SMP tools use every core).
#include "bench_report.h"
#include "resampling/embree_scene.h"
#include "resampling/point_grid.h"
#include "resampling/scan_surface.h"

#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/resampling/scan_resampler.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkModifiedBSPTree.h>
#include <vtkOBBTree.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <pcl/common/io.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <memory>
#include <thread>

namespace
{
constexpr double kReach = 5.0; ///< mm, the resampler's default search distance

struct Fixture
{
  morphreg::TriangleMesh reference;
  Eigen::Matrix3Xd normals;
  morphreg::synthetic::SimulatedScan scan;
  morphreg::TriangleMesh scan_mesh;
  vtkSmartPointer<vtkPolyData> scan_data;

  Fixture ()
  {
    const morphreg::synthetic::HeadGenerator generator (44);
    const morphreg::TriangleMesh head = generator.sample (1001).mesh;
    morphreg::synthetic::ScanSimulator::Parameters parameters;
    parameters.angular_samples = 440;
    parameters.range_mesh = true;
    scan = morphreg::synthetic::ScanSimulator (parameters).scan (head, 1001);
    scan_mesh = morphreg::fromPolygonMesh (scan.range_mesh, "range mesh");
    reference = head;
    reference.vertices = scan.head_to_scan * head.vertices;
    const Eigen::Matrix3Xd truth_normals = morphreg::vertexNormals (reference);
    for (Eigen::Index v = 0; v < reference.numVertices (); ++v) {
      const Eigen::Vector3d p = reference.vertices.col (v);
      reference.vertices.col (v) += 1.5 * std::sin (p.x () / 40.0) * std::cos (p.y () / 50.0) * truth_normals.col (v);
    }
    normals = morphreg::vertexNormals (reference);
    scan_data = polyData (scan_mesh);
  }

  static vtkSmartPointer<vtkPolyData>
  polyData (const morphreg::TriangleMesh& mesh)
  {
    auto points = vtkSmartPointer<vtkPoints>::New ();
    points->SetDataTypeToDouble ();
    for (Eigen::Index v = 0; v < mesh.numVertices (); ++v)
      points->InsertNextPoint (mesh.vertices.col (v).data ());
    auto cells = vtkSmartPointer<vtkCellArray>::New ();
    for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
      const vtkIdType ids[3] = {mesh.triangles (0, t), mesh.triangles (1, t), mesh.triangles (2, t)};
      cells->InsertNextCell (3, ids);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New ();
    data->SetPoints (points);
    data->SetPolys (cells);
    return data;
  }
};

const Fixture&
fixture ()
{
  static const Fixture f;
  return f;
}

void
sizeCounters (benchmark::State& state)
{
  const Fixture& f = fixture ();
  state.counters["reference_vertices"] = static_cast<double> (f.reference.numVertices ());
  state.counters["scan_points"] = static_cast<double> (f.scan.cloud->size ());
  state.counters["scan_triangles"] = static_cast<double> (f.scan_mesh.numTriangles ());
}

/** Building the resampler's search structure: the cloud's spacings and grid (0) or the mesh's Embree scene (1). */
void
BM_ResamplerSetScan (benchmark::State& state)
{
  const Fixture& f = fixture ();
  for (auto _ : state) {
    morphreg::ScanResampler resampler;
    if (state.range (0) == 0)
      resampler.setInputScan (*f.scan.cloud);
    else
      resampler.setInputScan (f.scan_mesh);
    benchmark::ClobberMemory ();
  }
  sizeCounters (state);
  morphreg::bench::reportNoExternalBaseline (state);
  if (state.range (0) == 1) // Embree's build runs on its own thread pool
    morphreg::bench::reportThreads (state, static_cast<int> (std::thread::hardware_concurrency ()));
}
BENCHMARK (BM_ResamplerSetScan)->ArgName ("mesh")->Arg (0)->Arg (1)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** resample(): the rays and the hole fills, on the cloud (0) or the mesh (1); the parts as counters (ms, mean over
 *  the iterations). */
void
BM_Resample (benchmark::State& state)
{
  const Fixture& f = fixture ();
  morphreg::ScanResampler resampler;
  resampler.setInputReference (f.reference);
  if (state.range (0) == 0)
    resampler.setInputScan (*f.scan.cloud);
  else
    resampler.setInputScan (f.scan_mesh);
  morphreg::ResamplingStatistics stats;
  double ray_seconds = 0.0, fill_seconds = 0.0;
  for (auto _ : state) {
    stats = resampler.resample ().statistics;
    ray_seconds += stats.ray_seconds;
    fill_seconds += stats.fill_seconds;
  }
  sizeCounters (state);
  state.counters["rays_ms"] = benchmark::Counter (1e3 * ray_seconds, benchmark::Counter::kAvgIterations);
  state.counters["fill_ms"] = benchmark::Counter (1e3 * fill_seconds, benchmark::Counter::kAvgIterations);
  state.counters["coverage"] = stats.coverage;
  state.counters["holes"] = static_cast<double> (stats.holes.size ());
  morphreg::bench::reportNoExternalBaseline (state);
}
BENCHMARK (BM_Resample)->ArgName ("mesh")->Arg (0)->Arg (1)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** A VTK locator over the scan mesh: 0 vtkOBBTree, 1 vtkStaticCellLocator, 2 vtkModifiedBSPTree. */
vtkSmartPointer<vtkAbstractCellLocator>
makeLocator (int kind)
{
  vtkSmartPointer<vtkAbstractCellLocator> locator;
  if (kind == 0)
    locator = vtkSmartPointer<vtkOBBTree>::New ();
  else if (kind == 1)
    locator = vtkSmartPointer<vtkStaticCellLocator>::New ();
  else
    locator = vtkSmartPointer<vtkModifiedBSPTree>::New ();
  locator->SetDataSet (fixture ().scan_data);
  locator->LazyEvaluationOff (); // vtkModifiedBSPTree would otherwise build on its first query
  locator->BuildLocator ();
  return locator;
}

void
BM_VtkLocatorBuild (benchmark::State& state)
{
  for (auto _ : state)
    benchmark::DoNotOptimize (makeLocator (static_cast<int> (state.range (0))).Get ());
  sizeCounters (state);
  // vtkStaticCellLocator builds through vtkSMPTools, the other two serially
  morphreg::bench::reportThreads (state, state.range (0) == 1 ? vtkSMPTools::GetEstimatedNumberOfThreads () : 1);
}
BENCHMARK (BM_VtkLocatorBuild)->ArgName ("locator")->DenseRange (0, 2)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** The resampler's ray queries without its normal test: from every reference vertex along +n and -n within the
 *  reach, the first hit of each; the locator as in makeLocator. */
void
BM_VtkLocatorRays (benchmark::State& state)
{
  const Fixture& f = fixture ();
  const auto locator = makeLocator (static_cast<int> (state.range (0)));
  auto cell = vtkSmartPointer<vtkGenericCell>::New ();
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (Eigen::Index v = 0; v < f.reference.numVertices (); ++v)
      for (const double sign : {1.0, -1.0}) {
        const Eigen::Vector3d from = f.reference.vertices.col (v);
        const Eigen::Vector3d to = from + sign * kReach * f.normals.col (v);
        double t = 0.0, x[3], pcoords[3];
        int sub_id = 0;
        vtkIdType cell_id = -1;
        hits += locator->IntersectWithLine (from.data (), to.data (), 0.0, t, x, pcoords, sub_id, cell_id, cell);
      }
  }
  sizeCounters (state);
  state.counters["hits"] = hits;
  morphreg::bench::reportThreads (state, 1);
}
BENCHMARK (BM_VtkLocatorRays)->ArgName ("locator")->DenseRange (0, 2)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** The resampler's Embree scene over the scan mesh. */
void
BM_EmbreeBuild (benchmark::State& state)
{
  for (auto _ : state)
    benchmark::DoNotOptimize (morphreg::detail::EmbreeScene (fixture ().scan_mesh).scene ());
  sizeCounters (state);
  morphreg::bench::reportThreads (state, static_cast<int> (std::thread::hardware_concurrency ()));
}
BENCHMARK (BM_EmbreeBuild)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** The queries of BM_VtkLocatorRays through Embree's rtcIntersect1, on one thread. */
void
BM_EmbreeRays (benchmark::State& state)
{
  const Fixture& f = fixture ();
  const morphreg::detail::EmbreeScene embree (f.scan_mesh);
  RTCIntersectContext context;
  rtcInitIntersectContext (&context);
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (Eigen::Index v = 0; v < f.reference.numVertices (); ++v)
      for (const double sign : {1.0, -1.0}) {
        RTCRayHit query = morphreg::detail::EmbreeScene::query (f.reference.vertices.col (v), sign * f.normals.col (v),
                                                                0.0f, static_cast<float> (kReach));
        rtcIntersect1 (embree.scene (), &context, &query);
        hits += query.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      }
  }
  sizeCounters (state);
  state.counters["hits"] = hits;
  morphreg::bench::reportThreads (state, 1);
}
BENCHMARK (BM_EmbreeRays)->Apply (morphreg::bench::wallAndProcessCpuMs);

constexpr int kNeighbours = 24; ///< the resampler's default

/** The scan cloud's points as 3 x N. */
Eigen::Matrix3Xd
scanPoints ()
{
  const auto& cloud = *fixture ().scan.cloud;
  Eigen::Matrix3Xd points (3, cloud.size ());
  for (std::size_t i = 0; i < cloud.size (); ++i)
    points.col (static_cast<Eigen::Index> (i)) = cloud[i].getVector3fMap ().cast<double> ();
  return points;
}

/** The 24 nearest scan points to every reference vertex (one thread): the resampler's grid (0) or PCL's KdTreeFLANN
 *  (1), the structures built outside the timing. */
void
BM_NeighbourSearch (benchmark::State& state)
{
  const Fixture& f = fixture ();
  const Eigen::Matrix3Xd points = scanPoints ();
  const double cell = 0.5 * morphreg::detail::usualKthDistance (morphreg::detail::localSpacings (points), kNeighbours);
  const morphreg::detail::PointGrid grid (points, cell);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  pcl::copyPointCloud (*f.scan.cloud, *cloud);
  tree.setInputCloud (cloud);
  std::vector<int> indices;
  std::vector<double> squared;
  std::vector<float> squared_float;
  double sum = 0.0;
  for (auto _ : state) {
    sum = 0.0;
    for (Eigen::Index v = 0; v < f.reference.numVertices (); ++v) {
      const Eigen::Vector3d query = f.reference.vertices.col (v);
      if (state.range (0) == 0)
        sum += grid.nearestK (query, kNeighbours, std::numeric_limits<double>::infinity (), indices, squared);
      else {
        pcl::PointXYZ at;
        at.getVector3fMap () = query.cast<float> ();
        tree.nearestKSearch (at, kNeighbours, indices, squared_float);
        sum += squared_float.back ();
      }
    }
  }
  sizeCounters (state);
  state.counters["mean_kth_mm2"] = sum / static_cast<double> (f.reference.numVertices ());
  state.counters["cell_mm"] = cell;
  morphreg::bench::reportThreads (state, 1);
}
BENCHMARK (BM_NeighbourSearch)->ArgName ("flann")->Arg (0)->Arg (1)->Apply (morphreg::bench::wallAndProcessCpuMs);
} // namespace

BENCHMARK_MAIN ();
