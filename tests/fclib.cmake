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

# Errors of the --fclib mode (see expect_error.sh).
set(_data ${CMAKE_CURRENT_SOURCE_DIR}/fclib/data)
function(fclib_expect_error _name _code _regex)
  set(_directory ${CMAKE_CURRENT_BINARY_DIR}/fclib/errors/${_name})
  file(MAKE_DIRECTORY ${_directory})
  add_test(NAME fclib/errors/${_name}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/expect_error.sh 0 ${_code} "${_regex}"
            $<TARGET_FILE:contact> ${ARGN}
    WORKING_DIRECTORY ${_directory})
  set_tests_properties(fclib/errors/${_name} PROPERTIES
    ENVIRONMENT "${_environment}")
endfunction()

set(_small ${_data}/LMGC_GFC3D-i00001-1-00000.hdf5)
fclib_expect_error(missing_file 1 "cannot open the FCLIB file 'missing.hdf5'"
  --fclib missing.hdf5)
fclib_expect_error(not_an_fclib_file 1 "has no global problem"
  --fclib ${CMAKE_CURRENT_SOURCE_DIR}/fclib/newton.prm)
fclib_expect_error(newton 1 "Contact solver/Method.*accelerated primal-dual"
  --fclib ${_small} ${CMAKE_CURRENT_SOURCE_DIR}/fclib/newton.prm)
fclib_expect_error(amg 1 "Linear solver/Preconditioner.*jacobi"
  --fclib ${_small} ${CMAKE_CURRENT_SOURCE_DIR}/fclib/amg.prm)
fclib_expect_error(no_convergence 2 "no convergence in 10 iterations.*Residuals.*no solution written"
  --fclib ${_small} --solution not_written.hdf5
  ${CMAKE_CURRENT_SOURCE_DIR}/fclib/few_iterations.prm)
fclib_expect_error(evaluate_without_solution 1 "has no solution"
  --fclib ${_small} --evaluate ${_small})
fclib_expect_error(solution_without_fclib 1 "go with --fclib"
  --solution out.hdf5 ${CMAKE_CURRENT_SOURCE_DIR}/fclib/newton.prm)
fclib_expect_error(bad_export_list 1 "Output/FCLIB export"
  --fclib-export first ${PROJECT_SOURCE_DIR}/parameters/example1.prm)
fclib_expect_error(not_symmetric 1 "M that is not symmetric"
  --fclib ${_data}/CubeH8.hdf5)
fclib_expect_error(empty_global_group 1 "has an incomplete global problem: fclib_global/spacedim is missing"
  --fclib ${_data}/empty_global_group.hdf5)
fclib_expect_error(export_past_the_end 1 "<Output/FCLIB export> = '5' is not valid: increment 5 is past the last increment of the loading history \\(1\\)"
  --fclib-export 5 ${PROJECT_SOURCE_DIR}/parameters/example1.prm)

# FCLIB problems from outside the project (tests/fclib/data/README.md),
# against Siconos' solutions of the same files.
foreach(_problem Box_Stacks-i0035-31-0 GFC3D_TwoRods1
                 LMGC_GFC3D-i00001-1-00000 LMGC_GFC3D-i00501-4-00000)
  set(_directory ${CMAKE_CURRENT_BINARY_DIR}/fclib/external/${_problem})
  file(MAKE_DIRECTORY ${_directory})
  add_test(NAME fclib/external/${_problem}
    COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/fclib_external.py
            $<TARGET_FILE:contact> ${_data}/${_problem}.hdf5
            ${_data}/${_problem}.siconos.hdf5
    WORKING_DIRECTORY ${_directory})
  set_tests_properties(fclib/external/${_problem} PROPERTIES
    ENVIRONMENT "${_environment}")
endforeach()
