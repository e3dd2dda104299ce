# The command line: parameter listings and help.
add_test(NAME command_line/print_parameters
  COMMAND $<TARGET_FILE:contact> --print-parameters)
set_tests_properties(command_line/print_parameters PROPERTIES
  PASS_REGULAR_EXPRESSION "# Coulomb friction coefficient mu[^\n]*\n( *#[^\n]*\n)* *set Friction coefficient *= 0\n")
add_test(NAME command_line/print_parameters_of_scene
  COMMAND $<TARGET_FILE:contact> --print-parameters
          ${PROJECT_SOURCE_DIR}/parameters/example2.prm)
set_tests_properties(command_line/print_parameters_of_scene PROPERTIES
  PASS_REGULAR_EXPRESSION "set Dimension *= 3.*set Traction *= top: 0, 0, -0.005.*set Friction coefficient *= 0.5")
add_test(NAME command_line/help COMMAND $<TARGET_FILE:contact> --help)
set_tests_properties(command_line/help PROPERTIES
  PASS_REGULAR_EXPRESSION "Usage: contact \\[options\\] <parameter file>")

# Every Python script answers --help without its heavy imports.
add_test(NAME command_line/script_help
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_script_help.py
          ${PROJECT_SOURCE_DIR})

# The ParaView script renders a run (skipped without ParaView and Xvfb).
add_test(NAME render_contact
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render_contact.sh ${PROJECT_SOURCE_DIR}
          ${CMAKE_CURRENT_BINARY_DIR}/one_increment/output-one_increment)
set_tests_properties(render_contact PROPERTIES
  FIXTURES_REQUIRED one_increment SKIP_RETURN_CODE 77 TIMEOUT 420)

# Paths in a parameter file are relative to the file that names them.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/paths)
add_test(NAME paths/relative_to_parameter_file
  COMMAND $<TARGET_FILE:contact> ${CMAKE_CURRENT_SOURCE_DIR}/paths/scene_in_a_folder.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/paths)
set_tests_properties(paths/relative_to_parameter_file PROPERTIES
  ENVIRONMENT "${_environment}")

# The documentation stays true: every parameter path, file, test name and
# script option that README.md and doc/ quote exists (check_docs.py), and
# doc/parameters.md is what scripts/parameter_reference.py makes of the
# program's parameters.
add_test(NAME docs/quoted_things_exist
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_docs.py
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:contact> ${CMAKE_BINARY_DIR})
add_test(NAME docs/parameter_reference
  COMMAND ${PYTHON3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/parameter_reference.py
          --contact $<TARGET_FILE:contact> --check)

# The tables of doc/ that quote the bench CSVs are what bench/doc_tables.py
# makes of those CSVs.
add_test(NAME docs/tables_from_csv
  COMMAND ${PYTHON3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/bench/doc_tables.py --check)

# Numbers in README.md and doc/ that drift (the suite's size and time,
# issue numbers, bench figures typed by hand, unlisted CSVs and plugins,
# tolerances and tmpfs sizes that the tests do not use): check_doc_numbers.py,
# and its self-test shows that each check finds what it looks for.
add_test(NAME docs/stale_numbers
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_doc_numbers.py
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:contact>)
# Facts the pages state that drift with the code (check_doc_facts.py): the
# README's two commands, quoted defaults, the values every Selection's
# description names, the scenes the quoted plotting commands run on, the
# fuzz test's numbers, build times typed by hand; and against the scene
# runs of a linear, a J2 and a finite-strain scene with a tool, every VTU
# field and output file and the user guide's tables of them.
add_test(NAME docs/facts
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_doc_facts.py
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:contact>)
add_test(NAME docs/facts_self_test
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_doc_facts.py --self-test)
set(_scene_runs ${CMAKE_CURRENT_BINARY_DIR}/scenes)
add_test(NAME docs/output_files_and_fields
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_doc_facts.py
          ${PROJECT_SOURCE_DIR} $<TARGET_FILE:contact> --runs
          ${_scene_runs}/example1/1/output-example1
          ${_scene_runs}/step42_indentation/1/output-step42-indentation
          ${_scene_runs}/ironing_2d/1/output-ironing-2d)
set_tests_properties(docs/output_files_and_fields PROPERTIES
  FIXTURES_REQUIRED "scene_example1;scene_step42_indentation;scene_ironing_2d")
add_test(NAME docs/stale_numbers_self_test
  COMMAND ${PYTHON3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/check_doc_numbers.py --self-test)
