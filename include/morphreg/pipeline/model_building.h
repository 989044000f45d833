// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_building.h
 *  \brief A shape model built the way `morphreg build-model` does it, for every front end: from meshes in
 *  correspondence (ModelFromMeshes), from the ICT-FaceKit (ModelFromIct), or from raw scans (ModelFromScans: each
 *  registered with ScanRegistration and resampled into the registering model's topology with resampleFit, the scans
 *  that fail left out and said why). Each returns a ModelBuildingOutcome: the model, one row per input and the
 *  summary.
 *
 *  \code
 *  morphreg::ModelFromMeshes building;
 *  const morphreg::ModelBuildingOutcome built = building.build (morphreg::readMeshFolder ("population"));
 *  morphreg::saveModel ("model.h5", *built.model);
 *  \endcode
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/io/mesh_folder.h>
#include <morphreg/io/scan_manifest.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/model/region_segmentation.h>
#include <morphreg/pipeline/scan_registration.h>
#include <morphreg/resampling/resampling_settings.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace morphreg
{
/** \brief One input of a model (a mesh, or a scan and what became of it). */
struct ModelInput
{
  std::string id;        ///< the scan's id (scan_manifest.h), or the mesh's file
  std::string file;      ///< the mesh or scan file ("" for a mesh given in memory)
  bool included = true;  ///< whether the model was built from it
  std::string reason;    ///< why it was left out
  nlohmann::json report; ///< from a scan: its registration report with "resampling"; else null

  /** \brief The input's summary row: id, file ("scan" for a scan), status ("ok" or "failed"), included and
   *  reason; for a scan also fit_rms_mm, coverage and hole_count (null when not known).
   *  \return the row */
  nlohmann::json
  row () const;
};

/** \brief The outcome of a model building: the model and what it was built from. */
struct ModelBuildingOutcome
{
  MorphableModel::Ptr model;      ///< the model (mm)
  std::vector<ModelInput> inputs; ///< every input, included or not, in the order given
  nlohmann::json source;          ///< what the model was built from (counts, annotation files, ICT samples)

  /** \brief The summary: "source", the builder "settings", "regions" (names), "components" per region,
   *  "vertices" and "landmarks".
   *  \param[in] settings the builder's settings
   *  \return the JSON summary */
  nlohmann::json
  summary (const ModelBuilderSettings& settings) const;
};

/** \brief What a model building tells as it goes; every method does nothing by default. */
class ModelBuildingObserver
{
public:
  virtual ~ModelBuildingObserver () = default;

  /** A stage over \a count inputs starts ("loading meshes", "registering and resampling scans"). */
  virtual void
  stageStarted (const std::string& /*stage*/, int /*count*/)
  {}

  /** Input \a done (from 1) of the stage is finished; \a detail says how the stage stands. */
  virtual void
  inputDone (int /*done*/, const std::string& /*detail*/)
  {}

  /** The stage ended. */
  virtual void
  stageFinished ()
  {}

  /** An input was left out (input.reason says why). */
  virtual void
  inputLeftOut (const ModelInput& /*input*/)
  {}

  /** Every input has been tried, before the model is built (and before too few inputs are refused). */
  virtual void
  inputsTried (const std::vector<ModelInput>& /*inputs*/)
  {}

  /** Something about an input the user should know that does not leave it out (its colours could not be read). */
  virtual void
  warning (const std::string& /*text*/)
  {}
};

/** \brief Settings of ModelFromMeshes. */
struct ModelFromMeshesSettings
{
  ModelBuilderSettings builder;  ///< the PCA: components, variance, blending, alignment
  std::string regions;           ///< region label file (mesh_annotations.h); empty: one global region
  std::string landmark_vertices; ///< landmark vertex file (mesh_annotations.h); empty: no landmarks
};

/** \brief Annotations of meshes in memory (ModelFromMeshes::build of meshes); a file the settings name takes the
 *  place of the same annotation here. */
struct MeshAnnotations
{
  std::optional<RegionLabels> regions; ///< the region of each vertex; none: one global region
  LandmarkVertices landmarks;          ///< landmark id -> vertex; empty: none
  std::vector<int> profile_line;       ///< the profile line's vertices; empty: none
};

/** \brief Builds a model from meshes in correspondence: loaded and checked to share one topology (a mesh that
 *  does not is named), the region and landmark vertex files read against them, the PCA, the landmarks and the
 *  profile line set. */
class ModelFromMeshes
{
public:
  /** \param[in] settings the builder's settings and annotation files */
  explicit ModelFromMeshes (ModelFromMeshesSettings settings = {});

  /** \brief Who hears of progress.
   *  \param[in] observer the observer (not owned; nullptr: nobody) */
  void
  setObserver (ModelBuildingObserver* observer);

  /** \brief Builds from the mesh files of \a folder (readMeshFolder; or a MeshFolder of files listed by hand) and
   *  its profile line. Throws InvalidInputError for fewer than two files, naming a mesh not in correspondence with
   *  the first, and FormatError naming the annotation file or population.json that does not fit the meshes.
   *  \param[in] folder the mesh files and profile line
   *  \return the model and its inputs */
  ModelBuildingOutcome
  build (const MeshFolder& folder) const;

  /** \brief Builds from meshes in memory, \a names[k] naming meshes[k] in messages. Throws as build(MeshFolder),
   *  and InvalidInputError for annotations that do not fit the meshes.
   *  \param[in] meshes the training meshes
   *  \param[in] names one name per mesh
   *  \param[in] annotations their regions, landmarks and profile line
   *  \return the model and its inputs */
  ModelBuildingOutcome
  build (const std::vector<TriangleMesh>& meshes, const std::vector<std::string>& names,
         const MeshAnnotations& annotations = {}) const;

private:
  /** InvalidInputError unless \a count >= 2. */
  static void
  requireTwoMeshes (std::size_t count);

  /** The model of meshes already checked, annotated (the profile line from \a profile_source). */
  ModelBuildingOutcome
  buildLoaded (const std::vector<TriangleMesh>& meshes, const std::vector<std::string>& names,
               const MeshAnnotations& annotations, const std::string& profile_source) const;

  ModelFromMeshesSettings settings_;
  ModelBuildingObserver* observer_ = nullptr;
};

/** \brief Settings of buildModelFromIct. */
struct ModelFromIctSettings
{
  ModelBuilderSettings builder; ///< the PCA of the sampled heads
  int samples = 300;            ///< heads drawn from the ICT model
  std::uint64_t seed = 1;       ///< seed of the draws
};

/** \brief About how many bytes buildModelFromIct allocates at its peak for \a ict: ModelBuilder::memoryEstimate of
 *  the samples. For a front end's requireMemory before the build.
 *  \param[in] ict the ICT model as loaded
 *  \param[in] settings the build's settings
 *  \return bytes */
double
ictModelMemory (const MorphableModel& ict, const ModelFromIctSettings& settings);

/** \brief The 7-region model of the ICT-FaceKit (buildIctRegionModel on heads drawn from it), after checking that
 *  the samples fit in memory (InvalidInputError naming their number otherwise).
 *  \param[in] ict the ICT model as loaded (loadIctFaceKit)
 *  \param[in] directory its folder, for the outcome's source
 *  \param[in] settings samples, seed and the builder's settings
 *  \return the model; the ICT model as the one input */
ModelBuildingOutcome
buildModelFromIct (const MorphableModel& ict, const std::string& directory, const ModelFromIctSettings& settings);

/** \brief Settings of ModelFromScans: one set of defaults for every front end. */
struct ModelFromScansSettings
{
  ModelBuilderSettings builder;  ///< the PCA of the resampled scans
  std::string regions;           ///< region label file; empty: the registering model's regions (if more than one)
  std::string landmark_vertices; ///< landmark vertex file; empty: the registering model's landmarks
  /** The registration: ScanRegistration's defaults, but up to 60 components per region refined at a weak prior
   *  (0.2), so that each fit follows its scan and the model is built from close correspondences. */
  RegistrationSettings registration = defaultRegistration ();
  ResamplingSettings resampling; ///< how each fit takes in its scan

  /** \brief The registration settings above.
   *  \return RegistrationSettings with components {60} and refinement_prior 0.2 */
  static RegistrationSettings
  defaultRegistration ();
};

/** \brief One scan made a training mesh: its registration report (with "resampling", or "failure" when it could
 *  not be registered) and the resampled mesh when both steps succeeded. */
struct ScanForModel
{
  nlohmann::json report;            ///< "status" "ok" or "failed"; see ScanRegistration::report
  std::optional<TriangleMesh> mesh; ///< the scan in the registering model's topology
};

/** \brief Builds a model from raw scans: each registered to a model and resampled into its topology, the scans
 *  that fail (refused, lost, failed checks, not resampled) left out, the rest the training meshes; the registering
 *  model's regions, landmarks and profile line carried over unless the settings name annotation files. */
class ModelFromScans
{
public:
  /** \brief How one scan becomes a training mesh (a front end's own, which writes the scan's outputs as it goes).
   *  The default: registerAndResample. */
  using ScanStep = std::function<ScanForModel (const ScanEntry&)>;

  /** \param[in] registering the model that registers the scans (mm); InvalidInputError if null
   *  \param[in] settings the build's settings */
  explicit ModelFromScans (MorphableModel::ConstPtr registering, ModelFromScansSettings settings = {});

  /** \brief Who hears of progress and of the scans left out.
   *  \param[in] observer the observer (not owned; nullptr: nobody) */
  void
  setObserver (ModelBuildingObserver* observer);

  /** \brief Replaces registerAndResample as the step of each scan (whose registration and resampling settings
   *  are then the step's own).
   *  \param[in] step the step */
  void
  setScanStep (ScanStep step);

  /** \brief Writes each scan's outputs into \a folder as the scans are tried, as `morphreg register` and `resample`
   *  write them (ScanFileRegistration::registerStudyScan): \<id\>_fit.ply (the fit, coloured as \a colours says),
   *  \<id\>.json (its report) and \<id\>.ply (the resampled mesh); once every scan was tried, summary.json (a row per
   *  scan with its report's file). Replaces the scan step (setScanStep).
   *  \param[in] folder the folder (it must exist)
   *  \param[in] model_file the registering model's file, for the reports
   *  \param[in] colours the fits' colours (ScanFileSettings::colours)
   *  \param[in] report_fields fields every report and the summary get at their top level (setReportFields) */
  void
  writeScanFilesInto (const std::string& folder, const std::string& model_file, const std::string& colours = "auto",
                      const nlohmann::json& report_fields = nlohmann::json::object ());

  /** \brief The files writeScanFilesInto writes for \a scans into \a folder, each with what it is ("the report of
   *  scan 'a'"), for an output plan.
   *  \param[in] scans the scans
   *  \param[in] folder the folder
   *  \return path and description, the summary last */
  static std::vector<std::pair<std::string, std::string>>
  scanFolderOutputs (const ScanManifest& scans, const std::string& folder);

  /** \brief Registers and resamples every scan (the step), then builds the model from those that made it.
   *  Throws InvalidInputError naming \a study when fewer than two remain.
   *  \param[in] scans the scans (scan_manifest.h)
   *  \param[in] study the manifest or folder they came from, for messages
   *  \return the model and a row per scan */
  ModelBuildingOutcome
  build (const ScanManifest& scans, const std::string& study) const;

  /** \brief One scan read (readScanFile), registered with its landmarks (ScanRegistration with the settings'
   *  registration) and resampled (resampleFit); any error becomes a failed report naming it.
   *  \param[in] entry the scan
   *  \return its report and mesh */
  ScanForModel
  registerAndResample (const ScanEntry& entry) const;

  /** \brief The model that registers the scans.
   *  \return the model */
  const MorphableModel::ConstPtr&
  registeringModel () const
  {
    return registering_;
  }

private:
  std::vector<TriangleMesh>
  tryScans (const ScanManifest& scans, std::vector<ModelInput>& inputs) const;

  MorphableModel::Ptr
  buildModel (const std::vector<TriangleMesh>& meshes) const;

  ScanForModel
  writeScanFiles (const ScanEntry& entry, const std::string& model_file, const std::string& colours,
                  const nlohmann::json& report_fields) const;

  void
  writeSummary (const std::vector<ModelInput>& inputs) const;

  MorphableModel::ConstPtr registering_;
  ModelFromScansSettings settings_;
  ModelBuildingObserver* observer_ = nullptr;
  ScanStep step_;
  std::string folder_;            ///< writeScanFilesInto's folder, or empty
  std::string model_file_;        ///< its registering model's file
  nlohmann::json summary_fields_; ///< fields of its summary.json
};

} // namespace morphreg
