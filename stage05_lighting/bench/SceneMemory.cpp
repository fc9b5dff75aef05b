// What one sphere costs in a LitScene: the shape, its row index of the appearance table, and its
// share of the table. Prints the figures; not a test.
//
//   build/release/stage05_lighting/stage05_scene_memory [N]        (default N = 1000000)
//
// It builds a scene of N spheres of two looks (the galaxy's stars) and measures the heap the
// scene holds with glibc's mallinfo2 (bytes in use, before and after), so vector growth and
// allocator overhead are counted, not only sizeof.
#include <malloc.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "geometries/Geometry.h"
#include "lighting/LitScene.h"

namespace {
std::size_t heapInUse() { return mallinfo2().uordblks + mallinfo2().hblkhd; }
}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 1000000;
  if (n < 1 || n > 100000000) {
    std::fprintf(stderr, "stage05_scene_memory: N must be in 1..1e8, got '%s'\n", argv[1]);
    return 2;
  }
  const std::size_t before = heapInUse();
  {
    rt::LitScene scene;
    rt::Material star;
    star.kD = rt::Double3(0.2);
    star.kS = rt::Double3(0.33);
    star.shininess = 10;
    const std::uint32_t blue = scene.addAppearance(rt::Color(80, 255, 230), star);
    const std::uint32_t white = scene.addAppearance(rt::Color(200, 250, 255), star);
    scene.geometries.reserve(static_cast<std::uint32_t>(n));
    scene.appearanceIndex.reserve(static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i)
      scene.add(rt::Sphere(rt::Point(static_cast<double>(i) * 0.1, 0, 0), 0.05),
                i % 2 ? white : blue);
    const std::size_t after = heapInUse();
    const double perSphere = static_cast<double>(after - before) / static_cast<double>(n);
    std::printf("spheres                  %ld\n", n);
    std::printf("sizeof(Geometry)         %zu bytes (the largest shape, Triangle, sets it)\n",
                sizeof(rt::Geometry));
    std::printf("sizeof(appearance row)   %zu bytes\n", sizeof(std::uint32_t));
    std::printf("sizeof(Appearance)       %zu bytes, once per look (2 here)\n",
                sizeof(rt::Appearance));
    std::printf("heap held by the scene   %zu bytes\n", after - before);
    std::printf("per sphere               %.1f bytes\n", perSphere);
  }
  return 0;
}
