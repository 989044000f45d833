// SPDX-License-Identifier: BSD-3-Clause
// Reading glTF (issue 39): morphreg's reader (readGltfFile, and loadPolygonMesh, which adds the PCL mesh) on GLB files
// of a synthetic head (HeadGenerator resolution 44: 11,618 vertices) and of the same head subdivided twice (185,858
// vertices, the size of a phone capture), plain and Draco-compressed (lossless Edgebreaker), against the baselines
// in the same process: VTK 9.1's vtkGLTFReader on the same GLB files, and PCL's PLY reader on the mesh as binary PLY.
// The files are written by the tests' glTF writer (test/support/glb_writer.h) into the temporary folder. Every
// reader runs on one thread (counter "threads").
#include "bench_report.h"
#include "support/glb_writer.h"

#include <morphreg/io/gltf_reader.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/synthetic/head_generator.h>

#include <pcl/io/ply_io.h>
#include <vtkGLTFReader.h>
#include <vtkSmartPointer.h>

#include <benchmark/benchmark.h>

#include <array>
#include <filesystem>
#include <map>

namespace
{
namespace gltf = morphreg::test::gltf;

/** Each triangle cut into four at its edges' midpoints. */
morphreg::TriangleMesh
subdivided (const morphreg::TriangleMesh& mesh)
{
  std::vector<Eigen::Vector3d> vertices (mesh.vertices.colwise ().begin (), mesh.vertices.colwise ().end ());
  std::map<std::pair<int, int>, int> midpoints;
  const auto midpoint = [&] (int a, int b) {
    const auto [entry, added] = midpoints.emplace (std::minmax (a, b), static_cast<int> (vertices.size ()));
    if (added)
      vertices.push_back (0.5 * (mesh.vertices.col (a) + mesh.vertices.col (b)));
    return entry->second;
  };
  morphreg::TriangleMesh result;
  result.triangles.resize (3, 4 * mesh.numTriangles ());
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    const int a = mesh.triangles (0, t), b = mesh.triangles (1, t), c = mesh.triangles (2, t);
    const int ab = midpoint (a, b), bc = midpoint (b, c), ca = midpoint (c, a);
    result.triangles.middleCols<4> (4 * t) << a, ab, ca, ab, ab, b, bc, bc, ca, bc, c, ca;
  }
  result.vertices.resize (3, static_cast<Eigen::Index> (vertices.size ()));
  for (std::size_t v = 0; v < vertices.size (); ++v)
    result.vertices.col (static_cast<Eigen::Index> (v)) = vertices[v];
  return result;
}

/** The test files of one head: <name>.ply, <name>.glb, <name>_draco.glb. */
std::string
writeFiles (const morphreg::TriangleMesh& mesh, const std::string& name)
{
  const std::string stem = (std::filesystem::temp_directory_path () / ("morphreg_bench_gltf_" + name)).string ();
  pcl::io::savePLYFileBinary (stem + ".ply", morphreg::toPolygonMesh (mesh));
  const gltf::Primitive primitive = gltf::meshPrimitive (mesh);
  gltf::writeGlb (stem + ".glb", gltf::build (gltf::singleNode (primitive)));
  gltf::Primitive draco = primitive;
  draco.draco = true;
  gltf::writeGlb (stem + "_draco.glb", gltf::build (gltf::singleNode (draco)));
  return stem;
}

/** The files' stems: the head ([0]) and the subdivided head ([1]), written once. */
const std::array<std::string, 2>&
stems ()
{
  static const std::array<std::string, 2> written = [] {
    const morphreg::TriangleMesh head = morphreg::synthetic::HeadGenerator (44).sample (1).mesh;
    return std::array<std::string, 2>{writeFiles (head, "head"), writeFiles (subdivided (subdivided (head)), "dense")};
  }();
  return written;
}

/** The GLB of benchmark arguments (size, draco). */
std::string
glbPath (const benchmark::State& state)
{
  return stems ()[state.range (0)] + (state.range (1) ? "_draco.glb" : ".glb");
}

void
BM_MorphregReadGltf (benchmark::State& state)
{
  const std::string path = glbPath (state);
  for (auto _ : state)
    benchmark::DoNotOptimize (morphreg::readGltfFile (path));
  morphreg::bench::reportThreads (state, 1);
}

void
BM_MorphregLoadPolygonMeshGlb (benchmark::State& state)
{
  const std::string path = glbPath (state);
  for (auto _ : state)
    benchmark::DoNotOptimize (morphreg::loadPolygonMesh (path));
  morphreg::bench::reportThreads (state, 1);
}

void
BM_VtkGltfReader (benchmark::State& state)
{
  const std::string path = glbPath (state);
  for (auto _ : state) {
    const auto reader = vtkSmartPointer<vtkGLTFReader>::New ();
    reader->SetFileName (path.c_str ());
    reader->Update ();
    benchmark::DoNotOptimize (reader->GetOutput ());
  }
  morphreg::bench::reportThreads (state, 1);
}

void
BM_PclLoadPly (benchmark::State& state)
{
  const std::string path = stems ()[state.range (0)] + ".ply";
  for (auto _ : state) {
    pcl::PolygonMesh mesh;
    pcl::io::loadPLYFile (path, mesh);
    benchmark::DoNotOptimize (mesh);
  }
  morphreg::bench::reportThreads (state, 1);
}

void
BM_MorphregLoadPolygonMeshPly (benchmark::State& state)
{
  const std::string path = stems ()[state.range (0)] + ".ply";
  for (auto _ : state)
    benchmark::DoNotOptimize (morphreg::loadPolygonMesh (path));
  morphreg::bench::reportThreads (state, 1);
}
} // namespace

BENCHMARK (BM_PclLoadPly)->Arg (0)->Arg (1)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_MorphregLoadPolygonMeshPly)->Arg (0)->Arg (1)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_VtkGltfReader)->Args ({0, 0})->Args ({1, 0})->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_MorphregReadGltf)->ArgsProduct ({{0, 1}, {0, 1}})->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_MorphregLoadPolygonMeshGlb)->ArgsProduct ({{0, 1}, {0, 1}})->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK_MAIN ();
