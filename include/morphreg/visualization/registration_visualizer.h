// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file registration_visualizer.h
 *  \brief Overlays of a registration on pcl::visualization::PCLVisualizer: target scan, fitted model, correspondences,
 *  residual heat map with colour bar, landmarks, before/after viewports, live updates from align() and PNG output.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/PolygonMesh.h>
#include <pcl/correspondence.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <vtkSmartPointer.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pcl
{
namespace visualization
{
class PCLVisualizer;
}
} // namespace pcl
class vtkScalarBarActor;

namespace morphreg
{
/** \brief Shows what a registration did, in a window or headless (PNG files for reports, docs and tests).
 *
 *  Every add* method takes an \a id (unique per kind, as in PCLVisualizer; adding an existing id replaces it) and
 *  a \a viewport (0 = all, or one from createBeforeAfterViewports()). Coordinates are millimetres.
 *  Debian's VTK renders through X, also offscreen: run headless programs under `xvfb-run -a`.
 *
 *  \code
 *  morphreg::RegistrationVisualizer viewer (morphreg::RegistrationVisualizer::Display::Offscreen);
 *  viewer.addTargetCloud<pcl::PointXYZ> (*scan);
 *  viewer.addResidualHeatMap (fitted, residuals_mm);
 *  viewer.addLandmarks (scan_landmarks, morphreg::RegistrationVisualizer::LandmarkRole::Target);
 *  viewer.resetCamera ();
 *  viewer.saveScreenshot ("fit.png", 1280, 960);
 *  \endcode
 */
class RegistrationVisualizer
{
public:
  using Ptr = std::shared_ptr<RegistrationVisualizer>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const RegistrationVisualizer>; ///< shared pointer to const

  /** \brief An on-screen window with an interactor, or offscreen rendering only (no interactor, no window). */
  enum class Display
  {
    Window,   ///< a window the user can interact with
    Offscreen ///< rendering for screenshots only
  };

  /** \brief Landmarks of the moving side (model, source) or of the fixed side (scan, target): different colours. */
  enum class LandmarkRole
  {
    Source, ///< the moving side: the model
    Target  ///< the fixed side: the scan
  };

  /** \brief PCL's registration callback signature (Registration::UpdateVisualizerCallbackSignature). */
  template <typename PointSource, typename PointTarget>
  using RegistrationCallback = std::function<void (const pcl::PointCloud<PointSource>&, const pcl::Indices&,
                                                   const pcl::PointCloud<PointTarget>&, const pcl::Indices&)>;

  /** \brief Opens the visualiser. Throws morphreg::Error if there is no X display ($DISPLAY unset).
   *  \param[in] display a window or offscreen rendering
   *  \param[in] window_name the window's title
   */
  explicit RegistrationVisualizer (Display display = Display::Window,
                                   const std::string& window_name = "morphreg registration");

  /** \brief Closes the window and releases the renderer. */
  ~RegistrationVisualizer ();

  /// \cond
  RegistrationVisualizer (const RegistrationVisualizer&) = delete;
  RegistrationVisualizer&
  operator= (const RegistrationVisualizer&) = delete;
  /// \endcond

  /** \brief The underlying PCL visualiser, for anything not covered here.
   *  \return the PCLVisualizer
   */
  pcl::visualization::PCLVisualizer&
  getVisualizer ();

  /** \brief Sets the background of every viewport (RGB in [0, 1]); text colours follow its brightness.
   *  \param[in] r red
   *  \param[in] g green
   *  \param[in] b blue
   */
  void
  setBackgroundColour (double r, double g, double b);

  /** \brief Splits the window into a left "before" and a right "after" viewport, sharing one camera, each with a
   *  caption.
   *  \param[out] before the left viewport
   *  \param[out] after the right viewport
   *  \param[in] before_caption the left viewport's caption
   *  \param[in] after_caption the right viewport's caption
   */
  void
  createBeforeAfterViewports (int& before, int& after, const std::string& before_caption = "before",
                              const std::string& after_caption = "after");

  /** \brief Shows a target scan as points (uniform colour, \a point_size pixels). Missing points (NaN, as in an
   *  organised depth-camera frame) are left out; an infinite coordinate or a cloud without a valid point throws
   *  InvalidInputError.
   *  \param[in] cloud the scan
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   *  \param[in] point_size the points' size in pixels
   */
  template <typename PointT>
  void
  addTargetCloud (const pcl::PointCloud<PointT>& cloud, const std::string& id = "target", int viewport = 0,
                  double point_size = 2.0);

