// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_registration.h
 *  \brief A scan registered to a model the way `morphreg register` does it, for every front end (the command line,
 *  the Python module, a user's program): the scan brought to mm (its unit given, guessed from its size, or estimated
 *  from the head when it has none), the landmarks the model has, a MorphableICP fit configured by
 *  RegistrationSettings and checked for plausibility, and the report.
 *
 *  \code
 *  morphreg::ScanRegistration registration (morphreg::loadModel ("model.h5"));
 *  const morphreg::ScanRegistrationOutcome fit = registration.registerScan (morphreg::readScanFile ("scan.ply"));
 *  if (fit.lostScan ()) ...               // fit.lost says why
 *  fit.fittedMesh ();                      // mm, the scan's frame scaled to mm
 *  registration.report (fit);              // what `morphreg register` writes, but the file names
 *  \endcode
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/pipeline/scan_input.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/registration_settings.h>

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <memory>
#include <string>

namespace morphreg
{
/** \brief What a scan registration tells as it goes; every method does nothing by default. Called on the thread
 *  that runs ScanRegistration::registerScan. */
class RegistrationObserver
{
public:
  virtual ~RegistrationObserver () = default;

  /** A fit starts (one per scale tried: the unit estimate may fit twice). */
  virtual void
  fitStarted (const std::string& /*scan_name*/, int /*max_iterations*/)
  {}

  /** An iteration ended: its number (from 1), its correspondences and their RMS distance (mm). */
  virtual void
  iterationDone (int /*iteration*/, std::size_t /*correspondences*/, double /*rms*/)
  {}

  /** The fit ended after \a iterations (also when it lost the scan). */
  virtual void
  fitFinished (int /*iterations*/)
  {}

  /** A finding worth a line on a console: how the scan's unit was found. */
  virtual void
  message (const std::string& /*text*/)
  {}

  /** Something the user asked for that is not done: landmarks the model lacks. */
  virtual void
  warning (const std::string& /*text*/)
  {}
};

/** \brief The outcome of ScanRegistration::registerScan. */
struct ScanRegistrationOutcome
{
  using Icp = MorphableICP<pcl::PointNormal>; ///< the registration the pipeline runs

  ScanInput scan;           ///< the scan in mm (the fit's frame)
  LengthUnitGuess unit;     ///< how the scan was brought to mm
  std::shared_ptr<Icp> icp; ///< the finished registration; null when the fit lost the scan
  std::string lost;         ///< why the fit lost the scan (too few correspondences), if it did
  double fit_seconds = 0.0; ///< the final fit's time

  /** \brief Whether the fit lost the scan (no registration to report).
   *  \return true when icp is null */
  bool
  lostScan () const
  {
    return !icp;
  }

  /** \brief The fitted model instance; InvalidInputError naming the scan when the fit lost it.
   *  \return the mesh in the scan's frame (mm) */
  TriangleMesh
  fittedMesh () const;
};

/** \brief Where landmarks given to ScanRegistration::setLandmarks are: in the scan's own unit (as the points were
 *  given), or in mm (landmark files: loadLandmarks gives mm). */
enum class LandmarkUnit
{
  scan,
  millimetre
};

/** \brief Registers scans to one model with one set of settings: the sequence every front end runs. */
class ScanRegistration
{
public:
  using Icp = ScanRegistrationOutcome::Icp; ///< the registration the pipeline runs

  /** \param[in] model the model to fit (mm); InvalidInputError if null
   *  \param[in] settings the registration settings (checked: requireValidSettings) */
  explicit ScanRegistration (MorphableModel::ConstPtr model, const RegistrationSettings& settings = {});

  /** \brief Landmarks on the scans to start from (and, with settings.landmark_weight, to fit); those the model
   *  lacks are named in a warning and skipped; InvalidInputError naming \a source when none is left.
   *  \param[in] landmarks the landmarks by id
   *  \param[in] source their name for messages (the landmark file)
   *  \param[in] unit the unit they are in */
  void
  setLandmarks (LandmarkPositions landmarks, const std::string& source, LandmarkUnit unit);

  /** \brief Who hears of progress, units and warnings.
   *  \param[in] observer the observer (not owned; nullptr: nobody) */
  void
  setObserver (RegistrationObserver* observer);

  /** \brief Registers \a scan: brought to mm (scan.unit, else settings.units; "auto" guesses the unit from its
   *  size, and estimates the scale of a scan in no unit, or of one whose fit at the guessed unit found no
   *  plausible head, from the head itself, see head_scale_unit.h), then fitted. Throws InvalidInputError naming the
   *  scan when it cannot be registered (no head found to estimate its scale; landmarks off the scan).
   *  \param[in] scan the scan (see scan_input.h)
   *  \return the fit, or why it lost the scan */
  ScanRegistrationOutcome
  registerScan (const ScanInput& scan) const;

  /** \brief The report of \a outcome as `morphreg register` writes it (status, checks, similarity, shape,
   *  residuals, coverage, iterations, scan and its unit, settings), without the names of files, which front ends
   *  add. A lost fit's report has status "failed" and its reason as the one failed check.
   *  \param[in] outcome a fit of registerScan
   *  \return the JSON report */
  nlohmann::json
  report (const ScanRegistrationOutcome& outcome) const;

  /** \brief The model fitted.
   *  \return the model */
  const MorphableModel::ConstPtr&
  model () const
  {
    return model_;
  }

  /** \brief The settings of the fits.
   *  \return the settings */
  const RegistrationSettings&
  settings () const
  {
    return settings_;
  }

private:
  ScanRegistrationOutcome
  fitAt (const ScanInput& as_given, const LengthUnitGuess& unit) const;

  ScanRegistrationOutcome
  fitAtHeadScale (const ScanInput& as_given, ScanRegistrationOutcome suggested) const;

  bool
  needsHeadScale (const ScanInput& scan, const ScanRegistrationOutcome& fit) const;

  LandmarkPositions
  landmarksOn (const ScanInput& scan_mm, const LengthUnitGuess& unit) const;

  void
  runFit (Icp& icp, const std::string& scan_name) const;

  /** setObserver's observer, or one that does nothing. */
  RegistrationObserver&
  observer () const;

  MorphableModel::ConstPtr model_;
  RegistrationSettings settings_;
  LandmarkPositions landmarks_;
  std::string landmark_source_;
  LandmarkUnit landmark_unit_ = LandmarkUnit::millimetre;
  RegistrationObserver* observer_ = nullptr;
};

} // namespace morphreg
