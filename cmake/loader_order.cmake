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
# symbol relocations first (read from their dynamic sections with readelf
# at configure time, so it holds for the libraries this machine has). It is
# an optimisation only: without ldd or readelf, or configured with
# -DFRICTIONAL_CONTACT_LOADER_ORDER=OFF, the order stays as the linker left
# it. bench/process_start.py measures it against such a build.
option(FRICTIONAL_CONTACT_LOADER_ORDER
  "Name the libraries with the most symbol relocations first" ON)

# deal.II and the libraries it loads, those with at least @p _minimum
# symbol relocations, most first, into @p _result (half a second for some
# 200 libraries).
function(frictional_contact_heavy_libraries _result _minimum)
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
  find_program(_ldd ldd)
  find_program(_readelf readelf)
  set(_ordered "")
  if(_deal_ii AND _ldd AND _readelf)
    execute_process(COMMAND ${_ldd} ${_deal_ii} OUTPUT_VARIABLE _ldd_output
      RESULT_VARIABLE _ldd_result ERROR_QUIET)
    if(_ldd_result EQUAL 0)
      string(REGEX MATCHALL "=> (/[^ ]+) " _found "${_ldd_output}")
      set(_libraries ${_deal_ii})
      foreach(_entry ${_found})
        string(REGEX REPLACE "=> (/[^ ]+) " "\\1" _library "${_entry}")
        # Not the BLAS and LAPACK: which ones load is chosen at run time
        # (Debian's alternatives, LD_LIBRARY_PATH: the tests' other BLAS),
        # and OpenBLAS named here would serve every BLAS call even where
        # the reference BLAS was chosen.
        if(NOT _library MATCHES "/lib(open|c)?blas[^/]*$|/liblapack[^/]*$")
          list(APPEND _libraries ${_library})
        endif()
      endforeach()
      set(_keyed "")
      foreach(_library ${_libraries})
        execute_process(COMMAND ${_readelf} -dW ${_library}
          OUTPUT_VARIABLE _dynamic ERROR_QUIET)
        # Symbol relocations: all relocation entries (24 bytes each) less
        # the relative ones, which need no lookup.
        set(_bytes 0)
        foreach(_tag RELASZ PLTRELSZ)
          if(_dynamic MATCHES "\\(${_tag}\\) +([0-9]+) \\(bytes\\)")
            math(EXPR _bytes "${_bytes} + ${CMAKE_MATCH_1}")
          endif()
        endforeach()
        set(_relative 0)
        if(_dynamic MATCHES "\\(RELACOUNT\\) +([0-9]+)")
          set(_relative ${CMAKE_MATCH_1})
        endif()
        math(EXPR _count "${_bytes} / 24 - ${_relative}")
        if(_count GREATER_EQUAL _minimum)
          # Zero-padded, so that sorting the strings sorts the counts.
          string(LENGTH "${_count}" _digits)
          math(EXPR _padding "12 - ${_digits}")
          string(REPEAT "0" ${_padding} _zeros)
          list(APPEND _keyed "${_zeros}${_count}|${_library}")
        endif()
      endforeach()
      list(SORT _keyed ORDER DESCENDING)
      foreach(_entry ${_keyed})
        string(REGEX REPLACE "^[0-9]+\\|" "" _library "${_entry}")
        list(APPEND _ordered ${_library})
      endforeach()
    endif()
  endif()
  set(${_result} "${_ordered}" PARENT_SCOPE)
endfunction()

# Names those libraries right after what @p _target already links, in
# their order (--no-as-needed keeps every one in the list the loader reads).
function(frictional_contact_loader_order _target)
  if(NOT FRICTIONAL_CONTACT_LOADER_ORDER)
    return()
  endif()
  # Read once per configure run, kept in a global property.
  get_property(_known GLOBAL PROPERTY FRICTIONAL_CONTACT_LOADER_ORDER SET)
  if(NOT _known)
    frictional_contact_heavy_libraries(_found 200)
    list(LENGTH _found _n)
    message(STATUS "Libraries named first for the dynamic loader: ${_n}")
    set_property(GLOBAL PROPERTY FRICTIONAL_CONTACT_LOADER_ORDER "${_found}")
  endif()
  get_property(_libraries GLOBAL PROPERTY FRICTIONAL_CONTACT_LOADER_ORDER)
  if(_libraries)
    target_link_libraries(${_target}
      -Wl,--no-as-needed ${_libraries} -Wl,--as-needed)
  endif()
endfunction()