  /** \brief Shows a scan over a fit: at most \a max_points of its points, drawn at random (a scanner's regular grid
   *  drawn densely over a surface makes moiré), 2 pixels wide and in a neutral grey, so the fit's colours stay
   *  readable. Missing (NaN) points are left out, as in addTargetCloud.
   *  \param[in] cloud the scan
   *  \param[in] max_points the most points drawn
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  template <typename PointT>
  void
  addScanOverlay (const pcl::PointCloud<PointT>& cloud, std::size_t max_points, const std::string& id = "scan",
                  int viewport = 0);

  /** \brief Shows a target scan given as a mesh (its vertex colours if it has any, else the target colour).
   *  \param[in] mesh the scan
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  void
  addTargetMesh (const pcl::PolygonMesh& mesh, const std::string& id = "target", int viewport = 0);

  /** \brief Shows a target scan given as a triangle mesh.
   *  \param[in] mesh the scan
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  void
  addTargetMesh (const TriangleMesh& mesh, const std::string& id = "target", int viewport = 0);

  /** \brief Shows the fitted model as a smooth-shaded mesh with \a opacity in [0, 1].
   *  \param[in] mesh the fitted model
   *  \param[in] opacity 0 transparent, 1 opaque
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  void
  addModelMesh (const pcl::PolygonMesh& mesh, double opacity = 0.6, const std::string& id = "model", int viewport = 0);

  /** \brief Shows the fitted model given as a triangle mesh.
   *  \param[in] mesh the fitted model
   *  \param[in] opacity 0 transparent, 1 opaque
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  void
  addModelMesh (const TriangleMesh& mesh, double opacity = 0.6, const std::string& id = "model", int viewport = 0);

  /** \brief Changes the opacity (in [0, 1]) of a mesh already shown.
   *  \param[in] opacity 0 transparent, 1 opaque
   *  \param[in] id the mesh's id
   */
  void
  setMeshOpacity (double opacity, const std::string& id = "model");

  /** \brief Draws lines from source[index_query] to target[index_match], at most \a max_lines of them (an evenly
   *  spaced subset keeps dense correspondences readable). Throws InvalidInputError for out-of-range indices.
   *  \param[in] source the source cloud (e.g. the model's vertices in the scan frame)
   *  \param[in] target the target cloud (the scan)
   *  \param[in] correspondences pairs of source and target indices
   *  \param[in] max_lines the most lines drawn
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  template <typename PointSource, typename PointTarget>
  void
  addCorrespondences (const pcl::PointCloud<PointSource>& source, const pcl::PointCloud<PointTarget>& target,
                      const pcl::Correspondences& correspondences, std::size_t max_lines = 300,
                      const std::string& id = "correspondences", int viewport = 0);

  /** \brief Colours \a mesh by per-vertex \a residuals_mm (viridis: low = blue, high = yellow; NaN = grey, no
   *  residual) and adds a colour bar titled "residual (mm)" with its scale [0, \a max_residual_mm]. A
   *  non-positive \a max_residual_mm uses the largest residual. Throws InvalidInputError if the sizes differ
   *  or a residual is negative or infinite.
   *  \param[in] mesh the fitted mesh
   *  \param[in] residuals_mm one residual per vertex (mm), NaN for none
   *  \param[in] max_residual_mm the top of the colour scale (<= 0: the largest residual)
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  void
  addResidualHeatMap (const TriangleMesh& mesh, const Eigen::VectorXd& residuals_mm, double max_residual_mm = 0.0,
                      const std::string& id = "residuals", int viewport = 0);

  /** \brief As above for a pcl::PolygonMesh of triangles.
   *  \param[in] mesh the fitted mesh
   *  \param[in] residuals_mm one residual per vertex (mm), NaN for none
   *  \param[in] max_residual_mm the top of the colour scale (<= 0: the largest residual)
   *  \param[in] id the shape's id
   *  \param[in] viewport where to show it (0: every viewport)
   */
  void
  addResidualHeatMap (const pcl::PolygonMesh& mesh, const Eigen::VectorXd& residuals_mm, double max_residual_mm = 0.0,
                      const std::string& id = "residuals", int viewport = 0);

