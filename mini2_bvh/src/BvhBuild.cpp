// Building the BVH: binned surface-area heuristic, nodes written depth-first into one array.
//
// Each primitive enters the build as a 28-byte record (its conservative float box and its
// index in the scene). A node's range of records is split in place (std::partition), so the
// build allocates nothing but the records, the node array and the leaves' index arrays.
//
// The surface-area heuristic (Goldsmith and Salmon 1987, MacDonald and Booth 1990): a ray that
// meets a node's box B meets a child's box B' inside it with probability SA(B')/SA(B), so
//
//     cost(split) = C_trav + (SA(L)·n_L + SA(R)·n_R) / SA(B)      (in units of one shape test)
//     cost(leaf)  = n
//
// and a node is split where cost(split) is lowest, if it is below cost(leaf). The candidate
// splits are the borders of BINS equal bins over the centroids' extent on each axis (Wald 2007):
// one pass puts every centroid in its bin, a sweep from each end accumulates the counts and
// boxes, and the cheapest border over the three axes wins.

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <variant>

#include "bvh/BoundingBox.h"
#include "bvh/Bvh.h"

namespace rt {

namespace {

struct BuildRecord {
  FloatBox box;
  std::uint32_t shape;
};
static_assert(sizeof(BuildRecord) == 28, "a build record is 28 bytes");

/// A record's centroid on an axis. Bounds beyond the float range are ±∞ in the box; they are
/// clamped here so that every centroid is finite and the bin arithmetic never meets ∞ − ∞.
double centroid(const BuildRecord& r, int axis) noexcept {
  constexpr double big = FLT_MAX;
  return 0.5 * (std::clamp<double>(r.box.lo[axis], -big, big) +
                std::clamp<double>(r.box.hi[axis], -big, big));
}

Double3 centroid(const BuildRecord& r) noexcept {
  return Double3(centroid(r, 0), centroid(r, 1), centroid(r, 2));
}

/// The bins along one axis: bin b holds the centroids c with b = floor((c − lo)·scale), scale =
/// BINS / extent, the last bin also holding c = hi.
struct Binning {
  double lo = 0;
  double scale = 0;  ///< 0: the centroids do not spread along this axis

  int bin(double c) const noexcept {
    return std::min(static_cast<int>((c - lo) * scale), Bvh::BINS - 1);
  }
};

struct Bin {
  Aabb box;
  std::uint32_t count = 0;
};

/// Where to split a range, or that it becomes a leaf.
struct Split {
  bool leaf = true;
  int axis = 0;
  std::uint32_t mid = 0;
};

class Builder {
 public:
  Builder(std::span<const Geometry> shapes, std::vector<BuildRecord>& records,
          std::vector<BvhNode>& nodes, std::vector<std::uint32_t>& sphereShapes,
          std::vector<std::uint32_t>& otherShapes, int sahMaxDepth)
      : sahMaxDepth_(std::clamp(sahMaxDepth, 0, Bvh::SAH_MAX_DEPTH)),
        shapes_(shapes),
        records_(records),
        nodes_(nodes),
        sphereShapes_(sphereShapes),
        otherShapes_(otherShapes) {}

  /// Builds the tree over every record; returns the deepest leaf's depth.
  int build() {
    buildNode(0, static_cast<std::uint32_t>(records_.size()), 0);
    return maxDepth_;
  }

 private:
  /// Writes the node of records [begin, end) at the end of the array, then its subtree right
  /// after it (depth-first); returns its index.
  std::uint32_t buildNode(std::uint32_t begin, std::uint32_t end, int depth) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Aabb box, centroids;
    for (std::uint32_t i = begin; i < end; ++i) {
      box.expand(records_[i].box.widen());
      centroids.expand(centroid(records_[i]));
    }
    const FloatBox floatBox = FloatBox::enclosing(box);  // exact: the bounds are floats
    const Split split = chooseSplit(begin, end, box, centroids, depth);
    if (split.leaf) {
      makeLeaf(index, floatBox, begin, end, depth);
      return index;
    }
    buildNode(begin, split.mid, depth + 1);  // the first child: index + 1
    const std::uint32_t second = buildNode(split.mid, end, depth + 1);
    nodes_[index] = interior(floatBox, second, split.axis);
    return index;
  }

