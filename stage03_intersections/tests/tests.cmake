# Stage 3 test sources (owned by the tests; the stage's CMakeLists.txt includes this file).
set(STAGE_TESTS
    tests/RootsTests.cpp
    tests/SphereIntersectionTests.cpp
    tests/PlaneIntersectionTests.cpp
    tests/TriangleIntersectionTests.cpp
    tests/PolygonIntersectionTests.cpp
    tests/TubeIntersectionTests.cpp
    tests/CylinderIntersectionTests.cpp
    tests/GeometriesTests.cpp
    tests/HitRulesTests.cpp
    tests/PropertyTests.cpp
    tests/MeshIntersectionTests.cpp)
