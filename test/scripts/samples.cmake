# SPDX-License-Identifier: BSD-3-Clause
# SampleTest: each sample runs on small inputs, writes its files and prints figures within measured bounds; bad
# arguments give the usage (exit 2) and bad files an error naming them (exit 1). See test/samples/run_sample.cmake.
if(NOT TARGET sample_register_scan)
  return()
endif()
set(sample_dir "${CMAKE_CURRENT_BINARY_DIR}/samples")

# sample_test(<name> COMMAND ... [PATTERNS ...] [MAXIMA regex=>bound ...] [FILES ...] [EXIT_CODE n]
#             [PROPERTIES ...] [REQUIRES_DATA ...] [XVFB]): the sample's outputs go to ${sample_dir}/<name>; run and checked by
#             morphreg_command_test (test/support/command_test.cmake).
function(sample_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "XVFB" "EXIT_CODE" "COMMAND;PATTERNS;MAXIMA;FILES;PROPERTIES;REQUIRES_DATA")
  file(MAKE_DIRECTORY ${sample_dir}/${name})
  set(xvfb "")
  if(arg_XVFB)
    set(xvfb XVFB)
  endif()
  set(fixtures "")
  foreach(kind REQUIRED SETUP)
    list(FIND arg_PROPERTIES FIXTURES_${kind} index)
    if(index GREATER -1)
      math(EXPR value "${index} + 1")
      list(GET arg_PROPERTIES ${value} fixture)
      list(REMOVE_AT arg_PROPERTIES ${index} ${value})
      list(APPEND fixtures FIXTURES_${kind} "${fixture}")
    endif()
  endforeach()
  morphreg_command_test(SampleTest.${name} COMMAND ${arg_COMMAND} EXPECT_CODE "${arg_EXIT_CODE}"
    OUTPUT ${arg_PATTERNS} MAXIMA ${arg_MAXIMA} FILES ${arg_FILES} REQUIRES_DATA ${arg_REQUIRES_DATA} TIMEOUT 120
    ${fixtures} ${xvfb} PROPERTIES ${arg_PROPERTIES})
endfunction()

# register_scan: a 30-head synthetic model and a scan of an unseen head (measured: vertex RMS 1.00 mm where the scan
# saw the head, 2.78 mm over all vertices: the scanner never sees the base of the neck, which the small model
# extrapolates up to 20 mm off); then the files route: that fitted mesh registered to build_model's model
# (measured fitness 1.01 mm).
sample_test(RegisterScanSynthetic
  COMMAND $<TARGET_FILE:sample_register_scan> --out ${sample_dir}/RegisterScanSynthetic/fitted.ply
  PATTERNS "termination: [a-z_]+ after [0-9]+ similarity" "fitness: mean [0-9.]+ mm"
  MAXIMA "RMS ([0-9.]+) mm over the [0-9]+ the scan saw=>1.6" "RMS ([0-9.]+) mm \\(max [0-9.]+ mm\\) over all=>3.5"
  FILES ${sample_dir}/RegisterScanSynthetic/fitted.ply
  PROPERTIES FIXTURES_SETUP sample_fitted)
sample_test(BuildModelSynthetic
  COMMAND $<TARGET_FILE:sample_build_model> ${sample_dir}/BuildModelSynthetic/model.h5 --count 30
  PATTERNS "30 training meshes of 9602 vertices" "global PCA +9602 vertices +29 components"
           "wrote .*model.h5: 7 regions, 203 components in all, [0-9]+ landmarks"
  MAXIMA "skull_neck +[0-9]+ vertices +29 components +first +[0-9.]+ % +first 5 +[0-9.]+ % +95 % with ([0-9]+)=>12"
  FILES ${sample_dir}/BuildModelSynthetic/model.h5
  PROPERTIES FIXTURES_SETUP sample_model)
sample_test(RegisterScanFromFiles
  COMMAND $<TARGET_FILE:sample_register_scan> --scan ${sample_dir}/RegisterScanSynthetic/fitted.ply
          --model ${sample_dir}/BuildModelSynthetic/model.h5 --out ${sample_dir}/RegisterScanFromFiles/fitted.ply
  PATTERNS "model: 9602 vertices, 7 regions; scan: 9602 points"
  MAXIMA "fitness: mean ([0-9.]+) mm=>2.0"
  FILES ${sample_dir}/RegisterScanFromFiles/fitted.ply
  PROPERTIES FIXTURES_REQUIRED "sample_fitted;sample_model")
