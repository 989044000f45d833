# SPDX-License-Identifier: BSD-3-Clause
# The bad-input catalogue (CliTest.BadInput.*): files and arguments a hostile or careless user gives each subcommand.
# Every case runs in its own folder with copies of its inputs (CASE_DIR of test/support/command_test.cmake) and asserts
# the exit code, that stderr names the file or option and the problem, that the inputs are unchanged and that no
# output, whole or partial, is left. It uses the small synthetic population and model of cli.cmake.
if(NOT TARGET morphreg_cli)
  return()
endif()
set(bad_dir ${CMAKE_CURRENT_BINARY_DIR}/cli_bad)
set(bad ${bad_dir}/inputs)
set(small ${CMAKE_CURRENT_BINARY_DIR}/cli/small)
set(small_model ${CMAKE_CURRENT_BINARY_DIR}/cli/small_model.h5)
file(MAKE_DIRECTORY ${bad})

# morphreg_bad_input(<name> <exit code> TEXT <parts>... [SETUP <op,src,dst[,n]>...] ARGS <arguments>...
#                    [WRAP <command prefix>...] [FORBID <regex>] [ENVIRONMENT <changes>...] [XVFB])
# "@CASE@" in SETUP, ARGS and TEXT is the case's folder; the small population and model are its fixtures.
function(morphreg_bad_input name code)
  cmake_parse_arguments(PARSE_ARGV 2 case "XVFB" "FORBID" "TEXT;SETUP;ARGS;WRAP;ENVIRONMENT")
  set(options "")
  if(case_XVFB)
    list(APPEND options XVFB)
  endif()
  if(case_ENVIRONMENT)
    list(APPEND options PROPERTIES ENVIRONMENT_MODIFICATION "${case_ENVIRONMENT}")
  endif()
  if(case_FORBID)
    list(APPEND options FORBID "${case_FORBID}")
  endif()
  morphreg_command_test(CliTest.BadInput.${name} EXPECT_CODE ${code} ERROR ${case_TEXT} CASE_DIR ${bad_dir}/${name}
    SETUP ${case_SETUP} FIXTURES_REQUIRED cli_small cli_model cli_bad_inputs TIMEOUT 120 ${options}
    COMMAND ${case_WRAP} $<TARGET_FILE:morphreg_cli> ${case_ARGS})
endfunction()

# The crafted binary files (corrupt models, photos whose headers lie): test/scripts/cli/make_bad_inputs.py.
find_package(Python3 COMPONENTS Interpreter)
morphreg_command_test(CliTest.BadInput.CraftedFilesMade FIXTURES_REQUIRED cli_model FIXTURES_SETUP cli_bad_inputs
  FILES ${bad}/model_mean_bit_flip.h5 ${bad}/huge.png ${bad}/huge.jpg
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/cli/make_bad_inputs.py ${small_model} ${bad})

# scan_grid_rows(<out> <odd> <odd row> <tail>): the 200 rows of a scan spread in 3D (a grid bent in depth), each ending
# with <tail> (e.g. normal components), row <odd> replaced by <odd row>; joined by newlines.
function(scan_grid_rows out odd odd_row tail)
  set(rows "")
  foreach(i RANGE 199)
    math(EXPR a "${i} % 20 * 5")
    math(EXPR b "${i} / 20 * 5")
    math(EXPR c "${i} * 7 % 13")
    if(i EQUAL odd)
      list(APPEND rows "${odd_row}")
    else()
      list(APPEND rows "${a} ${b} ${c}${tail}")
    endif()
  endforeach()
  list(JOIN rows "\n" joined)
  set(${out} "${joined}" PARENT_SCOPE)
endfunction()

# Inputs copied into the cases: the population's files and the model.
set(scan copy,${small}/scan_0.pcd,@CASE@/scan.pcd)
set(mesh copy,${small}/head_000.ply,@CASE@/head.ply)
set(mesh_1 copy,${small}/head_001.ply,@CASE@/head_1.ply)
set(model copy,${small_model},@CASE@/model.h5)
set(source copy,${small}/head_000_landmarks.json,@CASE@/source.json)
set(target copy,${small}/head_001_landmarks.json,@CASE@/target.json)
set(scan_landmarks copy,${small}/scan_0_landmarks.json,@CASE@/landmarks.json)
set(profile copy,${small}/photo_0_profile.json,@CASE@/profile.json)
set(frontal copy,${small}/photo_0_frontal.json,@CASE@/frontal.json)
function(bad_file name)
  list(JOIN ARGN "\n" content)
  file(WRITE ${bad}/${name} "${content}\n")
endfunction()
macro(given file)
  list(APPEND setup copy,${bad}/${file},@CASE@/${file})
endmacro()
set(register_args --model @CASE@/model.h5 --out @CASE@/fit.ply)

# --- Files that crashed PCL's or VTK's readers, or claim more than they hold -----------------------------------------
morphreg_bad_input(PlyNamedPcdAndCutShort 1 TEXT "scan.pcd" "PLY"
  SETUP head,${small}/head_000.ply,@CASE@/scan.pcd,3000 ${model} ARGS register --scan @CASE@/scan.pcd ${register_args})
morphreg_bad_input(RenderPlyNamedPcdAndCutShort 1 TEXT "scan.pcd" "PLY" XVFB
  SETUP head,${small}/head_000.ply,@CASE@/scan.pcd,3000 ${mesh}
  ARGS render --mesh @CASE@/head.ply --cloud @CASE@/scan.pcd --width 64 --height 64 --out @CASE@/render.png)
bad_file(short_vertex.obj "v 0 0 0" "v 1 0 0" "v 1 2" "f 1 2 3")
bad_file(face_out_of_range.obj "v 0 0 0" "v 1 0 0" "v 0 1 0" "f 1 2 9")
bad_file(not_a_number.obj "v 0 0 x" "v 1 0 0" "v 0 1 0" "f 1 2 3")
foreach(case "short_vertex;short_vertex.obj:3" "face_out_of_range;face_out_of_range.obj:4"
        "not_a_number;not_a_number.obj:1")
  list(GET case 0 kind)
  list(GET case 1 text)
  set(setup ${source} ${target})
  given(${kind}.obj)
  morphreg_bad_input(WarpObj_${kind} 1 TEXT "${text}" SETUP ${setup}
    ARGS warp --mesh @CASE@/${kind}.obj --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/warped.ply)
