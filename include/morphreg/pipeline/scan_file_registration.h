// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_file_registration.h
 *  \brief One scan registered to files (ScanRegistration, then the fitted mesh and the report written): the step
 *  the single-scan front ends and every scan of a batch (batch_registration.h) run. The fitted mesh is written
 *  first and the report last, each atomically, so that a report on disk means complete outputs.
 *
 *  \code
 *  morphreg::ScanFileRegistration registration (morphreg::loadModel ("model.h5"));
 *  morphreg::ScanFiles files{"scan.ply", "", "model.h5", "fit.ply", "fit.json"};
 *  const morphreg::ScanFileOutcome outcome = registration.registerScan (morphreg::readScanFile ("scan.ply"), files);
 *  outcome.report["status"];               // "ok" or "failed" (checks, or a lost scan: no mesh written)
 *  \endcode
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/pipeline/scan_input.h>
#include <morphreg/pipeline/scan_registration.h>
#include <morphreg/registration/registration_settings.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The settings of one scan's registration to files: the fit's (RegistrationSettings) and the fitted
 *  mesh's colours. */
struct ScanFileSettings : RegistrationSettings
{
  double colour_max = 0.0; ///< the residual colour scale's maximum, mm; 0: the 95th percentile of the residuals
  /** The fitted mesh's vertex colours: "auto" (the scan's if it has any, else the residual's), "scan" or
   *  "residual". */
  std::string colours = "auto";
};

/** \brief The files of one scan's registration: what it reads and what it writes. */
struct ScanFiles
{
  std::string scan;        ///< the scan file (its name in the report; its colours, see ScanFileSettings::colours)
  std::string landmarks;   ///< landmarks on the scan (mm); empty: none
  std::string model;       ///< the model file, for the report
  std::string fitted_mesh; ///< the fitted mesh to write
  std::string report;      ///< the JSON report to write
};

/** \brief Refuses bad settings, naming the setting (InvalidInputError): the fit's (requireValidSettings of
 *  RegistrationSettings), a negative colour_max, an unknown colours mode.
 *  \param[in] settings the settings */
void
requireValidSettings (const ScanFileSettings& settings);

/** \brief The outcome of ScanFileRegistration::registerScan. */
struct ScanFileOutcome
{
  ScanRegistrationOutcome fit; ///< the fit (fit.lostScan (): only the report was written)
  nlohmann::json report;       ///< the report as written
  double colour_scale = 0.0;   ///< the residual colour scale's maximum used, mm

  /** \brief Whether the fit passed its checks (and did not lose the scan).
   *  \return true when the report's status is "ok" */
  bool
  passed () const
  {
    return report.value ("status", "") == "ok";
  }
};

/** \brief Work on a finished fit before its report is written (resampling, a figure, an error against a truth): it
 *  adds its results to the report; an exception it throws fails the scan. */
using FitFollowUp =
    std::function<void (const ScanRegistrationOutcome& fit, const TriangleMesh& fitted, nlohmann::json& report)>;

/** \brief Registers scans to one model with one set of settings, writing each fit's mesh and report. */
class ScanFileRegistration
{
public:
  /** \param[in] model the model to fit (mm); InvalidInputError if null (as ScanRegistration)
   *  \param[in] settings the settings (checked: requireValidSettings) */
  explicit ScanFileRegistration (MorphableModel::ConstPtr model, const ScanFileSettings& settings = {});

  /** \brief Who hears of progress, units and warnings.
   *  \param[in] observer the observer (not owned; nullptr: nobody) */
  void
  setObserver (RegistrationObserver* observer);

  /** \brief Fields every report gets at its top level (e.g. "morphreg": the front end's version and command line,
   *  "provenance": what made the outputs); replaced, not merged, where the report has the key.
   *  \param[in] fields a JSON object */
  void
  setReportFields (const nlohmann::json& fields);

