// rt export SCENE [-o FILE.json]
#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include "CommandRegistration.h"
#include "camera/AtomicFile.h"
#include "cli/Commands.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {

namespace {

/// rt export's arguments, as the command line binds them.
struct ExportArgs {
  std::string name;
  std::vector<std::string> params;
  std::optional<std::string> output;
};

int exportScene(const ExportArgs& args, const Io& io) {
  const std::optional<std::string>& output = args.output;
  if (output) checkOutputWritable(*output, SCENE_FILE);
  // A model file's path is written relative to the written file's folder (standard output: the
  // current directory's), so that the export finds the model where the scene file found it.
  const std::filesystem::path folder =
      output ? std::filesystem::path(*output).parent_path() : std::filesystem::path();
  const SceneDocument doc = loadSceneArgument(args.name, args.params);
  // Written over the scene file it reads (or a model file), the export would replace it.
  if (output) checkOutputIsNoInput(*output, "-o", "the exported scene", args.name, doc);
  const std::string text = dumpScene(doc, folder);
  if (output)
    writeFileAtomically(*output, text);
  else
    io.out << text << std::flush;
  return EXIT_OK;
}

}  // namespace

void addExportCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "export", "write a built-in scene (or a scene file, again) as a JSON scene file",
      "Rendering the exported file gives the same image, byte for byte, as rendering the\n"
      "scene (with the same --param values, for a built-in scene that has parameters). A\n"
      "scene file's model files keep their places: their paths are written relative to the\n"
      "exported file's folder. The repository keeps every built-in scene's export in scenes/\n"
      "(cmake --build BUILD --target export-scenes refreshes them).\n",
      exportScene);
  command->add_option("SCENE", args->name, "a built-in scene's name, or a .json scene file");
  addParamOption(*command, args->params);
  addOptional(*command, "-o,--output", args->output, "where to write it (default: standard output)",
              "FILE.json");
}

}  // namespace rt::cli
