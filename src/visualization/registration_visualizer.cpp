// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/common/colour_map.h>
#include <morphreg/visualization/impl/registration_visualizer.hpp>

#include "window_png.h"

#include <morphreg/visualization/x_display.h>

#include <pcl/visualization/pcl_visualizer.h>

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkLookupTable.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <Eigen/Geometry>

#include <cstdlib>
#include <algorithm>
#include <random>

// Debian's VTK needs its rendering back end registered explicitly in programs that use it directly.
VTK_MODULE_INIT (vtkRenderingOpenGL2)
VTK_MODULE_INIT (vtkRenderingFreeType)
VTK_MODULE_INIT (vtkInteractionStyle)

namespace morphreg
{
namespace
{
const Eigen::Vector3d kTargetColour (0.35, 0.55, 0.85);
const Eigen::Vector3d kModelColour (0.92, 0.78, 0.62);
const Eigen::Vector3d kSourceLandmarkColour (0.95, 0.45, 0.1);
const Eigen::Vector3d kTargetLandmarkColour (0.1, 0.65, 0.3);
const Eigen::Vector3d kCorrespondenceColour (0.9, 0.2, 0.2);
const Eigen::Vector3d kScanOverlayColour (0.3, 0.3, 0.3);

/** The renderers of \a viewport (0 = all of them), in PCL's numbering (the index in the collection). */
std::vector<vtkRenderer*>
renderersOf (pcl::visualization::PCLVisualizer& visualizer, int viewport)
{
  std::vector<vtkRenderer*> renderers;
  vtkRendererCollection* collection = visualizer.getRendererCollection ();
  collection->InitTraversal ();
  int index = 0;
  for (vtkRenderer* renderer = collection->GetNextItem (); renderer; renderer = collection->GetNextItem (), ++index)
    if (viewport == 0 || index == viewport)
      renderers.push_back (renderer);
  return renderers;
}

void
removeExisting (pcl::visualization::PCLVisualizer& visualizer, const std::string& id)
{
  visualizer.removePointCloud (id);
  visualizer.removeShape (id);
}

vtkSmartPointer<vtkLookupTable>
viridisTable (double max_value)
{
  auto table = vtkSmartPointer<vtkLookupTable>::New ();
  const int entries = 256;
  table->SetNumberOfTableValues (entries);
  table->SetRange (0.0, max_value);
  for (int i = 0; i < entries; ++i) {
    const Rgb8 colour = viridis (static_cast<double> (i) / (entries - 1));
    table->SetTableValue (i, colour[0] / 255.0, colour[1] / 255.0, colour[2] / 255.0, 1.0);
  }
  table->Build ();
  return table;
}

/** Largest finite residual, or 1 when there is none (so the scale stays valid). */
double
largestResidual (const Eigen::VectorXd& residuals)
{
  double largest = 0.0;
  for (Eigen::Index i = 0; i < residuals.size (); ++i)
    if (std::isfinite (residuals[i]))
      largest = std::max (largest, residuals[i]);
  return largest > 0.0 ? largest : 1.0;
}

/** \a cloud without its missing (NaN) points, as an organised depth frame holds them; InvalidInputError naming
 *  \a name for an infinite coordinate or when no point is left. */
pcl::PointCloud<pcl::PointXYZ>::Ptr
withoutMissingPoints (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::string& name)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr kept (new pcl::PointCloud<pcl::PointXYZ>);
  kept->reserve (cloud.size ());
  for (std::size_t i = 0; i < cloud.size (); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if (std::isnan (p.x) || std::isnan (p.y) || std::isnan (p.z))
      continue;
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      throw InvalidInputError ("RegistrationVisualizer: " + name + ": point " + std::to_string (i) +
                               " has an infinite coordinate");
    kept->push_back (p);
  }
  if (kept->empty ())
    throw InvalidInputError ("RegistrationVisualizer: " + name + " has no valid point (" +
                             std::to_string (cloud.size ()) + " points, all missing)");
  return kept;
}

/** Appends to \a points those of \a prop's data set (an actor's mapper input), in the world frame, a subset of
 *  about \a most; props without a data set (text, colour bars) add none. */
void
appendPropPoints (vtkProp* prop, std::size_t most, std::vector<Eigen::Vector3d>& points)
{
  auto* actor = vtkActor::SafeDownCast (prop);
  if (actor == nullptr || !actor->GetVisibility () || actor->GetMapper () == nullptr)
    return;
  vtkDataSet* data = actor->GetMapper ()->GetInput ();
  if (data == nullptr || data->GetNumberOfPoints () == 0)
    return;
  vtkMatrix4x4* matrix = actor->GetMatrix ();
  const vtkIdType count = data->GetNumberOfPoints ();
  const vtkIdType step = std::max<vtkIdType> (1, count / static_cast<vtkIdType> (most));
  for (vtkIdType i = 0; i < count; i += step) {
    double point[4] = {0.0, 0.0, 0.0, 1.0}, world[4];
    data->GetPoint (i, point);
    matrix->MultiplyPoint (point, world);
    const Eigen::Vector3d position (world[0], world[1], world[2]);
    if (position.allFinite ())
      points.push_back (position);
  }
}

} // namespace

