# SPDX-License-Identifier: BSD-3-Clause
# CliTest: the command line end to end on small synthetic inputs; bad arguments exit 2, bad files exit 1 with a
# message naming the file. Every test runs through morphreg_cli_test (test/support/command_test.cmake), which checks
# the exit code, the report's status and the files besides what the test is named for.
if(NOT TARGET morphreg_cli)
  return()
endif()
set(cli_dir ${CMAKE_CURRENT_BINARY_DIR}/cli)
set(cli_scripts ${CMAKE_CURRENT_SOURCE_DIR}/scripts/cli)
file(MAKE_DIRECTORY ${cli_dir})
file(WRITE ${cli_dir}/corrupt_model.h5 "not an HDF5 file\n")
file(WRITE ${cli_dir}/corrupt_regions.json "{\"regions\": [\"a\"], \"labels\": [0, 0,\n")
file(WRITE ${cli_dir}/unknown_landmarks.csv "id,x,y,z\nnot_a_landmark,1,2,3\n")

# Expects exit code `code` and `text` on stderr from morphreg run with the remaining arguments.
function(morphreg_cli_expect_exit name code text)
  morphreg_cli_test(${name} EXPECT_CODE ${code} ERROR "${text}" ARGS ${ARGN})
endfunction()

morphreg_cli_test(VersionPrints OUTPUT "morphreg [0-9]+\\.[0-9]+" ARGS --version)
foreach(command synth build-model register resample fit-photos warp render view demo model-info merge-summaries
    evaluate-model)
  morphreg_cli_test(Help.${command} OUTPUT "Usage: .*${command}.*-q,--quiet.*-v,--verbose" ARGS ${command} --help)
endforeach()

morphreg_cli_test(SynthWritesHeadsAndScans FIXTURES_SETUP cli_synth
  OUTPUT "wrote 2 heads, 1 scans and 0 photo pairs"
  FILES ${cli_dir}/synth/head_000.ply ${cli_dir}/synth/head_001.ply ${cli_dir}/synth/scan_0.pcd
        ${cli_dir}/synth/regions.json
  ARGS synth --count 2 --scans 1 --range-mesh --quiet --out-dir ${cli_dir}/synth)
morphreg_cli_expect_exit(BadArgumentExits2 2 "--count" synth --count 0)
# An unknown option or command is named with the nearest known one, before a missing required option is reported;
# negative numbers as values are not taken for options.
morphreg_cli_test(UnknownOptionNamesTheNearest EXPECT_CODE 2 ERROR "register: unknown option --scna; did you mean --scan?"
  ARGS register --scna scan.ply)
morphreg_cli_test(UnknownOptionFarFromAnyIsNamed EXPECT_CODE 2 ERROR "synth: unknown option --zzzzzzzzzz" FORBID "did you mean"
  ARGS synth --zzzzzzzzzz)
morphreg_cli_test(UnknownCommandNamesTheNearest EXPECT_CODE 2 ERROR "unknown command regster; did you mean register?"
  ARGS regster --scan scan.ply)
morphreg_cli_test(NegativeValueIsNotAnOption EXPECT_CODE 2 ERROR "--noise" FORBID "unknown option"
  ARGS synth --count 1 --scans 1 --noise -1 --quiet --out-dir ${cli_dir}/negative)
morphreg_cli_expect_exit(BadScannerSettingIsNamed 2 "--noise" synth --count 1 --scans 1 --noise -1 --quiet
  --out-dir ${cli_dir}/bad)

# build-model and register on a small population (12 heads of 3458 vertices, a coarse scan of the first).
morphreg_cli_test(SmallPopulation FIXTURES_SETUP cli_small
  FILES ${cli_dir}/small/head_011.ply ${cli_dir}/small/scan_0.pcd ${cli_dir}/small/scan_0_truth.ply
        ${cli_dir}/small/photo_0_profile.json ${cli_dir}/small/photo_0_frontal.json
  ARGS synth --count 12 --resolution 24 --scans 1 --photos 1 --angular-samples 200 --row-spacing 3 --quiet
       --out-dir ${cli_dir}/small)
morphreg_cli_test(BuildModelFromSynthFolder FIXTURES_REQUIRED cli_small FIXTURES_SETUP cli_model
  OUTPUT "small_model.h5: 3458 vertices, 7 region\\(s\\), components per region \\[8,8,8,8,8,8,8\\], 45 landmarks"
  FILES ${cli_dir}/small_model.h5
  ARGS build-model --dir ${cli_dir}/small --regions ${cli_dir}/small/regions.json
       --landmark-vertices ${cli_dir}/small/landmark_vertices.json --components 8 --out ${cli_dir}/small_model.h5)
morphreg_cli_test(BuildModelGlobalFromFiles FIXTURES_REQUIRED cli_small
  OUTPUT "global.h5: 3458 vertices, 1 region\\(s\\)" FILES ${cli_dir}/global.h5
  ARGS build-model --mesh ${cli_dir}/small/head_000.ply --mesh ${cli_dir}/small/head_001.ply
       --mesh ${cli_dir}/small/head_002.ply --variance 0.9 --no-procrustes --quiet --out ${cli_dir}/global.h5)
morphreg_cli_expect_exit(BuildModelMismatchedMeshIsNamed 1 "synth/head_000.ply: 9602 vertices, expected 3458"
  build-model --mesh ${cli_dir}/small/head_000.ply --mesh ${cli_dir}/synth/head_000.ply --out ${cli_dir}/bad.h5)
morphreg_cli_expect_exit(BuildModelCorruptRegionsIsNamed 1 "corrupt_regions.json: malformed JSON"
  build-model --dir ${cli_dir}/small --regions ${cli_dir}/corrupt_regions.json --out ${cli_dir}/bad.h5)
morphreg_cli_expect_exit(BuildModelWrongRegionCountIsNamed 1 "synth/regions.json: region labels: 9602 labels for 3458"
  build-model --dir ${cli_dir}/small --regions ${cli_dir}/synth/regions.json --out ${cli_dir}/bad.h5)
morphreg_cli_expect_exit(BuildModelNeedsInput 2 "--mesh, --dir, --from-ict or --from-scans" build-model)
morphreg_cli_expect_exit(BuildModelOneMeshFails 1 "at least two meshes" build-model --mesh ${cli_dir}/small/head_000.ply)
set_tests_properties(CliTest.BuildModelMismatchedMeshIsNamed CliTest.BuildModelCorruptRegionsIsNamed
  CliTest.BuildModelWrongRegionCountIsNamed CliTest.BuildModelOneMeshFails PROPERTIES
  FIXTURES_REQUIRED "cli_small;cli_synth")

# model-info: the small model's regions, components and landmarks, as text and as JSON.
morphreg_cli_test(ModelInfoPrintsRegionsAndLandmarks FIXTURES_REQUIRED cli_model
  OUTPUT "3458 vertices, [0-9]+ triangles, units mm\nregions \\(7\\):\n  eyes: [0-9]+ vertices, 8 components.*global PCA: 8 components.*landmarks \\(45\\):.* nose_tip=[0-9]+"
  ARGS model-info --model ${cli_dir}/small_model.h5)
morphreg_cli_test(ModelInfoPrintsJson FIXTURES_REQUIRED cli_model
  OUTPUT "\"components\": 8,.*\"nose_tip\": [0-9]+.*\"vertices\": 3458"
  ARGS model-info --model ${cli_dir}/small_model.h5 --json)
morphreg_cli_expect_exit(ModelInfoCorruptModelIsNamed 1 "corrupt_model.h5" model-info --model ${cli_dir}/corrupt_model.h5)
# A model's unit: statismo files (written by the independent h5py writer of the model tests) in m are recognised by
# their size and converted, in micrometres refused; a built model states mm.
file(MAKE_DIRECTORY ${cli_dir}/unit_models)
morphreg_command_test(CliTest.ModelFilesInOtherUnits FIXTURES_SETUP cli_unit_models
  FILES ${cli_dir}/unit_models/statismo_metres.h5 ${cli_dir}/unit_models/statismo_micrometres.h5
  COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/model/statismo_fixture.py write ${cli_dir}/unit_models)
morphreg_cli_test(ModelInfoShowsAModelInMetresConverted FIXTURES_REQUIRED cli_unit_models
  OUTPUT "units mm\n.*the file's unit: m \\(guessed from its size: the mean's RMS radius is 0\\.173: taken as m \\(x1000 to mm\\), it is 1\\.73 times a head model's 100 mm\\); converted to mm on loading"
  ARGS model-info --model ${cli_dir}/unit_models/statismo_metres.h5)
morphreg_cli_expect_exit(ModelInfoRefusesAModelInNoUnit 1
  "statismo_micrometres.h5: not a head model in any unit: the mean's RMS radius is 1.73e+05"
  model-info --model ${cli_dir}/unit_models/statismo_micrometres.h5)
set_tests_properties(CliTest.ModelInfoRefusesAModelInNoUnit PROPERTIES FIXTURES_REQUIRED cli_unit_models)
morphreg_cli_test(ModelInfoShowsTheStatedUnit FIXTURES_REQUIRED cli_model
  OUTPUT "the file's unit: mm \\(the file's units\\)" ARGS model-info --model ${cli_dir}/small_model.h5)

