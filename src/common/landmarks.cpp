// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

namespace morphreg
{
namespace
{
std::vector<std::string>
makeKnownLandmarkIds ()
{
  std::vector<std::string> ids = {"right_eyebrow",   "right_eye_outer",    "right_eye_inner",   "left_eyebrow",
                                  "left_eye_outer",  "left_eye_inner",     "right_nose_wing",   "nose_tip",
                                  "left_nose_wing",  "right_mouth_corner", "left_mouth_corner", "upper_lip_center",
                                  "mouth_center",    "lower_lip_center",   "right_philtrum",    "left_philtrum",
                                  "right_lower_lip", "left_lower_lip"};
  for (const char* side : {"right", "left"})
    for (const char* part : {"ear_attachment_top", "ear_top", "ear_middle", "earlobe", "earlobe_attachment"})
      ids.push_back (std::string (side) + "_" + part);
  const std::vector<std::string> rest = {"right_jaw",
                                         "right_jaw_middle",
                                         "right_chin",
                                         "left_jaw",
                                         "left_jaw_middle",
                                         "left_chin",
                                         "right_neck_top",
                                         "right_neck_contour",
                                         "left_neck_top",
                                         "left_neck_contour",
                                         "right_head_contour",
                                         "left_head_contour",
                                         "nasion",
                                         "chin",
                                         "forehead",
                                         "right_tragus",
                                         "left_tragus"};
  ids.insert (ids.end (), rest.begin (), rest.end ());
  return ids;
}

/** BFM-2017 landmark ids (metadata/landmarks/json) with a project equivalent. */
const std::map<std::string, std::string> kBfmLandmarkIds = {{"center.nose.tip", "nose_tip"},
                                                            {"center.chin.tip", "chin"},
                                                            {"left.eye.corner_outer", "left_eye_outer"},
                                                            {"left.eye.corner_inner", "left_eye_inner"},
                                                            {"right.eye.corner_outer", "right_eye_outer"},
                                                            {"right.eye.corner_inner", "right_eye_inner"},
                                                            {"left.lips.corner", "left_mouth_corner"},
                                                            {"right.lips.corner", "right_mouth_corner"},
                                                            {"left.nose.wing.tip", "left_nose_wing"},
                                                            {"right.nose.wing.tip", "right_nose_wing"},
                                                            {"center.lips.upper.outer", "upper_lip_center"},
                                                            {"center.lips.lower.outer", "lower_lip_center"}};
} // namespace

const std::vector<std::string>&
knownLandmarkIds ()
{
  static const std::vector<std::string> ids = makeKnownLandmarkIds ();
  return ids;
}

std::string
ibug68LandmarkId (int number)
{
  if (number < 0 || number >= 68)
    throw InvalidInputError ("iBUG-68 point number " + std::to_string (number) + " is outside 0-67");
  return (number < 10 ? "ibug68_0" : "ibug68_") + std::to_string (number);
}

const std::vector<std::string>&
ibug68LandmarkIds ()
{
  static const std::vector<std::string> ids = [] {
    std::vector<std::string> all;
    for (int k = 0; k < 68; ++k)
      all.push_back (ibug68LandmarkId (k));
    return all;
  }();
  return ids;
}

bool
isKnownLandmarkId (const std::string& id)
{
  for (const auto* ids : {&knownLandmarkIds (), &ibug68LandmarkIds ()})
    if (std::find (ids->begin (), ids->end (), id) != ids->end ())
      return true;
  return false;
}

std::string
fromBfmLandmarkId (const std::string& id)
{
  const auto it = kBfmLandmarkIds.find (id);
  return it == kBfmLandmarkIds.end () ? id : it->second;
}

void
requireKnownLandmarkId (const std::string& id, const std::string& source)
{
  if (isKnownLandmarkId (id))
    return;
  std::ostringstream msg;
  msg << source << ": unknown landmark id '" << id << "'; known ids are:";
  for (const auto& known : knownLandmarkIds ())
    msg << ' ' << known;
  msg << " and the iBUG-68 points ibug68_00 .. ibug68_67";
  throw InvalidInputError (msg.str ());
}

namespace
{
/** The diagonal of the bounding box of \a landmarks (0 for fewer than two). */
double
extentOf (const LandmarkPositions& landmarks)
{
  Eigen::Vector3d low = Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity ()), high = -low;
  for (const auto& entry : landmarks) {
    low = low.cwiseMin (entry.second);
    high = high.cwiseMax (entry.second);
  }
  return landmarks.size () < 2 ? 0.0 : (high - low).norm ();
}
} // namespace

void
requireOneTargetPerPoint (const LandmarkPositions& source, const LandmarkPositions& target,
                          const std::string& source_name, const std::string& target_name)
{
  const double source_tolerance = 1e-9 * extentOf (source), target_tolerance = 1e-9 * extentOf (target);
  for (auto a = source.begin (); a != source.end (); ++a)
    for (auto b = std::next (a); b != source.end (); ++b) {
      if ((a->second - b->second).norm () > source_tolerance || !target.count (a->first) || !target.count (b->first))
        continue;
      const double apart = (target.at (a->first) - target.at (b->first)).norm ();
      if (apart > target_tolerance) {
        std::ostringstream msg;
        msg << "landmarks " << a->first << " and " << b->first << " are at one position (" << a->second.x () << ", "
            << a->second.y () << ", " << a->second.z () << ") in " << source_name << " but " << apart << " mm apart in "
            << target_name << "; a warp cannot send one point to two places";
        throw InvalidInputError (msg.str ());
      }
    }
}

std::vector<std::string>
frontalLandmarkIds ()
{
  const auto& ids = knownLandmarkIds ();
  return std::vector<std::string> (ids.begin (), ids.begin () + 40);
}

bool
isOutlineLandmarkId (const std::string& id)
{
  const auto& ids = knownLandmarkIds ();
  const auto contour_begin = ids.begin () + 28, contour_end = ids.begin () + 40; // docs/landmarks.md 29-40
  const auto& ibug = ibug68LandmarkIds ();
  const auto jaw_end = ibug.begin () + 17; // iBUG-68 points 0-16: the jaw line
  return id == "chin" || std::find (contour_begin, contour_end, id) != contour_end ||
         std::find (ibug.begin (), jaw_end, id) != jaw_end;
}

LandmarkVertices
frontalLandmarks (const LandmarkVertices& landmarks)
{
  const std::vector<std::string> frontal = frontalLandmarkIds ();
  LandmarkVertices selected;
  for (const auto& landmark : landmarks)
    if (std::find (frontal.begin (), frontal.end (), landmark.first) != frontal.end ())
      selected.insert (landmark);
  return selected;
}

std::vector<std::string>
keepKnownLandmarks (LandmarkPositions& landmarks, const LandmarkVertices& known)
{
  std::vector<std::string> removed;
  for (auto it = landmarks.begin (); it != landmarks.end ();)
    if (known.count (it->first)) {
      ++it;
    }
    else {
      removed.push_back (it->first);
      it = landmarks.erase (it);
    }
  return removed;
}

} // namespace morphreg
