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