# register: the fit of the small scan against its true head, and the report's contents.
morphreg_cli_test(RegisterSynthScanMatchesTruth FIXTURES_REQUIRED "cli_small;cli_model" FIXTURES_SETUP cli_fit
  OUTPUT "vertices the scan covers: RMS 0\\.[0-9]+ mm.*registered .* iterations \\([a-z_]*converged"
  # progress: iterations with their correspondences (none for PCL's call at callback registration)
  FORBID "/[0-9]+. 0 correspondences"
  REPORT ${cli_dir}/fit.json FILES ${cli_dir}/fit.ply
  CHECKS ${cli_scripts}/check_register_report.cmake DEFINE MAX_TRUTH_RMS=1.0
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5
       --truth ${cli_dir}/small/scan_0_truth.ply --out ${cli_dir}/fit.ply --report ${cli_dir}/fit.json)
# The fitted mesh in each format other tools open: the "wrote" line says what the format carries, and the file,
# read back by an independent reader, carries it (PLY: colours and the residual as vertex quality; OBJ: v x y z r g b;
# VTK: colours).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
foreach(format ply obj vtk)
  morphreg_command_test(CliTest.RegisterOutputCarriesWhatItSays.${format} FIXTURES_REQUIRED "cli_small;cli_model"
    COMMAND ${Python3_EXECUTABLE} ${cli_scripts}/check_mesh_output.py $<TARGET_FILE:morphreg_cli>
            ${cli_dir}/fit_format.${format} --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5)
endforeach()
# The synthetic scan's landmarks are exact: weighted 10 (the default 1 suits landmarks placed with a few mm of error).
morphreg_cli_test(RegisterWithRejectorChainAndLandmarks FIXTURES_REQUIRED "cli_small;cli_model"
  MAXIMA "vertices the scan covers: RMS ([0-9.]+) mm=>1.0"
  REPORT ${cli_dir}/fit_rejectors.json FILES ${cli_dir}/fit_rejectors.ply
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5
       --landmarks ${cli_dir}/small/scan_0_landmarks.json --landmark-weight 10 --reject-distance 20 --reject-median 3
       --reject-one-to-one --reject-trimmed 0.95 --point-to-point --loss huber --components 5 --iterations 40
       --truth ${cli_dir}/small/scan_0_truth.ply --quiet --out ${cli_dir}/fit_rejectors.ply)
morphreg_cli_expect_exit(RegisterCorruptModelIsNamed 1 "corrupt_model.h5"
  register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/corrupt_model.h5 --out ${cli_dir}/bad.ply)
morphreg_cli_expect_exit(RegisterMissingScanIsNamed 1 "no_such_scan.pcd"
  register --scan ${cli_dir}/no_such_scan.pcd --model ${cli_dir}/small_model.h5 --out ${cli_dir}/bad.ply)
morphreg_cli_expect_exit(RegisterUnknownLandmarkIsNamed 1 "unknown_landmarks.csv"
  register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5
  --landmarks ${cli_dir}/unknown_landmarks.csv --out ${cli_dir}/bad.ply)
morphreg_cli_expect_exit(RegisterWrongTruthIsNamed 1 "synth/head_000.ply: 9602 vertices"
  register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --iterations 2 --quiet
  --truth ${cli_dir}/synth/head_000.ply --out ${cli_dir}/bad.ply)
morphreg_cli_expect_exit(RegisterBadLossExits2 2 "--loss" register --scan a.pcd --model b.h5 --loss bisquare)
morphreg_cli_expect_exit(RegisterNegativeRefinementPriorExits2 2 "--refinement-prior"
  register --scan a.pcd --model b.h5 --refinement-prior -1)

# Output on stderr in a log (a file, not a terminal): progress as separate lines, no '\r'; PCL's warnings (a PLY
# scan's unhandled faces; a PCD scan without normals: "Failed to find match for field 'normal_x'") only with
# --verbose; nothing at all with -q.
set(register_ply_scan register --scan ${cli_dir}/small/head_001.ply --model ${cli_dir}/small_model.h5 --iterations 30)
morphreg_cli_test(RegisterLogHasProgressLinesAndNoPclWarnings FIXTURES_REQUIRED "cli_small;cli_model"
  LOG ${cli_dir}/RegisterLogHasProgressLinesAndNoPclWarnings.log
  OUTPUT "(^|\n)registering [^\n]*\\[1/30\\] [0-9]+ correspondences[^\n]*\n(.*\n)?registering [^\n]*. done\n"
  FORBID "\\[pcl::[A-Za-z:]+\\]" FILES ${cli_dir}/log_fit.ply REPORT ${cli_dir}/log_fit.json
  ARGS ${register_ply_scan} --out ${cli_dir}/log_fit.ply)
morphreg_cli_test(RegisterVerboseShowsPclWarnings FIXTURES_REQUIRED "cli_small;cli_model"
  LOG ${cli_dir}/RegisterVerboseShowsPclWarnings.log OUTPUT "\\[pcl::PLYReader\\]"
  FILES ${cli_dir}/verbose_fit.ply REPORT ${cli_dir}/verbose_fit.json
  ARGS ${register_ply_scan} --verbose --out ${cli_dir}/verbose_fit.ply)
morphreg_cli_test(RegisterQuietPrintsNothingOnStderr FIXTURES_REQUIRED "cli_small;cli_model"
  LOG ${cli_dir}/RegisterQuietPrintsNothingOnStderr.log EMPTY_STDERR
  FILES ${cli_dir}/quiet_fit.ply REPORT ${cli_dir}/quiet_fit.json
  ARGS ${register_ply_scan} -q --out ${cli_dir}/quiet_fit.ply)
morphreg_cli_test(RegisterScanWithoutNormalsHasNoPclWarning FIXTURES_REQUIRED "cli_small;cli_model" EXPECT_CODE 1
  LOG ${cli_dir}/RegisterScanWithoutNormalsHasNoPclWarning.log ERROR "scan_few.pcd: 50 points"
  FORBID "Failed to find match|\\[pcl::[A-Za-z:]+\\]" ABSENT ${cli_dir}/bad.ply
  ARGS register --scan ${cli_dir}/scan_few.pcd --model ${cli_dir}/small_model.h5 --out ${cli_dir}/bad.ply)
morphreg_cli_test(RegisterVerboseShowsMissingNormals FIXTURES_REQUIRED "cli_small;cli_model" EXPECT_CODE 1
  LOG ${cli_dir}/RegisterVerboseShowsMissingNormals.log ERROR "Failed to find match for field 'normal_x'"
  ARGS register --scan ${cli_dir}/scan_few.pcd --model ${cli_dir}/small_model.h5 --verbose --out ${cli_dir}/bad.ply)
morphreg_cli_expect_exit(VerboseExcludesQuiet 2 "--quiet excludes --verbose" synth --count 1 -v -q)

# Scans that cannot be registered are rejected before fitting, naming the file and the problem.
function(write_ascii_pcd path points)
  list(LENGTH points count)
  list(JOIN points "\n" body)
  file(WRITE ${path} "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH ${count}\nHEIGHT 1\n"
                     "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS ${count}\nDATA ascii\n${body}\n")
endfunction()
set(few "")
set(flat "")
set(line "")
set(same "")
set(nan "")
set(inf "")
foreach(i RANGE 199)
  math(EXPR a "${i} % 20 * 5")
  math(EXPR b "${i} / 20 * 5")
  math(EXPR c "${i} * 7 % 13")
  math(EXPR d "2 * ${i}")
  math(EXPR e "3 * ${i}")
  if(i LESS 50)
    list(APPEND few "${a} ${b} ${c}")
  endif()
  list(APPEND flat "${a} ${b} 0")
  list(APPEND line "${i} ${d} ${e}")
  list(APPEND same "1 2 3")
  list(APPEND nan "nan nan nan")
  if(i EQUAL 17)
    list(APPEND inf "inf 0 1")
  else()
    list(APPEND inf "${a} ${b} ${c}")
  endif()
endforeach()
foreach(kind few flat line same nan inf)
  write_ascii_pcd(${cli_dir}/scan_${kind}.pcd "${${kind}}")