RegistrationVisualizer::RegistrationVisualizer (Display display, const std::string& window_name)
  : display_ (display), background_ (1.0, 1.0, 1.0)
{
  requireXDisplay ("RegistrationVisualizer");
  visualizer_ = std::make_shared<pcl::visualization::PCLVisualizer> (window_name, display == Display::Window);
  if (display == Display::Offscreen)
    visualizer_->getRenderWindow ()->SetOffScreenRendering (1);
  setBackgroundColour (background_.x (), background_.y (), background_.z ());
}

RegistrationVisualizer::~RegistrationVisualizer () = default;

pcl::visualization::PCLVisualizer&
RegistrationVisualizer::getVisualizer ()
{
  return *visualizer_;
}

void
RegistrationVisualizer::setBackgroundColour (double r, double g, double b)
{
  background_ = Eigen::Vector3d (r, g, b);
  visualizer_->setBackgroundColor (r, g, b);
  for (auto& [viewport, bar] : colour_bars_)
    bar->GetTitleTextProperty ()->SetColor (textColour ().data ());
}

Eigen::Vector3d
RegistrationVisualizer::textColour () const
{
  const double brightness = 0.299 * background_.x () + 0.587 * background_.y () + 0.114 * background_.z ();
  return brightness > 0.5 ? Eigen::Vector3d::Zero () : Eigen::Vector3d::Ones ();
}

void
RegistrationVisualizer::createBeforeAfterViewports (int& before, int& after, const std::string& before_caption,
                                                    const std::string& after_caption)
{
  visualizer_->createViewPort (0.0, 0.0, 0.5, 1.0, before);
  visualizer_->createViewPort (0.5, 0.0, 1.0, 1.0, after);
  // Background after the viewports exist, or the new renderers keep VTK's default.
  setBackgroundColour (background_.x (), background_.y (), background_.z ());
  const Eigen::Vector3d text = textColour ();
  visualizer_->addText (before_caption, 10, 10, 18, text.x (), text.y (), text.z (), "caption_before", before);
  visualizer_->addText (after_caption, 10, 10, 18, text.x (), text.y (), text.z (), "caption_after", after);
  vtkCamera* shared = renderersOf (*visualizer_, before).front ()->GetActiveCamera ();
  renderersOf (*visualizer_, after).front ()->SetActiveCamera (shared);
}

void
RegistrationVisualizer::addColouredCloud (const CloudXYZ::ConstPtr& cloud, const Eigen::Vector3d& colour,
                                          double point_size, const std::string& id, int viewport)
{
  removeExisting (*visualizer_, id);
  const Eigen::Vector3d rgb = 255.0 * colour;
  pcl::visualization::PointCloudColorHandlerCustom<pcl::PointXYZ> handler (cloud, rgb.x (), rgb.y (), rgb.z ());
  visualizer_->addPointCloud<pcl::PointXYZ> (cloud, handler, id, viewport);
  visualizer_->setPointCloudRenderingProperties (pcl::visualization::PCL_VISUALIZER_POINT_SIZE, point_size, id);
}

