// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>
#include <morphreg/photo/frontal_view.h>

namespace morphreg
{
FrontalView::FrontalView (int width, int height, LandmarkPixels landmarks, const std::string& source)
  : normalisation_ (width, height, noseTip (landmarks, source), source), landmarks_ (std::move (landmarks))
{
  for (const auto& landmark : landmarks_) {
    requireKnownLandmarkId (landmark.first, source);
    requireFinitePixel (landmark.second, source + ": landmark '" + landmark.first + "'");
  }
}

Eigen::Vector2d
FrontalView::noseTip (const LandmarkPixels& landmarks, const std::string& source)
{
  for (const std::string& id : {std::string ("nose_tip"), ibug68LandmarkId (30)})
    if (const auto it = landmarks.find (id); it != landmarks.end ())
      return it->second;
  throw InvalidInputError (source + ": the frontal landmarks have no nose tip (nose_tip, or iBUG-68's point 30 as "
                                    "ibug68_30); it centres the normalised frame");
}

std::map<std::string, Eigen::Vector2d>
FrontalView::normalisedLandmarks () const
{
  std::map<std::string, Eigen::Vector2d> points;
  for (const auto& landmark : landmarks_)
    points[landmark.first] = normalisation_.normalise (landmark.second);
  return points;
}
} // namespace morphreg