  Split chooseSplit(std::uint32_t begin, std::uint32_t end, const Aabb& box, const Aabb& centroids,
                    int depth) {
    const std::uint32_t n = end - begin;
    if (n == 1) return Split{};
    std::array<Binning, 3> binnings;
    bool spread = false;
    for (int a = 0; a < 3; ++a) {
      const double lo = component(centroids.lo, a);
      const double scale = Bvh::BINS / (component(centroids.hi, a) - lo);
      if (std::isfinite(scale)) {  // not for a zero (or denormal) extent
        binnings[a] = Binning{lo, scale};
        spread = true;
      }
    }
    if (!spread) {
      // Every centroid is the same point: no border separates them. A few make a leaf; more are
      // cut in two halves of the range (their boxes may still differ, and a leaf's count is
      // bounded).
      if (n <= Bvh::MAX_LEAF_SIZE) return Split{};
      return Split{false, box.longestAxis(), begin + n / 2};
    }
    if (depth >= sahMaxDepth_) {
      if (n <= Bvh::MAX_LEAF_SIZE) return Split{};
      return medianSplit(begin, end, centroids.longestAxis());
    }
    return sahSplit(begin, end, box, binnings);
  }

  /// The binned SAH over the axes along which the centroids spread.
  Split sahSplit(std::uint32_t begin, std::uint32_t end, const Aabb& box,
                 const std::array<Binning, 3>& binnings) {
    std::array<std::array<Bin, Bvh::BINS>, 3> bins{};
    for (std::uint32_t i = begin; i < end; ++i) {
      const Aabb b = records_[i].box.widen();
      for (int a = 0; a < 3; ++a) {
        if (binnings[a].scale == 0) continue;
        Bin& bin = bins[a][binnings[a].bin(centroid(records_[i], a))];
        ++bin.count;
        bin.box.expand(b);
      }
    }
    // Unnormalised costs (times SA(box)), so that a flat or huge box never divides 0 or ∞.
    double bestCost = INFINITE_DISTANCE;
    int bestAxis = -1, bestBorder = 0;
    for (int a = 0; a < 3; ++a) {
      if (binnings[a].scale == 0) continue;
      // above[b]: SA·count of bins b..BINS-1, the right side of the border below bin b.
      std::array<double, Bvh::BINS> above{};
      Aabb right;
      std::uint32_t rightCount = 0;
      for (int b = Bvh::BINS - 1; b > 0; --b) {
        right.expand(bins[a][b].box);
        rightCount += bins[a][b].count;
        above[b] = rightCount * right.surfaceArea();
      }
      Aabb left;
      std::uint32_t leftCount = 0;
      for (int b = 0; b < Bvh::BINS - 1; ++b) {
        left.expand(bins[a][b].box);
        leftCount += bins[a][b].count;
        // Both sides are non-empty: bin 0 holds the lowest centroid, bin BINS-1 the highest.
        const double cost = leftCount * left.surfaceArea() + above[b + 1];
        if (bestAxis < 0 || cost < bestCost) {
          bestCost = cost;
          bestAxis = a;
          bestBorder = b;
        }
      }
    }
    const std::uint32_t n = end - begin;
    const double area = box.surfaceArea();
    const bool splitPays = Bvh::TRAVERSAL_COST * area + bestCost < n * area;
    if (bestAxis < 0 || (!splitPays && n <= Bvh::MAX_LEAF_SIZE)) return Split{};
    const Binning& binning = binnings[bestAxis];
    const auto mid = static_cast<std::uint32_t>(
        std::partition(records_.begin() + begin, records_.begin() + end,
                       [&](const BuildRecord& r) {
                         return binning.bin(centroid(r, bestAxis)) <= bestBorder;
                       }) -
        records_.begin());
    // Both sides hold a record (see above); the median is only a guard against the impossible.
    if (mid == begin || mid == end) return medianSplit(begin, end, bestAxis);
    return Split{false, bestAxis, mid};
  }

  /// Half the records on each side of the median centroid along axis: the depth then grows by
  /// one per halving, at most 32 levels for 2^32 records.
  Split medianSplit(std::uint32_t begin, std::uint32_t end, int axis) {
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(records_.begin() + begin, records_.begin() + mid, records_.begin() + end,
                     [axis](const BuildRecord& a, const BuildRecord& b) {
                       return centroid(a, axis) < centroid(b, axis);
                     });
    return Split{false, axis, mid};
  }

