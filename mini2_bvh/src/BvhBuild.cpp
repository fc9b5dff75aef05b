// Building the BVH: binned surface-area heuristic, nodes written depth-first into one array.
//
// Each primitive enters the build as a 32-byte record (its conservative float box, its index in
// the scene and whether it is a sphere). A node's range of records is split in place
// (std::partition), so the build allocates nothing but the records, the node array and the leaves'
// index arrays (and, on several threads, each subtree's own arrays and the top phase's lists).
//
// The surface-area heuristic (Goldsmith and Salmon 1987, MacDonald and Booth 1990): a ray that
// meets a node's box B meets a child's box B' inside it with probability SA(B')/SA(B), so
//
//     cost(split) = C_trav + (SA(L)·c_L + SA(R)·c_R) / SA(B)      (in units of one sphere test)
//     cost(leaf)  = c
//
// where c is the sum of the primitives' test costs: 1 for a sphere, Bvh::SHAPE_COST for any other
// shape (a polygon's test costs several sphere tests; counting it as one would leave polygons
// in large leaves whose boxes every ray meets).
//
// and a node is split where cost(split) is lowest, if it is below cost(leaf). The candidate
// splits are the borders of BINS equal bins over the centroids' extent on each axis (Wald 2007):
// one pass puts every centroid in its bin, a sweep from each end accumulates the counts and
// boxes, and the cheapest border over the three axes wins. The children's bounds come out of the
// bins and of the partition, without another pass over the records.

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <limits>
#include <mutex>
#include <thread>
#include <utility>
#include <variant>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "Concurrently.h"
#include "bvh/BoundingBox.h"
#include "bvh/Bvh.h"
#include "bvh/HugePages.h"

namespace rt {

namespace {

struct BuildRecord {
  FloatBox box;
  std::uint32_t shape;
  /// 1 for a sphere, else 0: kept here so that making a leaf never reads the (large) shapes
  /// again. A whole word, so that the record has no padding: a copy (the partition's swaps) is
  /// then two 16-byte moves, where a bool left 29 bytes to copy, which the compiler did through
  /// overlapping moves on the stack that the processor cannot forward from one to the next.
  std::uint32_t sphere;

  /// Left unset: the records' array is made at its size, and each build thread writes (and
  /// first touches) its own part of it; every record is written before it is read.
  BuildRecord() noexcept {}  // NOLINT(cppcoreguidelines-pro-type-member-init)
  BuildRecord(const FloatBox& b, std::uint32_t s, bool isSphere) noexcept
      : box(b), shape(s), sphere(isSphere ? 1 : 0) {}
};
static_assert(sizeof(BuildRecord) == 32, "a build record is 32 bytes");
static_assert(sizeof(FloatBox) + 2 * sizeof(std::uint32_t) == sizeof(BuildRecord),
              "a build record has no padding");

/// What testing a record's shape costs the SAH, in sphere tests.
double testCost(const BuildRecord& r) noexcept { return r.sphere != 0 ? 1.0 : Bvh::SHAPE_COST; }

/// A record's centroid on an axis: 0.5·lo + 0.5·hi (halved first, so no sum overflows). Every
/// record's box is finite (see the constructor), so every centroid is.
float centroid(const BuildRecord& r, int axis) noexcept {
  return 0.5f * r.box.lo[axis] + 0.5f * r.box.hi[axis];
}

bool isFinite(const FloatBox& b) noexcept {
  return std::isfinite(b.lo[0]) && std::isfinite(b.lo[1]) && std::isfinite(b.lo[2]) &&
         std::isfinite(b.hi[0]) && std::isfinite(b.hi[1]) && std::isfinite(b.hi[2]);
}

/// What the build knows of a set of records: the box around their boxes and the box around
/// their centroids. Both are unions of floats, so exact.
struct Bounds {
  FloatBox box = FloatBox::empty();
  FloatBox centroids = FloatBox::empty();

  void add(const BuildRecord& r) noexcept {
    add(r, {centroid(r, 0), centroid(r, 1), centroid(r, 2)});
  }
  void add(const BuildRecord& r, const std::array<float, 3>& c) noexcept {
    box.expand(r.box);
    centroids.expand(FloatBox{c, c});
  }
  void add(const Bounds& b) noexcept {
    box.expand(b.box);
    centroids.expand(b.centroids);
  }
};

/// The bins along one axis: bin b holds the centroids c with b = floor((c − lo)·scale), scale =
/// bins / extent, the last bin also holding c = hi. (c − lo may overflow to +∞ for coordinates
/// near the float range's end; the minimum with the last bin is taken before the conversion.)
struct Binning {
  float lo = 0;
  float scale = 0;  ///< 0: the centroids do not spread along this axis
  float last = 0;   ///< the number of bins − 1

