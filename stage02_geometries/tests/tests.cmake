# Stage 2 test sources (owned by the tests; the stage's CMakeLists.txt includes this file).
set(STAGE_TESTS
    tests/SphereTests.cpp
    tests/PlaneTests.cpp
    tests/TriangleTests.cpp
    tests/PolygonTests.cpp
    tests/TubeTests.cpp
    tests/CylinderTests.cpp
    tests/GeometryTests.cpp
    tests/TriangleMeshTests.cpp
    tests/UtahTeapotTests.cpp)
