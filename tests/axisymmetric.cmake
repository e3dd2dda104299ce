# Axisymmetric bodies (<Material/Two-dimensional model> = axisymmetric: the
# section x = r >= 0 of a body of revolution) against the closed forms of
# the 3D problems they stand for.
# - The shipped ball on a rigid plane (parameters/hertz_axisymmetric.prm)
#   and ball on a plate (ball_on_plate_axisymmetric.prm, a mortar pair),
#   their runs on 1 and 3 ranks: Hertz's 3D contact radius within 1 %, the
#   peak pressure within 2 %, the pressure profile within 5 % of p0; and
#   the ball on the plate's force within 0.5 % of the 3D scene's
#   (ball_on_plate.prm, a quarter: its meshes change the force by 0.2 %
#   from one refinement to the next, bench/axisymmetric.py).
# add_shipped_scene_check(<scene> <folder> <check> <script> <arguments...>):
# the test <scene>.<check> (and <scene>.mpirun=3.<check>) runs
# tests/<script> on what the shipped scene's run on 1 (and 3) ranks of
# tests/scenes.cmake wrote, OUTPUT in the arguments standing for its
# output folder <folder>.
function(add_shipped_scene_check _name _folder _check _script)
  foreach(_variant 1 3)
    set(_test ${_name}.${_check})
    set(_fixture scene_${_name})
    if(_variant EQUAL 3)
      set(_test ${_name}.mpirun=3.${_check})
      set(_fixture scene_${_name}_3)
    endif()
    set(_arguments ${ARGN})
    list(TRANSFORM _arguments REPLACE "^OUTPUT$"
         "${CMAKE_CURRENT_BINARY_DIR}/scenes/${_name}/${_variant}/${_folder}")
    add_test(NAME ${_test}
      COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/${_script} ${_arguments})
    set_tests_properties(${_test} PROPERTIES FIXTURES_REQUIRED ${_fixture})
  endforeach()
endfunction()
add_shipped_scene_check(hertz_axisymmetric output-hertz-axisymmetric hertz
  check_analytic.py hertz OUTPUT --radius-tolerance 0.01 --pressure-tolerance 0.02
  --profile-tolerance 0.05)
add_shipped_scene_check(ball_on_plate_axisymmetric output-ball-on-plate-axisymmetric hertz
  check_analytic.py hertz OUTPUT --radius-tolerance 0.01 --pressure-tolerance 0.02
  --profile-tolerance 0.05)
add_test(NAME ball_on_plate_axisymmetric.same_force_as_3d
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_analytic.py same-force
    ${CMAKE_CURRENT_BINARY_DIR}/scenes/ball_on_plate_axisymmetric/1/output-ball-on-plate-axisymmetric
    --reference ${CMAKE_CURRENT_BINARY_DIR}/scenes/ball_on_plate/2/output-ball-on-plate
    --tolerance 0.005)
set_tests_properties(ball_on_plate_axisymmetric.same_force_as_3d PROPERTIES
  FIXTURES_REQUIRED "scene_ball_on_plate_axisymmetric;scene_ball_on_plate_2")
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
# - The contact patch tests of axisymmetric bodies, their meshes not
#   matching: two cylinders through a mortar pair pressed by a pressure,
#   friction 0.3, on 3 ranks (to 1e-8), the same pressed by a displacement
#   with Kanno's method (1e-8), and a cylinder pressed by a rigid plate
#   from a Gmsh line mesh (1e-10, 2 ranks): the exact linear displacement
#   of uniaxial stress and the uniform contact pressure.
foreach(_case "patch_test_axisymmetric:3:1e-8:ux=0.15*x:uy=-0.5*y:0.5"
              "patch_test_axisymmetric_primal_dual:1:1e-8:ux=0.0015*x:uy=-0.005*y:0.005"
              "patch_test_tool_axisymmetric:2:1e-10:ux=0.003*x:uy=-0.01*y:0.01")
  string(REPLACE ":" ";" _case "${_case}")
  list(GET _case 0 _scene)
  list(GET _case 1 _ranks)
  list(GET _case 2 _tolerance)
  list(GET _case 3 _ux)
  list(GET _case 4 _uy)
  list(GET _case 5 _pressure)
  add_scene_check(${_scene} ${_ranks} exact compare_csv.py
    OUTPUT/displacement-00001.csv --exact ${_ux} ${_uy} --tolerance ${_tolerance})
  add_test(NAME ${_scene}.uniform_pressure
    COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py
      ${CMAKE_CURRENT_BINARY_DIR}/${_scene}/output-${_scene}/contact-00001.csv
      --exact "pressure=${_pressure}" --tolerance ${_tolerance})
  set_tests_properties(${_scene}.uniform_pressure PROPERTIES FIXTURES_REQUIRED ${_scene})
endforeach()
# - scripts/revolve_section.py draws the shipped ball on the plate turned
#   about its axis (skipped without ParaView and Xvfb).
add_test(NAME revolve_section
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render_contact.sh ${PROJECT_SOURCE_DIR}
          ${CMAKE_CURRENT_BINARY_DIR}/scenes/ball_on_plate_axisymmetric/1/output-ball-on-plate-axisymmetric
          revolve_section.py)
set_tests_properties(revolve_section PROPERTIES
  FIXTURES_REQUIRED scene_ball_on_plate_axisymmetric SKIP_RETURN_CODE 77 TIMEOUT 420)
# - A press fit: a ring on a shaft with a radial interference, two bodies
#   from one Gmsh file through a mortar pair (<Contact/Interference fit>):
#   Lame's interference-fit pressure within 1 %, uniform along the fit, on
#   3 ranks; without the entry the overlap is refused.
add_scene_check(press_fit_axisymmetric 3 lame check_press_fit.py OUTPUT
  --shaft-radius 1 --outer-radius 2 --interference 0.001 --tolerance 0.01)
# - The shipped ball indentation, shrink fit and O-ring, their runs on 1
#   and 3 ranks: the indentation's mean pressure within 10 % of Tabor's 2.8
#   times the flow stress, the ball off the block at the end and 80 % of
#   the impression kept; the shrink fit's pressure highest at the hub's
#   ends and, pushed out, every node of the fit slipping with Coulomb's
#   |r_t| = mu |r_n| and the push the fit's friction; the O-ring sealing
#   (its contact pressure above the fluid's on the bore and the groove),
#   pushed onto the back wall, and no vertex of it inside the bore or the
#   shaft.
add_shipped_scene_check(ball_indentation_axisymmetric output-ball-indentation-axisymmetric
  indentation check_indentation.py OUTPUT --radius 1 --depth 0.05)
add_shipped_scene_check(shrink_fit_axisymmetric output-shrink-fit-axisymmetric
  push_out check_shrink_fit.py OUTPUT)
add_shipped_scene_check(o_ring_axisymmetric output-o-ring-axisymmetric
  seal check_o_ring.py OUTPUT --bore 10.6 --bottom 9 --shaft 10.5 --walls=-1.4,1.4)
# - The statistics of an axisymmetric run say that their forces and areas
#   are totals over the revolution.
add_test(NAME hertz_axisymmetric.statistics_say_totals
  COMMAND grep "every force and area a total over the full revolution"
          ${CMAKE_CURRENT_BINARY_DIR}/scenes/hertz_axisymmetric/1/output-hertz-axisymmetric/statistics)
set_tests_properties(hertz_axisymmetric.statistics_say_totals PROPERTIES
  FIXTURES_REQUIRED scene_hertz_axisymmetric)