void
RegistrationVisualizer::addTargetPositions (const CloudXYZ::ConstPtr& cloud, const std::string& id, int viewport,
                                            double point_size)
{
  addColouredCloud (withoutMissingPoints (*cloud, "target cloud '" + id + "'"), kTargetColour, point_size, id,
                    viewport);
}

void
RegistrationVisualizer::addOverlayPositions (const CloudXYZ::ConstPtr& cloud, std::size_t max_points,
                                             const std::string& id, int viewport)
{
  CloudXYZ::Ptr shown = withoutMissingPoints (*cloud, "scan overlay '" + id + "'");
  if (shown->size () > max_points) {
    std::mt19937 random (1); // the same picture every time
    std::shuffle (shown->begin (), shown->end (), random);
    shown->resize (std::max<std::size_t> (max_points, 1));
  }
  addColouredCloud (shown, kScanOverlayColour, 2.0, id, viewport);
}

void
RegistrationVisualizer::addMesh (const pcl::PolygonMesh& mesh, const Eigen::Vector3d& colour, double opacity,
                                 const std::string& id, int viewport)
{
  if (!(opacity >= 0.0 && opacity <= 1.0))
    throw InvalidInputError ("RegistrationVisualizer: opacity of '" + id + "' must be in [0, 1]");
  removeExisting (*visualizer_, id);
  visualizer_->addPolygonMesh (mesh, id, viewport);
  const bool has_colours = pcl::getFieldIndex (mesh.cloud, "rgb") >= 0 || pcl::getFieldIndex (mesh.cloud, "rgba") >= 0;
  if (!has_colours)
    visualizer_->setPointCloudRenderingProperties (pcl::visualization::PCL_VISUALIZER_COLOR, colour.x (), colour.y (),
                                                   colour.z (), id);
  visualizer_->setPointCloudRenderingProperties (pcl::visualization::PCL_VISUALIZER_OPACITY, opacity, id);
}

void
RegistrationVisualizer::addTargetMesh (const pcl::PolygonMesh& mesh, const std::string& id, int viewport)
{
  addMesh (mesh, kTargetColour, 1.0, id, viewport);
}

void
RegistrationVisualizer::addTargetMesh (const TriangleMesh& mesh, const std::string& id, int viewport)
{
  validateMesh (mesh, "target mesh '" + id + "'");
  addTargetMesh (toPolygonMesh (mesh), id, viewport);
}

void
RegistrationVisualizer::addModelMesh (const pcl::PolygonMesh& mesh, double opacity, const std::string& id, int viewport)
{
  addMesh (mesh, kModelColour, opacity, id, viewport);
}

void
RegistrationVisualizer::addModelMesh (const TriangleMesh& mesh, double opacity, const std::string& id, int viewport)
{
  validateMesh (mesh, "model mesh '" + id + "'");
  addModelMesh (toPolygonMesh (mesh), opacity, id, viewport);
}

void
RegistrationVisualizer::setMeshOpacity (double opacity, const std::string& id)
{
  if (!(opacity >= 0.0 && opacity <= 1.0))
    throw InvalidInputError ("RegistrationVisualizer: opacity of '" + id + "' must be in [0, 1]");
  if (!visualizer_->setPointCloudRenderingProperties (pcl::visualization::PCL_VISUALIZER_OPACITY, opacity, id))
    throw InvalidInputError ("RegistrationVisualizer: no mesh with id '" + id + "'");
}