  /// Makes node `index` a leaf of records [begin, end). A leaf holds one kind of primitive, so
  /// that a sphere leaf runs the sphere solver on compact data without asking each primitive
  /// its kind; a range with both kinds becomes an interior node over a leaf of each.
  void makeLeaf(std::uint32_t index, const FloatBox& box, std::uint32_t begin, std::uint32_t end,
                int depth) {
    const auto spheresEnd = static_cast<std::uint32_t>(
        std::partition(records_.begin() + begin, records_.begin() + end,
                       [this](const BuildRecord& r) {
                         return std::holds_alternative<Sphere>(shapes_[r.shape]);
                       }) -
        records_.begin());
    if (spheresEnd == begin || spheresEnd == end) {
      nodes_[index] = leaf(box, begin, end, spheresEnd == end);
      maxDepth_ = std::max(maxDepth_, depth);
      return;
    }
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(leaf(boundsOf(begin, spheresEnd), begin, spheresEnd, true));
    nodes_.push_back(leaf(boundsOf(spheresEnd, end), spheresEnd, end, false));
    nodes_[index] = interior(box, first + 1, box.widen().longestAxis());
    maxDepth_ = std::max(maxDepth_, depth + 1);
  }

  FloatBox boundsOf(std::uint32_t begin, std::uint32_t end) const {
    Aabb box;
    for (std::uint32_t i = begin; i < end; ++i) box.expand(records_[i].box.widen());
    return FloatBox::enclosing(box);
  }

  /// A leaf node; its shapes are appended to the array of its kind.
  BvhNode leaf(const FloatBox& box, std::uint32_t begin, std::uint32_t end, bool spheres) {
    std::vector<std::uint32_t>& primitives = spheres ? sphereShapes_ : otherShapes_;
    BvhNode node;
    node.box = box;
    node.offset = static_cast<std::uint32_t>(primitives.size());
    node.count = static_cast<std::uint16_t>(end - begin);
    node.kind = spheres ? BvhNode::Kind::Spheres : BvhNode::Kind::Shapes;
    for (std::uint32_t i = begin; i < end; ++i) primitives.push_back(records_[i].shape);
    return node;
  }

  static BvhNode interior(const FloatBox& box, std::uint32_t second, int axis) {
    BvhNode node;
    node.box = box;
    node.offset = second;
    node.axis = static_cast<std::uint8_t>(axis);
    node.kind = BvhNode::Kind::Interior;
    return node;
  }

  int sahMaxDepth_;
  std::span<const Geometry> shapes_;
  std::vector<BuildRecord>& records_;
  std::vector<BvhNode>& nodes_;
  std::vector<std::uint32_t>& sphereShapes_;
  std::vector<std::uint32_t>& otherShapes_;
  int maxDepth_ = 0;
};

}  // namespace

Bvh::Bvh(std::span<const Geometry> shapes, BvhBuildOptions options) : shapes_(shapes) {
  std::vector<BuildRecord> records;
  records.reserve(shapes.size());
  std::size_t sphereCount = 0;
  for (std::uint32_t i = 0; i < shapes.size(); ++i) {
    if (const std::optional<Aabb> box = boundingBox(shapes[i])) {
      records.push_back(BuildRecord{conservativeBox(*box), i});
      sphereCount += std::holds_alternative<Sphere>(shapes[i]) ? 1 : 0;
    } else {
      unbounded_.push_back(i);
    }
  }
  if (records.empty()) return;

  // A binary tree over n leaves-worth of primitives has at most 2n − 1 nodes. The reservation
  // is address space: only the nodes written take memory, and shrink_to_fit returns the rest.
  nodes_.reserve(2 * records.size() - 1);
  sphereShapes_.reserve(sphereCount);
  otherShapes_.reserve(records.size() - sphereCount);
  depth_ =
      Builder(shapes, records, nodes_, sphereShapes_, otherShapes_, options.sahMaxDepth).build();

  // The records are done with before the compact spheres are made: the two never coexist.
  std::vector<BuildRecord>().swap(records);
  nodes_.shrink_to_fit();
  spheres_.reserve(sphereShapes_.size());
  for (std::uint32_t i : sphereShapes_) {
    const Sphere& s = std::get<Sphere>(shapes[i]);
    spheres_.push_back(CompactSphere{s.center().xyz(), s.radius()});
  }
}

}  // namespace rt
