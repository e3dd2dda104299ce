# Every shipped scene sets only entries that differ from the defaults, each
# with a comment; and the check does find a redundant entry.
file(GLOB _scenes ${PROJECT_SOURCE_DIR}/parameters/*.prm)
foreach(_scene ${_scenes})
  get_filename_component(_name ${_scene} NAME_WE)
  add_test(NAME scenes/${_name}
    COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_scene_entries.py
            $<TARGET_FILE:contact> ${_scene})
endforeach()
add_test(NAME scenes/redundant_entry_is_found
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_scene_entries.py
          $<TARGET_FILE:contact> ${CMAKE_CURRENT_SOURCE_DIR}/scene_with_default_entry.prm)
set_tests_properties(scenes/redundant_entry_is_found PROPERTIES
  PASS_REGULAR_EXPRESSION "Dimension = '2' is the default.*Poisson's ratio = '0.30' is the default.*FAILED")

# Every shipped scene runs as shipped, with its own output settings, on 1
# rank (without mpirun), 2 and 3 MPI ranks (run_scene.py: exit code 0, no
# NaN, the VTU files it announces complete). The four smallest scenes with
# contact pairs or a rigid tool, in 2D and 3D, also run on 2 ranks under
# AddressSanitizer: a write beyond a vector's entries corrupts the heap
# without failing on every machine. (The other three, ball_on_plate,
# bracket_3d and scratch_3d, go through the same pair and tool code on
# larger meshes, at several times the cost there.)
set(_sanitized_scenes block_on_block_2d block_on_block_3d bracket_2d flat_punch_2d)
foreach(_scene ${_scenes})
  get_filename_component(_name ${_scene} NAME_WE)
  set(_run ${_scene})
  set(_variants 1 2 3)
  if(_name IN_LIST _sanitized_scenes)
    list(APPEND _variants sanitized)
  endif()
  foreach(_variant ${_variants})
    set(_directory ${CMAKE_CURRENT_BINARY_DIR}/scenes/${_name}/${_variant})
    file(MAKE_DIRECTORY ${_directory})
    if(_variant STREQUAL "sanitized")
      add_test(NAME scenes/${_name}.sanitized.mpirun=2
        COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/run_scene.py
                $<TARGET_FILE:contact_sanitized> ${_run} 2 --sanitized
        WORKING_DIRECTORY ${_directory})
      set_tests_properties(scenes/${_name}.sanitized.mpirun=2 PROPERTIES
        FIXTURES_REQUIRED sanitized_program ENVIRONMENT "${_environment}"
        PROCESSORS 2 TIMEOUT 600)
    else()
      set(_test scenes/${_name}.mpirun=${_variant})
      if(_variant EQUAL 1)
        set(_test scenes/${_name}.serial)
      endif()
      add_test(NAME ${_test}
        COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/run_scene.py
                $<TARGET_FILE:contact> ${_run} ${_variant}
        WORKING_DIRECTORY ${_directory})
      # Each run is the fixture scene_<name>[_<ranks>] of the checks that
      # read its files (the serial one: scene_<name>).
      set(_fixture scene_${_name}_${_variant})
      if(_variant EQUAL 1)
        set(_fixture scene_${_name})
      endif()
      set_tests_properties(${_test} PROPERTIES FIXTURES_SETUP ${_fixture}
        ENVIRONMENT "${_environment}" PROCESSORS ${_variant} TIMEOUT 600)
      if(_name STREQUAL "step42_indentation")
        # Its solve on the last mesh starts from the solve on the mesh
        # before it (doc/algorithm.md, "Nonlinear laws"): at most 10 Newton
        # steps there on 1, 2 and 3 ranks (7 measured; from the increment's
        # start 24, 24 and 11).
        add_test(NAME ${_test}.newton_steps
          COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_statistics.py
                  ${_directory}/output-step42-indentation/statistics
                  --rows 1-1 --at-most "Contact solver iterations" 10)
        set_tests_properties(${_test}.newton_steps PROPERTIES
          FIXTURES_REQUIRED ${_fixture})
      endif()
    endif()
  endforeach()
endforeach()

