# Stage 1 test sources (owned by the tests; the stage's CMakeLists.txt includes this file).
set(STAGE_TESTS
    tests/UtilTests.cpp
    tests/PointTests.cpp
    tests/VectorTests.cpp
    tests/RayTests.cpp
    tests/ColorTests.cpp
    tests/CourseMainTests.cpp)
