// SPDX-License-Identifier: BSD-3-Clause
// `morphreg fit-photos`: a head model fitted to photos (docs/method.md, "Fitting to photographs"): any number of
// `--view` photos with their landmarks, cameras and outlines, or the orthographic `--profile` and `--frontal` pair;
// written as PLY (coloured by the photos, or by the error against a known truth) with a JSON report.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "pipeline.h"
#include "provenance.h"
#include "table_options.h"

#include <morphreg/common/error.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/photo/photo_fit_options.h>
#include <morphreg/pipeline/photo_registration.h>

#include <chrono>
#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>

namespace morphreg
{
namespace tools
{
namespace
{
struct FitPhotosOptions : PhotoFitOptions
{
  std::string model, truth, report, shape_prior_text = "auto";
  PhotoSetFiles photos; ///< --view groups in order, or --profile, --frontal and --photo
  std::string out = "fitted.ply";
  double colour_max = 5.0;
  bool quiet = false;
};

/** The approach needs frontal landmarks: a pair without its frontal annotation fits only the profile. (The library
 *  refuses the other combinations as it reads the photos.) */
void
requirePhotoOptions (const FitPhotosOptions& options)
{
  if (options.photos.views.empty () && options.photos.frontal.empty () && options.approach != "profile")
    throw InvalidInputError ("fit-photos --approach " + options.approach +
                             " needs --frontal (the frontal landmarks); only --approach profile fits without them");
}

/** Says on stderr what the fit does and what it warns of. */
class ConsolePhotoObserver : public PhotoRegistrationObserver
{
public:
  explicit ConsolePhotoObserver (bool quiet) : quiet_ (quiet) {}

  void
  fitStarted (const std::string& model, const std::string& sources, const std::string& approach) override
  {
    if (!quiet_)
      std::cerr << "fitting " << model << " to " << sources << " (" << approach << ")\n";
  }

