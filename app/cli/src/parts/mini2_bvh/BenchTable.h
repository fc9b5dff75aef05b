#pragma once
// Internal to mini2's part of rt: the tables `rt bench` prints, as data, and their three formats
// (Markdown, CSV, JSON). docs/bench.json is read by the gallery generator with exactly the JSON
// keys written here.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera/SampleContext.h"

namespace rt::cli {

enum class TableFormat { Markdown, Csv, Json };

/// One render of the timing table: a row name, how it was rendered, and what it cost.
struct BenchRow {
  std::string name;    ///< "no acceleration, 1 thread", ..., or the tracer's stage
  std::string tracer;  ///< a tracer's name (--tracer)
  /// none, cbr, bvh, bvh4, grid, or embree (the row "Embree 3"); "+lights" after the name: with
  /// a light buffer per point light for the shadow rays (render.lightBuffers)
  std::string accel;
  int threads = 1;     ///< threads that rendered (never more than the image's tiles)
  double seconds = 0;  ///< wall time of the render: the median of the repeats
  RayCounts counts{};  ///< the render's rays and intersection queries (the same every repeat)
  std::optional<double> referenceSeconds{};  ///< the reference report's time for this row, if any
  /// False for a row that was not rendered (Embree 3 in a build without Embree): its figures are
  /// null in JSON, empty in CSV, "—" in Markdown; its note says why.
  bool rendered = true;
  /// False when the structure does not report its nodes (Embree): nodesPerRay is then null.
  bool countsNodes = true;
  /// Pixels whose 8-bit colour differs from the first row's image ("no acceleration"): for the
  /// rows of the first row's tracer (0 for the project's structures, which are bit-identical);
  /// none for the rows of other tracers, which render another image.
  std::optional<std::uint64_t> pixelsDiffering{};
  std::string note{};  ///< what the figures alone do not say ("" for most rows)

  double raysPerSecond() const;  ///< every ray (primary, secondary, shadow) per wall second
  double nodesPerRay() const;    ///< BVH nodes visited per ray, of every kind
};

struct BenchTable {
  std::string scene;  ///< SCENE as given
  int width = 0, height = 0;
  int threads = 1;      ///< the threads the multi-threaded rows asked for
  std::string machine;  ///< "AMD EPYC 7B13, 2 CPUs"
  int repeat = 1;       ///< renders per row; seconds are their medians
  /// Whose the rows' referenceSeconds are, and what they timed ("" when no row has one).
  std::string reference{};
  std::vector<BenchRow> rows{};

  /// The first row's wall time over row's (1 for the first row itself; 0 for a row of no time).
  double speedup(const BenchRow& row) const;
};

/// What a scaling scales, and the names its table gives it: the galaxy's stars (bytes per star)
/// or the teapot's detail (bytes per triangle).
struct ScalingKind {
  std::string_view scene;  ///< "galaxy", "teapot": the JSON's scene
  std::string_view size;   ///< the parameter scaled: "stars", "detail"
  std::string_view count;  ///< what the scene is counted in: "shapes", "triangles"
  std::string_view per;    ///< what the bytes are counted per: "star", "triangle"
};
inline constexpr ScalingKind GALAXY_SCALING{"galaxy", "stars", "shapes", "star"};
inline constexpr ScalingKind TEAPOT_SCALING{"teapot", "detail", "triangles", "triangle"};

/// One structure's figures for one scene of a scaling, measured in a process of its own.
struct ScalingFigures {
  double buildSeconds = 0;     ///< the structure's build: CPU time (it runs on one thread)
  double renderSeconds = 0;    ///< wall time of the render: the median of the repeats
  std::int64_t peakBytes = 0;  ///< the process's peak resident size (ru_maxrss)
  /// (peakBytes - the empty process's) per star (galaxy) or per triangle (teapot), at least 0
  std::int64_t bytesPer = 0;
  double nodesPerRay = 0;  ///< BVH nodes (grid cells) visited per ray, every ray
};

/// One scene of a scaling, through the BVH and through the grid.
struct ScalingRow {
  long size = 0;            ///< the scaled parameter: the galaxy's stars, the teapot's detail
  std::uint64_t count = 0;  ///< the galaxy's shapes (stars, suns, core, box, frame, ...), or
                            ///< the teapot's triangles
  ScalingFigures bvh;
  ScalingFigures grid;
};

struct ScalingTable {
  ScalingKind kind = GALAXY_SCALING;
  int width = 0, height = 0;
  int threads = 1;  ///< the threads the renders asked for
  std::string machine;
  int repeat = 1;
  std::int64_t baselineBytes = 0;  ///< the peak resident size of a child that does nothing
  std::vector<ScalingRow> rows{};
};

/// The table as text in format, ending with a newline. Markdown: a line that says what was
/// measured, an empty line, then the table; CSV: a header line, then a line per row; JSON: the
/// documented objects, written by formatJson.
std::string formatBenchTable(const BenchTable& table, TableFormat format);
std::string formatScalingTable(const ScalingTable& table, TableFormat format);

/// The CSV header line of the timing table (the tests and the docs quote it).
inline constexpr std::string_view BENCH_CSV_HEADER =
    "name,tracer,accel,threads,seconds,primary,secondary,shadow,raysPerSecond,nodesPerRay,speedup,"
    "referenceSeconds,pixelsDiffering,note";

/// The note of the row "Embree 3" in a build without Embree.
inline constexpr std::string_view EMBREE_NOT_BUILT =
    "not built: install libembree-dev (scripts/deps.sh --embree) and reconfigure";

/// The keys of a scaling's row, in order: its CSV header's fields and its JSON objects' keys
/// (the galaxy's: stars, shapes, buildSeconds, ..., bytesPerStar, ..., gridCellsPerRay).
std::vector<std::string> scalingKeys(const ScalingKind& kind);

}  // namespace rt::cli
