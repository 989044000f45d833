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
    SETUP ${case_SETUP} FIXTURES_REQUIRED "cli_small;cli_model" ${options}
    COMMAND ${case_WRAP} $<TARGET_FILE:morphreg_cli> ${case_ARGS})
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
  if(i EQUAL 17)
    list(APPEND inf "inf 0 1")
  else()
    list(APPEND inf "${a} ${b} ${c}")
  endif()
endforeach()
foreach(case "one;1 point" "three;3 points" "few;50 points, at least 100" "flat;the 200 points lie in a plane"
        "line;the 200 points are collinear" "same;all 200 points are identical"
        "nan;the scan has no valid (finite) points" "inf;point 17 is not finite (inf, 0, 1)"
        "enormous;no head in any unit")
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
  ARGS synth --count 1 --resolution 20 --quiet --out @CASE@/head.ply)
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
  ARGS synth --count 2 --resolution 20 --quiet --out @CASE@/synth)

# --- Options out of range ---------------------------------------------------------------------------------------------
morphreg_bad_input(ComponentsNegative 2 TEXT "--components" SETUP ${scan} ${model}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --components -1)
morphreg_bad_input(IterationsZero 2 TEXT "--iterations" SETUP ${scan} ${model}
  ARGS register --scan @CASE@/scan.pcd ${register_args} --iterations 0)
morphreg_bad_input(SynthAngularSamplesTooMany 2 TEXT "--angular-samples"
  ARGS synth --count 1 --scans 1 --angular-samples 2000000000 --out @CASE@/synth)
morphreg_bad_input(SynthCountTooMany 2 TEXT "--count" ARGS synth --count 2000000000 --out @CASE@/synth)
morphreg_bad_input(RenderTooWide 2 TEXT "--width" SETUP ${mesh}
  ARGS render --mesh @CASE@/head.ply --width 100000 --out @CASE@/render.png)
