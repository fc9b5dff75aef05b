#include "cli/Commands.h"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <ostream>
#include <vector>

#include "CommandRegistration.h"
#include "camera/Image.h"
#include "cli/BuiltinScenes.h"
#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "cli/Tracers.h"
#include "common/NearestName.h"
#include "scenefile/SceneFile.h"

#ifndef RT_VERSION
#error "RT_VERSION must be defined (the CMake project's version)"
#endif

namespace rt::cli {

namespace {

const char* const kDescription = ": the staged ray tracer's command-line program";

const char* const kFooter =
    "Examples:\n"
    "  rt list\n"
    "  rt render two-color -o two-color.png --width 400 --height 400\n"
    "  rt render my-scene.json --tracer shadow\n"
    "  rt probe two-color --pixel 500,500\n"
    "  rt export two-color -o two-color.json\n"
    "  rt compare mine.png docs/images/two-color.png\n\n"
    "Exit codes: 0 ok, 1 runtime failure, 2 bad usage or input, 130 interrupted (Ctrl-C).\n";

int list(const Io& io) {
  std::size_t width = 0;
  for (const BuiltinScene& s : builtinScenes()) width = std::max(width, s.name.size());
  for (const BuiltinScene& s : builtinScenes()) {
    io.out << s.name << std::string(width - s.name.size() + 2, ' ') << s.description << "\n";
    if (!s.params.empty()) {
      io.out << std::string(width + 2, ' ') << "parameters (--param NAME=VALUE):";
      for (const SceneParam& p : s.params) io.out << " " << p.name << "=" << p.defaultValue;
      io.out << "\n";
    }
  }
  return EXIT_OK;
}

/// rt's command line: the program and its commands.
CommandLine makeCommandLine() {
  CommandLine rt("rt", versionString() + kDescription, kFooter, versionString());
  addListCommand(rt);
  addRenderCommand(rt);
  addAnimateCommand(rt);
  addProbeCommand(rt);
  addExportCommand(rt);
  addCompareCommand(rt);
  for (const auto& add : cliRegistry().commands) add(rt);
  return rt;
}

}  // namespace

void addListCommand(CommandLine& rt) {
  rt.addCommand(
      "list", "list the built-in scenes, one per line: name, then a short description",
      "Every scene of the course's stages present in this build is built in; `rt render NAME`\n"
      "renders one with its stage's tracer, and `rt export NAME` writes it as a scene file. A\n"
      "scene with parameters lists them with their defaults; give others with\n"
      "--param NAME=VALUE (render, probe, export).\n",
      list);
}

std::string versionString() { return std::string("rt ") + RT_VERSION; }

ErrorReport describeError(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const UsageError& e) {
    return {EXIT_BAD_INPUT, e.what()};
  } catch (const SceneError& e) {
    return {EXIT_BAD_INPUT, e.what()};
  } catch (const std::invalid_argument& e) {
    // A scene or camera the engine refuses (the constructors name the argument and the value).
    return {EXIT_BAD_INPUT, e.what()};
  } catch (const std::bad_alloc&) {
    return {EXIT_FAILURE_RUNTIME, "out of memory"};
  } catch (const std::exception& e) {
    return {EXIT_FAILURE_RUNTIME, e.what()};
  } catch (...) {
    return {EXIT_FAILURE_RUNTIME, "an unknown error"};
  }
}

int runRt(std::span<const std::string> args, const Io& io) {
  try {
    CommandLine rt = makeCommandLine();
    const CommandLine::Parsed parsed = rt.parse(args);
    if (!parsed.run) {
      io.out << parsed.text;
      return EXIT_OK;
    }
    return parsed.run(io);
  } catch (...) {
    const ErrorReport report = describeError(std::current_exception());
    io.err << "rt: " << report.message << "\n";
    return report.code;
  }
}

const BuiltinScene& requireBuiltinScene(std::string_view name, std::string_view hint) {
  if (const BuiltinScene* builtin = findBuiltinScene(name)) return *builtin;
  std::vector<std::string_view> names;
  for (const BuiltinScene& s : builtinScenes()) names.push_back(s.name);
  throw UsageError("unknown scene '" + std::string(name) + "'" + didYouMean(name, names) + " (" +
                   std::string(hint) + ")");
}

bool isSceneFileArgument(std::string_view scene) {
  return scene.ends_with(".json") && !findBuiltinScene(scene);
}

SceneDocument loadSceneArgument(std::string_view scene, std::span<const std::string> params,
                                const SceneFileInput* input) {
  if (isSceneFileArgument(scene)) {
    if (!params.empty())
      throw UsageError("--param: a scene file has no parameters (only built-in scenes have)");
    if (input) return parseScene(input->text, std::string(scene), input->models);
    return loadScene(std::string(scene));
  }
  return makeBuiltinScene(
      requireBuiltinScene(scene, "rt list shows the built-in scenes; a scene file ends in .json"),
      params);
}

std::string defaultOutputPath(std::string_view scene) {
  if (findBuiltinScene(scene)) return std::string(scene) + ".png";
  return std::filesystem::path(scene).stem().string() + ".png";
}

CLI::Option* addParamOption(CLI::App& command, std::vector<std::string>& into) {
  return command
      .add_option("--param", into,
                  "a built-in scene's parameter, NAME=VALUE (repeatable; see rt list)")
      ->type_name("NAME=VALUE")
      // One NAME=VALUE per --param: `--param arms=3 galaxy` leaves SCENE alone.
      ->allow_extra_args(false);
}

void addSceneArguments(CLI::App& command, SceneArguments& into, const std::string& widthHelp,
                       const std::string& heightHelp, const std::string& tracerHelp) {
  command.add_option("SCENE", into.argument, "a built-in scene's name or a .json scene file");
  addParamOption(command, into.params);
  addOptional(command, "--view", into.view, "one of the scene's named views (its cameras)", "NAME");
  addOptional(command, "--width", into.width, widthHelp, "W")
      ->transform(integerValidator(1, Image::MAX_SIDE));
  addOptional(command, "--height", into.height, heightHelp, "H")
      ->transform(integerValidator(1, Image::MAX_SIDE));
  addOptional(command, "--tracer", into.tracer, tracerHelp, "T")
      ->check(CLI::Validator(
          [](std::string& name) {
            return tracerNamed(name) ? std::string() : unknownTracerMessage(name);
          },
          ""));
  addOptional(command, "--seed", into.seed,
              "the random numbers' seed: changes the noise of sampled renders (default: the "
              "scene's render.seed)",
              "N")
      ->transform(integerValidator(0, INT_MAX));
  for (const auto& add : cliRegistry().sceneOptions) add(command, into.settings);
}

}  // namespace rt::cli