sample_test(RegisterScanBadArgumentGivesUsage
  COMMAND $<TARGET_FILE:sample_register_scan> --iterations many
  EXIT_CODE 2 PATTERNS "--iterations expects a number, got 'many'" "usage: sample_register_scan")
sample_test(RegisterScanMissingFileIsNamed
  COMMAND $<TARGET_FILE:sample_register_scan> --scan ${sample_dir}/no_such_scan.pcd
          --model ${sample_dir}/BuildModelSynthetic/model.h5
  EXIT_CODE 1 PATTERNS "no_such_scan.pcd"
  PROPERTIES FIXTURES_REQUIRED sample_model)

# build_model from mesh files in the head topology (two written by the samples above): one component per region.
sample_test(BuildModelFromMeshes
  COMMAND $<TARGET_FILE:sample_build_model> ${sample_dir}/BuildModelFromMeshes/model.h5
          ${sample_dir}/RegisterScanSynthetic/fitted.ply ${sample_dir}/WarpHead/warped_head.ply
  PATTERNS "2 training meshes of 9602 vertices" "wrote .*model.h5: 7 regions, 7 components in all"
  FILES ${sample_dir}/BuildModelFromMeshes/model.h5
  PROPERTIES FIXTURES_REQUIRED "sample_fitted;sample_head")
sample_test(BuildModelMissingMeshIsNamed
  COMMAND $<TARGET_FILE:sample_build_model> ${sample_dir}/model.h5 ${sample_dir}/no_such_mesh.ply
  EXIT_CODE 1 PATTERNS "no_such_mesh.ply")

# warp_head: landmarks land exactly; the mean error against the other head falls (measured 6.74 -> 3.25 mm).
sample_test(WarpHead
  COMMAND $<TARGET_FILE:sample_warp_head> --out ${sample_dir}/WarpHead/warped_head.ply
  MAXIMA "largest landmark miss ([-+.e0-9]+) mm=>1e-6" "warped head vs target head: mean ([0-9.]+) mm=>4.0"
  FILES ${sample_dir}/WarpHead/warped_head.ply
  PROPERTIES FIXTURES_SETUP sample_head)

# warp_body on the MakeHuman bodies (only with ../shared/data): one subject re-postured and the base warped onto it.
sample_test(WarpBodyMissingFolderIsNamed
  COMMAND $<TARGET_FILE:sample_warp_body> ${sample_dir}/no_such_bodies
  EXIT_CODE 1 PATTERNS "no_such_bodies")
set(bodies_out ${sample_dir}/WarpBodyFemale)
sample_test(WarpBodyFemale REQUIRES_DATA ${MORPHREG_SHARED_DATA_DIR}/makehuman_bodies
    COMMAND $<TARGET_FILE:sample_warp_body> ${MORPHREG_SHARED_DATA_DIR}/makehuman_bodies --out ${bodies_out}
            --subject caucasian-female-young
    PATTERNS "standing->seated +global +mean +[0-9.]+ mm +max +[0-9.]+ mm"
    MAXIMA "standing->seated +hard +mean +([0-9.]+) mm=>5.5" "standing->seated +blended +mean +([0-9.]+) mm=>5.5"
           "standing->seated +blended +mean +[0-9.]+ mm +max +[0-9.]+ mm +seam ([0-9.]+)=>0.2"
           "base->caucasian-female-young \\(326 joints\\) +blended +mean +([0-9.]+) mm=>9.0"
    FILES ${bodies_out}/caucasian-female-young_seated_global.ply ${bodies_out}/caucasian-female-young_seated_hard.ply
          ${bodies_out}/caucasian-female-young_seated_blended.ply
          ${bodies_out}/base_to_caucasian-female-young_blended.ply)

# The viewers render offscreen under a virtual X server, one server at a time.
sample_test(LiveViewerWritesFrames XVFB
  COMMAND $<TARGET_FILE:sample_live_viewer> --frames ${sample_dir}/LiveViewerWritesFrames --iterations 4
          --width 320 --height 240
  PATTERNS "4 iterations" "wrote 4 frames \\(320x240\\)"
  MAXIMA "fitness RMS ([0-9.]+) mm=>2.0" "error against the true head RMS ([0-9.]+) mm=>8.0"
  FILES ${sample_dir}/LiveViewerWritesFrames/frame_000.png ${sample_dir}/LiveViewerWritesFrames/frame_003.png)