void
RegistrationVisualizer::addCorrespondenceLines (const CloudXYZ::ConstPtr& source, const CloudXYZ::ConstPtr& target,
                                                const pcl::Correspondences& correspondences, std::size_t max_lines,
                                                const std::string& id, int viewport)
{
  for (const auto& c : correspondences)
    if (c.index_query < 0 || static_cast<std::size_t> (c.index_query) >= source->size () || c.index_match < 0 ||
        static_cast<std::size_t> (c.index_match) >= target->size ())
      throw InvalidInputError ("RegistrationVisualizer: correspondence " + std::to_string (c.index_query) + " -> " +
                               std::to_string (c.index_match) + " is out of range of the clouds (" +
                               std::to_string (source->size ()) + " source, " + std::to_string (target->size ()) +
                               " target points)");
  removeExisting (*visualizer_, id);
  if (correspondences.empty () || max_lines == 0)
    return;
  // Subsample here: PCL's own every-nth option reads past its buffer when the count is not a multiple of nth.
  const std::size_t step = (correspondences.size () + max_lines - 1) / max_lines;
  pcl::Correspondences shown;
  for (std::size_t i = 0; i < correspondences.size (); i += step)
    shown.push_back (correspondences[i]);
  visualizer_->addCorrespondences<pcl::PointXYZ> (source, target, shown, 1, id, viewport);
  visualizer_->setShapeRenderingProperties (pcl::visualization::PCL_VISUALIZER_COLOR, kCorrespondenceColour.x (),
                                            kCorrespondenceColour.y (), kCorrespondenceColour.z (), id);
}

void
RegistrationVisualizer::addResidualHeatMap (const TriangleMesh& mesh, const Eigen::VectorXd& residuals_mm,
                                            double max_residual_mm, const std::string& id, int viewport)
{
  validateMesh (mesh, "residual mesh '" + id + "'");
  if (residuals_mm.size () != mesh.numVertices ())
    throw InvalidInputError ("RegistrationVisualizer: " + std::to_string (residuals_mm.size ()) +
                             " residuals for a mesh of " + std::to_string (mesh.numVertices ()) + " vertices");
  const double scale = max_residual_mm > 0.0 ? max_residual_mm : largestResidual (residuals_mm);
  addMesh (toPolygonMesh (mesh, residualColours (residuals_mm, scale)), kModelColour, 1.0, id, viewport);
  addColourBar (scale, id, viewport);
}

void
RegistrationVisualizer::addResidualHeatMap (const pcl::PolygonMesh& mesh, const Eigen::VectorXd& residuals_mm,
                                            double max_residual_mm, const std::string& id, int viewport)
{
  addResidualHeatMap (fromPolygonMesh (mesh, "residual mesh '" + id + "'"), residuals_mm, max_residual_mm, id,
                      viewport);
}

Eigen::Vector4d
RegistrationVisualizer::colourBarRegion ()
{
  return Eigen::Vector4d (0.86, 0.08, 0.98, 0.92);
}

void
RegistrationVisualizer::addColourBar (double max_residual_mm, const std::string& owner, int viewport)
{
  colour_bar_owners_[viewport] = owner;
  for (vtkRenderer* renderer : renderersOf (*visualizer_, viewport)) {
    auto& bar = colour_bars_[viewport];
    if (bar)
      renderer->RemoveActor2D (bar);
    bar = vtkSmartPointer<vtkScalarBarActor>::New ();
    bar->SetLookupTable (viridisTable (max_residual_mm));
    bar->SetTitle ("residual (mm)");
    bar->SetNumberOfLabels (5);
    bar->SetLabelFormat ("%-#6.3g");
    bar->UnconstrainedFontSizeOn (); // sizes follow the text properties, not the bar's width
    bar->GetTitleTextProperty ()->SetFontSize (16);
    bar->GetLabelTextProperty ()->SetFontSize (14);
    bar->GetTitleTextProperty ()->SetBold (0);
    bar->GetTitleTextProperty ()->SetItalic (0);
    bar->GetLabelTextProperty ()->SetItalic (0);
    bar->GetLabelTextProperty ()->SetShadow (0);
    bar->GetTitleTextProperty ()->SetShadow (0);
    const Eigen::Vector4d region = colourBarRegion ();
    bar->GetPositionCoordinate ()->SetCoordinateSystemToNormalizedViewport ();
    bar->GetPositionCoordinate ()->SetValue (region[0], region[1]);
    bar->GetPosition2Coordinate ()->SetCoordinateSystemToNormalizedViewport ();
    bar->GetPosition2Coordinate ()->SetValue (region[2] - region[0], region[3] - region[1]);
    bar->GetTitleTextProperty ()->SetColor (textColour ().data ());
    bar->GetLabelTextProperty ()->SetColor (textColour ().data ());
    renderer->AddActor2D (bar);
  }
}