endforeach()
bad_file(huge.ply "ply" "format binary_little_endian 1.0" "element vertex 2000000000" "property float x"
         "property float y" "property float z" "end_header" "0123456789ab")
bad_file(huge.pcd "VERSION .7" "FIELDS x y z" "SIZE 4 4 4" "TYPE F F F" "COUNT 1 1 1" "WIDTH 2000000000" "HEIGHT 1"
         "VIEWPOINT 0 0 0 1 0 0 0" "POINTS 2000000000" "DATA binary" "0123456789ab")
bad_file(malformed.stl "solid s" "facet normal 0 0 1" "outer loop" "vertex 0 0 0" "vertex 1 0" "vertex 0 1 0"
         "endloop" "endfacet" "endsolid s")
bad_file(too_few_points.vtk "# vtk DataFile Version 3.0" "head" "ASCII" "DATASET POLYDATA" "POINTS 1000 float"
         "0 0 0 1 0 0 0 1 0" "POLYGONS 1 4" "3 0 1 2")
bad_file(bad_count.off "OFF" "3 1 0" "0 0 0" "1 0 0" "0 1 0" "3 0 1 7")
bad_file(garbage.ply "this is not a mesh" "at all")
bad_file(points.xyz "0 0 0" "1 0 0")
# Doubles are narrowed to float on loading (Open3D writes them); one beyond float's range is refused.
bad_file(double_beyond_float.ply "ply" "format ascii 1.0" "element vertex 3" "property double x" "property double y"
         "property double z" "end_header" "0 0 0" "1e39 0 0" "0 1 0")
file(WRITE ${bad}/empty.ply "")
foreach(case "huge.ply;huge.ply: ;2000000000" "huge.pcd;huge.pcd: ;2000000000" "malformed.stl;malformed.stl:5"
        "bad_count.off;bad_count.off:6" "garbage.ply;garbage.ply: "
        "empty.ply;empty.ply: ;empty" "points.xyz;points.xyz: ;unsupported"
        "double_beyond_float.ply;double_beyond_float.ply:9;not a finite number")
  list(GET case 0 file)
  list(SUBLIST case 1 -1 text)
  string(REPLACE "." "_" name ${file})
  set(setup ${model})
  given(${file})
  morphreg_bad_input(Scan_${name} 1 TEXT ${text} SETUP ${setup} ARGS register --scan @CASE@/${file} ${register_args})
endforeach()
# VTK files are meshes only (register takes no .vtk scan): warp reads this one.
morphreg_bad_input(WarpVtk_too_few_points 1 TEXT "too_few_points.vtk: " "header claims 1000 points"
  SETUP copy,${bad}/too_few_points.vtk,@CASE@/too_few_points.vtk ${source} ${target}
  ARGS warp --mesh @CASE@/too_few_points.vtk --source @CASE@/source.json --target @CASE@/target.json
       --out @CASE@/warped.ply)
morphreg_bad_input(ScanBinaryPlyCutShort 1 TEXT "cut.ply: "
  SETUP head,${small}/head_000.ply,@CASE@/cut.ply,20000 ${model} ARGS register --scan @CASE@/cut.ply ${register_args})
morphreg_bad_input(ScanBinaryPcdCutShort 1 TEXT "cut.pcd: "
  SETUP head,${small}/scan_0.pcd,@CASE@/cut.pcd,20000 ${model} ARGS register --scan @CASE@/cut.pcd ${register_args})
morphreg_bad_input(ScanIsAFolder 1 TEXT "${bad}: is a directory" SETUP ${model} ARGS register --scan ${bad} ${register_args})
morphreg_bad_input(ScanMissing 1 TEXT "missing.ply: no such file" SETUP ${model}
  ARGS register --scan @CASE@/missing.ply ${register_args})

# --- Broken glTF files, written by the tests' glTF writer (gltf_test_files, test/scripts/gltf.cmake) ------------------
set(gltf_bad ${CMAKE_CURRENT_BINARY_DIR}/cli/gltf)
foreach(case "cut.glb;the GLB header gives a length of" "magic.glb;not a GLB file: it does not start with the magic bytes"
        "chunk_past_end.glb;the JSON chunk claims" "accessor_out_of_range.glb;POSITION: the accessor claims 5000000 elements"
        "index_out_of_range.glb;index 7 is 100000, beyond the primitive's 121 vertices"
        "bad_draco.glb;bad Draco payload: it cannot be decoded"
        "missing_buffer.gltf;buffer 0: its file 'missing_buffer.bin' does not exist"
        "absurd_counts.gltf;POSITION: the accessor claims 1000000000000000 elements")
  list(GET case 0 file)
  list(GET case 1 text)
  string(REPLACE "." "_" name ${file})
  morphreg_bad_input(Gltf_${name} 1 TEXT "${file}: " "${text}" SETUP copy,${gltf_bad}/${file},@CASE@/${file} ${model}
    ARGS register --scan @CASE@/${file} ${register_args})
  set_property(TEST CliTest.BadInput.Gltf_${name} APPEND PROPERTY FIXTURES_REQUIRED cli_gltf)
endforeach()
morphreg_bad_input(RenderGltfCut 1 TEXT "cut.glb: " "the GLB header gives a length of" XVFB
  SETUP copy,${gltf_bad}/cut.glb,@CASE@/cut.glb
  ARGS render --mesh @CASE@/cut.glb --width 64 --height 64 --out @CASE@/render.png)
morphreg_bad_input(ResampleGltfBadDraco 1 TEXT "bad_draco.glb: " "bad Draco payload" SETUP copy,${gltf_bad}/bad_draco.glb,@CASE@/bad_draco.glb ${model}
  ARGS resample --scan @CASE@/bad_draco.glb --model @CASE@/model.h5 --out @CASE@/resampled.ply)
set_property(TEST CliTest.BadInput.RenderGltfCut CliTest.BadInput.ResampleGltfBadDraco APPEND PROPERTY
             FIXTURES_REQUIRED cli_gltf)