  int bin(float c) const noexcept { return static_cast<int>(std::min((c - lo) * scale, last)); }
};

/// A float box as the binning pass grows it: with SSE2, its bounds in two registers of four
/// lanes (x, y, z and a fourth lane that is never read back), so that a union is two
/// instructions; a minimum or maximum of floats is exact either way, so the box is the same as
/// FloatBox::expand's.
struct LaneBox {
#if defined(__SSE2__)
  __m128 lo, hi;

  static LaneBox empty() noexcept {
    constexpr float inf = std::numeric_limits<float>::infinity();
    return {_mm_set1_ps(inf), _mm_set1_ps(-inf)};
  }
  /// A record's box. Its lo and hi are six consecutive floats: the lanes (lo0, lo1, lo2, hi0)
  /// and (lo2, hi0, hi1, hi2), the second turned to (hi0, hi1, hi2, hi0), so that no lane holds
  /// anything but the box's own bounds (the record's other fields are not floats).
  static LaneBox of(const BuildRecord& r) noexcept {
    const __m128 high = _mm_loadu_ps(&r.box.lo[2]);
    return {_mm_loadu_ps(&r.box.lo[0]), _mm_shuffle_ps(high, high, _MM_SHUFFLE(1, 3, 2, 1))};
  }
  void expand(const LaneBox& b) noexcept {
    lo = _mm_min_ps(lo, b.lo);
    hi = _mm_max_ps(hi, b.hi);
  }
  /// Lanes 0 to 2 of centre (the record's centroid: 0.5·lo + 0.5·hi, as centroid() computes it).
  __m128 centre() const noexcept {
    const __m128 half = _mm_set1_ps(0.5f);
    return _mm_add_ps(_mm_mul_ps(half, lo), _mm_mul_ps(half, hi));
  }
  FloatBox box() const noexcept {
    alignas(16) std::array<float, 4> l, h;
    _mm_store_ps(l.data(), lo);
    _mm_store_ps(h.data(), hi);
    return FloatBox{{l[0], l[1], l[2]}, {h[0], h[1], h[2]}};
  }
#else
  FloatBox b;

  static LaneBox empty() noexcept { return {FloatBox::empty()}; }
  static LaneBox of(const BuildRecord& r) noexcept { return {r.box}; }
  void expand(const LaneBox& other) noexcept { b.expand(other.b); }
  FloatBox box() const noexcept { return b; }
#endif
};

struct Bin {
  LaneBox box;
  std::uint32_t count;
  std::uint32_t spheres;  ///< of count: the records of cost 1, the others cost SHAPE_COST

  /// The sum of its records' testCost (exact: integers in a double).
  double cost() const noexcept {
    return spheres + Bvh::SHAPE_COST * static_cast<double>(count - spheres);
  }
};

/// Where to split a range, or that it becomes a leaf; with the bounds of both sides.
struct Split {
  bool leaf = true;
  int axis = 0;
  std::uint32_t mid = 0;
  Bounds left, right;
};

class Builder {
 public:
  Builder(std::vector<BuildRecord>& records, std::vector<BvhNode>& nodes,
          std::vector<std::uint32_t>& sphereShapes, std::vector<std::uint32_t>& otherShapes,
          int sahMaxDepth)
      : sahMaxDepth_(std::clamp(sahMaxDepth, 0, Bvh::SAH_MAX_DEPTH)),
        records_(records),
        nodes_(nodes),
        sphereShapes_(sphereShapes),
        otherShapes_(otherShapes) {}

