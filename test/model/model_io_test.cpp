// SPDX-License-Identifier: BSD-3-Clause
#include "population.h"

#include <morphreg/common/error.h>
#include <morphreg/io/model_io.h>
#include <morphreg/model/model_builder.h>
#include "support/expect_error.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <map>

using morphreg::MorphableModel;

namespace
{
bool
fixtureAvailable ()
{
  static const bool available = std::system (MORPHREG_SYSTEM_PYTHON " -c 'import h5py, numpy' > /dev/null 2>&1") == 0;
  return available;
}

int
runFixture (const std::string& arguments)
{
  return std::system ((std::string (MORPHREG_SYSTEM_PYTHON " " MORPHREG_STATISMO_FIXTURE " ") + arguments).c_str ());
}

/** The files written by the independent h5py writer, once per test program. */
class StatismoFixtureFiles
{
public:
  StatismoFixtureFiles ()
  {
    ok_ = fixtureAvailable () && runFixture ("write " + directory_.file ("")) == 0;
  }

  bool
  ok () const
  {
    return ok_;
  }

  std::string
  file (const std::string& name) const
  {
    return directory_.file (name);
  }

private:
  morphreg::test::TempDirectory directory_;
  bool ok_ = false;
};

const StatismoFixtureFiles&
fixture ()
{
  static const StatismoFixtureFiles files;
  return files;
}

#define REQUIRE_FIXTURE()                                                                                              \
  if (!fixture ().ok ())                                                                                               \
  GTEST_SKIP () << "/usr/bin/python3 with h5py and numpy is needed for the independent HDF5 writer"

const MorphableModel&
builtModel ()
{
  static const MorphableModel::ConstPtr model = [] {
    morphreg::ModelBuilderSettings settings;
    settings.max_components = 6;
    auto built =
        morphreg::ModelBuilder (settings).build (morphreg::test::trainingMeshes (12), morphreg::test::headRegions ());
    built->setLandmarks (morphreg::test::coarseGenerator ().landmarks ());
    built->setProfileLine (morphreg::test::coarseGenerator ().profileLine ());
    built->setNoiseVariance (0.5);
    return built;
  }();
  return *model;
}

void
expectLoadFails (const std::string& name, const std::string& expected_text)
{
  try {
    morphreg::loadModel (fixture ().file (name));
    ADD_FAILURE () << name << ": expected a FormatError";
  }
  catch (const morphreg::FormatError& e) {
    const std::string message = e.what ();
    EXPECT_NE (message.find (name), std::string::npos) << message;
    EXPECT_NE (message.find (expected_text), std::string::npos) << message;
  }
}

void
expectMatchesExpected (const MorphableModel& model)
{
  std::ifstream stream (fixture ().file ("expected.json"));
  const nlohmann::json expected = nlohmann::json::parse (stream);
  ASSERT_EQ (model.numVertices (), 8);
  ASSERT_EQ (model.triangles ().cols (), 12);
  for (int t = 0; t < 12; ++t)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ (model.triangles () (c, t), expected["cells"][t][c].get<int> ());
  for (int i = 0; i < 24; ++i)
    EXPECT_NEAR (model.mean ()[i], expected["mean"][i].get<double> (), 1e-5);
  ASSERT_EQ (model.globalBasis ().cols (), 3);
  for (int i = 0; i < 24; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR (model.globalBasis () (i, k), expected["basis"][i][k].get<double> (), 1e-6);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR (model.globalVariances ()[k], expected["variances"][k].get<double> (), 1e-6);
  EXPECT_NEAR (model.noiseVariance (), 0.25, 1e-7);
  EXPECT_EQ (model.numRegions (), 1);
}
} // namespace

TEST (ModelIoTest, SaveLoadRoundTripIsExact)
{
  morphreg::test::TempDirectory directory;
  const std::string path = directory.file ("model.h5");
  const MorphableModel& model = builtModel ();
  morphreg::saveModel (path, model);
  const MorphableModel::Ptr loaded = morphreg::loadModel (path);
  ASSERT_EQ (loaded->numRegions (), model.numRegions ());
  EXPECT_EQ (loaded->mean (), model.mean ());
  EXPECT_EQ (loaded->triangles (), model.triangles ());
  for (int j = 0; j < model.numRegions (); ++j) {
    EXPECT_EQ (loaded->region (j).name, model.region (j).name);
    EXPECT_EQ (loaded->region (j).vertices, model.region (j).vertices);
    EXPECT_EQ (loaded->region (j).weights, model.region (j).weights);
    EXPECT_EQ (loaded->region (j).basis, model.region (j).basis);
    EXPECT_EQ (loaded->region (j).variances, model.region (j).variances);
  }
  EXPECT_EQ (loaded->landmarks (), model.landmarks ());
  EXPECT_EQ (loaded->profileLine (), model.profileLine ());
  std::map<std::string, std::string> metadata = loaded->metadata ();
  EXPECT_EQ (metadata[morphreg::kFileUnitsKey], "mm (the file's units)");
  metadata.erase (morphreg::kFileUnitsKey);
  EXPECT_EQ (metadata, model.metadata ());
  EXPECT_EQ (loaded->units (), model.units ());
  EXPECT_EQ (loaded->gammaPairs ().size (), model.gammaPairs ().size ());
  // The statismo part is float32 by the layout.
  EXPECT_LT ((loaded->globalBasis () - model.globalBasis ()).cwiseAbs ().maxCoeff (), 1e-6);
  EXPECT_LT ((loaded->globalVariances () - model.globalVariances ()).cwiseAbs ().maxCoeff (),
             1e-6 * model.globalVariances ()[0]);
  EXPECT_FLOAT_EQ (static_cast<float> (loaded->noiseVariance ()), 0.5f);
}

TEST (ModelIoTest, WrittenFileFollowsTheStatismoLayoutForAnIndependentReader)
{
  REQUIRE_FIXTURE ();
  morphreg::test::TempDirectory directory;
  const std::string path = directory.file ("model.h5");
  morphreg::saveModel (path, builtModel ());
  EXPECT_EQ (runFixture ("verify " + path), 0);
  // Read as a plain statismo model, the file gives the global PCA.
  const MorphableModel::Ptr global = morphreg::loadStatismoModel (path);
  EXPECT_EQ (global->numRegions (), 1);
  EXPECT_LT ((global->mean () - builtModel ().mean ()).cwiseAbs ().maxCoeff (), 1e-3);
}

TEST (ModelIoTest, LoadsFilesOfAnIndependentWriter)
{
  REQUIRE_FIXTURE ();
  expectMatchesExpected (*morphreg::loadModel (fixture ().file ("statismo_v09.h5")));
}

TEST (ModelIoTest, LoadsBaselFaceModel2017PrefixLayout)
{
  REQUIRE_FIXTURE ();
  expectMatchesExpected (*morphreg::loadModel (fixture ().file ("bfm2017_style.h5")));
  expectMatchesExpected (*morphreg::loadStatismoModel (fixture ().file ("bfm2017_style.h5"), "shape"));
}

TEST (ModelIoTest, TakesTheLandmarksOfABaselFaceModel2017File)
{
  REQUIRE_FIXTURE ();
  const auto model = morphreg::loadModel (fixture ().file ("bfm2017_style.h5"));
  const morphreg::LandmarkVertices expected = {{"nose_tip", 6}, {"left.ear.helix.top", 1}};
  EXPECT_EQ (model->landmarks (), expected) << "BFM ids translated where the project has one, nearest mean vertex";
  expectLoadFails ("bfm2017_bad_landmarks.h5",
                   "dataset 'metadata/landmarks/json': [0] ('center.nose.tip'): \"coordinates\" must be an array");
}

// A model file carries its unit: a morphreg file states it and is converted from it, a statismo file (which cannot
// state it) is recognised by its size; a unit that is none, or a size no unit makes a head, is refused.
TEST (ModelIoTest, ModelInCentimetresOrMetresIsRecognisedAndConverted)
{
  REQUIRE_FIXTURE ();
  const MorphableModel::Ptr mm = morphreg::loadModel (fixture ().file ("statismo_v09.h5"));
  EXPECT_EQ (mm->metadata ().at (morphreg::kFileUnitsKey).rfind ("mm (guessed from its size: ", 0), 0u)
      << mm->metadata ().at (morphreg::kFileUnitsKey);
  for (const auto& [name, unit] : {std::pair<std::string, std::string> ("statismo_centimetres.h5", "cm"),
                                   std::pair<std::string, std::string> ("statismo_metres.h5", "m")}) {
    const MorphableModel::Ptr model = morphreg::loadModel (fixture ().file (name));
    expectMatchesExpected (*model);
    EXPECT_EQ (model->units (), "mm");
    const std::string found = model->metadata ().at (morphreg::kFileUnitsKey);
    EXPECT_EQ (found.rfind (unit + " (guessed from its size: the mean's RMS radius is ", 0), 0u) << found;
    EXPECT_NE (found.find ("; converted to mm on loading"), std::string::npos) << found;
  }
  expectLoadFails ("statismo_micrometres.h5", "not a head model in any unit: the mean's RMS radius is 1.73e+05");
}

TEST (ModelIoTest, StatedUnitIsConvertedOrRefused)
{
  morphreg::test::TempDirectory directory;
  MorphableModel in_cm = builtModel ();
  in_cm.setUnits ("cm");
  morphreg::saveModel (directory.file ("cm.h5"), in_cm);
  const MorphableModel::Ptr loaded = morphreg::loadModel (directory.file ("cm.h5"));
  EXPECT_EQ (loaded->units (), "mm");
  EXPECT_EQ (loaded->metadata ().at (morphreg::kFileUnitsKey), "cm (the file's units); converted to mm on loading");
  EXPECT_TRUE (loaded->mean ().isApprox (10.0 * builtModel ().mean ()));
  EXPECT_TRUE (loaded->globalVariances ().isApprox (100.0 * builtModel ().globalVariances (), 1e-6));
  EXPECT_TRUE (loaded->region (0).variances.isApprox (100.0 * builtModel ().region (0).variances));
  EXPECT_NEAR (loaded->noiseVariance (), 50.0, 1e-5);

  MorphableModel in_furlongs = builtModel ();
  in_furlongs.setUnits ("furlong");
  morphreg::saveModel (directory.file ("furlong.h5"), in_furlongs);
  morphreg::test::expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::loadModel (directory.file ("furlong.h5")); }, "'furlong' is no length unit");
}

