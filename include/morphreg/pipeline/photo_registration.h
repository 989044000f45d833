// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_registration.h
 *  \brief A model fitted to photos the way `morphreg fit-photos` does it, for every front end: the photos read (any
 *  number of views with their landmarks, cameras and outlines, or the orthographic profile and frontal pair), the fit
 *  configured by PhotoFitOptions, its warnings, the evaluation against a known head, the texture from the photos and
 *  the report.
 *
 *  \code
 *  morphreg::PhotoRegistration registration (morphreg::loadModel ("model.h5"), "model.h5");
 *  const morphreg::PhotoSet photos = morphreg::readPhotoSet ({{{"left.jpg", "left.pts", "", ""}}, "", "", ""});
 *  const morphreg::PhotoRegistrationOutcome outcome = registration.fit (photos);
 *  outcome.fit.model_mesh;   // the head, model frame, mm
 *  outcome.report;           // what `morphreg fit-photos` writes, but the output's name
 *  \endcode
 */
#include <morphreg/common/rgb_image.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/photo/photo_fit.h>
#include <morphreg/photo/photo_fit_options.h>
#include <morphreg/photo/photo_texture.h>
#include <morphreg/photo/photo_view.h>
#include <morphreg/photo/photo_view_io.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The files of a photo fit: views, or the orthographic pair (a profile annotation, optionally the frontal
 *  annotation and its photo), never both. */
struct PhotoSetFiles
{
  std::vector<PhotoViewFiles> views; ///< photos with their landmarks, cameras and outlines
  std::string profile;               ///< the pair's profile annotation (JSON), or empty
  std::string frontal;               ///< the pair's frontal annotation (JSON), or empty
  std::string photo;                 ///< the frontal photo (PNG/JPEG) to colour the head from, or empty
};

/** \brief Photos read for a fit: the views and, per view, its pixels (an empty image where there are none). */
struct PhotoSet
{
  std::vector<PhotoView> views; ///< landmarks, outlines and cameras
  std::vector<RgbImage> images; ///< per view; width 0 where the view has no photo to colour from
  std::string sources;          ///< the inputs' names, for messages and the report
};

/** \brief Reads the photos of \a files. Throws InvalidInputError when views and the pair are mixed (their frames
 *  differ), when there is neither, when the photo is given without its frontal annotation or its size differs from
 *  the annotation's, and the readers' errors naming the file.
 *  \param[in] files the views, or the pair
 *  \return the photos
 */
PhotoSet
readPhotoSet (const PhotoSetFiles& files);

/** \brief A head and the similarity that took it into the photos' normalised frame, as `synth --photos` writes them
 *  (JSON: "head", a mesh file next to it, and "head_to_photo", 16 numbers column-major). */
struct PhotoTruth
{
  TriangleMesh head;             ///< the true head, mm
  Eigen::Matrix4d head_to_photo; ///< the similarity into the photos' frame
  std::string source;            ///< the truth file's name
};

/** \brief Reads a photo truth file. Throws FormatError naming the file for a wrong layout or a similarity that
 *  cannot be inverted, and the mesh reader's errors.
 *  \param[in] path the truth file (JSON)
 *  \return the head and its similarity
 */
PhotoTruth
readPhotoTruth (const std::string& path);

/** \brief A fit's error against the true head. */
struct PhotoTruthErrors
{
  Eigen::VectorXd vertex_errors; ///< mm, per vertex: the fit taken back through the true similarity
  nlohmann::json json;           ///< "truth_error_mm" (statistics, width_rms, file) and "truth_scale_ratio"
};

/** \brief The vertex errors of \a fit against \a truth. Throws InvalidInputError naming the truth file when the
 *  topologies differ.
 *  \param[in] truth the true head
 *  \param[in] fit the fit
 *  \return the errors and their report entries
 */
PhotoTruthErrors
photoTruthErrors (const PhotoTruth& truth, const PhotoFit& fit);

/** \brief The fitted head's colours from every photo of \a photos, blended by visibility and angle; none when no
 *  view has a photo.
 *  \param[in] fit the fit (its views' cameras)
 *  \param[in] photos the photos it was fitted to
 *  \return the colours, or none
 */
std::optional<VertexTexture>
photoTexture (const PhotoFit& fit, const PhotoSet& photos);

/** \brief Writes the fitted head (model frame, mm) as the mesh file \a path: coloured by its error against
 *  \a truth_file (the error also as each vertex's quality; \a colour_max mm at the top of the scale) when one is given,
 *  else by the photos (photoTexture) when a view has one, else plain. Adds the truth errors (photoTruthErrors) or the
 *  texture's counts to \a report.
 *  \param[in] path the mesh file to write
 *  \param[in] fit the fit
 *  \param[in] photos the photos it was fitted to
 *  \param[in] truth_file the true head and pose (readPhotoTruth), or empty
 *  \param[in] colour_max the error at the top of the colour scale (mm)
 *  \param[in,out] report the fit's report
 *  \return what the colours show: "error against the truth, 0-C mm", the photos, or "none" */
std::string
writePhotoFitMesh (const std::string& path, const PhotoFit& fit, const PhotoSet& photos, const std::string& truth_file,
                   double colour_max, nlohmann::json& report);

/** \brief What a photo fit tells as it goes; every method does nothing by default. */
class PhotoRegistrationObserver
{
public:
  virtual ~PhotoRegistrationObserver () = default;

  /** The fit of \a model to \a sources with \a approach starts. */
  virtual void
  fitStarted (const std::string& /*model*/, const std::string& /*sources*/, const std::string& /*approach*/)
  {}

  /** Something in the fit a user should know: landmarks left out, a prior that keeps the mean head. */
  virtual void
  warning (const std::string& /*text*/)
  {}
};

/** \brief The outcome of PhotoRegistration::fit. */
struct PhotoRegistrationOutcome
{
  PhotoFit fit;                      ///< the fit
  std::vector<std::string> warnings; ///< the report's warnings
  nlohmann::json report;             ///< the fit, status, units, inputs, warnings and settings
};

/** \brief Fits a model to photos with one set of settings. */
class PhotoRegistration
{
public:
  /** Coefficients beyond this many prior standard deviations are warned about. */
  static constexpr double kCoefficientWarningSigma = 3.0;

  /** \brief A registration of \a model (named \a model_name in messages and the report) with \a settings.
   *  \param[in] model the model (with a profile line and landmarks)
   *  \param[in] model_name the model's name, e.g. its file
   *  \param[in] settings the fit's settings
   */
  PhotoRegistration (MorphableModel::ConstPtr model, std::string model_name, PhotoFitOptions settings = {});

  /** \brief Reports progress and warnings to \a observer (null: none); it must outlive the fits.
   *  \param[in] observer the observer
   */
  void
  setObserver (PhotoRegistrationObserver* observer)
  {
    observer_ = observer;
  }

  /** \brief Fits the model to \a photos. Throws InvalidInputError naming the model when it has no profile line, and
   *  fitPhotos' errors (the photos lack what the method needs, settings out of range).
   *  \param[in] photos the photos
   *  \return the fit, its warnings and report
   */
  PhotoRegistrationOutcome
  fit (const PhotoSet& photos) const;

private:
  /** The report's warnings for \a fit; the observer hears those that are not in the summary. */
  std::vector<std::string>
  fitWarnings (const PhotoFit& fit) const;

  MorphableModel::ConstPtr model_;
  std::string model_name_;
  PhotoFitOptions settings_;
  PhotoRegistrationObserver* observer_ = nullptr;
};
} // namespace morphreg
