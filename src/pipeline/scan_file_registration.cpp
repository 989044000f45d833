// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/colour_map.h>
#include <morphreg/common/distance_statistics.h>
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/file_format.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/pipeline/scan_colours.h>
#include <morphreg/pipeline/scan_file_registration.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <utility>

namespace morphreg
{
namespace
{
using Clock = std::chrono::steady_clock;

double
secondsSince (Clock::time_point start)
{
  return std::chrono::duration<double> (Clock::now () - start).count ();
}

/** Tells nobody: the observer of a registration without one. */
RegistrationObserver&
silentObserver ()
{
  static RegistrationObserver silent;
  return silent;
}

/** Forwards warnings (a scan whose colours cannot be read) to an observer, a line each. */
void
forwardLines (const std::string& text, RegistrationObserver& observer)
{
  std::istringstream lines (text);
  for (std::string line; std::getline (lines, line);)
    observer.warning (line);
}

/** The fitted mesh of \a fit written to \a path, coloured as \a settings say (the scan's colours read from
 *  \a scan_file, unless \a scan_has_colours is false); adds its colours and scale to \a report. */
double
writeFittedMesh (const ScanFileSettings& settings, const ScanRegistrationOutcome& fit, const TriangleMesh& fitted,
                 const ScanFiles& files, RegistrationObserver& observer, nlohmann::json& report)
{
  const Eigen::VectorXd& residuals = fit.icp->getVertexResiduals ();
  const double scale = residualColourScale (residuals, settings.colour_max);
  std::ostringstream warnings;
  const auto scan_colours =
      scanColoursAt (files.scan, fit.unit.scale_to_mm, settings.colours, fitted.vertices, warnings);
  forwardLines (warnings.str (), observer);
  savePolygonMesh (
      files.fitted_mesh,
      toPolygonMesh (fitted, scan_colours ? *scan_colours : residualColours (residuals, scale), residuals));
  report["residuals_mm"]["colour_scale_max"] = scale;
  report["fitted_mesh_colours"] = scan_colours ? "scan" : "residual";
  return scale;
}
} // namespace

std::string
modelFileUnitsMessage (const MorphableModel& model, const std::string& path)
{
  const auto file_units = model.metadata ().find (kFileUnitsKey);
  if (file_units == model.metadata ().end () || file_units->second.rfind ("mm ", 0) == 0)
    return "";
  return "units: the model file " + path + " is in " + file_units->second;
}

std::string
scanFileUnitMessage (const std::string& scan_file)
{
  const FileFormat format = sniffFileFormat (scan_file);
  const auto file_unit = specifiedLengthUnit (format);
  if (!file_unit)
    return "";
  std::ostringstream text;
  text << "units: " << scan_file << " is " << fileFormatName (format) << ", whose unit is the " << toString (*file_unit)
       << " by specification: converted to mm on reading (x" << millimetresPer (*file_unit) << ")";
  return text.str ();
}

void
requireValidSettings (const ScanFileSettings& settings)
{
  requireValidSettings (static_cast<const RegistrationSettings&> (settings));
  if (settings.colour_max < 0.0 || !std::isfinite (settings.colour_max))
    throw InvalidInputError ("colour_max " + std::to_string (settings.colour_max) +
                             ": must be 0 (the 95th percentile) or a positive number of mm");
  const std::string& colours = settings.colours;
  if (colours != "auto" && colours != "scan" && colours != "residual")
    throw InvalidInputError ("colours '" + colours + "': expected auto, scan or residual");
}

ScanFileRegistration::ScanFileRegistration (MorphableModel::ConstPtr model, const ScanFileSettings& settings)
  : registration_ (std::move (model), settings), settings_ (settings)
{
  requireValidSettings (settings_);
}

void
ScanFileRegistration::setObserver (RegistrationObserver* observer)
{
  observer_ = observer;
}

void
ScanFileRegistration::setReportFields (const nlohmann::json& fields)
{
  if (!fields.is_object ())
    throw InvalidInputError ("ScanFileRegistration::setReportFields: the fields are not a JSON object");
  report_fields_ = fields;
}

RegistrationObserver&
ScanFileRegistration::observer () const
{
  return observer_ ? *observer_ : silentObserver ();
}

void
ScanFileRegistration::writeReport (const std::string& path, nlohmann::json& report) const
{
  for (const auto& field : report_fields_.items ())
    report[field.key ()] = field.value ();
  writeJsonFile (path, report);
}

nlohmann::json
ScanFileRegistration::fileReport (const ScanRegistration& registration, const ScanRegistrationOutcome& fit,
                                  const ScanFiles& files) const
{
  nlohmann::json report = registration.report (fit);
  report["scan"]["file"] = files.scan;
  const FileFormat format = sniffFileFormat (files.scan);
  if (const auto file_unit = specifiedLengthUnit (format))
    report["scan"]["file_unit"] = {{"unit", toString (*file_unit)},
                                   {"scale_to_mm", millimetresPer (*file_unit)},
                                   {"reason", fileFormatName (format) +
                                                  "'s unit by specification, converted on reading; units "
                                                  "and scale_to_mm apply after it"}};
  report["model"]["file"] = files.model;
  report["settings"]["landmarks"] = files.landmarks;
  report["fitted_mesh"] = fit.lostScan () ? nlohmann::json () : nlohmann::json (files.fitted_mesh);
  return report;
}

ScanFileOutcome
ScanFileRegistration::registerScan (const ScanInput& scan, const ScanFiles& files, const FitFollowUp& follow_up,
                                    double seconds_before) const
{
  const auto start = Clock::now ();
  if (const std::string unit_message = scanFileUnitMessage (files.scan); !unit_message.empty ())
    observer ().message (unit_message);
  ScanRegistration registration = registration_; // the scan's own landmarks
  registration.setObserver (&observer ());
  if (!files.landmarks.empty ())
    registration.setLandmarks (loadLandmarks (files.landmarks), files.landmarks, LandmarkUnit::millimetre);
  const double load_seconds = seconds_before + secondsSince (start);
  ScanFileOutcome outcome;
  outcome.fit = registration.registerScan (scan);
  const ScanRegistrationOutcome& fit = outcome.fit;
  if (fit.lostScan ()) {
    outcome.report = fileReport (registration, fit, files);
    writeReport (files.report, outcome.report);
    return outcome;
  }
  const auto write_start = Clock::now ();
  const TriangleMesh fitted = fit.fittedMesh ();
  outcome.report = fileReport (registration, fit, files);
  outcome.colour_scale = writeFittedMesh (settings_, fit, fitted, files, observer (), outcome.report);
  const double write_seconds = secondsSince (write_start);
  if (follow_up)
    follow_up (fit, fitted, outcome.report);
  nlohmann::json& timings = outcome.report["timings_s"];
  timings.update ({{"load", load_seconds},
                   {"fit", fit.fit_seconds},
                   {"write_mesh", write_seconds},
                   {"total", seconds_before + secondsSince (start)}});
  // Written last and atomically: a report on disk means the scan's outputs are complete (batch resume trusts it).
  writeReport (files.report, outcome.report);
  return outcome;
}

nlohmann::json
ScanFileRegistration::registerStudyScan (const ScanFiles& files, const FitFollowUp& follow_up,
                                         const std::vector<std::string>& follow_up_outputs) const
{
  const auto start = Clock::now ();
  std::vector<std::string> outputs = {files.fitted_mesh, files.report};
  outputs.insert (outputs.end (), follow_up_outputs.begin (), follow_up_outputs.end ());
  for (const std::string& output : outputs)
    std::remove (partialPath (output).c_str ()); // left by a run killed mid-write
  std::string why;
  {
    OutputTransaction transaction (outputs);
    try {
      const auto read_start = Clock::now ();
      const ScanInput scan = readScanFile (files.scan);
      nlohmann::json report = registerScan (scan, files, follow_up, secondsSince (read_start)).report;
      transaction.commit (); // written, failed or not: the report says which
      return report;
    }
    catch (const std::exception& e) {
      why = e.what ();
    }
  } // the scan's outputs rolled back: its report records the failure alone
  nlohmann::json failure = {{"status", "failed"},
                            {"failure", why},
                            {"scan", {{"file", files.scan}, {"landmarks", files.landmarks}}},
                            {"timings_s", {{"total", secondsSince (start)}}}};
  writeReport (files.report, failure);
  return failure;
}

nlohmann::json
truthVertexErrors (const TriangleMesh& fitted, const Eigen::VectorXd& residuals, const std::string& truth_file)
{
  const TriangleMesh truth = loadTriangleMesh (truth_file);
  requireSameTopology (fitted, truth, truth_file);
  const Eigen::VectorXd errors = (fitted.vertices - truth.vertices).colwise ().norm ().transpose ();
  const Eigen::VectorXd covered = residuals.array ().isFinite ().select (errors, NAN);
  nlohmann::json report = distanceStatistics (errors);
  report["covered_by_scan"] = distanceStatistics (covered);
  report["file"] = truth_file;
  return report;
}

} // namespace morphreg
