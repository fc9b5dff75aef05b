// The tables of `rt bench` in Markdown, CSV and JSON.
#include "BenchTable.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/Progress.h"
#include "common/JsonText.h"
#include "primitives/Double3.h"

namespace rt::cli {

namespace {

using Json = nlohmann::ordered_json;

/// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string mebibytes(std::int64_t bytes) {
  return fixed(static_cast<double>(bytes) / (1024.0 * 1024.0), 1) + " MiB";
}

/// A Markdown table: the header, the alignment line (text left, numbers right), the rows.
class MarkdownTable {
 public:
  /// @param columns each column's title; numeric ones are right-aligned
  MarkdownTable(std::vector<std::string> titles, std::vector<bool> numeric)
      : titles_(std::move(titles)), numeric_(std::move(numeric)) {}
  void add(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  std::string text() const {
    std::string out = line(titles_) + "|";
    for (const bool n : numeric_) out += n ? " ---: |" : " --- |";
    out += "\n";
    for (const auto& row : rows_) out += line(row);
    return out;
  }

 private:
  static std::string line(const std::vector<std::string>& cells) {
    std::string out = "|";
    for (const std::string& c : cells) out += " " + c + " |";
    return out + "\n";
  }
  std::vector<std::string> titles_;
  std::vector<bool> numeric_;
  std::vector<std::vector<std::string>> rows_;
};

/// A Markdown cell of a figure that was not measured.
constexpr std::string_view NOT_MEASURED = "—";

/// Why the row "Embree 3" differs from the others, for the caption.
constexpr std::string_view EMBREE_CAPTION =
    " (Embree tests its boxes and its spheres, triangles and quads in float: a ray that grazes "
    "a shape's edge can miss it there, where the exact test hits it; every hit Embree offers is "
    "checked and ordered by the project's exact test, so only such rays change a pixel; the "
    "project's structures differ in none)";

std::string rendersOf(int repeat) {
  return repeat == 1
             ? "one render per row"
             : "the median of " + std::to_string(repeat) + " renders per row, rows taken in turn";
}

}  // namespace

double BenchRow::raysPerSecond() const {
  return seconds > 0 ? static_cast<double>(counts.total()) / seconds : 0;
}

double BenchRow::nodesPerRay() const {
  const std::uint64_t rays = counts.total();
  return rays > 0 ? static_cast<double>(counts.queries.nodesVisited) / static_cast<double>(rays)
                  : 0;
}

double BenchTable::speedup(const BenchRow& row) const {
  if (rows.empty() || row.seconds <= 0) return 0;
  return &row == &rows.front() ? 1.0 : rows.front().seconds / row.seconds;
}

std::string formatBenchTable(const BenchTable& table, TableFormat format) {
  switch (format) {
    case TableFormat::Json: {
      Json rows = Json::array();
      for (const BenchRow& r : table.rows) {
        const auto measured = [&r](Json value) { return r.rendered ? value : Json(); };
        rows.push_back(Json{
            {"name", r.name},
            {"tracer", r.tracer},
            {"accel", r.accel},
            {"threads", r.threads},
            {"seconds", measured(jsonNumber(r.seconds))},
            {"primary", measured(r.counts.primary)},
            {"secondary", measured(r.counts.secondary)},
            {"shadow", measured(r.counts.shadow)},
            {"raysPerSecond", measured(jsonNumber(std::round(r.raysPerSecond())))},
            {"nodesPerRay", r.countsNodes ? measured(jsonNumber(r.nodesPerRay())) : Json()},
            {"speedup", measured(jsonNumber(table.speedup(r)))},
            {"referenceSeconds", r.referenceSeconds ? jsonNumber(*r.referenceSeconds) : Json()},
            {"pixelsDiffering", r.pixelsDiffering ? Json(*r.pixelsDiffering) : Json()},
            {"note", r.note}});
      }
      return formatJson(
          Json{{"scene", table.scene},
               {"width", table.width},
               {"height", table.height},
               {"threads", table.threads},
               {"machine", table.machine},
               {"reference", table.reference.empty() ? Json() : Json(table.reference)},
               {"rows", rows}});
    }
    case TableFormat::Csv: {
      std::string out = std::string(BENCH_CSV_HEADER) + "\n";
      for (const BenchRow& r : table.rows) {
        const auto measured = [&r](std::string text) { return r.rendered ? text : std::string(); };
        out += csvField(r.name) + "," + csvField(r.tracer) + "," + csvField(r.accel) + "," +
               std::to_string(r.threads) + "," + measured(formatNumber(r.seconds)) + "," +
               measured(std::to_string(r.counts.primary)) + "," +
               measured(std::to_string(r.counts.secondary)) + "," +
               measured(std::to_string(r.counts.shadow)) + "," +
               measured(formatNumber(std::round(r.raysPerSecond()))) + "," +
               (r.countsNodes ? measured(formatNumber(r.nodesPerRay())) : std::string()) + "," +
               measured(formatNumber(table.speedup(r))) + "," +
               (r.referenceSeconds ? formatNumber(*r.referenceSeconds) : std::string()) + "," +
               (r.pixelsDiffering ? std::to_string(*r.pixelsDiffering) : std::string()) + "," +
               csvField(r.note) + "\n";
      }
      return out;
    }
    case TableFormat::Markdown:
      break;
  }
  bool reference = false;
  for (const BenchRow& r : table.rows) reference = reference || r.referenceSeconds.has_value();
  reference = reference && !table.reference.empty();
  MarkdownTable md(
      {"row", "tracer", "accel", "threads", "wall", "reference", "primary", "secondary", "shadow",
       "rays/s", "nodes/ray", "speed-up", "pixels differing", "note"},
      {false, false, false, true, true, true, true, true, true, true, true, true, true, false});
  bool embree = false;
  for (const BenchRow& r : table.rows) {
    embree = embree || (r.accel == "embree" && r.rendered);
    const auto measured = [&r](std::string text) {
      return r.rendered ? text : std::string(NOT_MEASURED);
    };
    md.add(
        {r.name, r.tracer, r.accel, std::to_string(r.threads), measured(formatDuration(r.seconds)),
         r.referenceSeconds ? formatDuration(*r.referenceSeconds) : std::string(),
         measured(std::to_string(r.counts.primary)), measured(std::to_string(r.counts.secondary)),
         measured(std::to_string(r.counts.shadow)), measured(fixed(r.raysPerSecond(), 0)),
         r.countsNodes ? measured(fixed(r.nodesPerRay(), 2)) : std::string(NOT_MEASURED),
         measured(fixed(table.speedup(r), 2)),
         r.pixelsDiffering ? std::to_string(*r.pixelsDiffering) : std::string(NOT_MEASURED),
         r.note});
  }
  return "rt bench " + table.scene + ": " + std::to_string(table.width) + "x" +
         std::to_string(table.height) + ", " + std::to_string(table.threads) +
         " threads for the multi-threaded rows, " + table.machine + "; " + rendersOf(table.repeat) +
         (reference ? "; reference: " + table.reference : "") +
         "; pixels differing: from the first row's image, for the rows of its tracer" +
         (embree ? std::string(EMBREE_CAPTION) : std::string()) + "\n\n" + md.text();
}

std::vector<std::string> scalingKeys(const ScalingKind& kind) {
  std::string per(kind.per);
  per[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(per[0])));
  return {std::string(kind.size),
          std::string(kind.count),
          "buildSeconds",
          "renderSeconds",
          "peakBytes",
          "bytesPer" + per,
          "nodesPerRay",
          "gridBuildSeconds",
          "gridRenderSeconds",
          "gridPeakBytes",
          "gridBytesPer" + per,
          "gridCellsPerRay"};
}

