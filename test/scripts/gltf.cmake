# SPDX-License-Identifier: BSD-3-Clause
# glTF on the command line: the tests' programs that write glTF files (test/support/glb_writer.h) and check a fitted
# mesh's colours; the files they write (the bad-input catalogue's broken ones, cli_catalogue.cmake, and the glTF
# versions of the shared real scans); each real scan registered from its glTF versions as from its original file
# (the same fit); the james capture's texture on the fitted and the resampled meshes. The real-scan tests are
# skipped without ../shared/data (and ICT-FaceKit, whose model registers them).
if(NOT TARGET morphreg_cli)
  return()
endif()
set(gltf_dir ${CMAKE_CURRENT_BINARY_DIR}/cli/gltf)
set(gltf_scripts ${CMAKE_CURRENT_SOURCE_DIR}/scripts/cli)
foreach(program gltf_test_files check_scan_colours check_unit_estimate)
  add_executable(${program} ${gltf_scripts}/${program}.cpp)
  target_link_libraries(${program} PRIVATE morphreg::core morphreg_test_support draco::draco)
  target_compile_options(${program} PRIVATE -Wall -Wextra)
endforeach()
set(gltf_broken cut.glb magic.glb chunk_past_end.glb accessor_out_of_range.glb index_out_of_range.glb bad_draco.glb
    missing_buffer.gltf absurd_counts.gltf)
list(TRANSFORM gltf_broken PREPEND ${gltf_dir}/)
morphreg_command_test(CliTest.GltfFilesWritten FIXTURES_SETUP cli_gltf FILES ${gltf_broken}
  COMMAND $<TARGET_FILE:gltf_test_files> ${gltf_dir} ${MORPHREG_SHARED_DATA_DIR})

set(real_scans ${MORPHREG_SHARED_DATA_DIR}/real_head_scans)
set(ict_basis ${MORPHREG_SHARED_DATA_DIR}/ict_facekit/ict_head_pca_basis.npy)
set(ict30 ${CMAKE_CURRENT_BINARY_DIR}/cli/ict30.h5) # CliTest.BuildIct30Model (cli.cmake)
# The arbitrary unit's version (1 unit = 93 mm, read as metres) fits at a scale estimated from the head: its fit,
# brought into the original's frame by the true scale, lies within BOUND (1.3 times the face median measured
# 2026-11-29: Lee 0.061, james 0.221, demoface 0.076 mm; the estimate 1 % off moves it 1-3 mm) of the original's.
set(sample 0)
foreach(scan "lee;leeperrysmith_head_mm.ply;0.08" "james;menpo3d_james/james.obj;0.29"
        "demoface;meshmonk_demoface/demoface_10k.obj;0.1")
  list(GET scan 0 name)
  list(GET scan 1 file)
  list(GET scan 2 bound)
  morphreg_command_test(CliTest.GltfEstimatedUnit.${name} FIXTURES_REQUIRED "cli_ict30;cli_gltf"
    REQUIRES_DATA ${real_scans}/${file} ${ict_basis}
    OUTPUT "estimated scale over the true .* face median from the original fit"
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:morphreg_cli> -DCHECKER=$<TARGET_FILE:check_unit_estimate>
            -DMODEL=${ict30} -DORIGINAL=${real_scans}/${file} -DVERSION=${gltf_dir}/${name}_arbitrary_unit.glb
            -DTRUE_SCALE=0.093 -DBOUND=${bound} -DOUT=${gltf_dir}/estimated_${name} -DSAMPLE=${sample}
            -P ${gltf_scripts}/check_unit_estimate.cmake)
  set(versions "")
  foreach(variant plain draco node_transform two_primitives)
    list(APPEND versions ${gltf_dir}/${name}_${variant}.glb)
  endforeach()
  list(JOIN versions "|" versions)
  morphreg_command_test(CliTest.GltfSameFit.${name} FIXTURES_REQUIRED "cli_ict30;cli_gltf"
    REQUIRES_DATA ${real_scans}/${file} ${ict_basis}
    OUTPUT "original .*${file}: exit [04], [0-9]+ iterations"
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:morphreg_cli> -DMODEL=${ict30} -DORIGINAL=${real_scans}/${file}
            "-DVERSIONS=${versions}" -DOUT=${gltf_dir}/fits_${name} -P ${gltf_scripts}/check_same_fit.cmake)
  math(EXPR sample "${sample} + 1")
endforeach()

# The james capture (textured OBJ and its GLB version, the texture embedded): registered with settings that pass its
# checks (at the defaults its fit fails them), and resampled; its photos' colours must arrive on the meshes
# (check_scan_colours, run by check_colours.cmake).
set(james_dir ${real_scans}/menpo3d_james)
set(james_fit --model ${ict30} --components 10 --reject-trimmed 0.8 --quiet)
foreach(case "Obj;${james_dir}/james.obj" "Glb;${gltf_dir}/james_plain.glb")
  list(GET case 0 kind)
  list(GET case 1 scan)
  set(out ${gltf_dir}/james_colours_${kind})
  morphreg_cli_test(GltfJamesColoursOnTheFit.${kind} FIXTURES_REQUIRED "cli_ict30;cli_gltf"
    REQUIRES_DATA ${james_dir}/james.obj ${ict_basis}
    OUTPUT "wrote .*james_colours_${kind}.ply \\(vertex colours: the scan's"
    REPORT ${out}.json REPORT_MATCH "\"fitted_mesh_colours\": \"scan\"" FILES ${out}.ply
    CHECKS ${gltf_scripts}/check_colours.cmake DEFINE CHECKER=$<TARGET_FILE:check_scan_colours> MESH=${out}.ply
           SCAN_DIR=${james_dir}
    ARGS register --scan ${scan} ${james_fit} --out ${out}.ply)
endforeach()
set(out ${gltf_dir}/james_resampled)
morphreg_cli_test(GltfJamesColoursOnTheResampledMesh FIXTURES_REQUIRED cli_ict30
  REQUIRES_DATA ${james_dir}/james.obj ${ict_basis}
  REPORT ${out}.json REPORT_MATCH "\"resampled_mesh_colours\": \"scan\"" FILES ${out}.ply
  CHECKS ${gltf_scripts}/check_colours.cmake DEFINE CHECKER=$<TARGET_FILE:check_scan_colours> MESH=${out}.ply
         SCAN_DIR=${james_dir}
  ARGS resample --scan ${james_dir}/james.obj ${james_fit} --max-hole-fraction 0.9 --out ${out}.ply)
