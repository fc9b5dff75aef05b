/// @file ModelFileWithoutAssimp.cpp
/// readModelFile in a build without Assimp: the declarations stay, and every call says how to
/// get the library.
#include <utility>

#include "scenefile/ModelFile.h"

namespace rt {

namespace {
constexpr const char* kNeedsAssimp =
    "reading model files needs Assimp: install libassimp-dev (scripts/deps.sh installs it)";
}  // namespace

ModelError::ModelError(std::string file, const std::string& what)
    : std::runtime_error(file + ": " + what), modelFile(std::move(file)), detail(what) {}

bool modelFilesSupported() { return false; }

ModelFile readModelFile(const std::filesystem::path& file, const ModelOptions&,
                        const ModelFileSource&) {
  throw ModelError(file.string(), kNeedsAssimp);
}

ModelFile readModelFromMemory(std::span<const std::byte>, std::string_view,
                              const std::string& sourceName, const ModelOptions&) {
  throw ModelError(sourceName, kNeedsAssimp);
}

}  // namespace rt
