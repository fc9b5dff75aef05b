// mini2_bvh_picture: the galaxy seen from straight above, with the boxes of its BVH drawn over
// it, one colour per depth: the picture of mini2_bvh/README.md.
//
//   build/release/bin/mini2_bvh_picture [OUT.png] [--depth D] [--width W] [--wide]
//
// The scene is rendered by the Whitted tracer through the BVH (the stars show through the glass
// lid), then the boxes of the nodes at depth D (the root is depth 0) and of the leaves above it
// are projected through the same camera and their twelve edges drawn as one-pixel lines, in a
// colour per depth from red (the root) to violet (the deepest leaves). Without --depth, every
// leaf: the finest partition of the scene. Default OUT: docs/images/bvh-boxes.png (run it from
// the repository root), W 960 (the height follows the view's 16:9). --wide: the wide BVH's
// slots instead (WideBvh.h), D counted in wide nodes.

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "bvh/Bvh.h"
#include "bvh/WideBvh.h"
#include "camera/Camera.h"
#include "camera/ImageWriter.h"
#include "camera/RenderBlock.h"
#include "glossy/Galaxy.h"
#include "reflections/WhittedTracer.h"

namespace rt {
namespace {

/// The colour of a box at depth of deepest: hues from red (the root) through yellow and green to
/// violet (the deepest leaves), at full saturation, so that neighbouring depths differ.
Color depthColour(int depth, int deepest) {
  const double hue = 280.0 * depth / std::max(1, deepest);  // degrees
  const double h = hue / 60, x = 1 - std::abs(std::fmod(h, 2.0) - 1);
  std::array<double, 3> rgb{};
  switch (static_cast<int>(h)) {
    case 0:
      rgb = {1, x, 0};
      break;
    case 1:
      rgb = {x, 1, 0};
      break;
    case 2:
      rgb = {0, 1, x};
      break;
    case 3:
      rgb = {0, x, 1};
      break;
    default:
      rgb = {x, 0, 1};
      break;
  }
  return Color(255 * rgb[0], 255 * rgb[1], 255 * rgb[2]);
}

/// Where a point lands in the image (pixel coordinates, centre of pixel (i, j) at i + 0.5,
/// j + 0.5), or nothing when it lies behind the view plane: the inverse of Camera::ray.
struct Projector {
  const Camera& camera;
  bool project(const Point& p, double& px, double& py) const {
    const CameraSpec& s = camera.spec();
    const Vector d = p - camera.location();
    const double z = d.dot(camera.vTo());
    if (z < s.vpDistance * 1e-3) return false;
    const double xRight = d.dot(camera.vRight()) * s.vpDistance / z;
    const double yUp = d.dot(camera.vUp()) * s.vpDistance / z;
    px = xRight * s.nX / s.vpWidth + s.nX / 2.0;
    py = -yUp * s.nY / s.vpHeight + s.nY / 2.0;
    return true;
  }
};

/// A one-pixel line from (x0, y0) to (x1, y1), clipped to the image.
void drawLine(Image& image, double x0, double y0, double x1, double y1, const Color& c) {
  const double steps = std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)));
  if (!(steps < 1e6)) return;  // a degenerate projection
  for (int k = 0; k <= static_cast<int>(steps); ++k) {
    const double f = steps > 0 ? k / steps : 0;
    const int x = static_cast<int>(std::floor(x0 + f * (x1 - x0)));
    const int y = static_cast<int>(std::floor(y0 + f * (y1 - y0)));
    if (x >= 0 && y >= 0 && x < image.nX() && y < image.nY()) image.setPixel(x, y, c);
  }
}

void drawBox(Image& image, const Projector& projector, const Aabb& box, const Color& c) {
  const auto corner = [&](int i) {
    return Point(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                 i & 4 ? box.hi.z : box.lo.z);
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4}) {
      if (i & bit) continue;  // each edge once, from its lower corner
      double x0, y0, x1, y1;
      if (projector.project(corner(i), x0, y0) && projector.project(corner(i | bit), x1, y1))
        drawLine(image, x0, y0, x1, y1, c);
    }
}

