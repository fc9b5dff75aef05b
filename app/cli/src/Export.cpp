// rt export NAME [-o FILE.json]
#include <optional>
#include <ostream>
#include <vector>

#include "CommandRegistration.h"
#include "camera/AtomicFile.h"
#include "cli/BuiltinScenes.h"
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
  const BuiltinScene& scene = requireBuiltinScene(args.name, "rt list shows the built-in scenes");
  const std::optional<std::string>& output = args.output;
  if (output) checkOutputWritable(*output, SCENE_FILE);
  const std::string text = dumpScene(makeBuiltinScene(scene, args.params));
  if (output)
    writeFileAtomically(*output, text);
  else
    io.out << text << std::flush;
  return EXIT_OK;
}

}  // namespace

void addExportCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "export", "write a built-in scene as a JSON scene file",
      "Rendering the exported file gives the same image, byte for byte, as rendering the\n"
      "built-in scene (with the same --param values, for a scene that has parameters). The "
      "repository keeps every built-in scene's export in scenes/\n"
      "(cmake --build BUILD --target export-scenes refreshes them).\n",
      exportScene);
  command->add_option("NAME", args->name, "a built-in scene's name");
  addParamOption(*command, args->params);
  addOptional(*command, "-o,--output", args->output, "where to write it (default: standard output)",
              "FILE.json");
}

}  // namespace rt::cli
