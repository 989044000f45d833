// A triangulated scan as ScanResampler's surface. The rays go through VTK's vtkStaticCellLocator: VTK is already a
// dependency (PCL's I/O links it), its data model needs none of VTK's rendering, and of VTK's locators (with
// vtkOBBTree and vtkModifiedBSPTree) it builds fastest and answers the resampler's short rays about as fast as the
// quickest (bench/RESULTS.md, "Scan resampling").
#include "scan_surface.h"

#include <morphreg/mesh/mesh_normals.h>

#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <cmath>

namespace morphreg
{
namespace detail
{
namespace
{
/** Hits whose normals disagree are stepped over; a ray crossing more surfaces than this within its reach misses. */
constexpr int kMaxCrossings = 8;

vtkSmartPointer<vtkPolyData>
polyData (const TriangleMesh& mesh)
{
  auto points = vtkSmartPointer<vtkPoints>::New ();
  points->SetDataTypeToDouble ();
  points->SetNumberOfPoints (mesh.numVertices ());
  for (Eigen::Index v = 0; v < mesh.numVertices (); ++v)
    points->SetPoint (v, mesh.vertices.col (v).data ());
  auto triangles = vtkSmartPointer<vtkCellArray>::New ();
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    const vtkIdType ids[3] = {mesh.triangles (0, t), mesh.triangles (1, t), mesh.triangles (2, t)};
    triangles->InsertNextCell (3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New ();
  data->SetPoints (points);
  data->SetPolys (triangles);
  return data;
}

class MeshSurface : public ScanSurface
{
public:
  explicit MeshSurface (const TriangleMesh& scan)
    : points_ (scan.vertices), face_normals_ (faceNormals (scan)), data_ (polyData (scan))
  {
    locator_->SetDataSet (data_);
    locator_->BuildLocator ();
  }

  bool
  intersect (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double max_distance, double min_cos,
             Eigen::Vector3d& hit) const override
  {
    double best = max_distance;
    bool found = false;
    for (const double sign : {1.0, -1.0}) {
      double reach = best;
      Eigen::Vector3d point;
      if (firstAgreeing (origin, sign * direction, direction, min_cos, reach, point)) {
        best = reach;
        hit = point;
        found = true;
      }
    }
    return found;
  }

  const Eigen::Matrix3Xd&
  points () const override
  {
    return points_;
  }

  bool
  threadSafe () const override
  {
    return false; // the queries share one generic cell; VTK 9.1 does not document the locator's queries as thread-safe
  }

private:
  /** The first surface crossing from \a start along \a ray (unit) within \a reach whose normal agrees with
   *  \a normal; on success \a reach becomes its distance. */
  bool
  firstAgreeing (const Eigen::Vector3d& start, const Eigen::Vector3d& ray, const Eigen::Vector3d& normal,
                 double min_cos, double& reach, Eigen::Vector3d& hit) const
  {
    const double step = 1e-6 * (1.0 + reach);
    double travelled = 0.0;
    for (int crossing = 0; crossing < kMaxCrossings && travelled < reach; ++crossing) {
      const Eigen::Vector3d from = start + travelled * ray;
      const Eigen::Vector3d to = start + reach * ray;
      double t = 0.0, x[3], pcoords[3];
      int sub_id = 0;
      vtkIdType cell_id = -1;
      if (!locator_->IntersectWithLine (from.data (), to.data (), 0.0, t, x, pcoords, sub_id, cell_id, cell_))
        return false;
      travelled += t * (reach - travelled);
      if (face_normals_.col (cell_id).dot (normal) >= min_cos) {
        hit = Eigen::Vector3d (x[0], x[1], x[2]);
        reach = travelled;
        return true;
      }
      travelled += step;
    }
    return false;
  }

  Eigen::Matrix3Xd points_;
  Eigen::Matrix3Xd face_normals_;
  vtkSmartPointer<vtkPolyData> data_;
  vtkSmartPointer<vtkStaticCellLocator> locator_ = vtkSmartPointer<vtkStaticCellLocator>::New ();
  vtkSmartPointer<vtkGenericCell> cell_ = vtkSmartPointer<vtkGenericCell>::New ();
};
} // namespace

std::unique_ptr<ScanSurface>
makeMeshSurface (const TriangleMesh& scan)
{
  return std::make_unique<MeshSurface> (scan);
}
} // namespace detail
} // namespace morphreg
