// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/common/head_scale_unit.h>
#include <morphreg/pipeline/scan_registration.h>
#include <morphreg/registration/fit_plausibility.h>
#include <morphreg/registration/iteration_progress.h>
#include <morphreg/registration/registration_result_json.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/pipeline/scan_units.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace morphreg
{
namespace
{
using Clock = std::chrono::steady_clock;
using Icp = ScanRegistration::Icp;

/** The fit's similarity scale (model to scan). */
double
fittedScale (Icp& icp)
{
  return std::cbrt (icp.getFinalTransformation ().topLeftCorner<3, 3> ().cast<double> ().determinant ());
}

/** Whether \a scale is outside the plausible head sizes of checkFitPlausibility. */
bool
implausibleScale (double scale)
{
  const FitPlausibilitySettings limits;
  return scale < limits.min_scale || scale > limits.max_scale;
}

/** What a fit found, for the message of a scan refused as no head: it lost the scan, or which checks it failed. */
std::string
whyNoHead (const ScanRegistrationOutcome& fit, const MorphableModel& model)
{
  if (fit.lostScan ())
    return "lost the scan (" + fit.lost + ")";
  std::string failures;
  for (const std::string& failure : checkRegistration (*fit.icp, model).failures)
    failures += (failures.empty () ? "" : "; ") + failure;
  return "failed its checks (" + failures + ")";
}

/** The report's description of the scan and how its unit was found. */
nlohmann::json
scanJson (const ScanRegistrationOutcome& outcome, const std::string& units_setting)
{
  const LengthUnitGuess& unit = outcome.unit;
  return {{"points", outcome.scan.cloud->size ()},
          {"units", unit.estimated ? "estimated" : toString (unit.unit)},
          {"unit_detection", units_setting == "auto" ? "auto" : "given"},
          {"unit_reason", unit.reason},
          {"scale_to_mm", unit.scale_to_mm}};
}
} // namespace

TriangleMesh
ScanRegistrationOutcome::fittedMesh () const
{
  if (!icp)
    throw InvalidInputError (scan.name + ": the fit lost the scan (" + lost + "), so there is no fitted mesh");
  return {icp->getFittedVertices (), icp->getModel ()->triangles ()};
}

ScanRegistration::ScanRegistration (MorphableModel::ConstPtr model, const RegistrationSettings& settings)
  : model_ (std::move (model)), settings_ (settings)
{
  if (!model_)
    throw InvalidInputError ("ScanRegistration: no model (a null pointer)");
  requireValidSettings (settings_);
}

void
ScanRegistration::setLandmarks (LandmarkPositions landmarks, const std::string& source, LandmarkUnit unit)
{
  std::string skipped;
  for (const std::string& id : keepKnownLandmarks (landmarks, model_->landmarks ()))
    skipped += " " + id;
  if (!skipped.empty ())
    observer ().warning (source + ": the model has no landmark" + skipped + "; using the other " +
                         std::to_string (landmarks.size ()));
  if (landmarks.empty ())
    throw InvalidInputError (source + ": none of its landmarks is on the model");
  landmarks_ = std::move (landmarks);
  landmark_source_ = source;
  landmark_unit_ = unit;
}

void
ScanRegistration::setObserver (RegistrationObserver* observer)
{
  observer_ = observer;
}

RegistrationObserver&
ScanRegistration::observer () const
{
  static RegistrationObserver silent; // stateless: shared by every registration and thread
  return observer_ ? *observer_ : silent;
}

LandmarkPositions
ScanRegistration::landmarksOn (const ScanInput& scan_mm, const LengthUnitGuess& unit) const
{
  LandmarkPositions landmarks = landmarks_;
  if (landmark_unit_ == LandmarkUnit::scan)
    for (auto& entry : landmarks)
      entry.second *= unit.scale_to_mm;
  requireLandmarksOnScan (landmarks, pointsOf (*scan_mm.cloud), landmark_source_);
  return landmarks;
}

void
ScanRegistration::runFit (Icp& icp, const std::string& scan_name) const
{
  observer ().fitStarted (scan_name, settings_.iterations);
  watchIterations (icp, [this] (int iteration, std::size_t correspondences, double rms) {
    observer ().iterationDone (iteration, correspondences, rms);
  });
  pcl::PointCloud<pcl::PointNormal> aligned;
  try {
    icp.align (aligned);
  }
  catch (const TooFewCorrespondencesError&) {
    observer ().fitFinished (static_cast<int> (icp.getRegistrationReport ().history.size ()));
    throw;
  }
  catch (const InvalidInputError& e) { // the scan passed the checks before the fit, but the fit cannot use it
    throw InvalidInputError (scan_name + ": cannot be registered: " + e.what ());
  }
  observer ().fitFinished (static_cast<int> (icp.getRegistrationReport ().history.size ()));
}

ScanRegistrationOutcome
ScanRegistration::fitAt (const ScanInput& as_given, const LengthUnitGuess& unit) const
{
  ScanRegistrationOutcome fit{scaledScan (as_given, unit.scale_to_mm), unit, std::make_shared<Icp> (), "", 0.0};
  Icp& icp = *fit.icp;
  configureRegistration (icp, settings_, model_);
  icp.setTargetViewpoint (fit.scan.viewpoint);
  if (!landmarks_.empty ())
    icp.setTargetLandmarks (landmarksOn (fit.scan, unit), settings_.landmark_weight);
  icp.setInputTarget (fit.scan.cloud);
  const auto start = Clock::now ();
  try {
    runFit (icp, as_given.name);
  }
  catch (const TooFewCorrespondencesError& e) {
    fit.lost = e.what ();
    fit.icp.reset ();
  }
  fit.fit_seconds = std::chrono::duration<double> (Clock::now () - start).count ();
  return fit;
}

bool
ScanRegistration::needsHeadScale (const ScanInput& scan, const ScanRegistrationOutcome& fit) const
{
  if (settings_.units != "auto" || scan.unit)
    return false;
  return !fit.unit.recognised || fit.lostScan () || implausibleScale (fittedScale (*fit.icp));
}

ScanRegistrationOutcome
ScanRegistration::fitAtHeadScale (const ScanInput& as_given, ScanRegistrationOutcome suggested) const
{
  const LengthUnitGuess provisional = provisionalHeadScale (suggested.unit);
  const std::string tried = suggested.unit.recognised ? "read as " + toString (suggested.unit.unit) + ", the fit " +
                                                            whyNoHead (suggested, *model_) + "; "
                                                      : "";
  ScanRegistrationOutcome measured = fitAt (as_given, provisional);
  std::string failure = "at the provisional scale the fit " + whyNoHead (measured, *model_);
  // the global alignment searches heads of 0.6-1.6 times the model: a fit far outside found no head to measure
  constexpr double kSmallestHead = 0.5, kLargestHead = 2.0;
  if (!measured.lostScan () &&
      (fittedScale (*measured.icp) < kSmallestHead || fittedScale (*measured.icp) > kLargestHead))
    measured.icp.reset ();
  if (!measured.lostScan ()) {
    const FitPlausibilitySettings limits;
    const LengthUnitGuess unit =
        unitFromHeadScale (provisional, fittedScale (*measured.icp), limits.min_scale, limits.max_scale);
    ScanRegistrationOutcome final = fitAt (as_given, unit);
    final.unit.reason = provisional.reason + "; " + unit.reason;
    if (!final.lostScan () && checkRegistration (*final.icp, *model_).plausible) {
      observer ().message ("units: " + as_given.name + ": " + final.unit.reason + "; rescaled to mm");
      return final;
    }
    std::ostringstream at;
    at << unit.reason << "; at x" << std::setprecision (4) << unit.scale_to_mm << " to mm the fit "
       << whyNoHead (final, *model_);
    failure = at.str ();
  }
  if (suggested.unit.recognised)
    return suggested;
  throw InvalidInputError (as_given.name + ": no head found, so its unit cannot be estimated: " + provisional.reason +
                           "; " + tried + failure + ". Give the unit (--units, units=) if it is a head");
}

ScanRegistrationOutcome
ScanRegistration::registerScan (const ScanInput& scan) const
{
  const LengthUnitGuess guess = scanInputUnit (scan, settings_.units, *model_);
  if (const std::string message = unitConversionMessage (guess); !message.empty ())
    observer ().message (message);
  ScanRegistrationOutcome fit{scaledScan (scan, guess.scale_to_mm), guess, nullptr, "", 0.0};
  if (guess.recognised || settings_.units != "auto")
    fit = fitAt (scan, guess);
  if (needsHeadScale (scan, fit))
    fit = fitAtHeadScale (scan, std::move (fit));
  return fit;
}

nlohmann::json
ScanRegistration::report (const ScanRegistrationOutcome& outcome) const
{
  nlohmann::json report;
  if (outcome.lostScan ())
    report = {{"status", "failed"}, {"checks", {{"passed", false}, {"failures", {outcome.lost}}}}};
  else
    report = registrationResultJson (*outcome.icp, *model_);
  report["scan"] = scanJson (outcome, settings_.units);
  report["model"] = {{"vertices", model_->numVertices ()}, {"regions", model_->numRegions ()}};
  report["settings"] = toJson (settings_);
  return report;
}

} // namespace morphreg