  /** \brief Registers \a scan (its landmarks from files.landmarks), writes the fitted mesh (coloured as the
   *  settings say) and then the report. A fit that loses the scan gets the report alone (status "failed"); a fit
   *  that fails its checks gets both (status "failed"). Throws for bad input (an unreadable landmark file, a scan
   *  that cannot be registered) before anything is written.
   *  \param[in] scan the scan, read from files.scan (readScanFile) or otherwise (a depth image: no colours)
   *  \param[in] files the files read and written
   *  \param[in] follow_up run on a passed or failed fit before the report is written; empty: none
   *  \param[in] seconds_before time already spent on this scan (loading the model and the scan), in the report's
   *  load and total times
   *  \return the fit and its report */
  ScanFileOutcome
  registerScan (const ScanInput& scan, const ScanFiles& files, const FitFollowUp& follow_up = {},
                double seconds_before = 0.0) const;

  /** \brief registerScan () for one scan of a study, which must not stop the study: the scan read from its file,
   *  and any failure (a bad file, a scan that cannot be registered, a follow-up that throws) recorded as a report
   *  {"status": "failed", "failure": why} written in the registration's place. The scan's outputs (with \a
   *  follow_up_outputs, the files \a follow_up writes) are committed together: a failure rolls them back.
   *  \param[in] files the files read and written
   *  \param[in] follow_up as for registerScan
   *  \param[in] follow_up_outputs the files \a follow_up writes
   *  \return the scan's report as written */
  nlohmann::json
  registerStudyScan (const ScanFiles& files, const FitFollowUp& follow_up = {},
                     const std::vector<std::string>& follow_up_outputs = {}) const;

  /** \brief The settings.
   *  \return the settings */
  const ScanFileSettings&
  settings () const
  {
    return settings_;
  }

private:
  /** The library's report of \a fit with the names of \a files. */
  nlohmann::json
  fileReport (const ScanRegistration& registration, const ScanRegistrationOutcome& fit, const ScanFiles& files) const;

  /** Adds the report fields to \a report and writes it to \a path (atomically). */
  void
  writeReport (const std::string& path, nlohmann::json& report) const;

  /** setObserver's observer, or one that does nothing. */
  RegistrationObserver&
  observer () const;

  ScanRegistration registration_; ///< the model and the fit's settings, without landmarks
  ScanFileSettings settings_;
  nlohmann::json report_fields_ = nlohmann::json::object ();
  RegistrationObserver* observer_ = nullptr;
};

/** \brief The line saying a model file's unit when it was not mm (loadModel converts it), or empty.
 *  \param[in] model a model as loadModel gives it
 *  \param[in] path its file
 *  \return e.g. "units: the model file m.h5 is in m (x1000)", or "" */
std::string
modelFileUnitsMessage (const MorphableModel& model, const std::string& path);

/** \brief The line saying that a scan file's format fixes its unit (glTF: metres), converted on reading, or empty.
 *  \param[in] scan_file the scan file
 *  \return e.g. "units: head.glb is glTF, whose unit is the m by specification: converted to mm on reading (x1000)" */
std::string
scanFileUnitMessage (const std::string& scan_file);

/** \brief The fit's vertex distances to the true mesh \a truth_file (the model's topology, in the scan's frame): over
 *  every vertex, and over the vertices the scan covers (those with a finite residual). InvalidInputError naming
 *  \a truth_file when its topology is not the fit's.
 *  \param[in] fitted the fitted mesh, in the scan's frame
 *  \param[in] residuals its per-vertex residuals (NaN where no scan point corresponds)
 *  \param[in] truth_file the true mesh
 *  \return the statistics (distance_statistics.h) with "covered_by_scan" and "file": a report's
 *  "truth_vertex_error_mm" */
nlohmann::json
truthVertexErrors (const TriangleMesh& fitted, const Eigen::VectorXd& residuals, const std::string& truth_file);

} // namespace morphreg