void
RegistrationVisualizer::addLandmarks (const LandmarkPositions& landmarks, LandmarkRole role, double radius, bool labels,
                                      const std::string& id_prefix, int viewport)
{
  if (!(radius > 0.0))
    throw InvalidInputError ("RegistrationVisualizer: landmark radius must be positive");
  const Eigen::Vector3d colour = role == LandmarkRole::Source ? kSourceLandmarkColour : kTargetLandmarkColour;
  for (const auto& [name, position] : landmarks) {
    if (!position.allFinite ())
      throw InvalidInputError ("RegistrationVisualizer: landmark '" + name + "' has a non-finite position");
    const std::string id = id_prefix + name;
    pcl::PointXYZ centre (static_cast<float> (position.x ()), static_cast<float> (position.y ()),
                          static_cast<float> (position.z ()));
    removeExisting (*visualizer_, id);
    visualizer_->addSphere (centre, radius, colour.x (), colour.y (), colour.z (), id, viewport);
    if (labels)
      addLabel (name, position, colour, id + "_label", viewport);
  }
}

int
RegistrationVisualizer::labelFontSize (int height)
{
  return std::max (12, height / 48);
}

void
RegistrationVisualizer::addLabel (const std::string& text, const Eigen::Vector3d& position,
                                  const Eigen::Vector3d& colour, const std::string& id, int viewport)
{
  removeExisting (*visualizer_, id);
  auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New ();
  label->SetInput (text.c_str ());
  label->SetPosition (position.x (), position.y (), position.z ());
  label->SetDisplayOffset (6, 6); // pixels up and right of the landmark, clear of its sphere
  vtkTextProperty* style = label->GetTextProperty ();
  style->SetFontSize (labelFontSize (visualizer_->getRenderWindow ()->GetSize ()[1]));
  style->SetColor (0.1, 0.1, 0.1);
  style->SetBackgroundColor (1.0, 1.0, 1.0);
  style->SetBackgroundOpacity (0.8);
  style->SetFrame (1);
  style->SetFrameColor (colour.x (), colour.y (), colour.z ());
  style->SetFrameWidth (2);
  for (vtkRenderer* renderer : renderersOf (*visualizer_, viewport))
    renderer->AddActor (label);
  (*visualizer_->getShapeActorMap ())[id] = label; // so removeShape and setVisibility find it
  if (std::find (label_ids_.begin (), label_ids_.end (), id) == label_ids_.end ())
    label_ids_.push_back (id);
}

void
RegistrationVisualizer::setColour (double r, double g, double b, const std::string& id)
{
  using pcl::visualization::PCL_VISUALIZER_COLOR;
  if (!visualizer_->setPointCloudRenderingProperties (PCL_VISUALIZER_COLOR, r, g, b, id) &&
      !visualizer_->setShapeRenderingProperties (PCL_VISUALIZER_COLOR, r, g, b, id))
    throw InvalidInputError ("RegistrationVisualizer::setColour: nothing shown with id '" + id + "'");
}

void
RegistrationVisualizer::setVisibility (const std::string& id, bool visible)
{
  bool found = false;
  const auto clouds = visualizer_->getCloudActorMap ();
  if (const auto cloud = clouds->find (id); cloud != clouds->end ()) {
    cloud->second.actor->SetVisibility (visible);
    found = true;
  }
  const auto shapes = visualizer_->getShapeActorMap ();
  if (const auto shape = shapes->find (id); shape != shapes->end ()) {
    shape->second->SetVisibility (visible);
    found = true;
  }
  for (const auto& [viewport, owner] : colour_bar_owners_)
    if (owner == id) {
      colour_bars_.at (viewport)->SetVisibility (visible);
      found = true;
    }
  if (!found)
    throw InvalidInputError ("RegistrationVisualizer::setVisibility: nothing shown with id '" + id + "'");
}

