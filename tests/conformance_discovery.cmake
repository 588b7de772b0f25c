# Included by CTest every time it runs (TEST_INCLUDE_FILES): asks test_app which conformance
# tests it registers now (one per tests/conformance/**/*.mpf, found when test_app starts) and
# adds each as a CTest test. Unlike gtest_discover_tests, which lists a binary once after it is
# built, this sees a program added since the last build. Needs TEST_APP (the test_app binary).
if(NOT EXISTS "${TEST_APP}")
  add_test(conformance_suite_not_built "${CMAKE_COMMAND}" -E false)  # fails: build test_app first
  return()
endif()
execute_process(COMMAND "${TEST_APP}" --gtest_list_tests "--gtest_filter=Conformance/*"
                OUTPUT_VARIABLE _listing RESULT_VARIABLE _rc TIMEOUT 120)
if(NOT _rc EQUAL 0)
  add_test(conformance_suite_listing_failed "${CMAKE_COMMAND}" -E false)
  return()
endif()
string(REPLACE "\n" ";" _lines "${_listing}")
set(_suite "")
foreach(_line IN LISTS _lines)
  if(_line MATCHES "^([A-Za-z0-9_/]+\\.)$")
    set(_suite "${CMAKE_MATCH_1}")
  elseif(_suite AND _line MATCHES "^  ([A-Za-z0-9_/]+)")
    set(_name "${_suite}${CMAKE_MATCH_1}")
    add_test("${_name}" "${TEST_APP}" "--gtest_filter=${_name}")
    set_tests_properties("${_name}" PROPERTIES LABELS "app;conformance" TIMEOUT 300)
  endif()
endforeach()