std::string formatScalingTable(const ScalingTable& table, TableFormat format) {
  const ScalingKind& kind = table.kind;
  const std::vector<std::string> keys = scalingKeys(kind);
  switch (format) {
    case TableFormat::Json: {
      Json rows = Json::array();
      for (const ScalingRow& r : table.rows) {
        Json row{{keys[0], r.size}, {keys[1], r.count}};
        std::size_t k = 2;
        for (const ScalingFigures* f : {&r.bvh, &r.grid}) {
          row[keys[k++]] = jsonNumber(f->buildSeconds);
          row[keys[k++]] = jsonNumber(f->renderSeconds);
          row[keys[k++]] = f->peakBytes;
          row[keys[k++]] = f->bytesPer;
          row[keys[k++]] = jsonNumber(f->nodesPerRay);
        }
        rows.push_back(std::move(row));
      }
      return formatJson(Json{{"scene", kind.scene},
                             {"width", table.width},
                             {"height", table.height},
                             {"scaling", rows}});
    }
    case TableFormat::Csv: {
      std::string out;
      for (const std::string& key : keys) out += (out.empty() ? "" : ",") + key;
      out += "\n";
      for (const ScalingRow& r : table.rows) {
        out += std::to_string(r.size) + "," + std::to_string(r.count);
        for (const ScalingFigures* f : {&r.bvh, &r.grid})
          out += "," + formatNumber(f->buildSeconds) + "," + formatNumber(f->renderSeconds) + "," +
                 std::to_string(f->peakBytes) + "," + std::to_string(f->bytesPer) + "," +
                 formatNumber(f->nodesPerRay);
        out += "\n";
      }
      return out;
    }
    case TableFormat::Markdown:
      break;
  }
  const std::string per(kind.per);
  MarkdownTable md({std::string(kind.size), std::string(kind.count), "BVH build", "BVH render",
                    "BVH peak", "BVH bytes/" + per, "nodes/ray", "grid build", "grid render",
                    "grid peak", "grid bytes/" + per, "cells/ray"},
                   std::vector<bool>(12, true));
  for (const ScalingRow& r : table.rows) {
    std::vector<std::string> cells{std::to_string(r.size), std::to_string(r.count)};
    for (const ScalingFigures* f : {&r.bvh, &r.grid})
      cells.insert(cells.end(), {formatDuration(f->buildSeconds), formatDuration(f->renderSeconds),
                                 mebibytes(f->peakBytes), std::to_string(f->bytesPer),
                                 fixed(f->nodesPerRay, 2)});
    md.add(cells);
  }
  const std::string what =
      kind.scene == TEAPOT_SCALING.scene
          ? "rt bench --scaling teapot: the course's teapot of 64*d^2 - 8*d flat triangles "
            "(detail d), " +
                std::to_string(table.width) + "x" + std::to_string(table.height) +
                " (the course's view), Whitted tracer"
          : "rt bench --scaling: the galaxy without diffusion, " + std::to_string(table.width) +
                "x" + std::to_string(table.height) +
                " (the middle of the reference report's view), beams tracer";
  return what + ", through the BVH and through the grid, " + std::to_string(table.threads) +
         " threads, " + table.machine + "; " + rendersOf(table.repeat) + "; each " +
         std::string(kind.scene) +
         " and structure in a process of its own: build and render in wall time, peak = "
         "its ru_maxrss, bytes per " +
         per + " = (peak - " + mebibytes(table.baselineBytes) + " of an empty process) / " +
         (kind.scene == GALAXY_SCALING.scene ? "stars" : std::string(kind.count)) + "\n\n" +
         md.text();
}

}  // namespace rt::cli