  void
  warning (const std::string& text) override
  {
    std::cerr << "fit-photos: warning: " << text << '\n';
  }

private:
  bool quiet_;
};

/** The fit's summary line on stdout, and a warning on stderr when a coefficient is implausibly large. */
void
printFitSummary (const FitPhotosOptions& options, const PhotoFit& fit)
{
  std::cout << "fit (" << options.approach
            << (fit.returned == options.approach || fit.returned == "tps_icp" ? std::string ()
                                                                              : ", returned the " + fit.returned +
                                                                                    " fit: no TPS-ICP round "
                                                                                    "lowered the image error")
            << "): " << fit.history.size () << " iterations, outline RMS " << fit.final_residuals.outline_rms
            << " mm over " << fit.final_residuals.outline_correspondences << " outline points";
  if (fit.final_residuals.landmark_rms > 0.0)
    std::cout << ", landmark RMS " << fit.final_residuals.landmark_rms << " mm";
  std::cout << "; lambda_2 " << fit.prior.weight << " (" << fit.prior.rule << "); largest coefficient "
            << fit.maxCoefficientSigma () << " standard deviations\n";
  if (fit.maxCoefficientSigma () > PhotoRegistration::kCoefficientWarningSigma)
    std::cerr << "fit-photos: warning: a shape coefficient is " << fit.maxCoefficientSigma ()
              << " standard deviations from the mean (beyond " << PhotoRegistration::kCoefficientWarningSigma
              << "): the head may be implausible; raise --shape-prior or --smoothness, or fit fewer --components\n";
}

/** Prints the fit's errors against the truth (added to the report). */
void
printTruthErrors (const nlohmann::json& report)
{
  const nlohmann::json& errors = report["truth_error_mm"];
  std::cout << "vertex RMS against the truth " << errors["file"].get<std::string> () << ": " << std::fixed
            << std::setprecision (3) << errors["rms"].get<double> () << " mm (max " << errors["max"].get<double> ()
            << ", width RMS " << errors["width_rms"].get<double> () << ")\n"
            << std::defaultfloat;
}

/** The run's inputs and outputs, checked before anything is read. */
OutputPlan
fitPhotosPlan (const FitPhotosOptions& options)
{
  OutputPlan plan;
  const PhotoSetFiles& photos = options.photos;
  for (const auto& [input, role] : {std::pair (options.model, "--model"), std::pair (photos.profile, "--profile"),
                                    std::pair (photos.frontal, "--frontal"), std::pair (photos.photo, "--photo"),
                                    std::pair (options.truth, "--truth")})
    plan.addInput (input, role);
  for (const PhotoViewFiles& view : photos.views)
    for (const std::string& input : {view.image, view.landmarks, view.camera, view.outline})
      plan.addInput (input, "--view");
  plan.addOutput (options.out, "--out");
  plan.addOptionalOutput (options.report, "--report");
  plan.check ();
  return plan;
}

void
runFitPhotos (const FitPhotosOptions& options)
{
  const auto start = std::chrono::steady_clock::now ();
  requirePhotoOptions (options);
  const OutputPlan plan = fitPhotosPlan (options);
  OutputTransaction outputs (plan.outputs ());
  PhotoRegistration registration (loadModelFile (options.model, std::cout), options.model, options);
  ConsolePhotoObserver observer (options.quiet);
  registration.setObserver (&observer);
  const PhotoSet photos = readPhotoSet (options.photos);
  PhotoRegistrationOutcome outcome = registration.fit (photos);
  printFitSummary (options, outcome.fit);
  const std::string colouring =
      writePhotoFitMesh (options.out, outcome.fit, photos, options.truth, options.colour_max, outcome.report);
  if (!options.truth.empty ())
    printTruthErrors (outcome.report);
  outcome.report["output"] = {{"mesh", options.out}, {"frame", "model, mm"}, {"colours", colouring}};
  outcome.report["seconds"] = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  if (!options.report.empty ())
    writeReport (options.report, outcome.report);
  outputs.commit ();
  std::cout << "wrote " << options.out << " (model frame, mm) "
            << (colouring == "none" ? "(no colours)"
                                    : meshContents (options.out, colouring,
                                                    options.truth.empty () ? "" : "error against the truth in mm"))
            << '\n';
}

/** Groups the --view, --landmarks, --camera and --outline values in the order given: each of the last three belongs
 *  to the --view before it. */
std::vector<PhotoViewFiles>
viewGroups (const CLI::App& command, const CLI::Option* view, const std::vector<const CLI::Option*>& parts)
{
  std::vector<PhotoViewFiles> groups;
  std::vector<size_t> used (4, 0);
  for (const CLI::Option* option : command.parse_order ()) {
    const auto part = std::find (parts.begin (), parts.end (), option) - parts.begin ();
    if (option != view && part == static_cast<long> (parts.size ()))
      continue;
    const std::string value = option->results ()[used[option == view ? 0 : part + 1]++];
    if (option == view) {
      groups.push_back ({value, "", "", ""});
      continue;
    }
    if (groups.empty ())
      throw InvalidInputError ("fit-photos " + option->get_name () + " " + value +
                               ": give it after the --view photo it belongs to");
    std::string& slot = part == 0   ? groups.back ().landmarks
                        : part == 1 ? groups.back ().camera
                                    : groups.back ().outline;
    if (!slot.empty ())
      throw InvalidInputError ("fit-photos: " + groups.back ().image + " has two " + option->get_name ());
    slot = value;
  }
  return groups;
}

/** Adds --view and the per-view --landmarks, --camera and --outline; returns what groups their values. */
std::function<std::vector<PhotoViewFiles> ()>
addViewOptions (CLI::App* command)
{
  const auto repeatable = [command] (const std::string& name, const std::string& help) {
    return command->add_option (name, help)->expected (1)->multi_option_policy (CLI::MultiOptionPolicy::TakeAll);
  };
  const CLI::Option* view = repeatable ("--view", "a photo (PNG/JPEG) to fit; repeat for more. The --landmarks, "
                                                  "--camera and --outline after it belong to it");
  const std::vector<const CLI::Option*> parts = {
      repeatable ("--landmarks", "the photo's landmarks (.json, .csv or .pts; ids of docs/landmarks.md or iBUG-68)"),
      repeatable ("--camera", "the photo's camera (JSON: K, R, t or P, or a list by image); estimated from the "
                              "landmarks when absent"),
      repeatable ("--outline", "the head's outline traced on the photo (JSON: outline, optional hairline)")};
  return [command, view, parts] () { return viewGroups (*command, view, parts); };
}

/** The photo fit's settings from the library's table (photo_fit_options.h); --shape-prior also takes auto. */
void
addFitSettingOptions (CLI::App* command, const std::shared_ptr<FitPhotosOptions>& options)
{
  for (const PhotoFitOption& option : photoFitOptionTable ()) {
    if (option.name != "shape_prior") {
      addTableOption<PhotoFitOptions> (command, *options, option);
      continue;
    }
    command->add_option ("--shape-prior", options->shape_prior_text, option.help)
        ->check (CLI::IsMember ({"auto"}) | nonNegative ())
        ->capture_default_str ();
  }
}
} // namespace

void
registerFitPhotosCommand (CLI::App& app)
{
  auto options = std::make_shared<FitPhotosOptions> ();
  CLI::App* command = app.add_subcommand (
      "fit-photos", "fit a head model to photos: --view photos with landmarks, or a profile and frontal photo");
  command->add_option ("-m,--model", options->model, "model file with a profile line and landmarks (HDF5)")
      ->required ();
  const auto view_groups = addViewOptions (command);
  command->add_option ("--profile", options->photos.profile, "profile annotation (JSON: silhouette, nose tip, pixels)");
  command->add_option ("--frontal", options->photos.frontal,
                       "frontal annotation (JSON: named landmarks, pixels); needed by --approach joint and tps");
  command->add_option ("--photo", options->photos.photo,
                       "frontal photo (PNG/JPEG) of --frontal: colour the head from it");
  command->add_option ("--truth", options->truth,
                       "true head and pose (JSON of `synth --photos`): report the fit's error, colour by it");
  addFitSettingOptions (command, options);
  command->add_option ("--colour-max", options->colour_max, "error (mm) at the top of the colour scale with --truth")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("-o,--out", options->out,
                    meshOutputHelp ("fitted head to write (model frame, mm); with --truth or --photo",
                                    "error against the truth, or the frontal photo", "with --truth, the error in mm"))
      ->capture_default_str ();
  command->add_option ("--report", options->report, "JSON report to write");
  command->add_flag ("-q,--quiet", options->quiet, "less output");
  command->callback ([options, view_groups] () {
    options->photos.views = view_groups ();
    if (options->shape_prior_text != "auto")
      options->shape_prior = std::stod (options->shape_prior_text);
    runFitPhotos (*options);
  });
}
} // namespace tools
} // namespace morphreg