# --- Scans that cannot be registered (degenerate geometry) ------------------------------------------------------------
set(one "1 2 3")
set(three "0 0 0" "10 0 0" "0 10 5")
set(few "")
set(flat "")
set(line "")
set(same "")
set(nan "")
set(inf "")
set(enormous "")
set(speck "") # a bent sheet 0.01 units across: a head in no unit, and no head when brought to a head's size
foreach(i RANGE 199)
  math(EXPR a "${i} % 20 * 5")
  math(EXPR b "${i} / 20 * 5")
  math(EXPR c "${i} * 7 % 13")
  math(EXPR d "2 * ${i}")
  math(EXPR e "3 * ${i}")
  if(i LESS 50)
    list(APPEND few "${a} ${b} ${c}")
  endif()
  list(APPEND line "${i} ${d} ${e}")
  list(APPEND flat "${a} ${b} 0")
  list(APPEND same "1 2 3")
  list(APPEND nan "nan nan nan")
  list(APPEND enormous "${a}e30 ${b}e30 ${c}e30")
  list(APPEND speck "${a}e-4 ${b}e-4 ${c}e-4")
  if(i EQUAL 17)
    list(APPEND inf "inf 0 1")
  else()
    list(APPEND inf "${a} ${b} ${c}")
  endif()
endforeach()
foreach(case "one;1 point" "three;3 points" "few;50 points, at least 100" "flat;the 200 points lie in a plane"
        "line;the 200 points are collinear" "same;all 200 points are identical"
        "nan;the scan has no valid (finite) points" "inf;point 17 is not finite (inf, 0, 1)"
        "enormous;no head in any unit" "speck;no head found, so its unit cannot be estimated")
  list(GET case 0 kind)
  list(GET case 1 text)
  list(LENGTH ${kind} count)
  list(JOIN ${kind} "\n" body)
  file(WRITE ${bad}/scan_${kind}.pcd "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH ${count}\n"
             "HEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS ${count}\nDATA ascii\n${body}\n")
  set(setup ${model})
  given(scan_${kind}.pcd)
  morphreg_bad_input(DegenerateScan_${kind} 1 TEXT "scan_${kind}.pcd: " "${text}" SETUP ${setup}
    ARGS register --scan @CASE@/scan_${kind}.pcd ${register_args})
endforeach()

# --- Model files ------------------------------------------------------------------------------------------------------
morphreg_bad_input(ModelIsAMesh 1 TEXT "model.h5: " SETUP ${scan} copy,${small}/head_000.ply,@CASE@/model.h5
  ARGS register --scan @CASE@/scan.pcd ${register_args})
morphreg_bad_input(ModelCutShort 1 TEXT "model.h5: " SETUP ${scan} head,${small_model},@CASE@/model.h5,4096
  ARGS register --scan @CASE@/scan.pcd ${register_args})
morphreg_bad_input(ModelMissing 1 TEXT "missing.h5: no such file" SETUP ${scan}
  ARGS register --scan @CASE@/scan.pcd --model @CASE@/missing.h5 --out @CASE@/fit.ply)

# --- Landmark files ---------------------------------------------------------------------------------------------------
# (JSON written as one argument: CMake does not split a list inside unbalanced square brackets)
bad_file(metres.json "{\"units\": \"m\", \"landmarks\": [{\"id\": \"nose_tip\", \"position\": [0, 30, 110]}, {\"id\": \"right_eye_outer\", \"position\": [-45, 60, 70]}, {\"id\": \"left_eye_outer\", \"position\": [45, 60, 70]}, {\"id\": \"chin\", \"position\": [0, -40, 95]}]}")
bad_file(malformed.json "{\"landmarks\": [{\"id\": \"nose_tip\", \"position\": [0, 30")
bad_file(wrong_columns.csv "id,x,y,z" "nose_tip,1,2" "chin,0,-40,95")
bad_file(malformed.pp "<!DOCTYPE PickedPoints>" "<PickedPoints>" "<point x=\"1\" y=\"2\" name=\"nose_tip\"/>"
         "<point x=\"abc\" y=\"2\" z=\"3\" name=\"chin\"/>" "</PickedPoints>")
bad_file(not_finite.json "{\"landmarks\": [{\"id\": \"nose_tip\", \"position\": [0, \"nan\", 110]}]}")
bad_file(duplicate.csv "id,x,y,z" "nose_tip,0,30,110" "chin,0,-40,95" "nose_tip,1,31,111")
foreach(case "metres.json;metres.json: ;units" "malformed.json;malformed.json: " "wrong_columns.csv;wrong_columns.csv:2"
        "malformed.pp;malformed.pp" "not_finite.json;not_finite.json: " "duplicate.csv;duplicate.csv:4;nose_tip")
  list(GET case 0 file)
  list(SUBLIST case 1 -1 text)
  string(REPLACE "." "_" name ${file})
  set(setup ${scan} ${model})
  given(${file})
  morphreg_bad_input(Landmarks_${name} 1 TEXT ${text} SETUP ${setup}
    ARGS register --scan @CASE@/scan.pcd --landmarks @CASE@/${file} ${register_args})
endforeach()
# TPS landmark pairs: two landmarks at one place sent to two places, no landmark in common, all on one line.
bad_file(coincident.csv "id,x,y,z" "nose_tip,0,30,110" "chin,0,-40,95" "right_eye_outer,-45,60,70"
         "left_eye_outer,45,60,70" "right_eyebrow,0,30,110")
bad_file(coincident_target.csv "id,x,y,z" "nose_tip,0,30,110" "chin,0,-40,95" "right_eye_outer,-45,60,70"
         "left_eye_outer,45,60,70" "right_eyebrow,-30,70,80")
bad_file(other_ids.csv "id,x,y,z" "a,0,30,110" "b,0,-40,95" "c,-45,60,70" "d,45,60,70")
bad_file(collinear.csv "id,x,y,z" "nose_tip,0,0,0" "chin,0,10,0" "right_eye_outer,0,20,0" "left_eye_outer,0,30,0"
         "right_eyebrow,0,40,0")
foreach(case "coincident;coincident_target.csv;nose_tip;right_eyebrow;one position"
        "other_ids;target.json;other_ids.csv;not in both" "collinear;collinear.csv;collinear.csv")
  list(GET case 0 kind)
  list(GET case 1 target_file)
  list(SUBLIST case 2 -1 text)
  set(setup ${mesh})
  given(${kind}.csv)
  if(target_file STREQUAL "target.json")
    list(APPEND setup ${target})
  elseif(NOT target_file STREQUAL "${kind}.csv")
    given(${target_file})
  endif()
  morphreg_bad_input(WarpLandmarks_${kind} 1 TEXT ${text} SETUP ${setup}
    ARGS warp --mesh @CASE@/head.ply --source @CASE@/${kind}.csv --target @CASE@/${target_file} --out @CASE@/warped.ply)
  # The same landmark pairs for the moving least squares warp, whose own check names it.
  if(kind STREQUAL "collinear")
    list(APPEND text "moving least squares warp needs landmarks that span 3D")
  endif()
  morphreg_bad_input(WarpLandmarksMls_${kind} 1 TEXT ${text} SETUP ${setup}
    ARGS warp --method mls --mesh @CASE@/head.ply --source @CASE@/${kind}.csv --target @CASE@/${target_file}
         --out @CASE@/warped.ply)
