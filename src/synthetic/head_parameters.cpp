// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/synthetic/head_parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace morphreg
{
namespace synthetic
{
namespace
{
HeadParameters::Range
makeRange (const char* name, double HeadParameters::*member, double stddev)
{
  const double mean = HeadParameters ().*member;
  return {name, member, mean, stddev, mean - 2.5 * stddev, mean + 2.5 * stddev};
}

/** Lengths share a common size factor; amplitudes and offsets vary independently. */
bool
isSizeLike (const std::string& name)
{
  static const char* sized[] = {"head_length", "head_breadth", "head_height",    "face_width", "jaw_width",
                                "nose_length", "mouth_width",  "eye_separation", "ear_length", "neck_girth"};
  return std::find (std::begin (sized), std::end (sized), name) != std::end (sized);
}
} // namespace

const std::vector<HeadParameters::Range>&
HeadParameters::ranges ()
{
  using P = HeadParameters;
  static const std::vector<Range> table = {makeRange ("head_length", &P::head_length, 7.0),
                                           makeRange ("head_breadth", &P::head_breadth, 6.0),
                                           makeRange ("head_height", &P::head_height, 9.0),
                                           makeRange ("face_width", &P::face_width, 6.0),
                                           makeRange ("jaw_width", &P::jaw_width, 6.0),
                                           makeRange ("nose_length", &P::nose_length, 4.0),
                                           makeRange ("nose_width", &P::nose_width, 3.0),
                                           makeRange ("nose_projection", &P::nose_projection, 2.5),
                                           makeRange ("mouth_width", &P::mouth_width, 4.0),
                                           makeRange ("lip_thickness", &P::lip_thickness, 1.8),
                                           makeRange ("chin_projection", &P::chin_projection, 2.5),
                                           makeRange ("eye_separation", &P::eye_separation, 3.0),
                                           makeRange ("eye_depth", &P::eye_depth, 1.5),
                                           makeRange ("brow_ridge", &P::brow_ridge, 1.6),
                                           makeRange ("cheek_fullness", &P::cheek_fullness, 1.6),
                                           makeRange ("ear_length", &P::ear_length, 4.0),
                                           makeRange ("ear_protrusion", &P::ear_protrusion, 4.0),
                                           makeRange ("ear_height", &P::ear_height, 4.0),
                                           makeRange ("neck_girth", &P::neck_girth, 25.0),
                                           makeRange ("neck_length", &P::neck_length, 8.0)};
  return table;
}

HeadParameters
HeadParameters::sample (std::mt19937_64& rng)
{
  std::normal_distribution<double> normal (0.0, 1.0);
  const double size = normal (rng);
  HeadParameters p;
  for (const auto& range : ranges ()) {
    const double z = isSizeLike (range.name) ? std::sqrt (0.5) * (size + normal (rng)) : normal (rng);
    p.*range.member = std::clamp (range.mean + range.stddev * z, range.min, range.max);
  }
  return p;
}

std::vector<double>
HeadParameters::asVector () const
{
  std::vector<double> values;
  for (const auto& range : ranges ())
    values.push_back (this->*range.member);
  return values;
}

void
HeadParameters::validate () const
{
  for (const auto& range : ranges ()) {
    const double value = this->*range.member;
    if (!std::isfinite (value) || value < range.min - 1e-9 || value > range.max + 1e-9) {
      std::ostringstream msg;
      msg << "HeadParameters: " << range.name << " = " << value << " mm is outside its range [" << range.min << ", "
          << range.max << "]";
      throw InvalidInputError (msg.str ());
    }
  }
}

} // namespace synthetic
} // namespace morphreg
