#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>

#include <algorithm>
#include <sstream>

namespace morphreg
{
namespace
{
std::vector<std::string>
makeKnownLandmarkIds ()
{
  std::vector<std::string> ids = {
      "right_eyebrow",      "right_eye_outer",   "right_eye_inner",    "left_eyebrow",
      "left_eye_outer",     "left_eye_inner",    "right_nose_wing",    "nose_tip",
      "left_nose_wing",     "right_mouth_corner", "left_mouth_corner", "upper_lip_center",
      "mouth_center",       "lower_lip_center",  "right_philtrum",     "left_philtrum",
      "right_lower_lip",    "left_lower_lip"};
  for (const char* side : {"right", "left"})
    for (const char* part : {"ear_attachment_top", "ear_top", "ear_middle", "earlobe", "earlobe_attachment"})
      ids.push_back (std::string (side) + "_" + part);
  const std::vector<std::string> rest = {
      "right_jaw",          "right_jaw_middle",  "right_chin",         "left_jaw",
      "left_jaw_middle",    "left_chin",         "right_neck_top",     "right_neck_contour",
      "left_neck_top",      "left_neck_contour", "right_head_contour", "left_head_contour",
      "nasion",             "chin",              "forehead",           "right_tragus",
      "left_tragus"};
  ids.insert (ids.end (), rest.begin (), rest.end ());
  return ids;
}
} // namespace

const std::vector<std::string>&
knownLandmarkIds ()
{
  static const std::vector<std::string> ids = makeKnownLandmarkIds ();
  return ids;
}

bool
isKnownLandmarkId (const std::string& id)
{
  const auto& ids = knownLandmarkIds ();
  return std::find (ids.begin (), ids.end (), id) != ids.end ();
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
  throw InvalidInputError (msg.str ());
}

std::vector<std::string>
frontalLandmarkIds ()
{
  const auto& ids = knownLandmarkIds ();
  return std::vector<std::string> (ids.begin (), ids.begin () + 40);
}

bool
isFrontalContourLandmarkId (const std::string& id)
{
  const auto& ids = knownLandmarkIds ();
  const auto contour_begin = ids.begin () + 28, contour_end = ids.begin () + 40; // LANDMARKS.md 29-40
  return id == "chin" || std::find (contour_begin, contour_end, id) != contour_end;
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

} // namespace morphreg