endforeach()

# --- Photo annotations ------------------------------------------------------------------------------------------------
bad_file(tiny_silhouette.json "{\"view\": \"profile\", \"image\": {\"width\": 1000, \"height\": 1200}, \"units\": \"px\", \"nose_tip\": [649, 600], \"silhouette\": [[641, 608], [642, 605], [643, 603], [644, 601], [645, 600], [646, 599], [647, 598], [648, 598], [649, 599], [648, 601], [647, 603], [646, 605]]}")
bad_file(malformed_profile.json "{\"view\": \"profile\", \"image\": {\"width\": 1000")
bad_file(negative_size.json "{\"view\": \"profile\", \"image\": {\"width\": -1000, \"height\": 1200}, \"units\": \"px\","
         "\"nose_tip\": [649, 600], \"silhouette\": [[641, 608], [642, 605], [643, 603]]}")
foreach(case "tiny_silhouette;tiny_silhouette.json;check that the outline traces" "malformed_profile;malformed_profile.json: "
        "negative_size;negative_size.json: ;image size -1000 x 1200 px must be positive")
  list(GET case 0 kind)
  list(SUBLIST case 1 -1 text)
  set(setup ${model} ${frontal})
  given(${kind}.json)
  morphreg_bad_input(FitPhotos_${kind} 1 TEXT ${text} SETUP ${setup}
    ARGS fit-photos --model @CASE@/model.h5 --profile @CASE@/${kind}.json --frontal @CASE@/frontal.json
         --out @CASE@/photos.ply)
endforeach()

# --- Outputs: never onto an input, checked before any work, nothing partial left on failure ---------------------------
morphreg_bad_input(RegisterOutIsTheScan 1 TEXT "head.ply" "input" SETUP ${mesh} ${model}
  ARGS register --scan @CASE@/head.ply --model @CASE@/model.h5 --out @CASE@/head.ply)
morphreg_bad_input(RegisterReportIsTheLandmarks 1 TEXT "landmarks.json" "input" SETUP ${scan} ${model} ${scan_landmarks}
  ARGS register --scan @CASE@/scan.pcd --landmarks @CASE@/landmarks.json --report @CASE@/landmarks.json ${register_args})
morphreg_bad_input(WarpOutIsTheMesh 1 TEXT "head.ply" "input" SETUP ${mesh} ${source} ${target}
  ARGS warp --mesh @CASE@/head.ply --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/head.ply)
morphreg_bad_input(BuildModelOutIsAMesh 1 TEXT "head.ply" "input" SETUP ${mesh} ${mesh_1}
  ARGS build-model --mesh @CASE@/head.ply --mesh @CASE@/head_1.ply --out @CASE@/head.ply)
morphreg_bad_input(FitPhotosReportIsTheFrontal 1 TEXT "frontal.json" "input" SETUP ${model} ${profile} ${frontal}
  ARGS fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json
       --report @CASE@/frontal.json --out @CASE@/photos.ply)
morphreg_bad_input(RenderOutIsTheMesh 1 TEXT "head.ply" "input" SETUP ${mesh} XVFB
  ARGS render --mesh @CASE@/head.ply --width 64 --height 64 --out @CASE@/head.ply)
morphreg_bad_input(SynthOutIsAFile 1 TEXT "head.ply: exists and is not a folder" SETUP ${mesh}
  ARGS synth --count 1 --resolution 20 --quiet --out-dir @CASE@/head.ply)
morphreg_bad_input(RegisterOutFolderMissing 1 TEXT "@CASE@/no_such_folder" SETUP ${scan} ${model} FORBID "registering"
  ARGS register --scan @CASE@/scan.pcd --model @CASE@/model.h5 --out @CASE@/no_such_folder/fit.ply)
morphreg_bad_input(RegisterOutUnderAFile 1 TEXT "scan.pcd" SETUP ${scan} ${model} FORBID "registering"
  ARGS register --scan @CASE@/scan.pcd --model @CASE@/model.h5 --out @CASE@/scan.pcd/fit.ply)
morphreg_bad_input(RegisterScreenshotFailsLeavesNoFit 1 TEXT "xvfb-run" SETUP ${scan} ${model}
  ENVIRONMENT "DISPLAY=unset:" ARGS register --scan @CASE@/scan.pcd --screenshot @CASE@/fit.png ${register_args})
# A full disk: a 2000-byte limit on the size of any file written (RLIMIT_FSIZE).
set(full_disk WRAP prlimit --fsize=2000 --)
morphreg_bad_input(RegisterDiskFull 1 TEXT "fit.ply" SETUP ${scan} ${model} ${full_disk}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --iterations 3)
morphreg_bad_input(WarpDiskFull 1 TEXT "warped.ply" SETUP ${mesh} ${source} ${target} ${full_disk}
  ARGS warp --mesh @CASE@/head.ply --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/warped.ply)
morphreg_bad_input(FitPhotosDiskFull 1 TEXT "photos.ply" SETUP ${model} ${profile} ${frontal} ${full_disk}
  ARGS fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json
       --out @CASE@/photos.ply)
morphreg_bad_input(BuildModelDiskFull 1 TEXT "model_out.h5" SETUP ${mesh} ${mesh_1} ${full_disk}
  ARGS build-model --mesh @CASE@/head.ply --mesh @CASE@/head_1.ply --out @CASE@/model_out.h5)
morphreg_bad_input(SynthDiskFull 1 TEXT "synth/" ${full_disk}
  ARGS synth --count 2 --resolution 20 --quiet --out-dir @CASE@/synth)

# --- Options out of range ---------------------------------------------------------------------------------------------
morphreg_bad_input(ComponentsNegative 2 TEXT "--components" SETUP ${scan} ${model}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --components -1)
morphreg_bad_input(IterationsZero 2 TEXT "--iterations" SETUP ${scan} ${model}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --iterations 0)
morphreg_bad_input(SynthAngularSamplesTooMany 2 TEXT "--angular-samples"
  ARGS synth --count 1 --scans 1 --angular-samples 2000000000 --out-dir @CASE@/synth)
