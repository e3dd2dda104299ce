# FCLIB: the round trip (export, FCLIB's error of the stored solution,
# import and solve again with the sparse LU, ML and Kanno's method, same
# solution) on 1 and 2 ranks, solves of FCLIB
# files from outside the project, and the errors of the --fclib mode.

# Also a two-body increment (fclib/round_trip_two_bodies), an axisymmetric
# one (fclib/round_trip_axisymmetric, 3 ranks) and one re-solved on adapted
# meshes (fclib/round_trip_adapted).
foreach(_case "0:example2_export:round_trip" "2:example2_export:round_trip"
              "2:two_bodies_export:round_trip_two_bodies"
              "3:axisymmetric_export:round_trip_axisymmetric:primal_dual_tight"
              "0:adapted_export:round_trip_adapted")
  string(REPLACE ":" ";" _case "${_case}")
  list(GET _case 0 _ranks)
  list(GET _case 1 _scene)
  list(GET _case 2 _name)
  # Kanno's parameters: fclib/primal_dual.prm, or the case's own.
  set(_primal_dual primal_dual)
  list(LENGTH _case _n)
  if(_n GREATER 3)
    list(GET _case 3 _primal_dual)
  endif()
  set(_name fclib/${_name})
  if(_ranks GREATER 0)
    set(_name ${_name}.mpirun=${_ranks})
  endif()
  set(_directory ${CMAKE_CURRENT_BINARY_DIR}/${_name})
  configure_file(fclib/${_scene}.prm ${_directory}/${_scene}.prm @ONLY)
  add_test(NAME ${_name}
    COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/fclib_round_trip.py
            $<TARGET_FILE:contact> ${_scene}.prm --ranks ${_ranks}
            --primal-dual ${CMAKE_CURRENT_SOURCE_DIR}/fclib/${_primal_dual}.prm
            --amg ${CMAKE_CURRENT_SOURCE_DIR}/fclib/amg.prm
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
set(_primal_dual ${CMAKE_CURRENT_SOURCE_DIR}/fclib/primal_dual.prm)
fclib_expect_error(not_an_fclib_file 1 "has no global problem"
  --fclib ${_primal_dual})
fclib_expect_error(amg_shared_nodes 1 "<Linear solver/Preconditioner> = 'amg' is not valid: contacts share nodes.*use jacobi"
  --fclib ${_small} ${CMAKE_CURRENT_SOURCE_DIR}/fclib/amg.prm)
fclib_expect_error(amg_not_symmetric 1 "<Linear solver/Preconditioner> = 'amg' is not valid: M is not symmetric .*conjugate gradients; use jacobi"
  --fclib ${_data}/CubeH8.hdf5 ${CMAKE_CURRENT_SOURCE_DIR}/fclib/amg.prm)
fclib_expect_error(no_convergence 2 "no convergence in 10 iterations.*Residuals.*no solution written"
  --fclib ${_small} --solution not_written.hdf5
  ${CMAKE_CURRENT_SOURCE_DIR}/fclib/few_iterations.prm)
fclib_expect_error(newton_no_convergence 2 "no convergence in 1 Newton iterations \\(FCLIB error .*Maximum iterations.*Residuals.*no solution written"
  --fclib ${_data}/LMGC_GFC3D-i00501-4-00000.hdf5 --solution not_written.hdf5
  ${CMAKE_CURRENT_SOURCE_DIR}/fclib/one_newton_iteration.prm)
fclib_expect_error(evaluate_without_solution 1 "has no solution"
  --fclib ${_small} --evaluate ${_small})
fclib_expect_error(solution_without_fclib 1 "go with --fclib"
  --solution out.hdf5 ${_primal_dual})
fclib_expect_error(bad_export_list 1 "Postprocess/FCLIB export/Increments"
  --fclib-export first ${PROJECT_SOURCE_DIR}/parameters/example1.prm)
fclib_expect_error(not_symmetric 1 "M that is not symmetric.*Kanno's method needs M symmetric positive definite: use <Contact solver/Method> = semismooth Newton"
  --fclib ${_data}/CubeH8.hdf5 ${_primal_dual})
fclib_expect_error(empty_global_group 1 "has an incomplete global problem: fclib_global/spacedim is missing"
  --fclib ${_data}/empty_global_group.hdf5)
fclib_expect_error(export_past_the_end 1 "<Postprocess/FCLIB export/Increments> = '5' is not valid: increment 5 is past the last increment of the loading history \\(1\\)"
  --fclib-export 5 ${PROJECT_SOURCE_DIR}/parameters/example1.prm)

# FCLIB problems from outside the project (tests/fclib/data/README.md),
# against Siconos' solutions of the same files where there is one, with the
# semismooth Newton method (the default) and with Kanno's method.
foreach(_problem Box_Stacks-i0035-31-0 GFC3D_TwoRods1
                 LMGC_GFC3D-i00001-1-00000 LMGC_GFC3D-i00501-4-00000 CubeH8)
  foreach(_method newton primal_dual)
    if(_problem STREQUAL "CubeH8" AND _method STREQUAL "primal_dual")
      continue() # M is not symmetric: fclib/errors/not_symmetric
    endif()
    set(_name fclib/external/${_problem}.${_method})
    set(_directory ${CMAKE_CURRENT_BINARY_DIR}/${_name})
    file(MAKE_DIRECTORY ${_directory})
    set(_reference ${_data}/${_problem}.siconos.hdf5)
    if(NOT EXISTS ${_reference})
      set(_reference -)
    endif()
    set(_parameters)
    if(_method STREQUAL "primal_dual")
      set(_parameters --parameters ${_primal_dual})
    endif()
    add_test(NAME ${_name}
      COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/fclib_external.py
              $<TARGET_FILE:contact> ${_data}/${_problem}.hdf5 ${_reference}
              ${_parameters}
      WORKING_DIRECTORY ${_directory})
    set_tests_properties(${_name} PROPERTIES ENVIRONMENT "${_environment}")
  endforeach()
endforeach()

# The same with the solves with M by the Cholesky factorization.
set(_name fclib/external/GFC3D_TwoRods1.cholesky)
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/${_name})
add_test(NAME ${_name}
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/fclib_external.py
          $<TARGET_FILE:contact> ${_data}/GFC3D_TwoRods1.hdf5
          ${_data}/GFC3D_TwoRods1.siconos.hdf5
          --parameters ${CMAKE_CURRENT_SOURCE_DIR}/fclib/primal_dual_cholesky.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/${_name})
set_tests_properties(${_name} PROPERTIES ENVIRONMENT "${_environment}")

# A failed increment is exported without its solution.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/fclib/failed_export)
add_test(NAME fclib/failed_export
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fclib_failed_export.sh
          $<TARGET_FILE:contact> ${PROJECT_SOURCE_DIR}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/fclib/failed_export)
set_tests_properties(fclib/failed_export PROPERTIES ENVIRONMENT "${_environment}")
