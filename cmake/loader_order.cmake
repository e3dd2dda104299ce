# The order in which a program names the shared libraries it loads.
#
# At the start of every process the dynamic loader binds each symbol that a
# library refers to by searching the libraries in the program's order
# (breadth first from its own list), a library's references to its own
# symbols included. deal.II pulls in some 200 libraries (Trilinos,
# OpenCASCADE, gmsh, BLAS, ...), and several with tens of thousands of such
# references sat a hundred places down that order: binding took three
# quarters of the start of `contact --help` (perf), which is about half a
# second of CPU in every process the test suite starts.
#
# frictional_contact_loader_order() names those libraries first, most
# symbol relocations first, of those that can move without changing what
# any symbol binds to (cmake/loader_order.py reads their dynamic sections
# and symbol tables at configure time, so it holds for the libraries this
# machine has; the BLAS and LAPACK stay where the linker puts them). It is
# an optimisation only: without python3, ldd, readelf or nm, or configured
# with -DFRICTIONAL_CONTACT_LOADER_ORDER=OFF, the order stays as the linker
# left it. bench/process_start.py measures it against such a build.
option(FRICTIONAL_CONTACT_LOADER_ORDER
  "Name the libraries with the most symbol relocations first" ON)

# The list loader_order.py prints for deal.II's library, into @p _result;
# kept in the cache while deal.II's library file and the script stay the
# same (it reads some 200 libraries' symbol tables: a few seconds).
function(frictional_contact_library_order _result)
  # The release library's file (Debian's package names its configuration
  # DEBUGRELEASE).
  set(_deal_ii "")
  foreach(_configuration RELEASE DEBUGRELEASE NOCONFIG)
    get_target_property(_location ${DEAL_II_TARGET_RELEASE}
      IMPORTED_LOCATION_${_configuration})
    if(_location AND NOT _deal_ii)
      set(_deal_ii ${_location})
    endif()
  endforeach()
  set(_script ${CMAKE_SOURCE_DIR}/cmake/loader_order.py)
  file(SHA1 ${_script} _script_hash)
  # An upgraded deal.II package (its file's time) may load other libraries.
  file(TIMESTAMP ${_deal_ii} _deal_ii_time)
  set(_key "${_deal_ii};${_deal_ii_time};${_script_hash}")
  if(DEFINED FRICTIONAL_CONTACT_LOADER_LIST
      AND FRICTIONAL_CONTACT_LOADER_LIST_OF STREQUAL "${_key}")
    set(${_result} "${FRICTIONAL_CONTACT_LOADER_LIST}" PARENT_SCOPE)
    return()
  endif()
  find_program(_python python3)
  set(_ordered "")
  if(_deal_ii AND _python)
    execute_process(COMMAND ${_python} ${_script} ${_deal_ii}
      OUTPUT_VARIABLE _output RESULT_VARIABLE _status ERROR_VARIABLE _error)
    if(_status EQUAL 0)
      string(REGEX MATCHALL "[^\n]+" _ordered "${_output}")
    else()
      message(STATUS "The linker's library order (${_error})")
    endif()
  endif()
  list(LENGTH _ordered _n)
  message(STATUS "Libraries the programs name for the dynamic loader: ${_n}")
  set(FRICTIONAL_CONTACT_LOADER_LIST "${_ordered}" CACHE INTERNAL "")
  set(FRICTIONAL_CONTACT_LOADER_LIST_OF "${_key}" CACHE INTERNAL "")
  set(${_result} "${_ordered}" PARENT_SCOPE)
endfunction()

# Names those libraries right after what @p _target already links, in
# that order (--no-as-needed keeps every one in the list the loader reads).
function(frictional_contact_loader_order _target)
  if(NOT FRICTIONAL_CONTACT_LOADER_ORDER)
    return()
  endif()
  frictional_contact_library_order(_libraries)
  if(_libraries)
    target_link_libraries(${_target}
      -Wl,--no-as-needed ${_libraries} -Wl,--as-needed)
  endif()
endfunction()