morphreg_bad_input(SynthCountTooMany 2 TEXT "--count" ARGS synth --count 2000000000 --out-dir @CASE@/synth)
morphreg_bad_input(RenderTooWide 2 TEXT "--width" SETUP ${mesh}
  ARGS render --mesh @CASE@/head.ply --width 100000 --out @CASE@/render.png)

# --- Outputs never touch inputs: resolved before any work, refused naming both -------------------------------------
bad_file(scans_here.csv "scan,landmarks,id" "head.ply,,head" "head_1.ply,,other")
bad_file(ids_a_and_a_fit.csv "scan,landmarks,id" "head.ply,,a" "head_1.ply,,a_fit")
bad_file(id_summary.csv "scan,landmarks,id" "head.ply,,summary" "head_1.ply,,b")
bad_file(id_summary_shard.csv "scan,landmarks,id" "head.ply,,summary.shard-0-of-2" "head_1.ply,,b")
morphreg_bad_input(BatchOutDirIsTheScanFolder 1 TEXT "@CASE@/scans (--scans)" "a folder whose files this run reads"
  SETUP copy,${small}/head_000.ply,@CASE@/scans/a.ply copy,${small}/head_001.ply,@CASE@/scans/b.ply ${model}
  ARGS register --scans @CASE@/scans --model @CASE@/model.h5 --out-dir @CASE@/scans)
morphreg_bad_input(BuildModelReportDirReplacesTheScans 1 TEXT "head.ply (the scan of id 'head')" "is also an input"
  SETUP ${mesh} ${mesh_1} ${model} copy,${bad}/scans_here.csv,@CASE@/list.csv
  ARGS build-model --from-scans @CASE@/list.csv --model @CASE@/model.h5 --report-dir @CASE@ --out @CASE@/out.h5)
morphreg_bad_input(BuildModelIdsCollide 1 TEXT "a_fit.ply: this run would write it twice"
  "the fit of scan 'a' and as the resampled mesh of scan 'a_fit'"
  SETUP ${mesh} ${mesh_1} ${model} copy,${bad}/ids_a_and_a_fit.csv,@CASE@/list.csv
  ARGS build-model --from-scans @CASE@/list.csv --model @CASE@/model.h5 --report-dir @CASE@/reports --out @CASE@/out.h5)
foreach(case "id_summary;summary" "id_summary_shard;summary.shard-0-of-2")
  list(GET case 0 file)
  list(GET case 1 id)
  morphreg_bad_input(BatchId_${file} 1 TEXT "the scan id '${id}' would name files of the run's summaries"
    SETUP ${mesh} ${mesh_1} ${model} copy,${bad}/${file}.csv,@CASE@/list.csv
    ARGS register --scans @CASE@/list.csv --model @CASE@/model.h5 --out-dir @CASE@/out)
endforeach()
morphreg_bad_input(BuildModelIdSummary 1 TEXT "summary.json: this run would write it twice"
  SETUP ${mesh} ${mesh_1} ${model} copy,${bad}/id_summary.csv,@CASE@/list.csv
  ARGS build-model --from-scans @CASE@/list.csv --model @CASE@/model.h5 --report-dir @CASE@/reports --out @CASE@/out.h5)
morphreg_bad_input(MergeSummariesOutputIsItsInput 1 TEXT "summary.json (the merged summary): is also an input"
  SETUP copy,${small}/population.json,@CASE@/summary.json
  ARGS merge-summaries --out-dir @CASE@ @CASE@/summary.json)
morphreg_bad_input(MergeSummariesNoShards 1 TEXT "no shard summaries" SETUP ${mesh}
  ARGS merge-summaries --out-dir @CASE@)
# The same file under another name: a symbolic link, a hard link, a path through "..".
foreach(link symlink hardlink)
  morphreg_bad_input(RegisterOutIsA${link}ToTheScan 1 TEXT "link.ply (--out): is also an input" "head.ply (--scan)"
    SETUP ${mesh} ${model} ${link},@CASE@/head.ply,@CASE@/link.ply
    ARGS register --scan @CASE@/head.ply --model @CASE@/model.h5 --out @CASE@/link.ply)
endforeach()
morphreg_bad_input(RegisterOutThroughDotDot 1 TEXT "(--out): is also an input" SETUP ${mesh} ${model}
  mkdir,-,@CASE@/sub ARGS register --scan @CASE@/head.ply --model @CASE@/model.h5 --out @CASE@/sub/../head.ply)
morphreg_bad_input(RegisterReportIsTheModel 1 TEXT "model.h5 (--report): is also an input" SETUP ${scan} ${model}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --report @CASE@/model.h5)
morphreg_bad_input(RegisterScreenshotIsTheOut 1 TEXT "this run would write it twice, as --out and as --screenshot"
  SETUP ${scan} ${model} ARGS register --scan @CASE@/scan.pcd ${register_args} --screenshot @CASE@/fit.ply)
morphreg_bad_input(RegisterTruthIsTheReport 1 TEXT "(--report): is also an input" SETUP ${scan} ${model} ${mesh}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --truth @CASE@/head.ply --report @CASE@/head.ply)
morphreg_bad_input(ResampleFitOutIsTheOut 1 TEXT "this run would write it twice, as --out and as --fit-out"
  SETUP ${scan} ${model}
  ARGS resample --scan @CASE@/scan.pcd --model @CASE@/model.h5 --out @CASE@/r.ply --fit-out @CASE@/r.ply)
morphreg_bad_input(ResampleReportIsTheScan 1 TEXT "scan.pcd (--report): is also an input" SETUP ${scan} ${model}
  ARGS resample --scan @CASE@/scan.pcd --model @CASE@/model.h5 --out @CASE@/r.ply --report @CASE@/scan.pcd)
morphreg_bad_input(WarpReportIsTheSource 1 TEXT "source.json (--report): is also an input"
  SETUP ${mesh} ${source} ${target}
  ARGS warp --mesh @CASE@/head.ply --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/w.ply
       --report @CASE@/source.json)
morphreg_bad_input(FitPhotosOutIsTheModel 1 TEXT "model.h5 (--out): is also an input" SETUP ${model} ${profile} ${frontal}
  ARGS fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json
       --out @CASE@/model.h5)
morphreg_bad_input(BuildModelOutIsTheRegions 1 TEXT "regions.json (--out): is also an input"
  SETUP ${mesh} ${mesh_1} copy,${small}/regions.json,@CASE@/regions.json
  ARGS build-model --mesh @CASE@/head.ply --mesh @CASE@/head_1.ply --regions @CASE@/regions.json
       --out @CASE@/regions.json)