  /** \brief Where the colour bar sits in its viewport: (x_min, y_min, x_max, y_max), normalised, origin bottom left.
   *  \return the bar's corners in viewport coordinates
   */
  static Eigen::Vector4d
  colourBarRegion ();

  /** \brief Draws each landmark as a sphere of \a radius (mm) in the colour of its \a role, labelled with its id
   *  when \a labels is set: dark text on a light box framed in the role's colour, beside the landmark, at a size in
   *  pixels that grows with the screenshot (readable at any zoom). Shapes are named \a id_prefix + landmark id
   *  (+ "_label").
   *  \param[in] landmarks the landmarks by id (mm)
   *  \param[in] role source or target, which sets the colour
   *  \param[in] radius the spheres' radius (mm)
   *  \param[in] labels whether to write each landmark's id beside it
   *  \param[in] id_prefix prefix of the shapes' ids
   *  \param[in] viewport where to show them (0: every viewport)
   */
  void
  addLandmarks (const LandmarkPositions& landmarks, LandmarkRole role, double radius = 2.5, bool labels = true,
                const std::string& id_prefix = "", int viewport = 0);

  /** \brief Changes a shape's colour (RGB in [0, 1]): a cloud's points or a mesh without vertex colours.
   *  Throws InvalidInputError for an unknown id.
   *  \param[in] r red
   *  \param[in] g green
   *  \param[in] b blue
   *  \param[in] id the shape's id
   */
  void
  setColour (double r, double g, double b, const std::string& id);

  /** \brief Shows or hides what was added under \a id: a cloud, a mesh, a residual heat map (with its colour bar),
   *  a landmark's sphere or label, correspondence lines. Throws InvalidInputError if nothing has that id.
   *  \param[in] id the shape's id
   *  \param[in] visible whether it is drawn
   */
  void
  setVisibility (const std::string& id, bool visible);

  /** \brief Whether what was added under \a id is drawn (false for an unknown id).
   *  \param[in] id the shape's id
   *  \return its visibility
   */
  bool
  isVisible (const std::string& id) const;

  /** \brief The shapes resetCamera() and screenshots frame: e.g. only the fitted head of a head-and-shoulders scan.
   *  Empty (the default): everything visible.
   *  \param[in] ids the shapes' ids
   */
  void
  setFramedShapes (const std::vector<std::string>& ids);

  /** \brief A callback for pcl::Registration::registerVisualizationCallback: each call shows the transformed
   *  source, the target (added on the first call) and up to \a max_lines of the current correspondences, with
   *  the iteration count. In a window it redraws at once, so a user watches align() converge. This visualiser
   *  must outlive the registration that holds the callback.
   *  \code
   *  auto callback = viewer.makeRegistrationCallback<pcl::PointXYZ, pcl::PointXYZ> ();
   *  icp.registerVisualizationCallback (callback);
   *  icp.align (aligned);
   *  \endcode
   *  \param[in] viewport where to draw (0: every viewport)
   *  \param[in] max_lines the most correspondence lines drawn per call
   *  \return the callback
   */
  template <typename PointSource, typename PointTarget>
  RegistrationCallback<PointSource, PointTarget>
  makeRegistrationCallback (int viewport = 0, std::size_t max_lines = 300);

  /** \brief How many times registration callbacks made by this visualiser have been called.
   *  \return the number of calls
   */
  std::size_t
  getRegistrationUpdateCount () const
  {
    return registration_updates_;
  }

  /** \brief Points the shared camera along -\a view_direction (default: looking at the face, +Z towards the
   *  viewer) with \a up upwards, and frames the points of what is shown (setFramedShapes) so that they fill the
   *  picture, beside the colour bar if there is one (again at each screenshot's size).
   *  \param[in] view_direction from the scene towards the camera
   *  \param[in] up the screen's up direction in the scene
   */
  void
  resetCamera (const Eigen::Vector3d& view_direction = Eigen::Vector3d::UnitZ (),
               const Eigen::Vector3d& up = Eigen::Vector3d::UnitY ());

  /** \brief Renders at \a width x \a height pixels and writes a PNG (vtkWindowToImageFilter + vtkPNGWriter; works
   *  without an interactor). Throws InvalidInputError for a non-positive size, IoError if the file cannot be
   *  written.
   *  \param[in] png_path the PNG file
   *  \param[in] width the image width in pixels
   *  \param[in] height the image height in pixels
   */
  void
  saveScreenshot (const std::string& png_path, int width, int height);

