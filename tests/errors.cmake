# Bad input and failed solves: each tests/errors/<name>.prm starts with a
# line "# ERROR <exit code>: <regular expression>" and must make the program
# exit with that code and that message, once, without a stack trace, and
# without touching the files in its folder (a 'statistics' file from an
# earlier run is put there first). A line "# MPI: N" runs it on N ranks.
# A few are broken on purpose here, from their header: windows_line_endings
# (CR LF), byte_order_mark, empty_file, random_bytes, garbage_mesh (a
# garbage.msh beside it), folder* (the argument
# is a folder), missing_file (it does not exist).

file(GLOB _error_scenes ${CMAKE_CURRENT_SOURCE_DIR}/errors/*.prm)
foreach(_scene ${_error_scenes})
  get_filename_component(_base ${_scene} NAME_WE)
  file(STRINGS ${_scene} _header REGEX "^# ERROR [0-9]+: ")
  if(NOT _header)
    message(FATAL_ERROR "${_scene} needs a first line '# ERROR <code>: <regex>'")
  endif()
  string(REGEX REPLACE "^# ERROR ([0-9]+): (.*)$" "\\1" _code "${_header}")
  string(REGEX REPLACE "^# ERROR ([0-9]+): (.*)$" "\\2" _regex "${_header}")
  file(STRINGS ${_scene} _mpi REGEX "^# MPI: [0-9]+")
  set(_ranks 0)
  if(_mpi)
    string(REGEX REPLACE "^# MPI: ([0-9]+).*$" "\\1" _ranks "${_mpi}")
  endif()

  set(_directory ${CMAKE_CURRENT_BINARY_DIR}/errors/${_base})
  configure_file(${_scene} ${_directory}/${_base}.prm @ONLY)
  file(WRITE ${_directory}/output-error/statistics "# results of an earlier run\n")
  set(_arguments ${_base}.prm)
  if(_base STREQUAL "missing_file")
    set(_arguments does_not_exist.prm)
  elseif(_base STREQUAL "windows_line_endings")
    file(READ ${_scene} _text)
    string(REPLACE "\n" "\r\n" _text "${_text}")
    file(WRITE ${_directory}/${_base}.prm "${_text}")
  elseif(_base STREQUAL "byte_order_mark")
    file(READ ${_directory}/${_base}.prm _text)
    string(ASCII 239 187 191 _mark)
    file(WRITE ${_directory}/${_base}.prm "${_mark}${_text}")
  elseif(_base STREQUAL "empty_file")
    file(WRITE ${_directory}/${_base}.prm "\n  \n")
  elseif(_base MATCHES "^folder")
    file(MAKE_DIRECTORY ${_directory}/scene.prm)
    set(_arguments scene.prm)
  elseif(_base STREQUAL "garbage_mesh")
    string(ASCII 7 200 1 27 255 3 _bytes)
    file(WRITE ${_directory}/garbage.msh
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n${_bytes}${_bytes}\n")
  elseif(_base STREQUAL "random_bytes_with_cr")
    # Binary bytes with a CR LF among them: "not a text file", not "Windows
    # line endings".
    string(ASCII 200 13 10 128 7 _bytes)
    file(WRITE ${_directory}/${_base}.prm "${_bytes}set Dimension = 2\n${_bytes}\n")
  elseif(_base STREQUAL "random_bytes")
    string(ASCII 7 200 1 27 255 3 _bytes)
    file(WRITE ${_directory}/${_base}.prm "set Dimension = 2${_bytes}\n${_bytes}${_bytes}\n")
  endif()
  add_test(NAME errors/${_base}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/expect_error.sh ${_ranks} ${_code}
            "${_regex}" $<TARGET_FILE:contact> ${_arguments}
    WORKING_DIRECTORY ${_directory})
  set(_processors 1)
  if(_ranks GREATER 0)
    set(_processors ${_ranks})
  endif()
  set_tests_properties(errors/${_base} PROPERTIES
    ENVIRONMENT "${_environment}" PROCESSORS ${_processors})
endforeach()

# A write that fails in the middle of a run (a file where the VTU folder
# goes) stops every rank with the same line, on 2 ranks; it used to leave
# rank 1 waiting for rank 0 for ever.
set(_directory ${CMAKE_CURRENT_BINARY_DIR}/errors/write_fails_mid_run)
file(MAKE_DIRECTORY ${_directory})
add_test(NAME errors/write_fails_mid_run.mpirun=2
  COMMAND sh -c "rm -rf out && mkdir out && touch out/solution && printf 'include ${PROJECT_SOURCE_DIR}/parameters/example1.prm\\nset Output directory = out\\n' > scene.prm && timeout 120 mpirun -np 2 $<TARGET_FILE:contact> scene.prm > output.raw 2> errors.raw; code=$?; cat output.raw errors.raw; test $code -eq 1 && test $(grep -c '^Error: cannot write .out/solution.*Not a directory.*check <Output directory>' errors.raw) -eq 1 && echo 'failed as expected, on both ranks'"
  WORKING_DIRECTORY ${_directory})
set_tests_properties(errors/write_fails_mid_run.mpirun=2 PROPERTIES
  ENVIRONMENT "${_environment}" PROCESSORS 2)
