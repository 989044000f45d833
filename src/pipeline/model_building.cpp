// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/memory_budget.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/model/ict_region_model.h>
#include <morphreg/model/region_segmentation.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/pipeline/model_building.h>

#include <cmath>
#include <utility>

namespace morphreg
{
namespace
{
/** The observer given, or one that does nothing. */
ModelBuildingObserver&
observerOr (ModelBuildingObserver* observer)
{
  static ModelBuildingObserver nobody;
  return observer != nullptr ? *observer : nobody;
}

/** The value at JSON pointer \a at of \a json, or null. */
nlohmann::json
valueAt (const nlohmann::json& json, const char* at)
{
  const nlohmann::json::json_pointer pointer (at);
  return json.contains (pointer) ? json.at (pointer) : nlohmann::json ();
}

/** Why the scan of \a report was left out: its failure, else its failed checks, else why it was not resampled. */
std::string
leftOutReason (const nlohmann::json& report)
{
  if (report.contains ("failure"))
    return report["failure"].get<std::string> ();
  std::string reason;
  if (report.contains ("checks"))
    for (const auto& failure : report["checks"].value ("failures", nlohmann::json::array ()))
      reason += (reason.empty () ? "" : "; ") + failure.get<std::string> ();
  if (reason.empty ())
    reason = report.value ("resampling", nlohmann::json::object ()).value ("reason", "not resampled");
  return reason;
}

/** Sets the landmarks and profile line of \a model: \a landmark_file's (read for the model's vertices) or
 *  \a landmarks, and \a profile_line (from \a profile_source, named when it does not fit). */
void
annotate (MorphableModel& model, const std::string& landmark_file, const LandmarkVertices& landmarks,
          const std::vector<int>& profile_line, const std::string& profile_source)
{
  model.setLandmarks (landmark_file.empty () ? landmarks : loadLandmarkVertices (landmark_file, model.numVertices ()));
  if (profile_line.empty ())
    return;
  try {
    model.setProfileLine (profile_line);
  }
  catch (const InvalidInputError& e) {
    throw FormatError (profile_source + ": profile_line does not fit the meshes (" + e.what () + ")");
  }
}

/** The PCA of \a meshes: by the regions of \a region_file if given, else by \a regions if given, else global. */
MorphableModel::Ptr
buildPca (const ModelBuilderSettings& settings, const std::vector<TriangleMesh>& meshes, const std::string& region_file,
          const std::optional<RegionLabels>& regions)
{
  const ModelBuilder builder (settings);
  if (!region_file.empty ())
    return builder.build (meshes, loadRegionLabels (region_file, meshes.front ().numVertices ()));
  return regions ? builder.build (meshes, *regions) : builder.buildGlobal (meshes);
}
} // namespace

nlohmann::json
ModelInput::row () const
{
  nlohmann::json row = {{"id", id}, {"status", included ? "ok" : "failed"}, {"included", included}, {"reason", reason}};
  if (report.is_null ()) {
    row["file"] = file;
    return row;
  }
  row["scan"] = file;
  const nlohmann::json rms = valueAt (report, "/residuals_mm/scan_to_model/rms");
  row["fit_rms_mm"] = rms.is_number () && std::isfinite (rms.get<double> ()) ? rms : nlohmann::json ();
  row["coverage"] = valueAt (report, "/resampling/coverage");
  row["hole_count"] = valueAt (report, "/resampling/hole_count");
  return row;
}

nlohmann::json
ModelBuildingOutcome::summary (const ModelBuilderSettings& settings) const
{
  nlohmann::json summary = {{"source", source},
                            {"settings",
                             {{"max_components", settings.max_components},
                              {"explained_variance", settings.explained_variance},
                              {"blend_rings", settings.blend_rings},
                              {"procrustes", settings.align}}}};
  std::vector<int> components;
  for (const ModelRegion& region : model->regions ()) {
    summary["regions"].push_back (region.name);
    components.push_back (static_cast<int> (region.variances.size ()));
  }
  summary["components"] = components;
  summary["vertices"] = model->numVertices ();
  summary["landmarks"] = model->landmarks ().size ();
  return summary;
}

ModelFromMeshes::ModelFromMeshes (ModelFromMeshesSettings settings) : settings_ (std::move (settings)) {}

void
ModelFromMeshes::setObserver (ModelBuildingObserver* observer)
{
  observer_ = observer;
}

ModelBuildingOutcome
ModelFromMeshes::build (const MeshFolder& folder) const
{
  const std::vector<std::string>& files = folder.files;
  requireTwoMeshes (files.size ());
  ModelBuildingObserver& observer = observerOr (observer_);
  std::vector<TriangleMesh> meshes;
  observer.stageStarted ("loading meshes", static_cast<int> (files.size ()));
  for (const std::string& file : files) {
    meshes.push_back (loadTriangleMesh (file));
    requireSameTopology (meshes.front (), meshes.back (), file);
    observer.inputDone (static_cast<int> (meshes.size ()), "");
  }
  observer.stageFinished ();
  ModelBuildingOutcome outcome = buildLoaded (meshes, files, {std::nullopt, {}, folder.profile_line}, folder.manifest);
  for (ModelInput& input : outcome.inputs)
    input.file = input.id;
  return outcome;
}

ModelBuildingOutcome
ModelFromMeshes::build (const std::vector<TriangleMesh>& meshes, const std::vector<std::string>& names,
                        const MeshAnnotations& annotations) const
{
  if (names.size () != meshes.size ())
    throw InvalidInputError (std::to_string (names.size ()) + " names for " + std::to_string (meshes.size ()) +
                             " meshes; give one name per mesh");
  requireTwoMeshes (meshes.size ());
  for (std::size_t k = 1; k < meshes.size (); ++k)
    requireSameTopology (meshes.front (), meshes[k], names[k]);
  return buildLoaded (meshes, names, annotations, "the profile line");
}

void
ModelFromMeshes::requireTwoMeshes (std::size_t count)
{
  if (count < 2)
    throw InvalidInputError (std::to_string (count) +
                             " mesh(es) given; a model needs at least two meshes in correspondence");
}

ModelBuildingOutcome
ModelFromMeshes::buildLoaded (const std::vector<TriangleMesh>& meshes, const std::vector<std::string>& names,
                              const MeshAnnotations& annotations, const std::string& profile_source) const
{
  ModelBuildingOutcome outcome;
  outcome.model = buildPca (settings_.builder, meshes, settings_.regions, annotations.regions);
  annotate (*outcome.model, settings_.landmark_vertices, annotations.landmarks, annotations.profile_line,
            profile_source);
  for (const std::string& name : names)
    outcome.inputs.push_back ({name, "", true, "", nullptr});
  outcome.source = {{"meshes", meshes.size ()},
                    {"regions", settings_.regions},
                    {"landmark_vertices", settings_.landmark_vertices},
                    {"profile_line_vertices", annotations.profile_line.size ()}};
  return outcome;
}

double
ictModelMemory (const MorphableModel& ict, const ModelFromIctSettings& settings)
{
  return ModelBuilder::memoryEstimate (static_cast<std::size_t> (std::max (settings.samples, 0)), ict.numVertices ());
}

ModelBuildingOutcome
buildModelFromIct (const MorphableModel& ict, const std::string& directory, const ModelFromIctSettings& settings)
{
  requireMemory (ictModelMemory (ict, settings), std::to_string (settings.samples) +
                                                     " heads drawn from the ICT model of " + directory + " (" +
                                                     std::to_string (ict.numVertices ()) + " vertices each)");
  ModelBuildingOutcome outcome;
  outcome.model = buildIctRegionModel (ict, settings.samples, settings.seed, settings.builder);
  outcome.inputs.push_back ({"ict_facekit", directory, true, "", nullptr});
  outcome.source = {{"ict_facekit", directory}, {"samples", settings.samples}, {"seed", settings.seed}};
  return outcome;
}

RegistrationSettings
ModelFromScansSettings::defaultRegistration ()
{
  RegistrationSettings settings;
  settings.components = {60};
  settings.refinement_prior = 0.2;
  return settings;
}

ModelFromScans::ModelFromScans (MorphableModel::ConstPtr registering, ModelFromScansSettings settings)
  : registering_ (std::move (registering)), settings_ (std::move (settings))
{
  if (!registering_)
    throw InvalidInputError ("model building from scans: no registering model (null)");
}

void
ModelFromScans::setObserver (ModelBuildingObserver* observer)
{
  observer_ = observer;
}

void
ModelFromScans::setScanStep (ScanStep step)
{
  step_ = std::move (step);
}

ScanForModel
ModelFromScans::registerAndResample (const ScanEntry& entry) const
{
  ScanForModel done;
  try {
    ScanRegistration registration (registering_, settings_.registration);
    if (!entry.landmarks.empty ())
      registration.setLandmarks (loadLandmarks (entry.landmarks), entry.landmarks, LandmarkUnit::millimetre);
    const ScanRegistrationOutcome fit = registration.registerScan (readScanFile (entry.scan));
    done.report = registration.report (fit);
    if (fit.lostScan ())
      return done;
    FitResampling resampled = resampleFit (*fit.scan.cloud, entry.scan, fit.fittedMesh (),
                                           done.report["checks"]["passed"].get<bool> (), settings_.resampling);
    done.report["resampling"] = resampled.report;
    if (resampled.result)
      done.mesh = std::move (resampled.result->mesh);
  }
  catch (const std::exception& e) {
    done.report = {{"status", "failed"}, {"failure", e.what ()}, {"scan", {{"file", entry.scan}}}};
    done.mesh.reset ();
  }
  return done;
}

std::vector<TriangleMesh>
ModelFromScans::tryScans (const ScanManifest& scans, std::vector<ModelInput>& inputs) const
{
  ModelBuildingObserver& observer = observerOr (observer_);
  std::vector<TriangleMesh> meshes;
  observer.stageStarted ("registering and resampling scans", static_cast<int> (scans.size ()));
  for (std::size_t k = 0; k < scans.size (); ++k) {
    ScanForModel done = step_ ? step_ (scans[k]) : registerAndResample (scans[k]);
    const bool included = done.mesh.has_value () && done.report.value ("status", "") == "ok";
    if (included)
      meshes.push_back (std::move (*done.mesh));
    inputs.push_back (
        {scans[k].id, scans[k].scan, included, included ? "" : leftOutReason (done.report), std::move (done.report)});
    if (!included)
      observer.inputLeftOut (inputs.back ());
    observer.inputDone (static_cast<int> (k + 1), " " + std::to_string (meshes.size ()) + " ok, " +
                                                      std::to_string (k + 1 - meshes.size ()) + " left out");
  }
  observer.stageFinished ();
  if (!folder_.empty ())
    writeSummary (inputs);
  observer.inputsTried (inputs);
  return meshes;
}

ModelBuildingOutcome
ModelFromScans::build (const ScanManifest& scans, const std::string& study) const
{
  ModelBuildingOutcome outcome;
  const std::vector<TriangleMesh> meshes = tryScans (scans, outcome.inputs);
  if (meshes.size () < 2)
    throw InvalidInputError (study + ": " + std::to_string (meshes.size ()) + " of " + std::to_string (scans.size ()) +
                             " scans registered and resampled, " + std::to_string (scans.size () - meshes.size ()) +
                             " left out; a model needs at least two");
  outcome.model = buildModel (meshes);
  annotate (*outcome.model, settings_.landmark_vertices, registering_->landmarks (), registering_->profileLine (),
            "the registering model");
  outcome.source = {
      {"scans", scans.size ()}, {"included", meshes.size ()}, {"left_out", scans.size () - meshes.size ()}};
  return outcome;
}

MorphableModel::Ptr
ModelFromScans::buildModel (const std::vector<TriangleMesh>& meshes) const
{
  std::optional<RegionLabels> regions;
  if (settings_.regions.empty () && registering_->numRegions () > 1)
    regions = strongestRegions (*registering_);
  return buildPca (settings_.builder, meshes, settings_.regions, regions);
}

} // namespace morphreg
