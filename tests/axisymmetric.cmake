# Axisymmetric bodies (<Material/Two-dimensional model> = axisymmetric: the
# section x = r >= 0 of a body of revolution) against the closed forms of
# the 3D problems they stand for.
# - The shipped ball on a rigid plane (parameters/hertz_axisymmetric.prm),
#   its runs on 1 and 3 ranks: Hertz's 3D contact radius within 1 %, the
#   peak pressure within 2 %, the pressure profile within 5 % of p0.
foreach(_variant 1 3)
  set(_name hertz_axisymmetric.hertz)
  set(_fixture scene_hertz_axisymmetric)
  if(_variant EQUAL 3)
    set(_name hertz_axisymmetric.mpirun=3.hertz)
    set(_fixture scene_hertz_axisymmetric_3)
  endif()
  add_test(NAME ${_name}
    COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_analytic.py hertz
      ${CMAKE_CURRENT_BINARY_DIR}/scenes/hertz_axisymmetric/${_variant}/output-hertz-axisymmetric
      --radius-tolerance 0.01 --pressure-tolerance 0.02 --profile-tolerance 0.05)
  set_tests_properties(${_name} PROPERTIES FIXTURES_REQUIRED ${_fixture})
endforeach()
# - A rigid ball pressed into an elastic half space, the same bounds.
add_scene_check(hertz_rigid_ball_axisymmetric 2 hertz check_analytic.py hertz OUTPUT
  --radius-tolerance 0.01 --pressure-tolerance 0.02 --profile-tolerance 0.05)
# - Lame's thick sphere: elastic (1 %), and past yield and unloaded with
#   J2 plasticity (Hill's solution, 2 % of p).
add_scene_check(lame_axisymmetric 1 analytic check_lame.py OUTPUT --tolerance 0.01)
add_scene_check(lame_plastic_sphere_axisymmetric 2 analytic check_lame_plastic.py OUTPUT)
# - A cylinder upset homogeneously to a logarithmic strain of -1 with the
#   finite-strain J2 law: exact to 1e-10, on 3 ranks.
add_scene_check(j2_finite_compression_axisymmetric 3 exact check_uniaxial.py OUTPUT
  --tolerance 1e-10)