  /// Builds the tree over every record (whose bounds are `all`) on up to `threads` threads;
  /// returns the deepest leaf's depth. The tree is the same, node for node, whatever the number
  /// of threads:
  ///  1. the top levels are split down to ranges of at most `grain` records, into a skeleton
  ///     whose leaves are subtrees still to build (tasks); each task is built by a Builder of
  ///     its own into arrays of its own (offsets relative to them). Splitting a range and
  ///     building a task are jobs that the threads take from one list as they come free, so
  ///     that a thread done with its side of an uneven split builds tasks of the other side
  ///     while it is still being split; the ranges of the jobs in flight are disjoint, so no
  ///     two threads touch the same record;
  ///  2. the skeleton is written depth-first, each task's nodes and primitives appended where
  ///     a one-thread build writes them, their offsets moved by what comes before.
  /// Every split is chosen from the records of its range alone, in the same order either way,
  /// so step 1 chooses exactly the splits of a one-thread build (BvhParallelBuildTests checks it).
  int build(int threads, const Bounds& all) {
    const auto n = static_cast<std::uint32_t>(records_.size());
    if (threads <= 1 || n < 2 * PARALLEL_GRAIN_MIN) {
      // A binary tree over n leaves-worth of primitives has at most 2n − 1 nodes. The
      // reservation is address space: only the nodes written take memory.
      reserveHuge(nodes_, 2 * static_cast<std::size_t>(n) - 1);
      buildNode(0, n, 0, all);
      return maxDepth_;
    }
    const std::uint32_t grain = std::max<std::uint32_t>(PARALLEL_GRAIN_MIN, n / TASKS_PER_BUILD);
    std::deque<SkeletonNode> skeleton;
    std::deque<Task> tasks;
    buildTop(all, grain, threads, skeleton, tasks);
    // The records are done with (the tasks hold every leaf's primitives): freed before the
    // tasks' arrays are copied into the tree, so that the two do not add up at the peak.
    std::vector<BuildRecord>().swap(records_);
    // The tree's nodes are now counted (the skeleton's interior ones and the tasks'): the array
    // at its size, its pages made at once.
    std::size_t count = skeleton.size() - tasks.size();
    for (const Task& t : tasks) count += t.nodes.size();
    reserveHugeWritten(nodes_, count);
    emit(0, skeleton, tasks);
    for (const Task& t : tasks) maxDepth_ = std::max(maxDepth_, t.maxDepth);
    return maxDepth_;
  }

 private:
  /// The parallel build's top phase stops at ranges of at most n / TASKS_PER_BUILD records:
  /// more tasks than threads, so that a thread that drew a large subtree is balanced by the
  /// others, yet few levels split in the top phase (on the 10^6-triangle teapot on 2 cores, 8,
  /// 16 and 64 tasks built within the machine's noise). No range below PARALLEL_GRAIN_MIN
  /// becomes a task of its own (a thread's start costs more than its build).
  static constexpr std::uint32_t TASKS_PER_BUILD = 16;
  static constexpr std::uint32_t PARALLEL_GRAIN_MIN = 4096;

  /// A subtree to build, and once built, its arrays.
  struct Task {
    std::uint32_t begin, end;
    int depth;
    Bounds bounds;
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> spheres, others;
    int maxDepth = 0;
  };
  /// A node of the top phase: an interior node (its children's skeleton indices), or a task.
  struct SkeletonNode {
    FloatBox box;
    int axis = 0;
    std::int32_t task = -1;  ///< the task's index, or -1 for an interior node
    std::uint32_t first = 0, second = 0;
  };
  /// A range of the top phase still to split, and the skeleton node it becomes.
  struct TopRange {
    std::uint32_t begin, end;
    int depth;
    Bounds bounds;
    std::uint32_t node;
  };