/// --wide: the wide BVH's slots instead, a wide node's slots at depth d (the root's at 0) drawn
/// in the colour of d, down to maxDepth (every level when negative), the leaves above it too.
int drawWide(const GalaxySetup& g, Camera& camera, const Projector& projector,
             const std::string& out, int maxDepth) {
  const WideBvh wide(g.scene.geometries);
  if (maxDepth < 0) maxDepth = wide.depth();
  std::vector<std::pair<std::uint32_t, int>> stack{{0, 0}};
  int drawn = 0;
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    const WideNode& node = wide.nodes()[index];
    for (int k = 0; k < node.used; ++k) {
      const bool interior = node.kind[k] == WideNode::Kind::Interior;
      if (!interior || depth == maxDepth) {
        drawBox(camera.image(), projector, node.box(k).widen(), depthColour(depth, wide.depth()));
        ++drawn;
      } else {
        stack.push_back({node.child[k], depth + 1});
      }
    }
  }
  PngImageWriter().write(camera.image(), out);
  std::printf("mini2_bvh_picture: %s: %d slots (wide depth 0..%d) of %zu wide nodes, depth %d\n",
              out.c_str(), drawn, maxDepth, wide.nodes().size(), wide.depth());
  return 0;
}

int run(int argc, char** argv) {
  std::string out = "docs/images/bvh-boxes.png";
  int maxDepth = -1, width = 960;  // -1: every leaf
  bool wideTree = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--wide") {
      wideTree = true;
    } else if ((a == "--depth" || a == "--width") && i + 1 < argc) {
      const int v = std::atoi(argv[++i]);
      if (a == "--depth" && v >= 0 && v <= Bvh::SAH_MAX_DEPTH) {
        maxDepth = v;
      } else if (a == "--width" && v >= 16 && v <= 8192) {
        width = v;
      } else {
        std::fprintf(stderr, "mini2_bvh_picture: %s: expected %s, got '%s'\n", a.c_str(),
                     a == "--depth" ? "0..64" : "16..8192", argv[i]);
        return 2;
      }
    } else if (!a.starts_with("-")) {
      out = a;
    } else {
      std::fprintf(stderr, "usage: mini2_bvh_picture [OUT.png] [--depth D] [--width W] [--wide]\n");
      return 2;
    }
  }

  const GalaxySetup g = galaxy(GalaxyParams{});
  const Bvh bvh(g.scene.geometries);
  // Straight down on the disc of stars, the box's long side across the picture.
  CameraSpec view;
  view.location = Point(6, 75, 4);
  view.to = Vector(0, -1, 0);
  view.up = Vector(0, 0, -1);
  view.vpWidth = 48;
  view.vpHeight = 27;
  view.vpDistance = 60;
  view.nX = width;
  view.nY = width * 9 / 16;
  Camera camera = view.builder().build();
  const WhittedTracer tracer(g.scene, &bvh);
  renderBlock({camera, tracer, CenterSampler{}}, {0, 0, view.nX, view.nY}, camera.image());

  const Projector projector{camera};
  if (wideTree) return drawWide(g, camera, projector, out, maxDepth);
  // Depth-first over the flat array: a node's first child is the next node.
  if (maxDepth < 0) maxDepth = bvh.depth();
  std::vector<std::pair<std::uint32_t, int>> stack{{0, 0}};
  int drawn = 0;
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh.nodes()[index];
    if (node.isLeaf() || depth == maxDepth) {
      drawBox(camera.image(), projector, node.box.widen(), depthColour(depth, bvh.depth()));
      ++drawn;
      continue;
    }
    stack.push_back({node.offset, depth + 1});
    stack.push_back({index + 1, depth + 1});
  }
  PngImageWriter().write(camera.image(), out);
  std::printf("mini2_bvh_picture: %s: %d boxes (depth 0..%d) of %zu nodes, tree depth %d\n",
              out.c_str(), drawn, maxDepth, bvh.nodes().size(), bvh.depth());
  return 0;
}

}  // namespace
}  // namespace rt

int main(int argc, char** argv) {
  try {
    return rt::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mini2_bvh_picture: %s\n", e.what());
    return 1;
  }
}