  /** \brief Runs the window's event loop until the user closes it (Display::Window only). */
  void
  spin ();

  /** \brief Processes window events for \a milliseconds and redraws (Display::Window only).
   *  \param[in] milliseconds how long to process events
   */
  void
  spinOnce (int milliseconds = 1);

private:
  using CloudXYZ = pcl::PointCloud<pcl::PointXYZ>;

  void
  addColouredCloud (const CloudXYZ::ConstPtr& cloud, const Eigen::Vector3d& colour, double point_size,
                    const std::string& id, int viewport);

  void
  addTargetPositions (const CloudXYZ::ConstPtr& cloud, const std::string& id, int viewport, double point_size);

  void
  addOverlayPositions (const CloudXYZ::ConstPtr& cloud, std::size_t max_points, const std::string& id, int viewport);

  void
  addMesh (const pcl::PolygonMesh& mesh, const Eigen::Vector3d& colour, double opacity, const std::string& id,
           int viewport);

  void
  addCorrespondenceLines (const CloudXYZ::ConstPtr& source, const CloudXYZ::ConstPtr& target,
                          const pcl::Correspondences& correspondences, std::size_t max_lines, const std::string& id,
                          int viewport);

  void
  addColourBar (double max_residual_mm, const std::string& owner, int viewport);

  void
  addLabel (const std::string& text, const Eigen::Vector3d& position, const Eigen::Vector3d& colour,
            const std::string& id, int viewport);

  /** The label font size (pixels) for a window \a height pixels high. */
  static int
  labelFontSize (int height);

  void
  showRegistrationState (const CloudXYZ::ConstPtr& source, const pcl::Indices& source_indices,
                         const CloudXYZ::ConstPtr& target, bool target_changed, const pcl::Indices& target_indices,
                         int viewport, std::size_t max_lines);

  void
  requireWindow (const char* method) const;

  /** \brief Places the camera of every viewport along camera_view_ so the framed points fill the window. */
  void
  fitCamera ();

  /** \brief The points (world frame) of the visible framed shapes, at most some tens of thousands. */
  std::vector<Eigen::Vector3d>
  framedPoints () const;

  Eigen::Vector3d
  textColour () const;

  std::shared_ptr<pcl::visualization::PCLVisualizer> visualizer_;
  Display display_;
  Eigen::Vector3d background_;
  std::map<int, vtkSmartPointer<vtkScalarBarActor>> colour_bars_;
  std::map<int, std::string> colour_bar_owners_; ///< the heat map id of each viewport's colour bar
  std::vector<std::string> label_ids_;           ///< landmark labels, resized with each screenshot
  std::vector<std::string> framed_ids_;
  std::size_t registration_updates_ = 0;
  /** The view direction (towards the camera) and up vector of the last resetCamera(), refitted per screenshot. */
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> camera_view_;
};

} // namespace morphreg

/// \cond
#define MORPHREG_DECLARE_REGISTRATION_VISUALIZER(T)                                                                    \
  extern template void morphreg::RegistrationVisualizer::addTargetCloud<T> (const pcl::PointCloud<T>&,                 \
                                                                            const std::string&, int, double);          \
  extern template void morphreg::RegistrationVisualizer::addScanOverlay<T> (const pcl::PointCloud<T>&, std::size_t,    \
                                                                            const std::string&, int);                  \
  extern template void morphreg::RegistrationVisualizer::addCorrespondences<T, T> (                                    \
      const pcl::PointCloud<T>&, const pcl::PointCloud<T>&, const pcl::Correspondences&, std::size_t,                  \
      const std::string&, int);                                                                                        \
  extern template morphreg::RegistrationVisualizer::RegistrationCallback<T, T>                                         \
  morphreg::RegistrationVisualizer::makeRegistrationCallback<T, T> (int, std::size_t);
MORPHREG_DECLARE_REGISTRATION_VISUALIZER (pcl::PointXYZ)
MORPHREG_DECLARE_REGISTRATION_VISUALIZER (pcl::PointNormal)
MORPHREG_DECLARE_REGISTRATION_VISUALIZER (pcl::PointXYZRGBNormal)
#undef MORPHREG_DECLARE_REGISTRATION_VISUALIZER
/// \endcond
