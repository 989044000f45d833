// SPDX-License-Identifier: BSD-3-Clause
// Approach 1 (docs/method.md, "One joint fit"): outlines, outline landmarks and landmarks of every photo in one
// Gauss-Newton.
#include <morphreg/photo/photo_fit_method.h>

namespace morphreg
{
namespace
{
class JointFitMethod : public PhotoFitMethod
{
public:
  std::string
  name () const override
  {
    return "joint";
  }

  PhotoRows
  rows () const override
  {
    return PhotoRows::all;
  }

  PhotoFit
  fit (MultiViewProblem& problem, const PoseShapeState& start) const override
  {
    problem.requireLandmarks ();
    return problem.stagedFit (start, PhotoRows::all, "joint");
  }
};
} // namespace

PhotoFitMethod::ConstPtr
makeJointFitMethod ()
{
  return std::make_shared<JointFitMethod> ();
}
} // namespace morphreg