TEST (ModelIoTest, NormalisesTheScaledBasisOfStatismoVersion08)
{
  REQUIRE_FIXTURE ();
  expectMatchesExpected (*morphreg::loadModel (fixture ().file ("statismo_v08.h5")));
  expectLoadFails ("scaled_labelled_v09.h5", "orthonormal");
}

TEST (ModelIoTest, CorruptFilesGiveClearErrors)
{
  REQUIRE_FIXTURE ();
  expectLoadFails ("missing_variance.h5", "'model/pcaVariance': missing");
  expectLoadFails ("wrong_basis_dims.h5", "'model/pcaBasis': has dimensions [21, 3]");
  expectLoadFails ("nan_mean.h5", "'model/mean': element 0 is not finite");
  expectLoadFails ("bad_cell_index.h5", "'representer/cells': index 8");
  expectLoadFails ("wrong_points_rank.h5", "'representer/points': has 1 dimensions");
  expectLoadFails ("corrupt_string_heap.h5",
                   "'metadata/landmarks/json': variable-length string: its global heap collection is corrupt");
  expectLoadFails ("wrapping_points_dims.h5", "'representer/points': implausibly large [3, 6148914691236517206]");
  expectLoadFails ("truncated.h5", "not a readable HDF5 file");
  expectLoadFails ("not_hdf5.h5", "not a readable HDF5 file");
  EXPECT_THROW (morphreg::loadModel (fixture ().file ("does_not_exist.h5")), morphreg::IoError);
}

