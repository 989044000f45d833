# SPDX-License-Identifier: BSD-3-Clause
# Writes the 51 major joints of one MakeHuman subject and pose as a landmark CSV (id,x,y,z) in MakeHuman's unit
# (decimetres; warp --units dm converts), for the command-line tests of warp --method articulated.
#   cmake -DBODIES=<makehuman_bodies folder> -DSUBJECT=<e.g. base or base_seated> -DOUT=<file.csv>
#         [-DCOINCIDE=<joint>,<other joint>] -P <this file>
# COINCIDE moves the second joint onto the first (a bad input: a bone of no length).
file(READ "${BODIES}/mh_landmark_sets.json" sets)
file(READ "${BODIES}/mh_joints.json" joints)
string(JSON count LENGTH "${sets}" major_joints)
math(EXPR last "${count} - 1")
set(lines "id,x,y,z\n")
set(moved "")
set(onto "")
if(COINCIDE)
  string(REPLACE "," ";" pair "${COINCIDE}")
  list(GET pair 0 onto)
  list(GET pair 1 moved)
endif()
foreach(i RANGE ${last})
  string(JSON name GET "${sets}" major_joints ${i})
  set(source "${name}")
  if(name STREQUAL moved)
    set(source "${onto}")
  endif()
  set(coordinates "")
  foreach(axis 0 1 2)
    string(JSON value GET "${joints}" subjects "${SUBJECT}" joints "${source}" ${axis})
    list(APPEND coordinates "${value}")
  endforeach()
  string(REPLACE ";" "," coordinates "${coordinates}")
  string(APPEND lines "${name},${coordinates}\n")
endforeach()
file(WRITE "${OUT}" "${lines}")
