# The tests: one executable per area, each registered with ctest by its
# GoogleTest cases and labelled unit, integration and (run again under the
# sanitizer preset) sanitize. Included from the top-level CMakeLists.txt,
# in its scope, so the executables land in the build folder's root.

enable_testing()
include(GoogleTest)

# Test executables whose tests carry the "sanitize" label: `./dev.sh test`
# builds just these under the sanitizer preset and runs their tests there.
add_custom_target(eikon_sanitize_tests)

function(eikon_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    EIKON_SOURCE_DIR="${CMAKE_SOURCE_DIR}" EIKON_EXECUTABLE="$<TARGET_FILE:eikon>")
  eikon_target_defaults(${name})
  gtest_discover_tests(${name} TEST_LIST ${name}_TESTS DISCOVERY_TIMEOUT 60)
  # Labels are set by a script ctest runs after discovery: through
  # gtest_discover_tests' PROPERTIES a list such as "unit;sanitize" loses its
  # second label (CMake 3.25 splits it into separate arguments).
  set(label_script ${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake)
  file(WRITE ${label_script}
       "if(${name}_TESTS)\n  set_tests_properties(\${${name}_TESTS} PROPERTIES LABELS \"${ARG_LABELS}\")\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${label_script})
  if("sanitize" IN_LIST ARG_LABELS)
    add_dependencies(eikon_sanitize_tests ${name})
  endif()
endfunction()

eikon_test(test_plot LABELS unit LIBS eikon_plot eikon_io SOURCES tests/unit/test_plot.cpp)
eikon_test(test_io LABELS unit LIBS eikon_io SOURCES
  tests/unit/SceneParserTestSupport.cpp
  tests/unit/test_scene_parser.cpp
  tests/unit/test_scene_parser_errors.cpp
  tests/unit/test_scene_file.cpp
  tests/unit/test_scene_parser_sim.cpp
  tests/unit/test_scene_parser_render_method.cpp
  tests/unit/test_scene_parser_diagnostic.cpp
  tests/unit/test_paint_parser.cpp
  tests/unit/test_grid_spec.cpp
  tests/unit/test_check_eq.cpp
  tests/unit/test_output_folder.cpp
  tests/unit/test_atomic_file.cpp
  tests/unit/test_orbit.cpp
  tests/unit/test_mesh_reader.cpp
  tests/unit/test_radiance_check.cpp
  tests/unit/test_scene_parser_mesh.cpp
  tests/unit/test_export_arrays.cpp
  tests/unit/test_scene_parser_export.cpp)
eikon_test(test_vtk_export LABELS "unit;sanitize" LIBS eikon_io VTK::CommonCore VTK::CommonDataModel VTK::IOXML SOURCES
  tests/unit/test_vtk_export.cpp
  tests/unit/test_vtp_export.cpp)
vtk_module_autoinit(TARGETS test_vtk_export MODULES VTK::CommonCore VTK::CommonDataModel VTK::IOXML)
# OpenVDB files written by OpenVDB's own API in the tests.
add_library(eikon_vdb_test_files STATIC tests/unit/VdbTestFiles.cpp)
target_include_directories(eikon_vdb_test_files PUBLIC ${CMAKE_SOURCE_DIR})
target_link_libraries(eikon_vdb_test_files PUBLIC OpenVDB::openvdb)
eikon_target_defaults(eikon_vdb_test_files)
eikon_test(test_vdb LABELS "unit;sanitize" LIBS eikon_io eikon_vdb_test_files SOURCES
  tests/unit/test_vdb_volume_file.cpp
  tests/unit/test_vdb_robustness.cpp
  tests/unit/test_vdb_export.cpp)
eikon_test(test_shared_cpp LABELS unit LIBS glm::glm SOURCES
  tests/unit/test_integrators.cpp
  tests/unit/test_fresnel.cpp
  tests/unit/test_footprint_coverage.cpp
  tests/unit/test_step_size.cpp
  tests/unit/test_lattice_directions.cpp)
target_include_directories(test_shared_cpp PRIVATE ${CMAKE_SOURCE_DIR})
eikon_test(test_reference LABELS "unit;sanitize" LIBS eikon_reference SOURCES
  tests/unit/test_reference_tracer.cpp
  tests/unit/test_sphere_caustic_reference.cpp
  tests/unit/test_slab_transport.cpp)
# VTK and OpenFOAM input for `volume`: plumes written with VTK's writers, a hand-written OpenFOAM case,
# a plume OpenFOAM computed (tests/data/openfoam_plume_coarse), a gas mixture by its mass fractions.
eikon_test(test_vtk_volume LABELS unit LIBS eikon_io eikon_sim eikon_vdb_test_files VTK::CommonCore VTK::CommonDataModel
  VTK::IOXML VTK::IOGeometry VTK::FiltersCore SOURCES
  tests/unit/test_vtk_volume.cpp
  tests/unit/test_openfoam_plume.cpp
  tests/unit/test_volume_mixture.cpp
  tests/unit/test_volume_follower.cpp)
eikon_test(test_sim LABELS unit LIBS eikon_io eikon_sim eikon_vdb_test_files SOURCES
  tests/unit/test_analytic_voxelizer.cpp
  tests/unit/test_volume_sequence.cpp
  tests/unit/test_volume_optical_grids.cpp
  tests/unit/test_volume_placement.cpp
  tests/unit/test_volume_painter.cpp
  tests/unit/test_air_profile.cpp
  tests/unit/SceneParserTestSupport.cpp
  tests/unit/test_mesh_coverage.cpp
  tests/unit/test_height_field_coverage.cpp
  tests/unit/test_row_parity.cpp
  tests/unit/test_water_surface.cpp
  tests/unit/test_deformers.cpp
  tests/unit/test_scene_fields_mesh.cpp)
eikon_test(test_deform_stability LABELS "unit;sanitize" LIBS eikon_sim SOURCES
  tests/unit/test_deform_stability.cpp)
eikon_test(test_fluid LABELS unit LIBS eikon_sim SOURCES
  tests/unit/FluidStiffRun.cpp
  tests/unit/test_fluid_pressure.cpp
  tests/unit/test_fluid_advection.cpp
  tests/unit/test_fluid_simulation.cpp
  tests/unit/test_fluid_vorticity.cpp
  tests/unit/test_fluid_frame_report.cpp
  tests/unit/test_optics.cpp
  tests/unit/test_solver_export.cpp)
eikon_test(test_blackbody LABELS unit LIBS eikon_sim SOURCES
  tests/unit/test_blackbody.cpp)
eikon_test(test_fluid_solvers LABELS "unit;sanitize" LIBS eikon_sim SOURCES
  tests/unit/test_fluid_diffusion.cpp
  tests/unit/test_wavefront_slices.cpp)
eikon_test(test_stability_inputs LABELS "unit;sanitize" LIBS eikon_sim SOURCES
  tests/unit/FluidStiffRun.cpp
  tests/unit/test_stability_inputs.cpp)
eikon_test(test_render LABELS integration LIBS eikon_io eikon_render eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_shared_math.cpp
  tests/integration/test_photon_physics.cpp
  tests/integration/test_wavefront_physics.cpp
  tests/integration/test_wavefront_fluence.cpp
  tests/integration/test_photon_paths.cpp
  tests/integration/test_photon_resume.cpp
  tests/integration/test_tracer_accuracy.cpp
  tests/integration/test_view_pass.cpp
  tests/integration/test_default_render.cpp
  tests/integration/test_frame_graph.cpp
  tests/integration/test_field_ring.cpp
  tests/integration/test_field_textures.cpp
  tests/integration/test_emission_region.cpp
  tests/integration/test_gpu_contract.cpp
  tests/integration/test_work_group_size.cpp
  tests/integration/test_shared_encodings.cpp
  tests/integration/test_memory_estimate.cpp
  tests/integration/test_step_structure.cpp
  tests/integration/test_grid_pass_devices.cpp
  tests/integration/test_mirage.cpp
  tests/integration/test_wavefront_cost.cpp
  tests/integration/test_shared_light_pass.cpp
  tests/integration/test_error_estimate.cpp)
# The photon pass's native tracer against its compute shader (render.device).
eikon_test(test_photon_devices LABELS integration LIBS eikon_io eikon_render eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_photon_devices.cpp)
# render.device for the wavefront pass: native against the compute shader.
eikon_test(test_wavefront_devices LABELS integration LIBS eikon_io eikon_render eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_wavefront_devices.cpp)
# How far light reaches and how much leaves a light: scaled scenes, spot-light power.
eikon_test(test_light_reach LABELS integration LIBS eikon_io eikon_render eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_far_flights.cpp
  tests/integration/test_spot_power.cpp
  tests/integration/test_emission_ledger.cpp
  apps/eikon/PowerWarning.cpp)
# The fluid solver's GPU backend against its CPU backend, on llvmpipe in CI.
eikon_test(test_gpu_advection LABELS integration LIBS eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_gpu_advection.cpp)
eikon_test(test_gpu_linear_solvers LABELS integration LIBS eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_gpu_linear_solvers.cpp)
eikon_test(test_gpu_water LABELS integration LIBS eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_gpu_water.cpp)
eikon_test(test_gpu_fluid LABELS integration LIBS eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/unit/FluidStiffRun.cpp
  tests/integration/test_fluid_flow.cpp
  tests/integration/test_gpu_fluid.cpp)
# Sharp surfaces against closed forms and the exact-sphere reference (verify/reference/SphereCaustic).
eikon_test(test_wavefront_graded LABELS integration LIBS eikon_accuracy eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_wavefront_graded.cpp)
# The wavefront's reflected branch on the default scene against the exact first-surface reflection.
eikon_test(test_wavefront_reflection LABELS integration LIBS eikon_io eikon_render eikon_sim eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_wavefront_reflection.cpp)
# `eikon accuracy`'s image-space rows on the glass-sphere cases, and the report's outputs carrying them.
eikon_test(test_accuracy_image_space LABELS integration LIBS eikon_accuracy eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_accuracy_image_space.cpp)
# An index grid made with OpenVDB's API, imported, against the closed-form Luneburg case.
eikon_test(test_imported_lens LABELS integration LIBS eikon_accuracy eikon_reference eikon_sim eikon_io eikon_vdb_test_files SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_imported_lens.cpp)
# The multiple-scattering lattice against diffusion theory and slab Monte Carlo.
eikon_test(test_lattice_scattering LABELS integration LIBS eikon_render eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_lattice_scattering.cpp)
# How the lattice shares Henyey–Greenstein light among its links: the moments kept, the phase table.
eikon_test(test_lattice_phase LABELS unit LIBS eikon_render SOURCES
  tests/unit/test_lattice_phase.cpp)
# The lattice in a forward-scattering (Henyey–Greenstein) slab against Monte Carlo; the reduced-scattering limit.
eikon_test(test_lattice_anisotropic LABELS integration LIBS eikon_render eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_lattice_anisotropic.cpp)
# Multiple scattering in rendered scenes: the albedo limits, the photons' scattered power as the lattice's source.
eikon_test(test_multiple_scattering LABELS integration LIBS eikon_io eikon_render eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/test_multiple_scattering.cpp)
# Emission in the view pass: a glowing slab, and a blackbody flame imported from an OpenVDB file.
eikon_test(test_volume_emission LABELS integration LIBS eikon_io eikon_render eikon_sim eikon_vdb_test_files SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_volume_emission.cpp)
eikon_test(test_sharp_surfaces LABELS integration LIBS eikon_io eikon_render eikon_sim eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_sharp_attenuation.cpp
  tests/integration/test_sharp_caustic.cpp
  tests/integration/test_sharp_mesh.cpp
  tests/integration/test_sharp_plume.cpp
  tests/integration/test_sharp_surfaces.cpp
  tests/integration/test_image_space.cpp
  tests/integration/test_image_space_water.cpp
  tests/integration/test_caustic_polygons.cpp)
# The diagnostics (interferometry, schlieren) against a Gaussian bump's closed forms, through a sharp glass sphere
# against its exact rays, their anti-aliasing and error estimate, and the orthographic view.
eikon_test(test_diagnostics LABELS integration LIBS eikon_io eikon_render eikon_sim eikon_reference eikon_vdb_test_files SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_diagnostics.cpp
  tests/integration/test_diagnostic_samples.cpp
  tests/integration/test_diagnostic_varying_voxels.cpp
  tests/integration/test_diagnostic_node_steps.cpp
  tests/integration/test_diagnostic_error_estimate.cpp
  tests/integration/test_diagnostic_sharp.cpp
  tests/integration/test_orthographic_view.cpp)
# The shadowgraph and BOS against the bump's closed forms: the weak lens's −L·∇²Φ, the strong lens's intensity law and caustic, BOS's displacement.
eikon_test(test_shadowgraph_bos LABELS integration LIBS eikon_io eikon_render eikon_sim SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_shadowgraph_bos.cpp)
# Anti-aliasing: a grazing checkerboard against its box-filtered image (render.samples_per_pixel).
eikon_test(test_anti_aliasing LABELS integration LIBS eikon_io eikon_render eikon_sim eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_anti_aliasing.cpp)
eikon_test(test_stability LABELS "integration;sanitize" LIBS eikon_io eikon_render eikon_sim eikon_reference SOURCES
  tests/integration/GlTestContext.cpp
  tests/integration/TraceHelpers.cpp
  tests/integration/test_stability.cpp)
eikon_test(test_cli LABELS integration LIBS eikon_io eikon_vdb_test_files VTK::CommonCore VTK::CommonDataModel VTK::IOXML SOURCES
  tests/integration/test_cli.cpp
  tests/integration/test_cli_live.cpp
  tests/integration/test_cli_follow.cpp
  tests/integration/test_cli_fluid.cpp
  tests/integration/test_cli_limits.cpp
  tests/integration/test_cli_output_folder.cpp
  tests/integration/test_converge_cli.cpp
  tests/integration/test_bench_cli.cpp)
vtk_module_autoinit(TARGETS test_cli MODULES VTK::CommonCore VTK::CommonDataModel VTK::IOXML)
add_dependencies(test_cli eikon)
# eikon converge's rungs: what each knob refines.
eikon_test(test_converge_ladder LABELS unit LIBS eikon_converge SOURCES tests/unit/test_converge_ladder.cpp)
eikon_test(test_diagnostic_cli LABELS integration LIBS eikon_io eikon_vdb_test_files VTK::CommonCore VTK::CommonDataModel VTK::IOXML SOURCES
  tests/integration/test_diagnostic_cli.cpp)
vtk_module_autoinit(TARGETS test_diagnostic_cli MODULES VTK::CommonCore VTK::CommonDataModel VTK::IOXML)
add_dependencies(test_diagnostic_cli eikon)
eikon_test(test_paraview_state LABELS integration LIBS eikon_io SOURCES
  tests/integration/test_paraview_state.cpp)
add_dependencies(test_paraview_state eikon)
# The ParaView and Blender round trips (issue 55's build item 5), each from its failure.
eikon_test(test_cli_roundtrip LABELS integration LIBS eikon_vdb_test_files VTK::CommonCore VTK::CommonDataModel VTK::IOXML SOURCES
  tests/integration/test_cli_roundtrip.cpp)
vtk_module_autoinit(TARGETS test_cli_roundtrip MODULES VTK::CommonCore VTK::CommonDataModel VTK::IOXML)
add_dependencies(test_cli_roundtrip eikon)
# `mpirun -n 2 eikon run` against one process (FindMPI's MPIEXEC_EXECUTABLE).
eikon_test(test_mpi LABELS integration LIBS eikon_io eikon_vdb_test_files SOURCES
  tests/integration/test_mpi.cpp)
target_compile_definitions(test_mpi PRIVATE EIKON_MPIEXEC="${MPIEXEC_EXECUTABLE}")
add_dependencies(test_mpi eikon)
# tests/hostile (tools/make_hostile_corpus.py): every case through `eikon run`.
eikon_test(test_hostile_corpus LABELS integration LIBS nlohmann_json::nlohmann_json SOURCES
  tests/integration/test_hostile_corpus.cpp)
add_dependencies(test_hostile_corpus eikon)
# CliRun.h, from the source root as every test includes it.
target_include_directories(test_hostile_corpus PRIVATE ${CMAKE_SOURCE_DIR})
# The cases are read when ctest lists the tests: relink (and so list anew) when they change.
set_property(TARGET test_hostile_corpus APPEND PROPERTY LINK_DEPENDS ${CMAKE_SOURCE_DIR}/tests/hostile/cases.jsonl)
# kill -9, a full and a read-only file system during a run that exports every frame.
eikon_test(test_run_faults LABELS integration LIBS eikon_io VTK::CommonCore VTK::CommonDataModel VTK::IOXML SOURCES
  tests/integration/test_run_faults.cpp)
vtk_module_autoinit(TARGETS test_run_faults MODULES VTK::CommonCore VTK::CommonDataModel VTK::IOXML)
add_dependencies(test_run_faults eikon)

# The windowed context needs an X server: ctest runs it under Xvfb.
add_executable(test_window tests/integration/test_window_context.cpp)
target_link_libraries(test_window PRIVATE eikon_render GTest::gtest_main)
eikon_target_defaults(test_window)
find_program(XVFB_RUN xvfb-run REQUIRED)
add_test(NAME WindowContext.OpensWithOpenGl45AndRunsComputeShaders
         COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24" $<TARGET_FILE:test_window>)
set_tests_properties(WindowContext.OpensWithOpenGl45AndRunsComputeShaders PROPERTIES LABELS integration)
eikon_test(test_light_frames LABELS unit LIBS eikon_render SOURCES tests/unit/test_light_frames.cpp)
eikon_test(test_camera_controls LABELS unit LIBS eikon_bridge SOURCES
  tests/unit/test_camera_controls.cpp
  apps/viewer/CameraControls.cpp)
eikon_test(test_view_preview LABELS unit LIBS eikon_bridge SOURCES
  tests/unit/test_view_preview.cpp
  apps/viewer/ViewPreview.cpp)
eikon_test(test_simulation_pacer LABELS unit LIBS eikon_bridge SOURCES
  tests/unit/test_simulation_pacer.cpp
  apps/eikon-view/SimulationPacer.cpp)
# The viewer in a window (it starts its own Xvfb through xvfb-run).
eikon_test(test_viewer_window LABELS integration LIBS eikon_io SOURCES tests/integration/test_viewer_window.cpp)
target_compile_definitions(test_viewer_window PRIVATE
  EIKON_VIEW_EXECUTABLE="$<TARGET_FILE:eikon-view>" EIKON_XVFB_RUN="${XVFB_RUN}")
add_dependencies(test_viewer_window eikon eikon-view)

# The library through its public header alone (include/eikon/eikon.h):
# fields handed in against the same fields read from an OpenVDB file (a
# temperature in each declared unit too), δn in a GL buffer against the same
# from host memory (the GPU path; the test makes the buffer with epoxy), and
# each refusal.
eikon_test(test_library LABELS integration
  LIBS eikon_library eikon_vdb_test_files nlohmann_json::nlohmann_json PkgConfig::EPOXY
  SOURCES tests/integration/test_library.cpp tests/integration/test_library_temperature.cpp
          tests/integration/test_library_gpu.cpp)
# The installed package builds and runs examples/cpp outside the source tree.
add_test(NAME Library.InstalledPackageBuildsTheExample
         COMMAND ${CMAKE_COMMAND} -DBUILD=${CMAKE_BINARY_DIR} -DSOURCE=${CMAKE_SOURCE_DIR}
                 -DWORK=${CMAKE_BINARY_DIR}/installed_package_test -P ${CMAKE_SOURCE_DIR}/tests/integration/InstalledPackage.cmake)
set_tests_properties(Library.InstalledPackageBuildsTheExample PROPERTIES LABELS integration)
# The Python module from the build folder (tests/python).
add_test(NAME Python.Module COMMAND ${Python3_EXECUTABLE} -m unittest -v test_module
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}/tests/python)
set_tests_properties(Python.Module PROPERTIES LABELS integration
                     ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python")
# A solver's 100-step loop: resident memory flat, the field not copied.
add_test(NAME Python.LoopMemory COMMAND ${Python3_EXECUTABLE} -m unittest -v test_loop_memory
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}/tests/python)
set_tests_properties(Python.LoopMemory PROPERTIES LABELS integration
                     ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python")
# eikon.View, the live viewer fed from Python, in a window under Xvfb.
add_test(NAME Python.View COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24" ${Python3_EXECUTABLE} -m unittest -v test_view
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}/tests/python)
set_tests_properties(Python.View PROPERTIES LABELS integration ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python")
