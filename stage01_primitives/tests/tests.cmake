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

# The tests' shared helpers, included as "support/...": rt_test_support, the headers (the portable
# random numbers of the tests' random scenes, tests/support/TestRandom.h, and the bit-for-bit
# comparisons, tests/support/SameBits.h); and the allocation
# counter every stage's "no allocation per ray" test links (an object library, so that its
# replacement of the global operator new is always linked in; see tests/support/AllocationCounter.h).
# rt_test_support exists without RT_BUILD_TESTS too: mini2's benchmark draws the tests' scenes.
if(NOT TARGET rt_test_support)
  add_library(rt_test_support INTERFACE)
  target_include_directories(rt_test_support INTERFACE "${CMAKE_CURRENT_SOURCE_DIR}/tests")
  target_link_libraries(rt_test_support INTERFACE rt_primitives)
endif()
if(RT_BUILD_TESTS AND NOT TARGET rt_test_allocation_counter)
  add_library(rt_test_allocation_counter OBJECT tests/support/AllocationCounter.cpp)
  target_link_libraries(rt_test_allocation_counter PUBLIC rt_test_support PRIVATE rt_options)
endif()