morphreg_bad_input(BuildModelOutInTheMeshFolder 1 TEXT "(--dir)" "a folder whose files this run reads"
  SETUP copy,${small}/head_000.ply,@CASE@/heads/a.ply copy,${small}/head_001.ply,@CASE@/heads/b.ply
  ARGS build-model --dir @CASE@/heads --out @CASE@/heads/model.ply)
morphreg_bad_input(RenderOutIsTheCloud 1 TEXT "scan.pcd (--out): is also an input" SETUP ${mesh} ${scan} XVFB
  ARGS render --mesh @CASE@/head.ply --cloud @CASE@/scan.pcd --width 64 --height 64 --out @CASE@/scan.pcd)
morphreg_bad_input(BatchOutDirIsAFile 1 TEXT "out" SETUP ${mesh} ${mesh_1} ${model}
  copy,${bad}/scans_here.csv,@CASE@/list.csv copy,${small}/population.json,@CASE@/out
  ARGS register --scans @CASE@/list.csv --model @CASE@/model.h5 --out-dir @CASE@/out)
morphreg_bad_input(DemoOutIsAFile 1 TEXT "demo.ply: exists and is not a folder" SETUP copy,${small}/head_000.ply,@CASE@/demo.ply
  ARGS demo --count 2 --resolution 20 --no-screenshot --quiet --out-dir @CASE@/demo.ply)
# An empty output name is named as such, for every subcommand that writes a file.
foreach(case "register;register --scan @CASE@/scan.pcd --model @CASE@/model.h5"
        "resample;resample --scan @CASE@/scan.pcd --model @CASE@/model.h5"
        "warp;warp --mesh @CASE@/head.ply --source @CASE@/source.json --target @CASE@/target.json"
        "fit_photos;fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json"
        "build_model;build-model --mesh @CASE@/head.ply --mesh @CASE@/head_1.ply")
  list(GET case 0 name)
  list(GET case 1 command)
  separate_arguments(command)
  # (an empty argument cannot pass through a CMake list: the shell appends it)
  morphreg_bad_input(EmptyOut_${name} 1 TEXT "--out: the output file name is empty"
    SETUP ${scan} ${model} ${mesh} ${mesh_1} ${source} ${target} ${profile} ${frontal}
    WRAP sh -c "exec \"$@\" --out ''" sh ARGS ${command})
endforeach()

# --- A failed run leaves the old results as they were (copies placed where the run writes must be unchanged) -------
set(old_fit copy,${small}/head_001.ply,@CASE@/fit.ply copy,${small}/scan_0_landmarks.json,@CASE@/fit.json)
morphreg_bad_input(RegisterDiskFullKeepsTheOldFit 1 TEXT "fit.ply" SETUP ${scan} ${model} ${old_fit} ${full_disk}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --iterations 3)
morphreg_bad_input(RegisterUnwritableReportKeepsTheOldFit 1 TEXT "/proc/version.json" SETUP ${scan} ${model} ${old_fit}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --iterations 3 --report /proc/version.json)
morphreg_bad_input(RegisterScreenshotFailsKeepsTheOldFit 1 TEXT "xvfb-run" SETUP ${scan} ${model} ${old_fit}
  ENVIRONMENT "DISPLAY=unset:" ARGS register --scan @CASE@/scan.pcd --screenshot @CASE@/fit.png ${register_args})
morphreg_bad_input(ResampleDiskFullKeepsTheOldOutputs 1 TEXT "@CASE@" SETUP ${scan} ${model}
  copy,${small}/head_001.ply,@CASE@/r.ply copy,${small}/head_000.ply,@CASE@/r_fit.ply ${full_disk}
  ARGS resample --scan @CASE@/scan.pcd --model @CASE@/model.h5 --out @CASE@/r.ply --iterations 3)
morphreg_bad_input(WarpDiskFullKeepsTheOldMesh 1 TEXT "warped.ply" SETUP ${mesh} ${source} ${target}
  copy,${small}/head_001.ply,@CASE@/warped.ply ${full_disk}
  ARGS warp --mesh @CASE@/head.ply --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/warped.ply)
morphreg_bad_input(FitPhotosDiskFullKeepsTheOldMesh 1 TEXT "photos.ply" SETUP ${model} ${profile} ${frontal}
  copy,${small}/head_001.ply,@CASE@/photos.ply ${full_disk}
  ARGS fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json
       --out @CASE@/photos.ply)
morphreg_bad_input(BuildModelDiskFullKeepsTheOldModel 1 TEXT "model_out.h5" SETUP ${mesh} ${mesh_1}
  copy,${small_model},@CASE@/model_out.h5 ${full_disk}
  ARGS build-model --mesh @CASE@/head.ply --mesh @CASE@/head_1.ply --out @CASE@/model_out.h5)
morphreg_bad_input(SynthDiskFullKeepsTheOldPopulation 1 TEXT "synth/" ${full_disk}
  SETUP copy,${small}/population.json,@CASE@/synth/population.json copy,${small}/head_000.ply,@CASE@/synth/head_000.ply
  ARGS synth --count 2 --resolution 20 --quiet --out-dir @CASE@/synth)
morphreg_bad_input(BuildModelFromScansFailsKeepsTheOldReports 1 TEXT "a model needs at least two"
  SETUP ${model} copy,${bad}/scan_one.pcd,@CASE@/scans/a.pcd copy,${bad}/scan_one.pcd,@CASE@/scans/b.pcd
  copy,${small}/population.json,@CASE@/reports/summary.json
  ARGS build-model --from-scans @CASE@/scans --model @CASE@/model.h5 --report-dir @CASE@/reports --out @CASE@/out.h5)

