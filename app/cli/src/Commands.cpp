#include "cli/Commands.h"

#include <filesystem>
#include <ostream>
#include <sstream>
#include <vector>

#include "CommandTable.h"
#include "camera/Image.h"
#include "cli/ArgParser.h"
#include "cli/BuiltinScenes.h"
#include "cli/Tracers.h"
#include "cli/Values.h"
#include "common/NearestName.h"
#include "scenefile/SceneFile.h"

#ifndef RT_VERSION
#error "RT_VERSION must be defined (the CMake project's version)"
#endif

namespace rt::cli {

namespace {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {listCommand(), renderCommand(), probeCommand(),
                                             exportCommand()};
  return table;
}

std::string mainHelp() {
  std::ostringstream os;
  os << versionString() << ": the staged ray tracer's command-line program\n\n"
     << "Usage: rt COMMAND [ARGUMENTS] [OPTIONS]\n\nCommands:\n";
  std::size_t width = 0;
  for (const Command& c : commands()) width = std::max(width, c.spec.name.size());
  for (const Command& c : commands())
    os << "  " << c.spec.name << std::string(width - c.spec.name.size() + 2, ' ') << c.spec.summary
       << "\n";
  os << "\nOptions:\n"
     << "  -h, --help  show this help; rt COMMAND --help shows a command's\n"
     << "  --version   print the version\n\n"
     << "Examples:\n"
     << "  rt list\n"
     << "  rt render two-color -o two-color.png --width 400 --height 400\n"
     << "  rt render my-scene.json --tracer shadow\n"
     << "  rt probe two-color --pixel 500,500\n"
     << "  rt export two-color -o two-color.json\n\n"
     << "Exit codes: 0 ok, 1 runtime failure, 2 bad usage or input, 130 interrupted (Ctrl-C).\n";
  return os.str();
}

int list(const ParsedArgs&, const Io& io) {
  std::size_t width = 0;
  for (const BuiltinScene& s : builtinScenes()) width = std::max(width, s.name.size());
  for (const BuiltinScene& s : builtinScenes())
    io.out << s.name << std::string(width - s.name.size() + 2, ' ') << s.description << "\n";
  return EXIT_OK;
}

bool endsWith(std::string_view s, std::string_view suffix) { return s.ends_with(suffix); }

}  // namespace

Command listCommand() {
  return {{"list",
           "list the built-in scenes, one per line: name, then a short description",
           {},
           {},
           "Every scene of the course's stages is built in; `rt render NAME` renders one with its\n"
           "stage's tracer, and `rt export NAME` writes it as a scene file.\n"},
          list};
}

std::string versionString() { return std::string("rt ") + RT_VERSION; }

int runRt(std::span<const std::string> args, const Io& io) {
  try {
    if (args.empty()) {
      io.err << "rt: missing COMMAND (see rt --help)\n";
      return EXIT_BAD_INPUT;
    }
    const std::string& first = args.front();
    if (first == "--help" || first == "-h" || first == "help") {
      io.out << mainHelp();
      return EXIT_OK;
    }
    if (first == "--version") {
      io.out << versionString() << "\n";
      return EXIT_OK;
    }
    for (const Command& c : commands()) {
      if (c.spec.name != first) continue;
      const ParsedArgs parsed = parseArgs(c.spec, args.subspan(1));
      if (parsed.help) {
        io.out << formatHelp(c.spec);
        return EXIT_OK;
      }
      return c.run(parsed, io);
    }
    std::vector<std::string_view> names;
    for (const Command& c : commands()) names.push_back(c.spec.name);
    io.err << "rt: unknown command '" << first << "'" << didYouMean(first, names)
           << " (see rt --help)\n";
    return EXIT_BAD_INPUT;
  } catch (const UsageError& e) {
    io.err << "rt: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch (const SceneError& e) {
    io.err << "rt: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch (const std::invalid_argument& e) {
    // A scene or camera the engine refuses (the constructors name the argument and the value).
    io.err << "rt: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch (const std::bad_alloc&) {
    io.err << "rt: out of memory\n";
    return EXIT_FAILURE_RUNTIME;
  } catch (const std::exception& e) {
    io.err << "rt: " << e.what() << "\n";
    return EXIT_FAILURE_RUNTIME;
  }
}

const BuiltinScene& requireBuiltinScene(std::string_view name, std::string_view hint) {
  if (const BuiltinScene* builtin = findBuiltinScene(name)) return *builtin;
  std::vector<std::string_view> names;
  for (const BuiltinScene& s : builtinScenes()) names.push_back(s.name);
  throw UsageError("unknown scene '" + std::string(name) + "'" + didYouMean(name, names) + " (" +
                   std::string(hint) + ")");
}

SceneDocument loadSceneArgument(std::string_view scene) {
  if (endsWith(scene, ".json") && !findBuiltinScene(scene)) return loadScene(std::string(scene));
  return requireBuiltinScene(scene, "rt list shows the built-in scenes; a scene file ends in .json")
      .make();
}

std::string defaultOutputPath(std::string_view scene) {
  if (findBuiltinScene(scene)) return std::string(scene) + ".png";
  return std::filesystem::path(scene).stem().string() + ".png";
}

void applySceneOverrides(const ParsedArgs& args, SceneDocument& doc) {
  constexpr int kMax = Image::MAX_SIDE;
  if (const std::string* w = args.value("--width"))
    doc.camera.nX = parseInt(*w, "--width", 1, kMax);
  if (const std::string* h = args.value("--height"))
    doc.camera.nY = parseInt(*h, "--height", 1, kMax);
  if (doc.camera.nX < 1 || doc.camera.nX > kMax || doc.camera.nY < 1 || doc.camera.nY > kMax)
    throw UsageError("the scene's resolution " + std::to_string(doc.camera.nX) + "x" +
                     std::to_string(doc.camera.nY) + " is outside 1.." + std::to_string(kMax) +
                     " per side");
  if (const std::string* t = args.value("--tracer")) doc.render.tracer = *t;
  findTracer(doc.render.tracer, args.has("--tracer") ? "--tracer" : "render.tracer");
}

}  // namespace rt::cli
