#include "cli/Commands.h"

#include <unistd.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <vector>

#include "CommandTable.h"
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

int runRt(std::span<const std::string> args, const Io& io) {
  try {
    CommandLine rt = makeCommandLine();
    const CommandLine::Parsed parsed = rt.parse(args);
    if (!parsed.run) {
      io.out << parsed.text;
      return EXIT_OK;
    }
    return parsed.run(io);
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

SceneDocument loadSceneArgument(std::string_view scene, std::span<const std::string> params) {
  if (scene.ends_with(".json") && !findBuiltinScene(scene)) {
    if (!params.empty())
      throw UsageError("--param: a scene file has no parameters (only built-in scenes have)");
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

// An Image keeps a Color (three doubles) per pixel, and the PNG writer an RGB byte triple.
void checkImageFits(int nX, int nY) {
  const double bytes = static_cast<double>(nX) * nY * (sizeof(Color) + 3);
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return;  // unknown: let the allocation decide
  const double memory = static_cast<double>(pages) * static_cast<double>(pageSize);
  if (bytes > memory) {
    std::ostringstream os;
    os.precision(3);
    os << "a " << nX << "x" << nY << " image needs " << bytes / (1u << 30)
       << " GiB, more than this machine's " << memory / (1u << 30) << " GiB of memory";
    throw UsageError(os.str());
  }
}

SceneDocument sceneFromArguments(const SceneArguments& arguments) {
  SceneDocument doc = loadSceneArgument(arguments.argument, arguments.params);
  if (arguments.view) {
    std::vector<std::string_view> names;
    const NamedView* chosen = nullptr;
    for (const NamedView& v : doc.views) {
      names.push_back(v.name);
      if (v.name == *arguments.view) chosen = &v;
    }
    if (!chosen) {
      const std::string known = joinNames(names);
      throw UsageError("--view: the scene has no view '" + *arguments.view + "'" +
                       didYouMean(*arguments.view, names) + " (" +
                       (names.empty() ? std::string("it has none") : "its views: " + known) + ")");
    }
    doc.camera = chosen->camera;
  }
  CameraSpec& c = doc.camera;
  constexpr int kMax = Image::MAX_SIDE;
  const int nX0 = c.nX, nY0 = c.nY;
  const auto scaled = [](int given, int num, int den) {
    return static_cast<int>(
        std::max<long long>(1, (2LL * given * num + den) / (2LL * den)));  // given·num/den, rounded
  };
  if (arguments.width && arguments.height) {
    c.nX = *arguments.width;
    c.nY = *arguments.height;
    // Another aspect ratio than the scene's: the view plane's height follows the image's, so
    // that pixels stay square and nothing is squashed.
    if (static_cast<long long>(c.nX) * nY0 != static_cast<long long>(c.nY) * nX0)
      c.vpHeight = c.vpWidth * c.nY / c.nX;
  } else if (arguments.width) {
    c.nX = *arguments.width;
    c.nY = scaled(c.nX, nY0, nX0);
  } else if (arguments.height) {
    c.nY = *arguments.height;
    c.nX = scaled(c.nY, nX0, nY0);
  }
  if (c.nX < 1 || c.nX > kMax || c.nY < 1 || c.nY > kMax)
    throw UsageError("the image's resolution " + std::to_string(c.nX) + "x" + std::to_string(c.nY) +
                     " is outside 1.." + std::to_string(kMax) + " per side");
  if (arguments.tracer) doc.render.tracer = *arguments.tracer;
  if (arguments.seed) doc.render.seed = static_cast<std::uint64_t>(*arguments.seed);
  if (arguments.settings.threads) doc.render.threads = *arguments.settings.threads;
  if (arguments.settings.accel) doc.render.accel = *arguments.settings.accel;
  findTracer(doc.render.tracer, arguments.tracer ? "--tracer" : "render.tracer");
  return doc;
}

void warnAboutScene(const SceneDocument& doc, const SceneArguments& arguments, bool rendering,
                    const Io& io) {
  for (const std::string& w : doc.warnings) io.err << "rt: warning: " << w << "\n";
  const Scene& scene = *doc.scene;
  const Double3& ambient = scene.ambientLight.intensity().rgb();
  const TracerKind* tracer = tracerNamed(doc.render.tracer);  // "": the build's default
  if (!rendering || !tracer || tracer->name != "ambient" || scene.geometries.size() == 0 ||
      !ambient.isExactlyZero())
    return;
  // The later stages' tracers, which show the lights (not the debugging views).
  std::string others;
  for (const TracerKind& t : tracerKinds())
    if (t.name != "ambient" && !t.debugView) others += (others.empty() ? "" : ", ") + t.name;
  io.err << "rt: warning: the ambient tracer ("
         << (arguments.tracer ? "--tracer ambient" : "the scene's render.tracer")
         << ") shows the ambient light wherever a ray hits a shape, and this scene's ambient "
            "light is zero (ambient.color x ambient.kA): every shape will be black; give the "
            "scene an ambient light"
         << (others.empty() ? ""
                            : ", or render with a tracer that shows its lights (" + others + ")")
         << "\n";
}

}  // namespace rt::cli
