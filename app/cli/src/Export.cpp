// rt export NAME [-o FILE.json]
#include <ostream>

#include "CommandTable.h"
#include "camera/AtomicFile.h"
#include "cli/BuiltinScenes.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {

namespace {

int exportScene(const ParsedArgs& args, const Io& io) {
  const std::string& name = args.positional[0];
  const BuiltinScene& scene = requireBuiltinScene(name, "rt list shows the built-in scenes");
  const std::string* output = args.value("--output");
  if (output && !output->ends_with(".json"))
    throw UsageError("-o: a scene file's name must end in .json; got '" + *output + "'");
  if (output) checkOutputWritable(*output, "-o");
  const std::string text = dumpScene(scene.make());
  if (output)
    writeFileAtomically(*output, text);
  else
    io.out << text << std::flush;
  return EXIT_OK;
}

}  // namespace

Command exportCommand() {
  return {{"export",
           "write a built-in scene as a JSON scene file",
           {"NAME"},
           {{"--output", "-o", 1, "FILE.json", "where to write it (default: standard output)"}},
           "Rendering the exported file gives the same image, byte for byte, as rendering the\n"
           "built-in scene. The repository keeps every built-in scene's export in scenes/\n"
           "(cmake --build BUILD --target export-scenes refreshes them).\n"},
          exportScene};
}

}  // namespace rt::cli
