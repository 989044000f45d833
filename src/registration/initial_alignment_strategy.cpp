// SPDX-License-Identifier: BSD-3-Clause
// The starts by name: the one place a new start is registered.
#include <morphreg/common/error.h>
#include <morphreg/registration/initial_alignment_strategy.h>
#include <morphreg/registration/starts/automatic_start.h>
#include <morphreg/registration/starts/coarse_start.h>
#include <morphreg/registration/starts/global_start.h>
#include <morphreg/registration/starts/guess_start.h>
#include <morphreg/registration/starts/landmark_start.h>

namespace morphreg
{
namespace
{
/** Every start, in the order settings list them. */
const std::vector<InitialAlignmentStrategy::ConstPtr>&
registry ()
{
  static const std::vector<InitialAlignmentStrategy::ConstPtr> starts = {
      std::make_shared<AutomaticStart> (), std::make_shared<GuessStart> (), std::make_shared<LandmarkStart> (),
      std::make_shared<CoarseStart> (), std::make_shared<GlobalStart> ()};
  return starts;
}
} // namespace

const std::vector<std::string>&
initialAlignmentNames ()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> listed;
    for (const auto& start : registry ())
      listed.push_back (start->name ());
    return listed;
  }();
  return names;
}

InitialAlignmentStrategy::ConstPtr
makeInitialAlignment (const std::string& name)
{
  for (const auto& start : registry ())
    if (start->name () == name)
      return start;
  std::string listed;
  for (const std::string& known : initialAlignmentNames ())
    listed += (listed.empty () ? "" : ", ") + known;
  throw InvalidInputError ("initial alignment \"" + name + "\" is none of " + listed);
}
} // namespace morphreg