  /// Step 1 on `threads` threads (the calling thread one of them): the skeleton, root first,
  /// and every task built. (Deques: a task or node being filled by one thread stays where it is
  /// while another thread appends.)
  void buildTop(const Bounds& all, std::uint32_t grain, int threads,
                std::deque<SkeletonNode>& skeleton, std::deque<Task>& tasks) {
    std::mutex lock;
    std::condition_variable changed;
    std::vector<TopRange> splits;     // ranges still to split, the last first
    std::vector<std::size_t> builds;  // tasks still to build: a heap, the largest on top
    const auto smaller = [&tasks](std::size_t a, std::size_t b) {
      return tasks[a].end - tasks[a].begin < tasks[b].end - tasks[b].begin;
    };
    int busy = 0;         // threads in a job
    bool failed = false;  // a job threw: the others take no more
    skeleton.emplace_back();
    splits.push_back(TopRange{0, static_cast<std::uint32_t>(records_.size()), 0, all, 0});
    // Splits first (each gives the threads more jobs), then the largest task first, so that
    // the last job to start is a small one and the threads end together.
    build::concurrently(threads, [&](int) {
      std::unique_lock<std::mutex> held(lock);
      for (;;) {
        changed.wait(held,
                     [&] { return failed || !splits.empty() || !builds.empty() || busy == 0; });
        if (failed || (splits.empty() && builds.empty())) return;  // failed, or all done
        ++busy;
        try {
          if (!splits.empty()) {
            const TopRange r = splits.back();
            splits.pop_back();
            held.unlock();
            const Split s =
                r.end - r.begin <= grain ? Split{} : chooseSplit(r.begin, r.end, r.bounds, r.depth);
            held.lock();
            if (s.leaf) {  // a small range, or a leaf: its Task chooses the same again
              skeleton[r.node].task = static_cast<std::int32_t>(tasks.size());
              tasks.push_back(Task{r.begin, r.end, r.depth, r.bounds, {}, {}, {}, 0});
              builds.push_back(tasks.size() - 1);
              std::push_heap(builds.begin(), builds.end(), smaller);
            } else {
              const auto first = static_cast<std::uint32_t>(skeleton.size());
              skeleton.resize(skeleton.size() + 2);
              skeleton[r.node] = SkeletonNode{r.bounds.box, s.axis, -1, first, first + 1};
              splits.push_back(TopRange{s.mid, r.end, r.depth + 1, s.right, first + 1});
              splits.push_back(TopRange{r.begin, s.mid, r.depth + 1, s.left, first});
            }
          } else {
            std::pop_heap(builds.begin(), builds.end(), smaller);
            Task& t = tasks[builds.back()];
            builds.pop_back();
            held.unlock();
            buildTask(t);
            held.lock();
          }
        } catch (...) {
          if (!held.owns_lock()) held.lock();
          failed = true;
          --busy;
          changed.notify_all();
          throw;  // concurrently throws it again after the joins
        }
        --busy;
        changed.notify_all();
      }
    });
  }

  /// Builds a task's subtree into its arrays.
  void buildTask(Task& t) const {
    // Address space for the most nodes a range can make (2n - 1, and two more per leaf of both
    // kinds): only the nodes written take memory, and no array is copied growing. On small
    // pages, so that the part reserved beyond the written nodes stays address space where the
    // system gives huge pages unasked (HugePages.h); the primitives' arrays at their sizes.
    const std::size_t n = t.end - t.begin;
    reserveSmall(t.nodes, 3 * n);
    std::size_t spheres = 0;
    for (std::uint32_t i = t.begin; i < t.end; ++i) spheres += records_[i].sphere;
    t.spheres.reserve(spheres);
    t.others.reserve(n - spheres);
    Builder b(records_, t.nodes, t.spheres, t.others, sahMaxDepth_);
    b.buildNode(t.begin, t.end, t.depth, t.bounds);
    t.maxDepth = b.maxDepth_;
  }

  /// Step 2 for skeleton node `index`: returns the index of its node in the tree.
  std::uint32_t emit(std::uint32_t index, const std::deque<SkeletonNode>& skeleton,
                     std::deque<Task>& tasks) {
    const SkeletonNode& s = skeleton[index];
    const auto at = static_cast<std::uint32_t>(nodes_.size());
    if (s.task < 0) {
      nodes_.emplace_back();
      emit(s.first, skeleton, tasks);
      const std::uint32_t second = emit(s.second, skeleton, tasks);
      nodes_[at] = interior(s.box, second, s.axis);
      return at;
    }
    Task& t = tasks[static_cast<std::size_t>(s.task)];
    const auto sphereBase = static_cast<std::uint32_t>(sphereShapes_.size());
    const auto otherBase = static_cast<std::uint32_t>(otherShapes_.size());
    for (BvhNode node : t.nodes) {
      node.offset += node.kind == BvhNode::Kind::Interior  ? at
                     : node.kind == BvhNode::Kind::Spheres ? sphereBase
                                                           : otherBase;
      nodes_.push_back(node);
    }
    sphereShapes_.insert(sphereShapes_.end(), t.spheres.begin(), t.spheres.end());
    otherShapes_.insert(otherShapes_.end(), t.others.begin(), t.others.end());
    std::vector<BvhNode>().swap(t.nodes);  // done with: freed as soon as it is copied
    return at;
  }

  /// Writes the node of records [begin, end) at the end of the array, then its subtree right
  /// after it (depth-first); returns its index.
  std::uint32_t buildNode(std::uint32_t begin, std::uint32_t end, int depth, const Bounds& bounds) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    const Split split = chooseSplit(begin, end, bounds, depth);
    if (split.leaf) {
      makeLeaf(index, bounds.box, begin, end, depth);
      return index;
    }
    buildNode(begin, split.mid, depth + 1, split.left);  // the first child: index + 1
    const std::uint32_t second = buildNode(split.mid, end, depth + 1, split.right);
    nodes_[index] = interior(bounds.box, second, split.axis);
    return index;
  }