endforeach()
foreach(case "few;50 points, at least 100" "flat;the 200 points lie in a plane" "line;the 200 points are collinear"
        "same;all 200 points are identical" "nan;the scan has no valid (finite) points"
        "inf;point 17 is not finite (inf, 0, 1)")
  list(GET case 0 kind)
  list(GET case 1 text)
  morphreg_cli_expect_exit(RegisterRejectsScan_${kind} 1 "scan_${kind}.pcd: ${text}"
    register --scan ${cli_dir}/scan_${kind}.pcd --model ${cli_dir}/small_model.h5 --out ${cli_dir}/bad.ply)
  set_tests_properties(CliTest.RegisterRejectsScan_${kind} PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")
endforeach()
morphreg_cli_expect_exit(RegisterBadUnitExits2 2 "--units" register --scan a.pcd --model b.h5 --units furlong)
# resample: the small scan registered and resampled into the model's topology; a scan refused by the resampler (its
# largest hole over the allowed share) exits 1 and leaves no output.
set(resample_small resample --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --quiet)
morphreg_cli_test(ResampleSynthScan FIXTURES_REQUIRED "cli_small;cli_model" FIXTURES_SETUP cli_resampled
  REPORT ${cli_dir}/resampled.json FILES ${cli_dir}/resampled.ply ${cli_dir}/resampled_fit.ply
  CHECKS ${cli_scripts}/check_resample.cmake DEFINE MIN_COVERAGE=0.5
  ARGS ${resample_small} --out ${cli_dir}/resampled.ply)
morphreg_cli_test(ResampleRefusedScanLeavesNoOutput FIXTURES_REQUIRED "cli_small;cli_model" EXPECT_CODE 1
  ERROR "scan_0.pcd: cannot be resampled into the model's topology: ScanResampler: a hole of"
  REPORT ${cli_dir}/refused.json ABSENT ${cli_dir}/refused.ply ${cli_dir}/refused_fit.ply
  ARGS ${resample_small} --max-hole-fraction 0.01 --out ${cli_dir}/refused.ply)
# resample --reference landmarks: the model's mean warped onto the scan's landmarks instead of a registration.
morphreg_cli_test(ResampleFromLandmarks FIXTURES_REQUIRED "cli_small;cli_model"
  REPORT ${cli_dir}/from_landmarks.json FILES ${cli_dir}/from_landmarks.ply ${cli_dir}/from_landmarks_fit.ply
  CHECKS ${cli_scripts}/check_resample.cmake DEFINE MIN_COVERAGE=0.85
  ARGS ${resample_small} --landmarks ${cli_dir}/small/scan_0_landmarks.json --reference landmarks
       --out ${cli_dir}/from_landmarks.ply)
morphreg_cli_expect_exit(ResampleFromLandmarksNeedsLandmarks 1 "--reference landmarks needs --landmarks"
  resample --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --reference landmarks
  --out ${cli_dir}/no_landmarks.ply)
set_tests_properties(CliTest.ResampleFromLandmarksNeedsLandmarks PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")
morphreg_cli_expect_exit(ResampleBadRayDistanceExits2 2 "--ray-distance" resample --scan a.pcd --model b.h5
  --ray-distance 0)

# The scan's unit: given (no rescaling, the report says "given"), or detected (a scan in metres, rescaled to mm).
morphreg_cli_test(RegisterGivenUnitIsReported FIXTURES_REQUIRED "cli_small;cli_model"
  REPORT ${cli_dir}/units_mm.json FILES ${cli_dir}/units_mm.ply
  CHECKS ${cli_scripts}/check_register_units.cmake DEFINE UNITS=mm DETECTION=given
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --units mm --quiet
       --out ${cli_dir}/units_mm.ply)
set(scan_in_metres ${MORPHREG_SHARED_DATA_DIR}/mne_fsaverage_head/fsaverage_head.ply) # MNE's scalp, in metres
morphreg_cli_test(RegisterDetectsAScanInMetres FIXTURES_REQUIRED "cli_small;cli_model" REQUIRES_DATA ${scan_in_metres}
  REPORT ${cli_dir}/units_m.json FILES ${cli_dir}/units_m.ply
  CHECKS ${cli_scripts}/check_register_units.cmake DEFINE UNITS=m DETECTION=auto
  ARGS register --scan ${scan_in_metres} --model ${cli_dir}/small_model.h5 --quiet --out ${cli_dir}/units_m.ply)
# A fit that fails its checks exits 4, and its report is written and marked failed: a mm scan read as cm. The fit
# either shrinks the model until its scale fails the checks or loses every correspondence (seen on one machine
# and the other); both are failed fits.
morphreg_cli_test(RegisterFailedChecksExit4 FIXTURES_REQUIRED "cli_small;cli_model" EXPECT_CODE 4
  ERROR "the fit failed its checks: " REPORT ${cli_dir}/failed.json
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --units cm --quiet
       --out ${cli_dir}/failed.ply)
morphreg_cli_expect_exit(RegisterWrongComponentCountExits1 1 "regions"
  register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --components 3 4 --out ${cli_dir}/bad.ply)
set_tests_properties(CliTest.RegisterCorruptModelIsNamed CliTest.RegisterMissingScanIsNamed
  CliTest.RegisterUnknownLandmarkIsNamed CliTest.RegisterWrongTruthIsNamed CliTest.RegisterWrongComponentCountExits1
  PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model;cli_synth")

# register --scans: four synthetic scans of the small model's population in a manifest.
morphreg_cli_test(BatchScans FIXTURES_SETUP cli_batch_scans
  FILES ${cli_dir}/batch_scans/scan_0.pcd ${cli_dir}/batch_scans/scan_3.pcd ${cli_dir}/batch_scans/scan_0_landmarks.json
  ARGS synth --count 4 --resolution 24 --scans 4 --angular-samples 200 --row-spacing 3 --quiet
       --out-dir ${cli_dir}/batch_scans)
file(WRITE ${cli_dir}/batch.csv "scan,landmarks,id\nbatch_scans/scan_0.pcd,batch_scans/scan_0_landmarks.json\n"
           "batch_scans/scan_1.pcd\nbatch_scans/scan_2.pcd,,third\nbatch_scans/scan_3.pcd\n")
file(WRITE ${cli_dir}/batch_failing.csv "batch_scans/scan_0.pcd\nscan_flat.pcd\nno_such_scan.pcd\nbatch_scans/scan_1.pcd\n")
file(WRITE ${cli_dir}/batch_duplicate.csv "scan,landmarks,id\nbatch_scans/scan_0.pcd\n\nbatch_scans/scan_1.pcd,,scan_0\n")
# Resume, interruption, shards, records of what made each output and locks (test/scripts/cli/batch.sh says what
# each case checks); exit 0 only when every check held, 77 when the case cannot apply here (skipped).
foreach(case resume-after-kill interrupt shards-equal-one-run merge-other-run other-model changed-scan
    changed-settings live-lock stale-lock shards-and-locks cores-from-affinity)
  morphreg_command_test(CliTest.Batch_${case} FIXTURES_REQUIRED "cli_model;cli_batch_scans" SKIP_CODE 77
    COMMAND ${cli_scripts}/batch.sh $<TARGET_FILE:morphreg_cli> ${cli_dir}/small_model.h5 ${cli_dir}/batch.csv
            ${cli_dir}/batch_${case} ${case})
endforeach()
# register --scans as a Slurm job array (docs/register_study.sbatch, 3 tasks, one cancelled and resubmitted) on a
# one-node Slurm the test starts and stops (scripts/local_slurm.sh); skipped, saying why, where Slurm cannot run
# (not installed, not root). The script docs/cluster.md shows is that file, byte for byte.
morphreg_command_test(SlurmTest.JobArrayEqualsOneRun FIXTURES_REQUIRED "cli_model;cli_batch_scans" SKIP_CODE 77
  TIMEOUT 900
  COMMAND ${cli_scripts}/slurm_array.sh $<TARGET_FILE:morphreg_cli> ${cli_dir}/small_model.h5 ${cli_dir}/batch_scans
          ${cli_dir}/slurm_array ${PROJECT_SOURCE_DIR})
morphreg_command_test(SlurmTest.ClusterDocShowsTheSbatchScript
  COMMAND ${CMAKE_COMMAND} -DDOC=${PROJECT_SOURCE_DIR}/docs/cluster.md
          -DFILE=${PROJECT_SOURCE_DIR}/docs/register_study.sbatch -P ${cli_scripts}/doc_shows_file.cmake)
# Failing scans are recorded in the summary, naming the problem, and the others registered; exit 4 at the end.
morphreg_cli_test(BatchFailingScanIsNamedInTheSummary FIXTURES_REQUIRED "cli_model;cli_batch_scans" EXPECT_CODE 4
  FIXTURES_SETUP cli_batch_failing
  ERROR "2 of 4 scans failed" CLEAN ${cli_dir}/batch_failing REPORT ${cli_dir}/batch_failing/summary.json STATUS none
  FILES ${cli_dir}/batch_failing/summary.csv ${cli_dir}/batch_failing/scan_0.ply ${cli_dir}/batch_failing/scan_1.ply
  CHECKS ${cli_scripts}/check_batch_failures.cmake DEFINE SUMMARY=${cli_dir}/batch_failing/summary.csv
  ARGS register --scans ${cli_dir}/batch_failing.csv --model ${cli_dir}/small_model.h5
       --out-dir ${cli_dir}/batch_failing --quiet)
morphreg_cli_expect_exit(BatchDuplicateIdIsNamed 1 "batch_duplicate.csv:4: duplicate scan id 'scan_0' (first at"
  register --scans ${cli_dir}/batch_duplicate.csv --model ${cli_dir}/small_model.h5 --out-dir ${cli_dir}/bad_batch)
morphreg_cli_expect_exit(BatchShardOutOfRangeIsNamed 1 "shard '2/2': expected I/N with 0 <= I < N"
  register --scans ${cli_dir}/batch.csv --model ${cli_dir}/small_model.h5 --out-dir ${cli_dir}/bad_batch --shard 2/2)
morphreg_cli_expect_exit(BatchShardAutoNeedsSlurm 1 "SLURM_ARRAY_TASK_ID is not set"
  register --scans ${cli_dir}/batch.csv --model ${cli_dir}/small_model.h5 --out-dir ${cli_dir}/bad_batch --shard auto)
set_tests_properties(CliTest.BatchShardAutoNeedsSlurm PROPERTIES
  ENVIRONMENT_MODIFICATION "SLURM_ARRAY_TASK_ID=unset:;SLURM_ARRAY_TASK_COUNT=unset:")
morphreg_cli_expect_exit(BatchNeedsOutDir 1 "give --out-dir" register --scans ${cli_dir}/batch.csv
  --model ${cli_dir}/small_model.h5)
morphreg_cli_expect_exit(BatchScanAndScansExit2 2 "--scan excludes --scans" register --scans ${cli_dir}/batch.csv
  --scan a.pcd --model b.h5)
morphreg_cli_expect_exit(RegisterNeedsAScan 2 "--scan or --scans is required" register --model b.h5)
morphreg_cli_expect_exit(MergeSummariesMissingShardIsNamed 1 "shard 1/2 is missing"
  merge-summaries --out-dir ${cli_dir}/merge_missing ${cli_dir}/batch_shard0_only.json)
file(WRITE ${cli_dir}/batch_shard0_only.json "{\"shard\": \"0/2\", \"scans\": [{\"id\": \"a\", \"status\": \"ok\"}]}")
morphreg_cli_expect_exit(MergeSummariesRejectsOtherJson 1 "batch.csv.json: not a batch summary"
  merge-summaries --out-dir ${cli_dir}/merge_bad ${cli_dir}/batch.csv.json)
file(WRITE ${cli_dir}/batch.csv.json "{\"rows\": []}")
# A lock file that is not morphreg's, a model that is not there (its content hash is taken first) and a malformed
# test hook are named.
file(WRITE ${cli_dir}/batch_corrupt_lock/.morphreg.lock "not a lock\n")
morphreg_cli_expect_exit(BatchUnreadableLockIsNamed 1 "batch_corrupt_lock/.morphreg.lock: not a lock file morphreg can read"
  register --scans ${cli_dir}/batch.csv --model ${cli_dir}/small_model.h5 --out-dir ${cli_dir}/batch_corrupt_lock)
morphreg_cli_expect_exit(BatchMissingModelIsNamed 1 "no_such_model.h5: no such file"
  register --scans ${cli_dir}/batch.csv --model ${cli_dir}/no_such_model.h5 --out-dir ${cli_dir}/bad_batch)
morphreg_cli_expect_exit(BatchMalformedTestHoldIsNamed 1 "MORPHREG_BATCH_TEST_HOLD='x': expected N:DIR"
  register --scans ${cli_dir}/batch.csv --model ${cli_dir}/small_model.h5 --out-dir ${cli_dir}/batch_bad_hold)
set_tests_properties(CliTest.BatchMalformedTestHoldIsNamed PROPERTIES ENVIRONMENT MORPHREG_BATCH_TEST_HOLD=x)
set_tests_properties(CliTest.BatchDuplicateIdIsNamed CliTest.BatchShardOutOfRangeIsNamed CliTest.BatchShardAutoNeedsSlurm
  CliTest.BatchNeedsOutDir CliTest.BatchUnreadableLockIsNamed CliTest.BatchMissingModelIsNamed
  CliTest.BatchMalformedTestHoldIsNamed PROPERTIES FIXTURES_REQUIRED "cli_model;cli_batch_scans")

# build-model --from-scans: the batch scans registered with the small model and resampled, a flat scan among them
# reported and left out; the model keeps the small model's regions and landmarks. With one usable scan it fails and
# leaves nothing behind.
file(WRITE ${cli_dir}/from_scans.csv "batch_scans/scan_0.pcd\nscan_flat.pcd\nbatch_scans/scan_1.pcd\nbatch_scans/scan_2.pcd\n")
file(WRITE ${cli_dir}/from_one_scan.csv "batch_scans/scan_0.pcd\nscan_flat.pcd\n")
morphreg_cli_test(BuildModelFromScans FIXTURES_REQUIRED "cli_model;cli_batch_scans" FIXTURES_SETUP cli_from_scans
  OUTPUT "3 of 4 scans registered and resampled, 1 left out.*from_scans.h5: 3458 vertices, 7 region\\(s\\), components per region \\[2,2,2,2,2,2,2\\], 45 landmarks"
  CLEAN ${cli_dir}/from_scans_scans FILES ${cli_dir}/from_scans.h5 ${cli_dir}/from_scans_scans/scan_0.ply ${cli_dir}/from_scans_scans/scan_0.json
  REPORT ${cli_dir}/from_scans_scans/summary.json STATUS none
  REPORT_MATCH "\"included\": 3,\n  \"left_out\": 1,.*\"id\": \"scan_flat\",\n *\"included\": false,\n *\"reason\": \"[^\"]*lie in a plane"
  CHECKS ${cli_scripts}/check_scan_report.cmake DEFINE SCAN_REPORT=${cli_dir}/from_scans_scans/scan_0.json
  ARGS build-model --from-scans ${cli_dir}/from_scans.csv --model ${cli_dir}/small_model.h5 --fit-components 8
       --components 2 --quiet --out ${cli_dir}/from_scans.h5)
morphreg_cli_test(BuildModelFromOneScanFailsAndLeavesNothing FIXTURES_REQUIRED "cli_model;cli_batch_scans" EXPECT_CODE 1
  ERROR "1 of 2 scans registered and resampled, 1 left out; a model needs at least two"
  ABSENT ${cli_dir}/from_one_scan.h5 ${cli_dir}/from_one_scan_scans
  ARGS build-model --from-scans ${cli_dir}/from_one_scan.csv --model ${cli_dir}/small_model.h5 --quiet
       --out ${cli_dir}/from_one_scan.h5)
morphreg_cli_expect_exit(BuildModelFromScansNeedsModel 2 "needs --model"
  build-model --from-scans ${cli_dir}/from_scans.csv --out ${cli_dir}/bad.h5)

# evaluate-model: the small model against two of its own heads and the heads of the scans' model.
morphreg_cli_test(EvaluateModelPrintsJson FIXTURES_REQUIRED "cli_small;cli_model"
  OUTPUT "\"global_components\": 8,.*\"components\": 8,\n *\"generalisation\": {\n *\"mean_mm\": [0-9.e-]+,.*\"specificity\": {\n *\"mean_mm\": [0-9.]+"
  ARGS evaluate-model --model ${cli_dir}/small_model.h5 --meshes ${cli_dir}/small/head_010.ply
       ${cli_dir}/small/head_011.ply --training ${cli_dir}/small --components 0,8 --samples 50 --json --quiet)
morphreg_cli_test(EvaluateModelFromScansTable FIXTURES_REQUIRED "cli_small;cli_from_scans"
  OUTPUT "components  compactness  generalisation mm \\(sd\\)  specificity mm \\(sd\\)\n +1 +0\\.[0-9]+ +[0-9.]+ \\([0-9.]+\\)  [0-9.]+ \\("
  ARGS evaluate-model --model ${cli_dir}/from_scans.h5 --meshes ${cli_dir}/small/head_005.ply
       --training ${cli_dir}/from_scans_scans/scan_0.ply ${cli_dir}/from_scans_scans/scan_1.ply --quiet)
morphreg_cli_expect_exit(EvaluateModelTooManyComponentsIsNamed 1 "99 components asked for; it has 8 global"
  evaluate-model --model ${cli_dir}/small_model.h5 --meshes ${cli_dir}/small/head_010.ply --components 99)
set_tests_properties(CliTest.EvaluateModelTooManyComponentsIsNamed PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")

# The real head-and-shoulders scan as a new user registers it (skipped without ../shared/data): the ICT model at 30
# components, no landmarks, the README's real-scan options; exit 0 and status "ok" mean the fit passed its checks.
set(real_scan ${MORPHREG_SHARED_DATA_DIR}/real_head_scans/leeperrysmith_scan_82k_mm.ply)
set(ict_dir ${MORPHREG_SHARED_DATA_DIR}/ict_facekit)
morphreg_cli_test(BuildIct30Model FIXTURES_SETUP cli_ict30 REQUIRES_DATA ${ict_dir}/ict_head_pca_basis.npy
  FILES ${cli_dir}/ict30.h5
  ARGS build-model --from-ict ${ict_dir} --samples 300 --components 30 --quiet --out ${cli_dir}/ict30.h5)
morphreg_cli_test(RegisterRealScanWithoutLandmarks FIXTURES_REQUIRED cli_ict30
  REQUIRES_DATA ${real_scan} ${ict_dir}/ict_head_pca_basis.npy
  REPORT ${cli_dir}/real_fit.json FILES ${cli_dir}/real_fit.ply
  ARGS register --scan ${real_scan} --model ${cli_dir}/ict30.h5 --components 30 --area-weighting --shape-prior 1.5
       --tangential-weight 0.1 --no-target-smoothing --quiet --out ${cli_dir}/real_fit.ply)

# fit-photos on menpo3d_james's two real photos (about 25 degrees to either side) with the cameras recovered with the
# scan (james_cameras.json, K R t and P by image) and their 68 landmarks as iBUG .pts files, which the test writes
# from the CSVs: those list the points in james.ljson's group order (chin, leye, reye, leyebrow, nose, reyebrow,
# mouth), not iBUG-68's, so each .pts line k holds CSV point ibug_from_ljson[k]. Measured: landmark RMS 2.34 mm.
set(james ${MORPHREG_SHARED_DATA_DIR}/real_head_scans/menpo3d_james)
if(EXISTS ${james}/james_cameras.json)
  set(ibug_from_ljson 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 29 30 31 32 33 43 44 45 46 47 34 35 36 37 38 39 40 41
      42 17 18 19 20 21 22 23 24 25 26 27 28 48 49 50 51 52 53 54 55 56 57 58 59 60 61 62 63 64 65 66 67)
  foreach(side left right)
    file(STRINGS ${james}/james_photo_${side}_landmarks68.csv csv_lines REGEX "^[0-9]")
    set(pts "version: 1\nn_points: 68\n{\n")
    foreach(k ${ibug_from_ljson})
      list(GET csv_lines ${k} line)
      string(REPLACE "," " " line "${line}")
      string(APPEND pts "${line}\n")
    endforeach()
    file(WRITE ${cli_dir}/james_${side}.pts "${pts}}\n")
  endforeach()
endif()
morphreg_cli_test(FitPhotosJamesRealPhotosWithTheirCameras FIXTURES_REQUIRED cli_ict30
  REQUIRES_DATA ${james}/james_cameras.json ${ict_dir}/ict_head_pca_basis.npy
  MAXIMA "landmark RMS ([0-9.]+) mm=>3.0"
  OUTPUT "fit \\(joint\\): [0-9]+ iterations.*wrote .*james_fit.ply \\(model frame, mm\\) \\(vertex colours: the photos"
  REPORT ${cli_dir}/james_fit.json REPORT_MATCH "\"camera_estimated\": false" "\"rule\": \"left-out landmarks\""
  FILES ${cli_dir}/james_fit.ply
  ARGS fit-photos --model ${cli_dir}/ict30.h5 --view ${james}/james_photo_left.jpg --landmarks ${cli_dir}/james_left.pts
       --camera ${james}/james_cameras.json --view ${james}/james_photo_right.jpg
       --landmarks ${cli_dir}/james_right.pts --camera ${james}/james_cameras.json --report ${cli_dir}/james_fit.json
       --out ${cli_dir}/james_fit.ply)

morphreg_cli_test(DemoRunsWithoutScreenshot
  OUTPUT "demo: 6 heads.*fitted mesh .*fitted.ply, report .*report.json\n.*vertex RMS [0-9.]+ mm"
  REPORT ${cli_dir}/demo/report.json FILES ${cli_dir}/demo/fitted.ply
  ARGS demo --count 6 --resolution 20 --angular-samples 150 --row-spacing 4 --iterations 40 --no-screenshot --quiet
       --out-dir ${cli_dir}/demo)

# Screenshots under a virtual X server, one at a time.
morphreg_cli_test(RenderWritesPng FIXTURES_REQUIRED cli_synth XVFB OUTPUT "wrote .*render.png \\(320x240\\)"
  FILES ${cli_dir}/render.png CHECKS ${cli_scripts}/check_png.cmake
  DEFINE PNG=${cli_dir}/render.png WIDTH=320 HEIGHT=240
  ARGS render --mesh ${cli_dir}/synth/head_000.ply --cloud ${cli_dir}/synth/scan_0.pcd --width 320 --height 240
       --view oblique --out ${cli_dir}/render.png)
# VTK's warnings reach stderr only with --verbose (landmark spheres: 12 deprecation warnings each, from VTK's
# mapper copies for PCL's level-of-detail actors); -q leaves stderr empty.
morphreg_cli_test(RenderPrintsNoVtkMessages FIXTURES_REQUIRED "cli_small;cli_synth" XVFB
  LOG ${cli_dir}/RenderPrintsNoVtkMessages.log FORBID "[vV][tT][kK]|Warning" FILES ${cli_dir}/render_log.png
  ARGS render --mesh ${cli_dir}/small/head_000.ply --landmarks ${cli_dir}/small/head_000_landmarks.json
       --cloud ${cli_dir}/synth/scan_0.pcd --width 320 --height 240 --out ${cli_dir}/render_log.png)
morphreg_cli_test(RenderQuietPrintsNothingOnStderr FIXTURES_REQUIRED cli_synth XVFB
  LOG ${cli_dir}/RenderQuietPrintsNothingOnStderr.log EMPTY_STDERR FILES ${cli_dir}/render_quiet.png
  ARGS render --mesh ${cli_dir}/synth/head_000.ply --width 320 --height 240 -q --out ${cli_dir}/render_quiet.png)
morphreg_cli_expect_exit(RenderMissingFileIsNamed 2 "no_such_mesh.ply" render --mesh ${cli_dir}/no_such_mesh.ply)
# --side-by-side: two meshes in a left and a right viewport (a fit and its resampled scan in docs/accuracy.md).
morphreg_cli_test(RenderSideBySide FIXTURES_REQUIRED cli_synth XVFB OUTPUT "wrote .*render_sides.png \\(320x240\\)"
  FILES ${cli_dir}/render_sides.png CHECKS ${cli_scripts}/check_png.cmake
  DEFINE PNG=${cli_dir}/render_sides.png WIDTH=320 HEIGHT=240
  ARGS render --mesh ${cli_dir}/synth/head_000.ply --mesh ${cli_dir}/synth/head_001.ply --side-by-side "head 0"
       "head 1" --width 320 --height 240 --out ${cli_dir}/render_sides.png)
morphreg_cli_expect_exit(RenderSideBySideNeedsTwoMeshes 1 "render --side-by-side shows two --mesh files"
  render --mesh ${cli_dir}/synth/head_000.ply --side-by-side left right --out ${cli_dir}/render_one.png)
set_tests_properties(CliTest.RenderSideBySideNeedsTwoMeshes PROPERTIES FIXTURES_REQUIRED cli_synth)
# The colour bar of a residual mesh sits at the right (RegistrationVisualizer::colourBarRegion); the fit is framed
# to fill the rest of the picture.
set(cli_bar_drawn "--drawn 0.86 0.1 0.98 0.9 0.05")
morphreg_cli_test(RenderResidualMeshShowsColourBar FIXTURES_REQUIRED cli_fit XVFB
  OUTPUT "wrote .*render_residuals.png \\(400x300\\)" FILES ${cli_dir}/render_residuals.png
  CHECKS ${cli_scripts}/check_png_pixels.cmake
  DEFINE PYTHON=${Python3_EXECUTABLE} PNG=${cli_dir}/render_residuals.png WIDTH=400 HEIGHT=300
         "PIXEL_CHECKS=${cli_bar_drawn} --drawn 0.05 0.05 0.8 0.95 0.4"
  ARGS render --mesh ${cli_dir}/fit.ply --cloud ${cli_dir}/small/scan_0.pcd --landmarks
       ${cli_dir}/small/scan_0_landmarks.json --width 400 --height 300 --out ${cli_dir}/render_residuals.png)
# A depth camera's organised frame holds NaN where it saw nothing: those points are skipped, the others drawn.
set(cli_organised ${cli_dir}/organised_nan.pcd)
set(organised_points "")
foreach(row RANGE 19)
  foreach(column RANGE 19)
    if(column LESS 5)
      string(APPEND organised_points "nan nan nan\n")
    else()
      string(APPEND organised_points "${column}0 ${row}0 500\n")
    endif()
  endforeach()
endforeach()
file(WRITE ${cli_organised} "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 20\nHEIGHT 20\n"
     "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 400\nDATA ascii\n${organised_points}")
morphreg_cli_test(RenderOrganisedCloudSkipsNaN XVFB OUTPUT "wrote .*render_organised.png \\(320x240\\)"
  FILES ${cli_dir}/render_organised.png CHECKS ${cli_scripts}/check_png_pixels.cmake
  DEFINE PYTHON=${Python3_EXECUTABLE} PNG=${cli_dir}/render_organised.png WIDTH=320 HEIGHT=240
         "PIXEL_CHECKS=--min-std 5 --drawn 0.3 0.3 0.7 0.7 0.02"
  ARGS render --cloud ${cli_organised} --width 320 --height 240 --out ${cli_dir}/render_organised.png)
file(WRITE ${cli_dir}/all_nan.pcd "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n"
     "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\nnan nan nan\nnan nan nan\nnan nan nan\nnan nan nan\n")
morphreg_cli_test(RenderAllMissingCloudIsNamed XVFB EXPECT_CODE 1 ERROR "all_nan.pcd" "no valid point"
  ABSENT ${cli_dir}/render_nan.png ARGS render --cloud ${cli_dir}/all_nan.pcd --out ${cli_dir}/render_nan.png)

# view: the window's picture headless (--screenshot): the scan over the fit coloured by residual, its colour bar, the
# landmarks and the correspondences.
morphreg_cli_test(ViewScreenshotShowsFitAndColourBar FIXTURES_REQUIRED cli_fit XVFB
  OUTPUT "wrote .*view.png \\(400x300\\)" FILES ${cli_dir}/view.png CHECKS ${cli_scripts}/check_png_pixels.cmake
  DEFINE PYTHON=${Python3_EXECUTABLE} PNG=${cli_dir}/view.png WIDTH=400 HEIGHT=300
         "PIXEL_CHECKS=${cli_bar_drawn} --drawn 0.05 0.05 0.8 0.95 0.4"
  ARGS view --scan ${cli_dir}/small/scan_0.pcd --fit ${cli_dir}/fit.ply --landmarks
       ${cli_dir}/small/scan_0_landmarks.json --screenshot ${cli_dir}/view.png --width 400 --height 300)
# A mesh without residuals has no colour bar: the right of the picture stays empty.
morphreg_cli_test(ViewPlainMeshHasNoColourBar FIXTURES_REQUIRED cli_synth XVFB FILES ${cli_dir}/view_plain.png
  CHECKS ${cli_scripts}/check_png_pixels.cmake
  DEFINE PYTHON=${Python3_EXECUTABLE} PNG=${cli_dir}/view_plain.png WIDTH=320 HEIGHT=240
         "PIXEL_CHECKS=--blank 0.9 0.1 1.0 0.9 0.0 --drawn 0.2 0.2 0.8 0.8 0.5"
  ARGS view --fit ${cli_dir}/synth/head_000.ply --screenshot ${cli_dir}/view_plain.png --width 320 --height 240)
morphreg_cli_expect_exit(ViewNeedsSomethingToShow 1 "nothing to show" view --screenshot ${cli_dir}/view_none.png)
morphreg_cli_test(ViewWithoutDisplayIsNamed EXPECT_CODE 1 ERROR "xvfb-run" PROPERTIES
  ENVIRONMENT_MODIFICATION "DISPLAY=unset:" FIXTURES_REQUIRED cli_synth
  ARGS view --fit ${cli_dir}/synth/head_000.ply)

# register --convergence-plot: the RMS per iteration as a PNG chart beside the report, which names it. What is drawn
# in the plot area measured 0.6 % (ten iterations) and 0.8 % (the demo's).
morphreg_cli_test(RegisterWritesConvergencePlot FIXTURES_REQUIRED "cli_small;cli_model" XVFB
  OUTPUT "wrote .*fit_plot.ply.*fit_plot_convergence.png" REPORT ${cli_dir}/fit_plot.json
  REPORT_MATCH "\"convergence_plot\": *{[^}]*fit_plot_convergence.png"
  CHECKS ${cli_scripts}/check_png_pixels.cmake
  DEFINE PYTHON=${Python3_EXECUTABLE} PNG=${cli_dir}/fit_plot_convergence.png WIDTH=800 HEIGHT=500
         "PIXEL_CHECKS=--drawn 0.15 0.15 0.9 0.85 0.003"
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --components 5 --iterations 30
       --quiet --out ${cli_dir}/fit_plot.ply --convergence-plot ${cli_dir}/fit_plot_convergence.png)
morphreg_cli_test(RegisterConvergencePlotWithoutDisplayFailsEarly EXPECT_CODE 1 ERROR "--convergence-plot" "xvfb-run"
  FIXTURES_REQUIRED "cli_small;cli_model" ABSENT ${cli_dir}/no_plot.ply ${cli_dir}/no_plot.png
  PROPERTIES ENVIRONMENT_MODIFICATION "DISPLAY=unset:"
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5 --out ${cli_dir}/no_plot.ply
       --convergence-plot ${cli_dir}/no_plot.png)
morphreg_cli_test(DemoWritesScreenshot XVFB FIXTURES_SETUP cli_demo_shot OUTPUT "overlay .*demo_shot/overlay.png"
  REPORT ${cli_dir}/demo_shot/report.json FILES ${cli_dir}/demo_shot/overlay.png ${cli_dir}/demo_shot/fitted.ply
  CHECKS ${cli_scripts}/check_png.cmake DEFINE PNG=${cli_dir}/demo_shot/overlay.png WIDTH=400 HEIGHT=300
  ARGS demo --count 6 --resolution 20 --angular-samples 150 --row-spacing 4 --iterations 40 --width 400 --height 300
       --convergence-plot --quiet --out-dir ${cli_dir}/demo_shot)
# The demo's overlay: the fit coloured by residual beside its colour bar, filling the picture.
morphreg_command_test(CliTest.DemoOverlayShowsFitAndColourBar FIXTURES_REQUIRED cli_demo_shot
  COMMAND ${Python3_EXECUTABLE} ${cli_scripts}/check_png_pixels.py ${cli_dir}/demo_shot/overlay.png 400 300
          --drawn 0.86 0.1 0.98 0.9 0.05 --drawn 0.1 0.1 0.75 0.9 0.4)
morphreg_command_test(CliTest.DemoConvergencePlotIsDrawn FIXTURES_REQUIRED cli_demo_shot
  COMMAND ${Python3_EXECUTABLE} ${cli_scripts}/check_png_pixels.py ${cli_dir}/demo_shot/convergence.png 800 500
          --drawn 0.15 0.15 0.9 0.85 0.003)
morphreg_cli_test(RegisterScreenshotWithoutDisplayFails FIXTURES_REQUIRED "cli_small;cli_model" EXPECT_CODE 1
  ERROR "xvfb-run" ABSENT ${cli_dir}/no_display.ply ${cli_dir}/no_display.png REPORT ${cli_dir}/no_display.json
  PROPERTIES ENVIRONMENT_MODIFICATION "DISPLAY=unset:"
  ARGS register --scan ${cli_dir}/small/scan_0.pcd --model ${cli_dir}/small_model.h5
       --screenshot ${cli_dir}/no_display.png --out ${cli_dir}/no_display.ply)
morphreg_cli_test(DemoScreenshotWithoutDisplayFailsEarly EXPECT_CODE 1 ERROR "--no-screenshot"
  ABSENT ${cli_dir}/bad_demo PROPERTIES ENVIRONMENT_MODIFICATION "DISPLAY=unset:"
  ARGS demo --count 2 --out-dir ${cli_dir}/bad_demo)

# fit-photos: the small model fitted to the annotated photos of the first head (measured: vertex RMS 1.07 mm against
# the truth with the joint fit, width RMS 0.20 mm).
set(small_photos fit-photos --model ${cli_dir}/small_model.h5 --profile ${cli_dir}/small/photo_0_profile.json)
morphreg_cli_test(FitPhotosAgainstTheTruth FIXTURES_REQUIRED "cli_small;cli_model" FIXTURES_SETUP cli_photos
  MAXIMA "vertex RMS against the truth .*photo_0_truth.json: ([0-9.]+) mm=>1.4"
  OUTPUT "wrote .*photos.ply" FILES ${cli_dir}/photos.ply
  REPORT ${cli_dir}/photos.json REPORT_MATCH "\"truth_error_mm\": *{[^}]*\"rms\": [01]\\."
  ARGS ${small_photos} --frontal ${cli_dir}/small/photo_0_frontal.json --truth ${cli_dir}/small/photo_0_truth.json
       --report ${cli_dir}/photos.json --out ${cli_dir}/photos.ply)
morphreg_cli_test(ModelWithoutProfileLine FIXTURES_REQUIRED cli_small FIXTURES_SETUP cli_no_profile
  FILES ${cli_dir}/no_profile_model.h5
  ARGS build-model --mesh ${cli_dir}/small/head_000.ply --mesh ${cli_dir}/small/head_001.ply --quiet
       --landmark-vertices ${cli_dir}/small/landmark_vertices.json --out ${cli_dir}/no_profile_model.h5)
morphreg_cli_expect_exit(FitPhotosWithoutProfileLineIsNamed 1 "no_profile_model.h5: the model has no profile line"
  fit-photos --model ${cli_dir}/no_profile_model.h5 --profile ${cli_dir}/small/photo_0_profile.json
  --frontal ${cli_dir}/small/photo_0_frontal.json --out ${cli_dir}/bad_photos.ply)
set_tests_properties(CliTest.FitPhotosWithoutProfileLineIsNamed PROPERTIES FIXTURES_REQUIRED "cli_small;cli_no_profile")
morphreg_cli_expect_exit(FitPhotosWrongViewIsNamed 1 "photo_0_frontal.json: \"view\" is \"frontal\""
  fit-photos --model ${cli_dir}/small_model.h5 --profile ${cli_dir}/small/photo_0_frontal.json
  --frontal ${cli_dir}/small/photo_0_frontal.json --out ${cli_dir}/bad_photos.ply)
set_tests_properties(CliTest.FitPhotosWrongViewIsNamed PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")
morphreg_cli_expect_exit(FitPhotosBadApproachExits2 2 "--approach" ${small_photos}
  --frontal ${cli_dir}/small/photo_0_frontal.json --approach x)

# fit-photos with the user's components and prior; the profile fit needs no frontal photo, the others do.
morphreg_cli_test(FitPhotosTakesComponentsAndShapePrior FIXTURES_REQUIRED "cli_small;cli_model"
  OUTPUT "largest coefficient [0-9.]+ standard deviations.*vertex RMS against the truth"
  REPORT ${cli_dir}/photos_prior.json REPORT_MATCH "\"components\": *.\n *4\n" "\"lambda2\": 2\\.0"
  FILES ${cli_dir}/photos_prior.ply
  ARGS ${small_photos} --frontal ${cli_dir}/small/photo_0_frontal.json --components 4 --shape-prior 2
       --truth ${cli_dir}/small/photo_0_truth.json --report ${cli_dir}/photos_prior.json
       --out ${cli_dir}/photos_prior.ply)
morphreg_cli_test(FitPhotosProfileNeedsNoFrontal FIXTURES_REQUIRED "cli_small;cli_model"
  OUTPUT "fit \\(profile\\): [0-9]+ iterations, outline RMS [0-9.]+ mm over [0-9]+ outline points;"
  FORBID "landmark RMS" FILES ${cli_dir}/photos_profile.ply
  ARGS ${small_photos} --approach profile --quiet --out ${cli_dir}/photos_profile.ply)
# The synthetic frontal photos mark the jaw, chin, neck and head contour: outline constraints by default, left out
# (with a warning) with --outline-landmarks ignored, fixed vertices with vertex; the coefficient limit must be > 0.
morphreg_cli_test(FitPhotosLeavesOutOutlineLandmarks FIXTURES_REQUIRED "cli_small;cli_model"
  OUTPUT "the outline landmarks .*chin.* are left out"
  REPORT ${cli_dir}/photos_outline.json FILES ${cli_dir}/photos_outline.ply
  ARGS ${small_photos} --frontal ${cli_dir}/small/photo_0_frontal.json --report ${cli_dir}/photos_outline.json
       --outline-landmarks ignored --out ${cli_dir}/photos_outline.ply)
morphreg_cli_test(FitPhotosContourWeightUsesOutlineLandmarks FIXTURES_REQUIRED "cli_small;cli_model"
  OUTPUT "wrote .*photos_contour.ply" FORBID "left out|largest coefficient [2-9]\\.[0-9]*[1-9]"
  REPORT ${cli_dir}/photos_contour.json FILES ${cli_dir}/photos_contour.ply
  ARGS ${small_photos} --frontal ${cli_dir}/small/photo_0_frontal.json --outline-landmarks vertex
       --outline-landmark-weight 1 --coefficient-limit 2
       --report ${cli_dir}/photos_contour.json --out ${cli_dir}/photos_contour.ply)
morphreg_cli_expect_exit(FitPhotosCoefficientLimitMustBePositive 2 "--coefficient-limit"
  fit-photos --model ${cli_dir}/small_model.h5 --profile ${cli_dir}/small/photo_0_profile.json
  --frontal ${cli_dir}/small/photo_0_frontal.json --coefficient-limit 0 --out ${cli_dir}/bad.ply)
set_tests_properties(CliTest.FitPhotosCoefficientLimitMustBePositive PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")
morphreg_cli_expect_exit(FitPhotosJointNeedsFrontal 1 "--approach joint needs --frontal"
  fit-photos --model ${cli_dir}/small_model.h5 --profile ${cli_dir}/small/photo_0_profile.json --out ${cli_dir}/bad.ply)
# Bad annotations: a profile facing left, a silhouette of 9 points, frontal landmarks without the nose tip.
set(silhouette "")
foreach(k RANGE 11)
  math(EXPR x "600 - 5 * ${k}")
  math(EXPR y "300 + 35 * ${k}")
  list(APPEND silhouette "[${x}, ${y}]")
endforeach()
list(JOIN silhouette ", " left_facing)
list(SUBLIST silhouette 0 9 nine)
list(JOIN nine ", " nine)
set(profile_head "{\"view\": \"profile\", \"image\": {\"width\": 1000, \"height\": 1200}, \"units\": \"px\"")
file(WRITE ${cli_dir}/profile_left.json "${profile_head}, \"nose_tip\": [500, 500], \"silhouette\": [${left_facing}]}")
file(WRITE ${cli_dir}/profile_nine.json "${profile_head}, \"nose_tip\": [700, 500], \"silhouette\": [${nine}]}")
file(WRITE ${cli_dir}/frontal_no_nose.json "{\"view\": \"frontal\", \"image\": {\"width\": 1000, \"height\": 1200}, "
           "\"units\": \"px\", \"landmarks\": [{\"id\": \"chin\", \"position\": [500, 900]}, "
           "{\"id\": \"left_eye_outer\", \"position\": [600, 400]}, "
           "{\"id\": \"right_eye_outer\", \"position\": [400, 400]}]}")
foreach(case "profile_left;the face looks left" "profile_nine;the silhouette polyline has 9 points")
  list(GET case 0 name)
  list(GET case 1 text)
  morphreg_cli_expect_exit(FitPhotosRejects_${name} 1 "${name}.json: ${text}"
    fit-photos --model ${cli_dir}/small_model.h5 --profile ${cli_dir}/${name}.json --approach profile
    --out ${cli_dir}/bad.ply)
endforeach()
morphreg_cli_expect_exit(FitPhotosRejects_frontal_no_nose 1 "frontal_no_nose.json: the frontal landmarks have no nose tip (nose_tip, or"
  fit-photos --model ${cli_dir}/small_model.h5 --profile ${cli_dir}/small/photo_0_profile.json
  --frontal ${cli_dir}/frontal_no_nose.json --out ${cli_dir}/bad.ply)
set_tests_properties(CliTest.FitPhotosJointNeedsFrontal CliTest.FitPhotosRejects_profile_left
  CliTest.FitPhotosRejects_profile_nine CliTest.FitPhotosRejects_frontal_no_nose
  PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")

# fit-photos --view: each --landmarks, --camera and --outline belongs to the --view before it; bad groups, cameras
# and landmarks are named with their file.
set(view_photo ${PROJECT_SOURCE_DIR}/docs/images/heads.png) # 1500 x 760 px
file(WRITE ${cli_dir}/view_landmarks.csv "id,x,y\nnose_tip,700,400\nleft_eye_outer,760,330\nright_eye_outer,640,330\n"
           "left_mouth_corner,730,470\nright_mouth_corner,670,470\nchin,700,560\n")
file(WRITE ${cli_dir}/view_far_landmarks.csv "id,x,y\nnose_tip,700,400\nchin,700,5000\n")
file(WRITE ${cli_dir}/view_camera_no_t.json "{\"K\": [[3000, 0, 750], [0, 3000, 380], [0, 0, 1]], "
           "\"R\": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]}")
file(WRITE ${cli_dir}/view_camera_singular.json "{\"P\": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]]}")
set(view_model fit-photos --model ${cli_dir}/small_model.h5 --out ${cli_dir}/bad_view.ply)
foreach(case
    "LandmarksBeforeView;give it after the --view photo it belongs to;--landmarks;${cli_dir}/view_landmarks.csv;--view;${view_photo}"
    "ViewAndPairTogether;cannot be fitted together;--view;${view_photo};--landmarks;${cli_dir}/view_landmarks.csv;--profile;${cli_dir}/small/photo_0_profile.json"
    "ViewWithoutAnnotations;heads.png: the photo has neither landmarks nor an outline;--view;${view_photo}"
    "LandmarksOutsideThePhoto;lies outside the 1500 x 760 px photo;--view;${view_photo};--landmarks;${cli_dir}/view_far_landmarks.csv"
    "CameraWithoutT;view_camera_no_t.json (camera of heads.png): missing \"t\";--view;${view_photo};--landmarks;${cli_dir}/view_landmarks.csv;--camera;${cli_dir}/view_camera_no_t.json"
    "SingularCamera;view_camera_singular.json (camera of heads.png): P's left 3 x 3 block is singular;--view;${view_photo};--landmarks;${cli_dir}/view_landmarks.csv;--camera;${cli_dir}/view_camera_singular.json"
    "TooFewLandmarksForACamera;heads.png: a camera is estimated from at least 6 landmarks the model has, got 5;--view;${view_photo};--landmarks;${cli_dir}/view_landmarks.csv")
  list(GET case 0 name)
  list(GET case 1 text)
  list(SUBLIST case 2 -1 view_args)
  morphreg_cli_expect_exit(FitPhotosView${name} 1 "${text}" ${view_model} ${view_args})
  set_tests_properties(CliTest.FitPhotosView${name} PROPERTIES FIXTURES_REQUIRED "cli_small;cli_model")
endforeach()

# warp: one small head onto the next head's landmarks, with the error against that head (measured mean 3.58 mm).
set(small_warp warp --mesh ${cli_dir}/small/head_000.ply --source ${cli_dir}/small/head_000_landmarks.json
    --target ${cli_dir}/small/head_001_landmarks.json)
morphreg_cli_test(WarpHeadOntoAnotherHeadsLandmarks FIXTURES_REQUIRED cli_small
  MAXIMA "error against .*head_001.ply: mean ([0-9.]+) mm=>4.6" OUTPUT "wrote .*warped.ply"
  REPORT ${cli_dir}/warp.json FILES ${cli_dir}/warped.ply
  ARGS ${small_warp} --truth ${cli_dir}/small/head_001.ply --report ${cli_dir}/warp.json --out ${cli_dir}/warped.ply)
# Segmented warp by the head's regions, with an overlap per segment (the last takes every landmark).
morphreg_cli_test(SegmentedWarpTakesAnOverlapPerSegment FIXTURES_REQUIRED cli_small
  MAXIMA "error against .*head_001.ply: mean ([0-9.]+) mm=>4.6" OUTPUT "wrote .*warped_segmented.ply"
  REPORT ${cli_dir}/warp_segmented.json REPORT_MATCH "\"overlap_mm\": *.[^\"]*30\\.0,[^\"]*\"all\""
  FILES ${cli_dir}/warped_segmented.ply
  ARGS ${small_warp} --truth ${cli_dir}/small/head_001.ply --labels ${cli_dir}/small/regions.json
       --overlap 30,30,30,30,30,30,inf --report ${cli_dir}/warp_segmented.json --out ${cli_dir}/warped_segmented.ply)
morphreg_cli_test(SegmentedWarpTakesABlendWidthPerSegment FIXTURES_REQUIRED cli_small FIXTURES_SETUP cli_warp_blend OUTPUT "wrote .*warped_blend.ply"
  REPORT ${cli_dir}/warp_blend.json REPORT_MATCH "\"blend_width_mm\": *.[^a-z]*0\\.0,[^a-z]*40\\.0"
  FILES ${cli_dir}/warped_blend.ply
  ARGS ${small_warp} --labels ${cli_dir}/small/regions.json --blend 0,0,0,0,0,0,40 --report ${cli_dir}/warp_blend.json
       --out ${cli_dir}/warped_blend.ply)
morphreg_cli_expect_exit(WarpBlendCountIsNamed 1 "the blend width has 3 values for 7 segments"
  warp --mesh ${cli_dir}/small/head_000.ply --source ${cli_dir}/small/head_000_landmarks.json
  --target ${cli_dir}/small/head_001_landmarks.json --labels ${cli_dir}/small/regions.json --blend 1,2,3
  --out ${cli_dir}/bad_warp.ply)
set_tests_properties(CliTest.WarpBlendCountIsNamed PROPERTIES FIXTURES_REQUIRED cli_small)
morphreg_cli_expect_exit(WarpOverlapCountIsNamed 1 "the overlap has 2 values for 7 segments"
  warp --mesh ${cli_dir}/small/head_000.ply --source ${cli_dir}/small/head_000_landmarks.json
  --target ${cli_dir}/small/head_001_landmarks.json --labels ${cli_dir}/small/regions.json --overlap 30,30
  --out ${cli_dir}/bad_warp.ply)
set_tests_properties(CliTest.WarpOverlapCountIsNamed PROPERTIES FIXTURES_REQUIRED cli_small)
morphreg_cli_expect_exit(WarpNegativeOverlapExits2 2 "--overlap" warp --mesh ${cli_dir}/small/head_000.ply
  --source ${cli_dir}/small/head_000_landmarks.json --target ${cli_dir}/small/head_001_landmarks.json
  --overlap 30,-1 --out ${cli_dir}/bad_warp.ply)
set_tests_properties(CliTest.WarpNegativeOverlapExits2 PROPERTIES FIXTURES_REQUIRED cli_small)
morphreg_cli_expect_exit(WarpMissingLandmarksIsNamed 1 "no_such_landmarks.json: no such file"
  warp --mesh ${cli_dir}/small/head_000.ply --source ${cli_dir}/small/head_000_landmarks.json
  --target ${cli_dir}/no_such_landmarks.json --out ${cli_dir}/bad_warp.ply)
set_tests_properties(CliTest.WarpMissingLandmarksIsNamed PROPERTIES FIXTURES_REQUIRED cli_small)

# warp --method articulated: the MakeHuman base body seated with rigid bones from its 51 major joints (landmark CSVs
# in MakeHuman's decimetres, written from ../shared/data by cli/makehuman_joints_csv.cmake). Measured: mean 0.74 mm.
set(bodies ${MORPHREG_SHARED_DATA_DIR}/makehuman_bodies)
set(mh_dir ${cli_dir}/makehuman)
set(joints_script ${cli_scripts}/makehuman_joints_csv.cmake)
file(MAKE_DIRECTORY ${mh_dir})
foreach(joints standing:base seated:base_seated coincident:base coincident_seated:base_seated
               male:caucasian-male-young)
  string(REPLACE ":" ";" joints ${joints})
  list(GET joints 0 name)
  list(GET joints 1 subject)
  set(coincide "")
  if(name MATCHES "^coincident")
    set(coincide -DCOINCIDE=upperleg01.L____head,lowerleg01.L____head)
  endif()
  morphreg_command_test(CliTest.WarpArticulatedWritesJoints.${name} FIXTURES_SETUP cli_mh_joints
    REQUIRES_DATA ${bodies}/mh_joints.json FILES ${mh_dir}/${name}.csv
    COMMAND ${CMAKE_COMMAND} -DBODIES=${bodies} -DSUBJECT=${subject} -DOUT=${mh_dir}/${name}.csv ${coincide}
            -P ${joints_script})
endforeach()
set(articulated warp --method articulated --mesh ${bodies}/mh_base.ply --labels ${bodies}/mh_segments.json --units dm)
morphreg_cli_test(WarpArticulatedSeatsABody FIXTURES_REQUIRED cli_mh_joints REQUIRES_DATA ${bodies}/mh_joints.json
  OUTPUT "converted to mm" "wrote .*seated.ply" MAXIMA "error against .*mh_base_seated.ply: mean ([0-9.]+) mm=>0.95"
  REPORT ${mh_dir}/seated.json REPORT_MATCH "\"limb_parts\".*\"thigh\".*\"bones\": \"upperleg\\*\""
  FILES ${mh_dir}/seated.ply
  ARGS ${articulated} --source ${mh_dir}/standing.csv --target ${mh_dir}/seated.csv
       --truth ${bodies}/mh_base_seated.ply --report ${mh_dir}/seated.json --out ${mh_dir}/seated.ply)
# A bad input of warp on the MakeHuman bodies: exit 1 with `text` on stderr (skipped without ../shared/data).
function(morphreg_mh_bad_input name text)
  morphreg_cli_test(${name} FIXTURES_REQUIRED cli_mh_joints REQUIRES_DATA ${bodies}/mh_joints.json EXPECT_CODE 1
    ERROR "${text}" ABSENT ${mh_dir}/bad.ply ARGS ${ARGN})
endfunction()
morphreg_mh_bad_input(WarpArticulatedNeedsLabels "the articulated warp needs the segment of each vertex"
  warp --method articulated --mesh ${bodies}/mh_base.ply --source ${mh_dir}/standing.csv
  --target ${mh_dir}/seated.csv --units dm --out ${mh_dir}/bad.ply)
# Hip and knee at one point: in the source only, the point would have two targets; in both, the thigh has no length.
morphreg_mh_bad_input(WarpArticulatedNamesCoincidentJoints
  "landmarks lowerleg01.L____head and upperleg01.L____head are at one position"
  ${articulated} --source ${mh_dir}/coincident.csv --target ${mh_dir}/seated.csv --out ${mh_dir}/bad.ply)
morphreg_mh_bad_input(WarpArticulatedNamesABoneOfNoLength
  "bone 'upperleg.L' in the source joints: joints 'upperleg01.L____head' and 'lowerleg01.L____head' coincide"
  ${articulated} --source ${mh_dir}/coincident.csv --target ${mh_dir}/coincident_seated.csv --out ${mh_dir}/bad.ply)
file(WRITE ${mh_dir}/legs_skeleton.json [=[{"bones": [{"name": "thigh", "head": "upperleg01.L____head",
  "tail": "lowerleg01.L____head", "segment": "legs"}]}]=])
morphreg_mh_bad_input(WarpArticulatedSkeletonMustMatchTheLabels
  "bone 'thigh' carries segment 'legs', which the labels do not have"
  ${articulated} --skeleton ${mh_dir}/legs_skeleton.json --source ${mh_dir}/standing.csv
  --target ${mh_dir}/seated.csv --out ${mh_dir}/bad.ply)
file(WRITE ${mh_dir}/missing_joint_skeleton.json [=[{"bones": [{"name": "thigh", "head": "upperleg01.L____head",
  "tail": "knee_of_nobody", "segment": "lower_body"}, {"name": "rest", "head": "spine05____head",
  "tail": "head____tail", "segment": "upper_body"}]}]=])
morphreg_mh_bad_input(WarpArticulatedNamesAMissingBoneJoint
  "lack joints the skeleton's bones need: knee_of_nobody"
  ${articulated} --skeleton ${mh_dir}/missing_joint_skeleton.json --source ${mh_dir}/standing.csv
  --target ${mh_dir}/seated.csv --out ${mh_dir}/bad.ply)
# warp --method mls: the base body warped to the male subject's proportions from the 51 joints alone (measured:
# mean 10.2 mm; 8.7 mm with the 16 surface landmarks too, MovingLeastSquaresWarpTest).
morphreg_cli_test(WarpMlsBetweenSubjects FIXTURES_REQUIRED cli_mh_joints REQUIRES_DATA ${bodies}/mh_joints.json
  MAXIMA "error against .*mh_caucasian-male-young.ply: mean ([0-9.]+) mm=>13.0" OUTPUT "wrote .*male.ply"
  REPORT ${mh_dir}/male.json FILES ${mh_dir}/male.ply
  ARGS warp --method mls --mesh ${bodies}/mh_base.ply --units dm --source ${mh_dir}/standing.csv
       --target ${mh_dir}/male.csv --truth ${bodies}/mh_caucasian-male-young.ply --report ${mh_dir}/male.json
       --out ${mh_dir}/male.ply)

# Provenance: every report names the version that wrote it and the command line that made it; a model names them in
# its metadata.
function(morphreg_cli_provenance name command fixture)
  morphreg_command_test(CliTest.ReportHasVersionAndCommandLine.${name} FIXTURES_REQUIRED "${fixture}"
    COMMAND ${CMAKE_COMMAND} -DCOMMAND=${command} -DVERSION=${PROJECT_VERSION} ${ARGN}
            -P ${cli_scripts}/check_provenance.cmake)
endfunction()
morphreg_cli_provenance(register register cli_fit -DREPORT=${cli_dir}/fit.json)
morphreg_cli_provenance(synth synth cli_small -DREPORT=${cli_dir}/small/population.json)
morphreg_cli_provenance(batch_summary register cli_batch_failing -DREPORT=${cli_dir}/batch_failing/summary.json)
morphreg_cli_provenance(build_model_from_scans build-model cli_from_scans
  -DREPORT=${cli_dir}/from_scans_scans/summary.json)
morphreg_cli_provenance(fit_photos fit-photos cli_photos -DREPORT=${cli_dir}/photos.json)
morphreg_cli_provenance(warp warp cli_warp_blend -DREPORT=${cli_dir}/warp_blend.json)
morphreg_cli_provenance(resample resample cli_resampled -DREPORT=${cli_dir}/resampled.json)
morphreg_cli_provenance(evaluate_model evaluate-model "cli_small;cli_model"
  "-DARGS=$<TARGET_FILE:morphreg_cli>|evaluate-model|--model|${cli_dir}/small_model.h5|--meshes|${cli_dir}/small/head_010.ply|${cli_dir}/small/head_011.ply|--samples|10|--json|--quiet")
morphreg_cli_provenance(model_info model-info cli_model
  "-DARGS=$<TARGET_FILE:morphreg_cli>|model-info|--model|${cli_dir}/small_model.h5|--json")
morphreg_cli_provenance(model_metadata build-model cli_model -DKEY=metadata
  "-DARGS=$<TARGET_FILE:morphreg_cli>|model-info|--model|${cli_dir}/small_model.h5|--json")
