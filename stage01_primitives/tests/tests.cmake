# Stage 1 test sources (owned by the tests; the stage's CMakeLists.txt includes this file).
set(STAGE_TESTS
    tests/UtilTests.cpp
    tests/ChecksTests.cpp
    tests/PointTests.cpp
    tests/VectorTests.cpp
    tests/RayTests.cpp
    tests/ColorTests.cpp
    tests/CourseMainTests.cpp
    tests/RandomTests.cpp)

# The allocation counter every stage's "no allocation per ray" test links (an object library, so
# that its replacement of the global operator new is always linked in; see
# tests/support/AllocationCounter.h). Tests include it as "support/AllocationCounter.h".
if(RT_BUILD_TESTS AND NOT TARGET rt_test_allocation_counter)
  add_library(rt_test_allocation_counter OBJECT tests/support/AllocationCounter.cpp)
  target_include_directories(rt_test_allocation_counter PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}/tests")
  target_link_libraries(rt_test_allocation_counter PRIVATE rt_options)
endif()