  Split chooseSplit(std::uint32_t begin, std::uint32_t end, const Bounds& bounds, int depth) {
    const std::uint32_t n = end - begin;
    // A split costs at least C_trav·SA(box), a leaf (its test costs)·SA(box): a range whose
    // tests cost no more than C_trav never splits. (Each test costs at least 1: n > C_trav does
    // not qualify, and needs no sum.)
    if (n <= Bvh::TRAVERSAL_COST && testCosts(begin, end) <= Bvh::TRAVERSAL_COST) return Split{};
    // A few centroids need no more bins than they are.
    const int bins = static_cast<int>(std::min<std::uint32_t>(Bvh::BINS, n));
    std::array<Binning, 3> binnings;
    bool spread = false;
    for (int a = 0; a < 3; ++a) {
      const float lo = bounds.centroids.lo[a];
      const float scale = static_cast<float>(bins / (double{bounds.centroids.hi[a]} - lo));
      if (std::isfinite(scale)) {  // not for a zero (or denormal) extent
        binnings[a] = Binning{lo, scale, static_cast<float>(bins - 1)};
        spread = true;
      }
    }
    if (!spread) {
      // Every centroid is the same point: no border separates them. A few make a leaf; more are
      // cut in two halves of the range (their boxes may still differ, and a leaf's count is
      // bounded).
      if (n <= Bvh::MAX_LEAF_SIZE) return Split{};
      return splitAt(begin, end, begin + n / 2, bounds.box.widen().longestAxis());
    }
    if (depth >= sahMaxDepth_) {
      if (n <= Bvh::MAX_LEAF_SIZE) return Split{};
      return medianSplit(begin, end, bounds.centroids.widen().longestAxis());
    }
    return sahSplit(begin, end, bounds, binnings, bins);
  }

  /// The binned SAH with `used` bins over the axes along which the centroids spread.
  Split sahSplit(std::uint32_t begin, std::uint32_t end, const Bounds& bounds,
                 const std::array<Binning, 3>& binnings, int used) {
    // BEGIN SOLUTION: hint: sahSplit, bin the centroids, sweep for the cheapest border
    std::array<std::array<Bin, Bvh::BINS>, 3> bins;
    for (auto& axis : bins)
      for (int b = 0; b < used; ++b) axis[b] = Bin{LaneBox::empty(), 0, 0};
#if defined(__SSE2__)
    // A record's three bins at once, each lane computing Binning::bin's operations in float (the
    // fourth lane: 0·c, bin 0, not read).
    const __m128 binLo = _mm_setr_ps(binnings[0].lo, binnings[1].lo, binnings[2].lo, 0);
    const __m128 binScale = _mm_setr_ps(binnings[0].scale, binnings[1].scale, binnings[2].scale, 0);
    const __m128 binLast = _mm_setr_ps(binnings[0].last, binnings[1].last, binnings[2].last, 0);
#endif
    for (std::uint32_t i = begin; i < end; ++i) {
      const BuildRecord& r = records_[i];
      const LaneBox box = LaneBox::of(r);
#if defined(__SSE2__)
      alignas(16) std::array<std::int32_t, 4> index;
      // (c − lo)·scale, its minimum with the last bin (minps keeps the first operand when it is
      // the smaller, as std::min does unless both are equal), truncated as static_cast<int> does.
      _mm_store_si128(reinterpret_cast<__m128i*>(index.data()),
                      _mm_cvttps_epi32(_mm_min_ps(
                          _mm_mul_ps(_mm_sub_ps(box.centre(), binLo), binScale), binLast)));
#else
      const std::array<int, 3> index{binnings[0].bin(centroid(r, 0)),
                                     binnings[1].bin(centroid(r, 1)),
                                     binnings[2].bin(centroid(r, 2))};
#endif
      for (int a = 0; a < 3; ++a) {  // (an axis of scale 0 puts all in bin 0, unused)
        Bin& bin = bins[a][index[a]];
        ++bin.count;
        bin.spheres += r.sphere;
        bin.box.expand(box);
      }
    }
    // The cheapest border. Costs are unnormalised (times SA(box)), so that a flat or huge box
    // never divides 0 or ∞. The border after an empty bin splits as the one before it: skipped.
    double bestCost = INFINITE_DISTANCE;
    int bestAxis = -1, bestBorder = 0;  // border b: bins 0..b on the left
    for (int a = 0; a < 3; ++a) {
      if (binnings[a].scale == 0) continue;
      std::array<double, Bvh::BINS> rightCost{};  // rightCost[b]: SA·cost of bins b..last
      LaneBox right = LaneBox::empty();
      double rightTests = 0;
      for (int b = used - 1; b > 0; --b) {
        rightTests += bins[a][b].cost();
        right.expand(bins[a][b].box);
        if (bins[a][b - 1].count > 0) rightCost[b] = rightTests * right.box().widen().surfaceArea();
      }
      LaneBox left = LaneBox::empty();
      double leftTests = 0;
      for (int b = 0; b < used - 1; ++b) {
        leftTests += bins[a][b].cost();
        left.expand(bins[a][b].box);
        if (bins[a][b].count == 0) continue;  // border b splits as border b - 1 does
        // Both sides are non-empty: bin 0 holds the lowest centroid, the last bin the highest.
        const double cost = leftTests * left.box().widen().surfaceArea() + rightCost[b + 1];
        if (bestAxis < 0 || cost < bestCost) {
          bestCost = cost;
          bestAxis = a;
          bestBorder = b;
        }
      }
    }
    const std::uint32_t n = end - begin;
    double leafCost = 0;  // every record is in one bin of each axis
    for (int b = 0; b < used; ++b) leafCost += bins[0][b].cost();
    const double area = bounds.box.widen().surfaceArea();
    const bool splitPays = Bvh::TRAVERSAL_COST * area + bestCost < leafCost * area;
    if (!splitPays && n <= Bvh::MAX_LEAF_SIZE) return Split{};
    // The children's boxes are the unions of their bins' boxes; their centroids' boxes are
    // gathered while the records are partitioned.
    Split split{false, bestAxis, 0, {}, {}};
    std::array<LaneBox, 2> sides{LaneBox::empty(), LaneBox::empty()};  // left, right
    for (int b = 0; b < used; ++b) sides[b <= bestBorder ? 0 : 1].expand(bins[bestAxis][b].box);
    split.left.box = sides[0].box();
    split.right.box = sides[1].box();
    const Binning& binning = binnings[bestAxis];
    split.mid = partition(begin, end, split, bestAxis,
                          [&](float c) { return binning.bin(c) <= bestBorder; });
    // Both sides hold a record (see above); the median is only a guard against the impossible.
    if (split.mid == begin || split.mid == end) return medianSplit(begin, end, bestAxis);
    return split;
    // END SOLUTION
  }