# --- Every file read is bounded and checked: no FIFO, device or folder; photos and models validated ---------------
set(fit_args "--model @CASE@/model.h5 --out @CASE@/fit.ply")
foreach(case "register_scan;scan.pcd;register --scan @CASE@/scan.pcd ${fit_args}"
        "register_model;model.h5;register --scan @CASE@/head.ply ${fit_args}"
        "register_landmarks;lm.json;register --scan @CASE@/head.ply --landmarks @CASE@/lm.json ${fit_args}"
        "warp_mesh;mesh.ply;warp --mesh @CASE@/mesh.ply --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/w.ply"
        "warp_source;src.json;warp --mesh @CASE@/head.ply --source @CASE@/src.json --target @CASE@/target.json --out @CASE@/w.ply"
        "fit_photos_profile;p.json;fit-photos --model @CASE@/model.h5 --profile @CASE@/p.json --frontal @CASE@/frontal.json --out @CASE@/o.ply"
        "fit_photos_photo;photo.png;fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json --photo @CASE@/photo.png --out @CASE@/o.ply"
        "build_model_mesh;m.ply;build-model --mesh @CASE@/head.ply --mesh @CASE@/m.ply --out @CASE@/o.h5"
        "model_info;model.h5;model-info --model @CASE@/model.h5"
        "resample_scan;scan.pcd;resample --scan @CASE@/scan.pcd --model @CASE@/model.h5 --out @CASE@/r.ply")
  list(GET case 0 name)
  list(GET case 1 file)
  list(GET case 2 command)
  separate_arguments(command)
  set(setup ${mesh} ${source} ${target} ${profile} ${frontal})
  if(NOT file STREQUAL "model.h5")
    list(APPEND setup ${model})
  endif()
  morphreg_bad_input(Fifo_${name} 1 TEXT "${file}: is not a regular file (a FIFO)" SETUP ${setup} fifo,-,@CASE@/${file}
    ARGS ${command})
  if(name MATCHES "register_|warp_source|model_info")
    string(REPLACE "@CASE@/${file}" "/dev/zero" device_command "${command}")
    morphreg_bad_input(Device_${name} 1 TEXT "/dev/zero: is not a regular file (a character device)" SETUP ${setup}
      ARGS ${device_command})
  endif()
  if(name MATCHES "model_info|register_landmarks|build_model_mesh")
    morphreg_bad_input(Folder_${name} 1 TEXT "${file}: is a directory" SETUP ${setup} mkdir,-,@CASE@/${file}
      ARGS ${command})
  endif()
endforeach()
# Photos: decoded before the fit; corrupt, cut, empty or lying headers are named.
set(photo_args fit-photos --model @CASE@/model.h5 --profile @CASE@/profile.json --frontal @CASE@/frontal.json
    --out @CASE@/o.ply)
file(WRITE ${bad}/not_an_image.png "this is text, not a picture\n")
set(heads_png ${PROJECT_SOURCE_DIR}/docs/images/heads.png)
file(SIZE ${heads_png} heads_png_size)
math(EXPR heads_png_half "${heads_png_size} / 2")
foreach(case "cut_png;head,${heads_png},@CASE@/photo.png,${heads_png_half};a corrupt or truncated PNG"
        "header_only_png;copy,${bad}/header_only.png,@CASE@/photo.png;a corrupt PNG header"
        "huge_png;copy,${bad}/huge.png,@CASE@/photo.png;is not 1 to 16384 a side"
        "not_an_image;copy,${bad}/not_an_image.png,@CASE@/photo.png;not a PNG or JPEG image"
        "huge_jpeg;copy,${bad}/huge.jpg,@CASE@/photo.png;the image size 60000 x 60000 is not 1 to 16384"
        "no_scan_jpeg;copy,${bad}/no_scan.jpg,@CASE@/photo.png;a corrupt or truncated JPEG"
        "cmyk_jpeg;copy,${bad}/cmyk.jpg,@CASE@/photo.png;a JPEG of 4 colour components")
  list(GET case 0 name)
  list(GET case 1 step)
  list(GET case 2 text)
  morphreg_bad_input(Photo_${name} 1 TEXT "photo.png: " "${text}" SETUP ${model} ${profile} ${frontal} ${step}
    ARGS ${photo_args} --photo @CASE@/photo.png)
endforeach()
file(WRITE ${bad}/empty.png "")
morphreg_bad_input(Photo_empty 1 TEXT "empty.png: file is empty" SETUP ${model} ${profile} ${frontal}
  copy,${bad}/empty.png,@CASE@/empty.png ARGS ${photo_args} --photo @CASE@/empty.png)
# Model files whose content is corrupt although HDF5 reads them.
foreach(case "mean_bit_flip;disagree at vertex 10" "basis_scaled;the basis of region" "triangles_zero;repeats a vertex"
        "mean_huge;beyond +-1e6" "landmark_wraps;4294967301 is not from 0 to 3457"
        "landmark_fraction;12.9 is not a whole number" "landmark_unknown;unknown landmark id 'not_a_landmark'"
        "structure_zeroed;model.h5: ")
  list(GET case 0 name)
  list(GET case 1 text)
  morphreg_bad_input(Model_${name} 1 TEXT "model.h5: " "${text}" SETUP copy,${bad}/model_${name}.h5,@CASE@/model.h5
    ARGS model-info --model @CASE@/model.h5)
endforeach()
morphreg_bad_input(RegisterModelMeanBitFlip 1 TEXT "model.h5: " "disagree" SETUP ${scan}
  copy,${bad}/model_mean_bit_flip.h5,@CASE@/model.h5 ARGS register --scan @CASE@/scan.pcd ${register_args})
morphreg_bad_input(EvaluateModelCorrupt 1 TEXT "model.h5: " "repeats a vertex" SETUP ${mesh}
  copy,${bad}/model_triangles_zero.h5,@CASE@/model.h5 ARGS evaluate-model --model @CASE@/model.h5 --meshes @CASE@/head.ply)
# Integers in JSON are whole numbers in range, never wrapped or truncated; landmark ids are known.
bad_file(lv_wraps.json "{\"landmark_vertices\": {\"nose_tip\": 4294967301}}")
bad_file(lv_fraction.json "{\"landmark_vertices\": {\"nose_tip\": 12.9}}")
bad_file(lv_unknown.json "{\"landmark_vertices\": {\"no_such_landmark\": 12}}")
bad_file(regions_fraction.json "{\"regions\": [\"a\", \"b\", \"c\"], \"labels\": [0, 1, 2.7]}")
foreach(case "lv_wraps;--landmark-vertices;4294967301 is not from 0 to 3457"
        "lv_fraction;--landmark-vertices;12.9 is not a whole number"
        "lv_unknown;--landmark-vertices;unknown landmark id 'no_such_landmark'"
        "regions_fraction;--regions;2.7 is not a whole number")
  list(GET case 0 file)
  list(GET case 1 option)
  list(GET case 2 text)
  morphreg_bad_input(Json_${file} 1 TEXT "${file}.json" "${text}" SETUP ${mesh} ${mesh_1}
    copy,${bad}/${file}.json,@CASE@/${file}.json
    ARGS build-model --mesh @CASE@/head.ply --mesh @CASE@/head_1.ply ${option} @CASE@/${file}.json --out @CASE@/o.h5)
