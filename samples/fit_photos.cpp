// SPDX-License-Identifier: BSD-3-Clause
// Fits a morphable head model to a profile photo (the silhouette) and a frontal photo (named landmarks) with
// PhotoFitting (docs/method.md, "Fitting to photographs": approach 1, "joint", or approach 2, "tps", on the
// orthographic pair), writes the fitted head as PLY and the fit's report as JSON.
//
//   sample_fit_photos [--profile side.json --frontal front.json --model model.h5 [--photo front.png]]
//                     [--approach joint|tps] [--out fitted.ply] [--report fit.json] [--scale 5] [--heads 30]
//
// Without annotation files it builds a model from --heads heads of the built-in synthetic population, photographs
// a head that is not among them (writing the annotations as side.json and front.json next to --out, in the
// format the options read), fits it, prints the error against that head's true shape and colours the PLY by that
// error (viridis, 0 to --scale mm); it also writes front.png, a checkerboard stand-in for the frontal photo. With
// files, the PLY is the fitted head in the model frame, coloured by the frontal photo (--photo, PNG or JPEG; grey
// where the camera does not see the head) or uncoloured.
#include "sample_heads.h"
#include "sample_options.h"

#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/photo/photo_texture.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/photo/photo_fitting.h>
#include <morphreg/synthetic/photo_simulator.h>
#include <morphreg/common/colour_map.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace
{
const char* const kUsage =
    "usage: sample_fit_photos [--profile SIDE.json --frontal FRONT.json --model MODEL.h5 [--photo FRONT.png]]\n"
    "                         [--approach joint|tps] [--out fitted.ply] [--report fit.json] [--scale MM] [--heads N]\n"
    "  without the files: a model of N synthetic heads (default 30) and photos of a head not among them\n";

/** A stand-in for a frontal photo: 40 px squares, light and dark. */
morphreg::RgbImage
checkerboard (int width, int height)
{
  morphreg::RgbImage image{width, height, std::vector<unsigned char> (3 * static_cast<size_t> (width) * height)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      std::fill_n (image.data.begin () + 3 * (static_cast<long> (y) * width + x), 3,
                   ((x / 40 + y / 40) % 2) ? 220 : 60);
  return image;
}

/** Approach 1 ("joint") or 2 ("tps") of \a fitting on the two annotation files. */
morphreg::PhotoFit
fitFiles (const morphreg::PhotoFitting& fitting, const std::string& approach, const std::string& side,
          const std::string& front)
{
  const morphreg::ProfileView profile = morphreg::loadProfileView (side);
  const morphreg::FrontalView frontal = morphreg::loadFrontalView (front);
  return approach == "tps" ? fitting.fitTpsIcp (profile, frontal) : fitting.fitJoint (profile, frontal);
}

/** Photographs an unseen head (a 6 degree nod), writes the annotations, fits them with \a approach and reports the
 *  error against the truth; returns the per-vertex error (mm) of \a fit.
 */
Eigen::VectorXd
fitSyntheticPhotos (const morphreg::synthetic::HeadGenerator& generator, int heads,
                    const morphreg::MorphableModel::ConstPtr& model, const std::filesystem::path& folder,
                    const std::string& approach, morphreg::PhotoFit& fit)
{
  const morphreg::synthetic::SyntheticHead head = generator.sample (1 + static_cast<std::uint64_t> (heads));
  morphreg::synthetic::PhotoSimulator::Parameters camera;
  camera.rotation = Eigen::AngleAxisd (6.0 * M_PI / 180.0, Eigen::Vector3d::UnitX ()).toRotationMatrix ();
  const morphreg::synthetic::SimulatedPhotos photos = morphreg::synthetic::PhotoSimulator (camera).photograph (
      head.mesh.vertices, morphreg::frontalLandmarks (generator.landmarks ()), generator.profileLine (), 7);
  const std::string side = (folder / "side.json").string (), front = (folder / "front.json").string ();
  morphreg::saveProfileView (side, photos.profile);
  morphreg::saveFrontalView (front, photos.frontal);
  morphreg::saveRgbImage ((folder / "front.png").string (), checkerboard (camera.width, camera.height));
  std::printf ("photos: %zu silhouette points in %s, %zu landmarks in %s\n", photos.profile.silhouette ().size (),
               side.c_str (), photos.frontal.landmarks ().size (), front.c_str ());

  morphreg::PhotoFitting fitting (model);
  // The simulator projects vertices for the outline landmarks (jaw, chin, neck): here they are fixed points.
  fitting.setOutlineLandmarks (morphreg::OutlineLandmarkMode::vertex);
  fit = fitFiles (fitting, approach, side, front);
  // The fitted head in the true head's frame: the known pose undone.
  const Eigen::Matrix3Xd back =
      photos.rotation.transpose () * (fit.image_mesh.vertices.colwise () - photos.translation) / photos.scale;
  const Eigen::VectorXd error = (back - head.mesh.vertices).colwise ().norm ().transpose ();
  const Eigen::VectorXd width_error = (back - head.mesh.vertices).row (0).cwiseAbs ().transpose ();
  std::printf ("error against the true head: RMS %.3f mm (max %.3f mm), width (x) RMS %.3f mm\n",
               std::sqrt (error.squaredNorm () / error.size ()), error.maxCoeff (),
               std::sqrt (width_error.squaredNorm () / width_error.size ()));
  std::printf ("scale: %.4f of the true one\n", fit.scale / photos.scale);
  return error;
}

void
fitPhotos (int argc, char** argv)
{
  const samples::Options options (argc, argv,
                                  {{"--profile", ""},
                                   {"--frontal", ""},
                                   {"--model", ""},
                                   {"--out", "fitted.ply"},
                                   {"--report", ""},
                                   {"--scale", "5"},
                                   {"--heads", "30"},
                                   {"--approach", "joint"},
                                   {"--photo", ""}});
  const std::string approach = options.text ("--approach");
  if (approach != "joint" && approach != "tps")
    throw samples::UsageError ("--approach is joint or tps, got '" + approach + "'");
  const bool from_files = !options.text ("--model").empty ();
  if (from_files != !options.text ("--profile").empty () || from_files != !options.text ("--frontal").empty ())
    throw samples::UsageError ("--profile, --frontal and --model go together");
  if (!from_files && !options.text ("--photo").empty ())
    throw samples::UsageError ("--photo goes with --profile, --frontal and --model");
  const int heads = options.integer ("--heads", 2);
  const double scale = options.number ("--scale");
  if (!(scale > 0.0))
    throw samples::UsageError ("--scale must be positive");
  const std::string out = options.text ("--out");
  const std::filesystem::path folder = std::filesystem::absolute (out).parent_path ();

  morphreg::PhotoFit fit;
  morphreg::VertexColours colours;
  if (from_files) {
    const morphreg::MorphableModel::ConstPtr model = morphreg::loadModel (options.text ("--model"));
    fit = fitFiles (morphreg::PhotoFitting (model), approach, options.text ("--profile"), options.text ("--frontal"));
    if (!options.text ("--photo").empty ()) {
      const morphreg::VertexTexture texture = morphreg::frontalTexture (
          fit.image_mesh, morphreg::loadFrontalView (options.text ("--frontal")).normalisation (),
          morphreg::loadRgbImage (options.text ("--photo")));
      std::printf ("texture: %d of %ld vertices seen in %s\n", texture.visibleCount (),
                   static_cast<long> (fit.image_mesh.numVertices ()), options.text ("--photo").c_str ());
      colours = texture.colours;
    }
  }
  else {
    const morphreg::synthetic::HeadGenerator generator;
    const morphreg::MorphableModel::ConstPtr model = samples::buildHeadModel (generator, heads, 10);
    std::printf ("model: %d heads, %ld vertices, %d regions\n", heads, static_cast<long> (model->numVertices ()),
                 model->numRegions ());
    colours = morphreg::residualColours (fitSyntheticPhotos (generator, heads, model, folder, approach, fit), scale);
  }
  const morphreg::PhotoFitIteration& final_residuals = fit.final_residuals;
  std::printf ("fit (%s): %zu iterations; outline RMS %.3f mm over %d outline points, landmark RMS %.3f mm; "
               "lambda_2 %.3f (%s)\n",
               approach.c_str (), fit.history.size (), final_residuals.outline_rms,
               final_residuals.outline_correspondences, final_residuals.landmark_rms, fit.prior.weight,
               fit.prior.rule.c_str ());
  if (colours.size () > 0) {
    morphreg::savePolygonMesh (out, morphreg::toPolygonMesh (fit.model_mesh, colours));
    if (from_files)
      std::printf ("wrote %s (model frame, mm; vertex colours from the frontal photo)\n", out.c_str ());
    else
      std::printf ("wrote %s (model frame, mm; vertex colours: error 0-%g mm)\n", out.c_str (), scale);
  }
  else {
    morphreg::saveTriangleMesh (out, fit.model_mesh);
    std::printf ("wrote %s (model frame, mm)\n", out.c_str ());
  }
  if (!options.text ("--report").empty ()) {
    morphreg::savePhotoFitReport (options.text ("--report"), fit);
    std::printf ("wrote %s\n", options.text ("--report").c_str ());
  }
}
} // namespace

int
main (int argc, char** argv)
{
  return samples::run (argc, argv, kUsage, fitPhotos);
}