  /// Moves the records of [begin, end) whose centroid c on axis has isLeft(c) to the front,
  /// adding their centroids to split.left's box and the others' to split.right's; returns where
  /// the right side begins. Lomuto's scheme, written without a branch on isLeft (on a random
  /// scene it is a coin toss, which a branch predictor cannot learn): every record is swapped
  /// with the first right one, and the border moves on when the record was a left one.
  template <typename IsLeft>
  std::uint32_t partition(std::uint32_t begin, std::uint32_t end, Split& split, int axis,
                          const IsLeft& isLeft) {
    std::uint32_t border = begin;
#if defined(__SSE2__)
    // The two sides' centroid boxes in registers: each record's centroid joins both, replaced
    // by the empty box's bound on the side it does not go to (a mask, not a branch).
    constexpr float inf = std::numeric_limits<float>::infinity();
    const __m128 plus = _mm_set1_ps(inf), minus = _mm_set1_ps(-inf);
    const auto pick = [](__m128 mask, __m128 yes, __m128 no) {
      return _mm_or_ps(_mm_and_ps(mask, yes), _mm_andnot_ps(mask, no));
    };
    std::array<LaneBox, 2> sides{LaneBox::empty(), LaneBox::empty()};  // left, right
    for (std::uint32_t i = begin; i < end; ++i) {
      const BuildRecord& r = records_[i];
      const __m128 c = LaneBox::of(r).centre();
      const bool left = isLeft(centroid(r, axis));  // lane `axis` of c, computed alike
      const __m128 toLeft = _mm_castsi128_ps(_mm_set1_epi32(left ? -1 : 0));
      sides[0].expand({pick(toLeft, c, plus), pick(toLeft, c, minus)});
      sides[1].expand({pick(toLeft, plus, c), pick(toLeft, minus, c)});
      std::swap(records_[i], records_[border]);
      border += left ? 1 : 0;
    }
    split.left.centroids.expand(sides[0].box());
    split.right.centroids.expand(sides[1].box());
#else
    for (std::uint32_t i = begin; i < end; ++i) {
      const BuildRecord& r = records_[i];
      const std::array<float, 3> c{centroid(r, 0), centroid(r, 1), centroid(r, 2)};
      const bool left = isLeft(c[axis]);
      (left ? split.left : split.right).centroids.expand(FloatBox{c, c});
      std::swap(records_[i], records_[border]);
      border += left ? 1 : 0;
    }
#endif
    return border;
  }