TEST (ModelIoTest, HandEditedRegionIsRejected)
{
  REQUIRE_FIXTURE ();
  morphreg::test::TempDirectory directory;
  morphreg::saveModel (directory.file ("model.h5"), builtModel ());
  ASSERT_EQ (runFixture ("break-region " + directory.file ("model.h5") + " " + directory.file ("broken.h5")), 0);
  try {
    morphreg::loadModel (directory.file ("broken.h5"));
    FAIL () << "expected a FormatError";
  }
  catch (const morphreg::FormatError& e) {
    const std::string message = e.what ();
    EXPECT_NE (message.find ("broken.h5"), std::string::npos) << message;
    EXPECT_NE (message.find ("morphreg/regions/region_0/vertices"), std::string::npos) << message;
  }
}

TEST (ModelIoTest, TruncatedOwnFileGivesAClearError)
{
  morphreg::test::TempDirectory directory;
  const std::string path = directory.file ("model.h5");
  morphreg::saveModel (path, builtModel ());
  std::ifstream in (path, std::ios::binary);
  const std::string bytes ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
  for (const double fraction : {0.1, 0.5, 0.9}) {
    std::ofstream (directory.file ("cut.h5"), std::ios::binary)
        .write (bytes.data (), static_cast<std::streamsize> (fraction * bytes.size ()));
    EXPECT_THROW (morphreg::loadModel (directory.file ("cut.h5")), morphreg::FormatError) << fraction;
  }
}