endforeach()
# Meshes and landmarks whose values are out of sense.
bad_file(no_triangles.stl "solid empty" "endsolid empty")
bad_file(far_landmark.csv "id,x,y,z" "nose_tip,0,30,110" "chin,1e200,-40,95" "right_eye_outer,-45,60,70"
         "left_eye_outer,45,60,70")
scan_grid_rows(body 42 "1e20 0 0" "")
file(WRITE ${bad}/scan_stray.pcd "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 200\n"
           "HEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 200\nDATA ascii\n${body}\n")
file(WRITE ${bad}/scan_one.pcd "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\n"
           "HEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n1 2 3\n")
morphreg_bad_input(StlWithoutTriangles 1 TEXT "no_triangles.stl" "has no triangles" SETUP ${source} ${target}
  copy,${bad}/no_triangles.stl,@CASE@/no_triangles.stl
  ARGS warp --mesh @CASE@/no_triangles.stl --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/w.ply)
morphreg_bad_input(LandmarkAt1e200 1 TEXT "far_landmark.csv:3" "beyond +-1e7" SETUP ${mesh} ${target}
  copy,${bad}/far_landmark.csv,@CASE@/far_landmark.csv
  ARGS warp --mesh @CASE@/head.ply --source @CASE@/far_landmark.csv --target @CASE@/target.json --out @CASE@/w.ply)
morphreg_bad_input(ScanStrayPoint 1 TEXT "scan_stray.pcd: point 42" "a stray point" SETUP ${model}
  copy,${bad}/scan_stray.pcd,@CASE@/scan_stray.pcd ARGS register --scan @CASE@/scan_stray.pcd ${register_args})

# --- Memory before allocation -------------------------------------------------------------------------------------
set(ict ${MORPHREG_SHARED_DATA_DIR}/ict_facekit)
if(EXISTS ${ict})
  morphreg_bad_input(IctSamplesNeedTooMuchMemory 1 TEXT "100000 heads drawn from the ICT model of" "of memory; this machine has"
    ARGS build-model --from-ict ${ict} --samples 100000 --quiet --out @CASE@/ict.h5)
endif()

# --- Options in sense: the option, the value as written and the range -------------------------------------------------
foreach(case "IterationsFraction;--iterations;12.9;Value 12.9 is not a whole number (a whole number from 1 to 10000)"
        "IterationsTooMany;--iterations;20000;Value 20000 is not from 1 to 10000"
        "WidthNotANumber;--width;wide;Value wide is not a number"
        "TrimmedBeyondOne;--reject-trimmed;2;Value 2 is not a number from 0 to 1"
        "TangentialWeightNaN;--tangential-weight;nan;Value nan is not a number from 0 to 1")
  list(GET case 0 name)
  list(GET case 1 option)
  list(GET case 2 value)
  list(GET case 3 text)
  morphreg_bad_input(Option${name} 2 TEXT "${option}" "${text}" SETUP ${scan} ${model}
    ARGS register --scan @CASE@/scan.pcd ${register_args} ${option} ${value})
endforeach()
set(warp_args warp --mesh @CASE@/head.ply --source @CASE@/source.json --target @CASE@/target.json --out @CASE@/w.ply)
foreach(case "Rigidity;--rigidity;1e300;Value 1e300 is not a number from 0 to 1000"
        "SkinningWidth;--skinning-width;1e30;Value 1e30 is not a number from 0.1 to 10000"
        "MlsFalloff;--mls-falloff;100;Value 100 is not a number from 0.1 to 10"
        "Lambda;--lambda;-1;Value -1 is not a number >= 0")
  list(GET case 0 name)
  list(GET case 1 option)
  list(GET case 2 value)
  list(GET case 3 text)
  morphreg_bad_input(Warp${name} 2 TEXT "${option}" "${text}" SETUP ${mesh} ${source} ${target}
    ARGS ${warp_args} ${option} ${value})
endforeach()
morphreg_bad_input(CoefficientLimitZero 2 TEXT "--coefficient-limit" "is not a number > 0 (or inf)"
  SETUP ${model} ${profile} ${frontal} ARGS ${photo_args} --coefficient-limit 0)
morphreg_bad_input(SamplesBeyondRange 2 TEXT "--samples" "Value 200000 is not from 2 to 100000"
  ARGS build-model --from-ict @CASE@/ict --samples 200000 --out @CASE@/o.h5)
morphreg_bad_input(JobsNegative 2 TEXT "--jobs" "Value -1 is not from 0 to 4096" SETUP ${model}
  ARGS register --scans @CASE@ --model @CASE@/model.h5 --out-dir @CASE@/out --jobs -1)
morphreg_bad_input(RenderOpacity 2 TEXT "--opacity" "Value 2 is not a number from 0 to 1" SETUP ${mesh}
  ARGS render --mesh @CASE@/head.ply --opacity 2 --out @CASE@/r.png)
morphreg_bad_input(DemoCountOne 2 TEXT "--count" "Value 1 is not from 2 to 5000"
  ARGS demo --count 1 --no-screenshot --out-dir @CASE@/demo)
morphreg_bad_input(EvaluateModelNoMeshes 2 TEXT "--meshes" SETUP ${model} ARGS evaluate-model --model @CASE@/model.h5)
morphreg_bad_input(ResampleLandmarkReferenceWithoutLandmarks 1 TEXT "--reference landmarks needs --landmarks"
  SETUP ${scan} ${model}
  ARGS resample --scan @CASE@/scan.pcd --model @CASE@/model.h5 --reference landmarks --out @CASE@/r.ply)
# Normals of absurd length: a corrupt file, not a direction to fit along.
scan_grid_rows(body 7 "35 0 7 1e30 0 0" " 0 0 1")
file(WRITE ${bad}/scan_long_normal.pcd "VERSION .7\nFIELDS x y z normal_x normal_y normal_z\nSIZE 4 4 4 4 4 4\n"
           "TYPE F F F F F F\nCOUNT 1 1 1 1 1 1\nWIDTH 200\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 200\n"
           "DATA ascii\n${body}\n")
morphreg_bad_input(ScanNormalOfLength1e30 1 TEXT "scan_long_normal.pcd: the normal of point 7" "has the length 1e+30"
  SETUP ${model} copy,${bad}/scan_long_normal.pcd,@CASE@/scan_long_normal.pcd
  ARGS register --scan @CASE@/scan_long_normal.pcd ${register_args})