  /// Half the records on each side of the median centroid along axis: the depth then grows by
  /// one per halving, at most 32 levels for 2^32 records.
  Split medianSplit(std::uint32_t begin, std::uint32_t end, int axis) {
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(records_.begin() + begin, records_.begin() + mid, records_.begin() + end,
                     [axis](const BuildRecord& a, const BuildRecord& b) {
                       return centroid(a, axis) < centroid(b, axis);
                     });
    return splitAt(begin, end, mid, axis);
  }

  Split splitAt(std::uint32_t begin, std::uint32_t end, std::uint32_t mid, int axis) const {
    return Split{false, axis, mid, boundsOf(begin, mid), boundsOf(mid, end)};
  }

  double testCosts(std::uint32_t begin, std::uint32_t end) const {
    double sum = 0;
    for (std::uint32_t i = begin; i < end; ++i) sum += testCost(records_[i]);
    return sum;
  }

  Bounds boundsOf(std::uint32_t begin, std::uint32_t end) const {
    Bounds bounds;
    for (std::uint32_t i = begin; i < end; ++i) bounds.add(records_[i]);
    return bounds;
  }

  /// Makes node `index` a leaf of records [begin, end). A leaf holds one kind of primitive, so
  /// that a sphere leaf runs the sphere solver on compact data without asking each primitive
  /// its kind; a range with both kinds becomes an interior node over a leaf of each.
  void makeLeaf(std::uint32_t index, const FloatBox& box, std::uint32_t begin, std::uint32_t end,
                int depth) {
    const auto isSphere = [](const BuildRecord& r) { return r.sphere != 0; };
    const auto spheresEnd = static_cast<std::uint32_t>(
        std::partition(records_.begin() + begin, records_.begin() + end, isSphere) -
        records_.begin());
    if (spheresEnd == begin || spheresEnd == end) {
      nodes_[index] = leaf(box, begin, end, spheresEnd == end);
      maxDepth_ = std::max(maxDepth_, depth);
      return;
    }
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(leaf(boundsOf(begin, spheresEnd).box, begin, spheresEnd, true));
    nodes_.push_back(leaf(boundsOf(spheresEnd, end).box, spheresEnd, end, false));
    nodes_[index] = interior(box, first + 1, box.widen().longestAxis());
    maxDepth_ = std::max(maxDepth_, depth + 1);
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
  std::vector<BuildRecord>& records_;
  std::vector<BvhNode>& nodes_;
  std::vector<std::uint32_t>& sphereShapes_;
  std::vector<std::uint32_t>& otherShapes_;
  int maxDepth_ = 0;
};

/// What one chunk of the primitives makes of its records (Bvh's constructor).
struct RecordChunk {
  std::size_t written = 0;               ///< records, from the chunk's first index on
  std::vector<std::uint32_t> unbounded;  ///< its primitives without a (float) box
  std::size_t spheres = 0;
  Bounds bounds;  ///< of its records
};

/// The record of every bounded primitive of [begin, end), written from records[begin] on.
void makeRecords(Primitives primitives, std::uint32_t begin, std::uint32_t end,
                 BuildRecord* records, RecordChunk& chunk) {
  const std::span<const Geometry> shapes = primitives.shapes();
  BuildRecord* out = records + begin;
  for (std::uint32_t i = begin; i < end; ++i) {
    // A shape without a box, or whose box does not fit in floats (coordinates beyond ±3.4e38),
    // is tested on its own, like a plane.
    const std::optional<Aabb> box = boundingBox(primitives, i);
    const FloatBox stored = box ? conservativeBox(*box) : FloatBox::empty();
    if (!box || !isFinite(stored)) {
      chunk.unbounded.push_back(i);
      continue;
    }
    const bool sphere = primitives.isShape(i) && std::holds_alternative<Sphere>(shapes[i]);
    *out = BuildRecord(stored, i, sphere);
    chunk.bounds.add(*out);
    ++out;
    chunk.spheres += sphere ? 1 : 0;
  }
  chunk.written = static_cast<std::size_t>(out - (records + begin));
}

}  // namespace

int Bvh::buildThreads(int threads) noexcept {
  return threads > 0 ? threads
                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

Bvh::Bvh(Primitives primitives, BvhBuildOptions options, SpheresLater) : primitives_(primitives) {
  const int threads = buildThreads(options.threads);
  // The records of consecutive chunks of the primitives are made at once, one chunk per
  // thread, each written where its first primitive is; the chunks are then moved together, so
  // that the records (and the unbounded shapes) come in the primitives' order whatever the
  // number of threads (build::chunkCount: a chunk per 16,384 primitives at least).
  const std::size_t count = primitives.size();
  const int chunks = build::chunkCount(count, threads);
  std::vector<BuildRecord> records;
  reserveHugeWritten(records, count);  // 32 MiB for 10^6 stars (HugePages.h)
  records.resize(count);
  std::vector<RecordChunk> made(static_cast<std::size_t>(chunks));
  build::concurrently(chunks, [&](int k) {
    makeRecords(primitives, static_cast<std::uint32_t>(build::chunkBegin(count, chunks, k)),
                static_cast<std::uint32_t>(build::chunkBegin(count, chunks, k + 1)), records.data(),
                made[static_cast<std::size_t>(k)]);
  });
  std::size_t unboundedCount = 0;  // reserved at once: its capacity too is the one-thread build's
  for (const RecordChunk& chunk : made) unboundedCount += chunk.unbounded.size();
  unbounded_.reserve(unboundedCount);
  std::size_t written = 0, sphereCount = 0;
  Bounds all;
  for (int k = 0; k < chunks; ++k) {
    const RecordChunk& chunk = made[static_cast<std::size_t>(k)];
    const auto from =
        records.begin() + static_cast<std::ptrdiff_t>(build::chunkBegin(count, chunks, k));
    const auto to = records.begin() + static_cast<std::ptrdiff_t>(written);
    if (to != from)
      std::copy(from, from + static_cast<std::ptrdiff_t>(chunk.written), to);  // leftwards
    written += chunk.written;
    sphereCount += chunk.spheres;
    all.add(chunk.bounds);
    unbounded_.insert(unbounded_.end(), chunk.unbounded.begin(), chunk.unbounded.end());
  }
  records.resize(written);
  if (records.empty()) return;

  // The node array is reserved by the build: at its size when several threads build, for the
  // most nodes the tree could have on one; the binary BVH's constructor then returns the rest
  // (shrink_to_fit, a copy, or nothing to do), the wide BVH frees the whole array once it has
  // collapsed it.
  reserveHugeWritten(sphereShapes_, sphereCount);
  otherShapes_.reserve(records.size() - sphereCount);
  depth_ = Builder(records, nodes_, sphereShapes_, otherShapes_, options.sahMaxDepth)
               .build(threads, all);

  // The records are done with before the compact spheres are made: the two never coexist.
  std::vector<BuildRecord>().swap(records);
  makeFlatShapes();
}

void Bvh::makeFlatShapes() {
  const std::span<const Geometry> shapes = primitives_.shapes();
  std::vector<std::uint32_t> flat;
  for (const std::uint32_t i : otherShapes_)
    if (primitives_.isShape(i) && FlatShapes::isFlat(shapes[i])) flat.push_back(i);
  if (flat.empty()) return;  // no table: a mesh of a million triangles costs nothing here
  otherFlat_.assign(otherShapes_.size(), NOT_FLAT);
  std::uint32_t next = 0;
  for (std::size_t k = 0; k < otherShapes_.size(); ++k) {
    const std::uint32_t i = otherShapes_[k];
    if (primitives_.isShape(i) && FlatShapes::isFlat(shapes[i])) otherFlat_[k] = next++;
  }
  flats_ = FlatShapes(primitives_, flat);
}

void Bvh::makeCompactSpheres(int threads) {
  // A gather from the scattered shapes: consecutive chunks of the spheres at once, one chunk
  // per thread (build::chunkCount).
  const std::span<const Geometry> shapes = primitives_.shapes();
  const std::size_t count = sphereShapes_.size();
  reserveHugeWritten(spheres_, count);
  spheres_.assign(count, CompactSphere{});
  const int chunks = build::chunkCount(count, threads);
  build::concurrently(chunks, [&](int k) {
    const std::size_t end = build::chunkBegin(count, chunks, k + 1);
    for (std::size_t i = build::chunkBegin(count, chunks, k); i < end; ++i) {
      const Sphere& s = std::get<Sphere>(shapes[sphereShapes_[i]]);
      spheres_[i] = CompactSphere{s.center().xyz(), s.radius()};
    }
  });
}

}  // namespace rt