bool
RegistrationVisualizer::isVisible (const std::string& id) const
{
  const auto clouds = visualizer_->getCloudActorMap ();
  if (const auto cloud = clouds->find (id); cloud != clouds->end ())
    return cloud->second.actor->GetVisibility () != 0;
  const auto shapes = visualizer_->getShapeActorMap ();
  const auto shape = shapes->find (id);
  return shape != shapes->end () && shape->second->GetVisibility () != 0;
}

void
RegistrationVisualizer::setFramedShapes (const std::vector<std::string>& ids)
{
  framed_ids_ = ids;
}

void
RegistrationVisualizer::showRegistrationState (const CloudXYZ::ConstPtr& source, const pcl::Indices& source_indices,
                                               const CloudXYZ::ConstPtr& target, bool target_changed,
                                               const pcl::Indices& target_indices, int viewport, std::size_t max_lines)
{
  if (source_indices.size () != target_indices.size ())
    throw InvalidInputError ("RegistrationVisualizer: " + std::to_string (source_indices.size ()) + " source but " +
                             std::to_string (target_indices.size ()) + " target indices");
  ++registration_updates_;
  if (target_changed)
    addColouredCloud (target, kTargetColour, 2.0, "registration_target", viewport);
  addColouredCloud (source, kModelColour, 2.0, "registration_source", viewport);
  pcl::Correspondences correspondences;
  for (std::size_t i = 0; i < source_indices.size (); ++i)
    correspondences.emplace_back (source_indices[i], target_indices[i], 0.0f);
  addCorrespondenceLines (source, target, correspondences, max_lines, "registration_correspondences", viewport);
  const std::string status = "iteration " + std::to_string (registration_updates_);
  if (!visualizer_->updateText (status, 10, 30, "registration_status")) {
    const Eigen::Vector3d text = textColour ();
    visualizer_->addText (status, 10, 30, 16, text.x (), text.y (), text.z (), "registration_status", viewport);
  }
  if (display_ == Display::Window)
    visualizer_->spinOnce (1, true);
}

void
RegistrationVisualizer::resetCamera (const Eigen::Vector3d& view_direction, const Eigen::Vector3d& up)
{
  if (view_direction.norm () == 0.0 || up.cross (view_direction).norm () == 0.0)
    throw InvalidInputError ("RegistrationVisualizer::resetCamera: the view direction must be non-zero and not "
                             "parallel to the up vector");
  camera_view_ = {view_direction.normalized (), up};
  fitCamera ();
}

std::vector<Eigen::Vector3d>
RegistrationVisualizer::framedPoints () const
{
  const std::size_t most = 20000;
  std::vector<Eigen::Vector3d> points;
  const auto clouds = visualizer_->getCloudActorMap ();
  const auto shapes = visualizer_->getShapeActorMap ();
  const auto framed = [this] (const std::string& id) {
    return framed_ids_.empty () || std::find (framed_ids_.begin (), framed_ids_.end (), id) != framed_ids_.end ();
  };
  for (const auto& [id, cloud] : *clouds)
    if (framed (id))
      appendPropPoints (cloud.actor, most, points);
  for (const auto& [id, shape] : *shapes)
    if (framed (id))
      appendPropPoints (shape, most, points);
  return points;
}

