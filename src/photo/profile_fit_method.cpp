// SPDX-License-Identifier: BSD-3-Clause
// The profile fit (docs/method.md, "Profile fit"): the model's outline fitted to the traced outlines alone.
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_fit_method.h>

namespace morphreg
{
namespace
{
class ProfileFitMethod : public PhotoFitMethod
{
public:
  std::string
  name () const override
  {
    return "profile";
  }

  PhotoRows
  rows () const override
  {
    return PhotoRows::outlines;
  }

  PhotoFit
  fit (MultiViewProblem& problem, const PoseShapeState& start) const override
  {
    if (!problem.hasOutline ())
      throw InvalidInputError ("PhotoFitting: the profile fit needs a traced outline (a profile silhouette)");
    if (problem.settings ().sagittal_weight <= 0.0 && !problem.hasPerspectiveCamera ())
      throw InvalidInputError ("PhotoFitting: the profile fit's sagittal weight is 0, so nothing fixes X");
    return problem.stagedFit (start, PhotoRows::outlines, "profile");
  }
};
} // namespace

PhotoFitMethod::ConstPtr
makeProfileFitMethod ()
{
  return std::make_shared<ProfileFitMethod> ();
}
} // namespace morphreg
