#include "scenefile/SceneFile.h"

namespace rt {

SceneError::SceneError(std::string file_, int line_, int column_, std::string path_,
                       std::string detail_)
    : std::runtime_error(format(file_, line_, column_, path_, detail_)),
      file(std::move(file_)),
      line(line_),
      column(column_),
      path(std::move(path_)),
      detail(std::move(detail_)) {}

SceneError::SceneError(const std::string& message) : std::runtime_error(message), detail(message) {}

std::string SceneError::format(const std::string& file, int line, int column,
                               const std::string& path, const std::string& detail) {
  std::string out = file;
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
    out += ':';
    out += std::to_string(column);
  }
  out += ": ";
  if (!path.empty()) {
    out += path;
    out += ": ";
  }
  out += detail;
  return out;
}

}  // namespace rt
