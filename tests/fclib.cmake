# FCLIB: the round trip (export, FCLIB's error of the stored solution,
# import and solve again, same solution) on 1 and 2 ranks, solves of FCLIB
# files from outside the project, and the errors of the --fclib mode.

foreach(_ranks 0 2)
  set(_name fclib/round_trip)
  if(_ranks GREATER 0)
    set(_name fclib/round_trip.mpirun=${_ranks})
  endif()
  set(_directory ${CMAKE_CURRENT_BINARY_DIR}/${_name})
  configure_file(fclib/example2_export.prm ${_directory}/example2_export.prm @ONLY)
  add_test(NAME ${_name}
    COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/fclib_round_trip.py
            $<TARGET_FILE:contact> example2_export.prm --ranks ${_ranks}
    WORKING_DIRECTORY ${_directory})
  set(_processors 1)
  if(_ranks GREATER 0)
    set(_processors ${_ranks})
  endif()
  set_tests_properties(${_name} PROPERTIES
    ENVIRONMENT "${_environment}" PROCESSORS ${_processors} TIMEOUT 600)
endforeach()