sample_test(PopulationGalleryRenders XVFB
  COMMAND $<TARGET_FILE:sample_population_gallery> ${sample_dir}/PopulationGalleryRenders/heads.png 2
  PATTERNS "wrote .*heads.png"
  FILES ${sample_dir}/PopulationGalleryRenders/heads.png)

# fit_photos: photos of an unseen head fitted by a 30-head model, approach 1 (measured: vertex RMS 2.27 mm against the truth,
# width 0.64 mm, scale within 0.8 %, profile 0.71 mm and landmark 0.76 mm RMS); then the files route with
# build_model's model, those photos' annotation files and the stand-in photo as texture.
sample_test(FitPhotosSynthetic
  COMMAND $<TARGET_FILE:sample_fit_photos> --out ${sample_dir}/FitPhotosSynthetic/fitted.ply
          --report ${sample_dir}/FitPhotosSynthetic/fit.json
  PATTERNS "photos: [0-9]+ silhouette points in .*side.json, 40 landmarks in .*front.json"
  MAXIMA "error against the true head: RMS ([0-9.]+) mm=>3.0" "width \\(x\\) RMS ([0-9.]+) mm=>1.0"
         "outline RMS ([0-9.]+) mm=>1.0" "landmark RMS ([0-9.]+) mm=>1.2"
  FILES ${sample_dir}/FitPhotosSynthetic/fitted.ply ${sample_dir}/FitPhotosSynthetic/fit.json
        ${sample_dir}/FitPhotosSynthetic/side.json ${sample_dir}/FitPhotosSynthetic/front.json
        ${sample_dir}/FitPhotosSynthetic/front.png
  PROPERTIES FIXTURES_SETUP sample_photos)
# Approach 2 on the same photos (measured: vertex RMS 3.00 mm, width 0.72 mm, landmark RMS 0.54 mm).
sample_test(FitPhotosTpsIcp
  COMMAND $<TARGET_FILE:sample_fit_photos> --approach tps --out ${sample_dir}/FitPhotosTpsIcp/fitted.ply
  PATTERNS "fit \\(tps\\): [0-9]+ iterations; outline RMS"
  MAXIMA "error against the true head: RMS ([0-9.]+) mm=>3.6" "width \\(x\\) RMS ([0-9.]+) mm=>1.0"
         "outline RMS ([0-9.]+) mm=>1.0" "landmark RMS ([0-9.]+) mm=>1.0"
  FILES ${sample_dir}/FitPhotosTpsIcp/fitted.ply)
sample_test(FitPhotosFromFiles
  COMMAND $<TARGET_FILE:sample_fit_photos> --model ${sample_dir}/BuildModelSynthetic/model.h5
          --profile ${sample_dir}/FitPhotosSynthetic/side.json --frontal ${sample_dir}/FitPhotosSynthetic/front.json
          --photo ${sample_dir}/FitPhotosSynthetic/front.png --out ${sample_dir}/FitPhotosFromFiles/fitted.ply
  PATTERNS "texture: [0-9]+ of 9602 vertices seen in .*front.png"
  MAXIMA "outline RMS ([0-9.]+) mm=>1.0" "landmark RMS ([0-9.]+) mm=>1.2"
  FILES ${sample_dir}/FitPhotosFromFiles/fitted.ply
  PROPERTIES FIXTURES_REQUIRED "sample_photos;sample_model")
sample_test(FitPhotosBadArgumentGivesUsage
  COMMAND $<TARGET_FILE:sample_fit_photos> --model model.h5
  EXIT_CODE 2 PATTERNS "--profile, --frontal and --model go together" "usage: sample_fit_photos")
sample_test(FitPhotosMissingFileIsNamed
  COMMAND $<TARGET_FILE:sample_fit_photos> --model ${sample_dir}/BuildModelSynthetic/model.h5
          --profile ${sample_dir}/no_such_side.json --frontal ${sample_dir}/FitPhotosSynthetic/front.json
  EXIT_CODE 1 PATTERNS "no_such_side.json"
  PROPERTIES FIXTURES_REQUIRED "sample_photos;sample_model")
