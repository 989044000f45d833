// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/datasets/makehuman_bodies.h>

namespace morphreg
{
namespace
{
std::string
head (const std::string& bone)
{
  return bone + "____head";
}

std::string
tail (const std::string& bone)
{
  return bone + "____tail";
}

/** The bones of one side (".L" or ".R") from the clavicle to the hand and from the pelvis to the foot. */
std::vector<Bone>
sideBones (const std::string& side)
{
  const std::string arm = side == ".L" ? "left_arm" : "right_arm";
  const std::string thumb = tail ("finger1-3" + side), little = tail ("finger5-3" + side);
  const std::string hip_r = head ("upperleg01.R"), hip_l = head ("upperleg01.L");
  return {{"clavicle" + side, head ("clavicle" + side), head ("shoulder01" + side), "upper_body", "", ""},
          {"shoulder" + side, head ("shoulder01" + side), head ("upperarm01" + side), arm, "", ""},
          {"upperarm" + side, head ("upperarm01" + side), head ("lowerarm01" + side), arm, head ("upperarm01.R"),
           head ("upperarm01.L")},
          {"lowerarm" + side, head ("lowerarm01" + side), head ("wrist" + side), arm, thumb, little},
          {"hand" + side, head ("wrist" + side), tail ("finger3-3" + side), arm, thumb, little},
          {"pelvis" + side, head ("spine05"), head ("upperleg01" + side), "lower_body", "", ""},
          {"upperleg" + side, head ("upperleg01" + side), head ("lowerleg01" + side), "lower_body", hip_r, hip_l},
          {"lowerleg" + side, head ("lowerleg01" + side), head ("foot" + side), "lower_body", hip_r, hip_l},
          {"foot" + side, head ("foot" + side), tail ("foot" + side), "lower_body", tail ("toe1-2" + side),
           tail ("toe5-3" + side)}};
}
} // namespace

Skeleton
makeHumanSkeleton ()
{
  const std::vector<std::string> spine = {"spine05", "spine04", "spine03", "spine02", "spine01",
                                          "neck01",  "neck02",  "neck03",  "head"};
  std::vector<Bone> bones;
  for (std::size_t i = 0; i + 1 < spine.size (); ++i)
    bones.push_back ({spine[i], head (spine[i]), head (spine[i + 1]), i < 2 ? "lower_body" : "upper_body", "", ""});
  bones.push_back ({"head", head ("head"), tail ("head"), "upper_body", head ("eye.R"), head ("eye.L")});
  // Major joints between a bone's ends: they follow the skin, not either bone rigidly (a thigh's upperleg02 head moves
  // closer to the hip when seated), so no bone uses them.
  std::vector<std::string> intermediate = {tail ("jaw")};
  for (const std::string side : {".L", ".R"}) {
    for (Bone& bone : sideBones (side))
      bones.push_back (std::move (bone));
    for (const std::string bone : {"upperarm02", "lowerarm02", "upperleg02", "lowerleg02"})
      intermediate.push_back (head (bone + side));
    intermediate.push_back (tail ("wrist" + side));
  }
  return Skeleton (std::move (bones), std::move (intermediate));
}

} // namespace morphreg