void
RegistrationVisualizer::fitCamera ()
{
  if (!camera_view_)
    return;
  const std::vector<Eigen::Vector3d> points = framedPoints ();
  if (points.empty ())
    return; // nothing to look at yet
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points)
    box.extend (p);
  const Eigen::Vector3d forward = -camera_view_->first;
  const Eigen::Vector3d right = forward.cross (camera_view_->second).normalized ();
  const Eigen::Vector3d upward = right.cross (forward);
  const std::vector<vtkRenderer*> renderers = renderersOf (*visualizer_, 0);
  for (std::size_t index = 0; index < renderers.size (); ++index) {
    vtkCamera* camera = renderers[index]->GetActiveCamera ();
    const bool bar = colour_bars_.count (0) > 0 || colour_bars_.count (static_cast<int> (index)) > 0;
    // Fill 94 % of the height and of the width left of the colour bar, if any (the bar takes the right 16 %).
    const double tan_v = std::tan (0.5 * camera->GetViewAngle () * M_PI / 180.0);
    const double tan_h = tan_v * std::max (renderers[index]->GetTiledAspectRatio (), 1e-3);
    const double width_share = bar ? 0.84 : 1.0;
    // The nearest camera distance at which every point lies inside the frustum (perspective: by its own depth).
    double distance = 0.0;
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d offset = p - box.center ();
      const double needed = std::max (std::abs (offset.dot (upward)) / (0.94 * tan_v),
                                      std::abs (offset.dot (right)) / (0.94 * width_share * tan_h));
      distance = std::max (distance, needed - offset.dot (forward));
    }
    // Move the view so the framed points sit in the middle of the part left of the bar.
    const Eigen::Vector3d shift = (1.0 - width_share) * distance * tan_h * right;
    const Eigen::Vector3d focus = box.center () + shift;
    const Eigen::Vector3d position = focus + distance * camera_view_->first;
    camera->SetFocalPoint (focus.data ());
    camera->SetPosition (position.data ());
    camera->SetViewUp (upward.data ());
    renderers[index]->ResetCameraClippingRange ();
  }
}

void
RegistrationVisualizer::saveScreenshot (const std::string& png_path, int width, int height)
{
  if (width <= 0 || height <= 0)
    throw InvalidInputError ("RegistrationVisualizer::saveScreenshot: size " + std::to_string (width) + "x" +
                             std::to_string (height) + " is not positive");
  vtkRenderWindow* window = visualizer_->getRenderWindow ();
  window->SetSize (width, height);
  const auto shapes = visualizer_->getShapeActorMap ();
  for (const std::string& id : label_ids_)
    if (const auto label = shapes->find (id); label != shapes->end ())
      vtkBillboardTextActor3D::SafeDownCast (label->second)->GetTextProperty ()->SetFontSize (labelFontSize (height));
  fitCamera (); // the aspect ratio may have changed
  detail::writeWindowPng (*window, png_path);
}

void
RegistrationVisualizer::requireWindow (const char* method) const
{
  if (display_ != Display::Window)
    throw InvalidInputError (std::string ("RegistrationVisualizer::") + method +
                             " needs a window; this visualiser renders offscreen");
}

void
RegistrationVisualizer::spin ()
{
  requireWindow ("spin");
  visualizer_->spin ();
}

void
RegistrationVisualizer::spinOnce (int milliseconds)
{
  requireWindow ("spinOnce");
  visualizer_->spinOnce (milliseconds, true);
}

} // namespace morphreg

#define MORPHREG_INSTANTIATE_REGISTRATION_VISUALIZER(T)                                                                \
  template void morphreg::RegistrationVisualizer::addTargetCloud<T> (const pcl::PointCloud<T>&, const std::string&,    \
                                                                     int, double);                                     \
  template void morphreg::RegistrationVisualizer::addScanOverlay<T> (const pcl::PointCloud<T>&, std::size_t,           \
                                                                     const std::string&, int);                         \
  template void morphreg::RegistrationVisualizer::addCorrespondences<T, T> (                                           \
      const pcl::PointCloud<T>&, const pcl::PointCloud<T>&, const pcl::Correspondences&, std::size_t,                  \
      const std::string&, int);                                                                                        \
  template morphreg::RegistrationVisualizer::RegistrationCallback<T, T>                                                \
  morphreg::RegistrationVisualizer::makeRegistrationCallback<T, T> (int, std::size_t);
MORPHREG_INSTANTIATE_REGISTRATION_VISUALIZER (pcl::PointXYZ)
MORPHREG_INSTANTIATE_REGISTRATION_VISUALIZER (pcl::PointNormal)
MORPHREG_INSTANTIATE_REGISTRATION_VISUALIZER (pcl::PointXYZRGBNormal)
