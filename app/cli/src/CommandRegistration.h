#pragma once
// Internal to rt_cli: the commands' registration functions (each adds its command to rt's command
// line; Commands.cpp gathers them) and the pieces they share: the scene arguments, the image-size
// check, the scene warnings.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "cli/Registry.h"

namespace rt::cli {

void addListCommand(CommandLine& rt);
void addRenderCommand(CommandLine& rt);
void addProbeCommand(CommandLine& rt);
void addExportCommand(CommandLine& rt);
void addCompareCommand(CommandLine& rt);

struct BuiltinScene;
/// The built-in scene called name. @throws UsageError "unknown scene 'x'; did you mean 'y'?
/// (hint)".
const BuiltinScene& requireBuiltinScene(std::string_view name, std::string_view hint);

/// Adds --param NAME=VALUE (repeatable, one value each) to command, bound to into.
CLI::Option* addParamOption(CLI::App& command, std::vector<std::string>& into);

/// The scene argument and the options that change the scene, which render and probe share.
struct SceneArguments {
  std::string argument;  ///< SCENE as given: a built-in scene's name or a .json scene file
  std::vector<std::string> params;  ///< --param NAME=VALUE, for a built-in scene's parameters
  std::optional<std::string> view;  ///< --view NAME: one of the scene's views
  std::optional<int> width, height;
  std::optional<std::string> tracer;
  std::optional<int> seed;
  SettingOverrides settings;  ///< the options stages add (--threads, --accel)
};

/// Adds SCENE, --param NAME=VALUE (repeatable), --view NAME, --width W and --height H (integers,
/// 1..Image::MAX_SIDE), --tracer T (a tracer of this build) and --seed N to command, bound to
/// into; the help texts of the size and the tracer are the command's own.
void addSceneArguments(CLI::App& command, SceneArguments& into, const std::string& widthHelp,
                       const std::string& heightHelp, const std::string& tracerHelp);

/// The scene (loadSceneArgument) with the options applied, and the result checked: the view
/// known; the resolution within Image::MAX_SIDE (one of width and height given: the other keeps
/// the scene's aspect ratio; both given with another aspect: the view plane's height follows,
/// so pixels stay square); the tracer known. @throws UsageError, SceneError.
SceneDocument sceneFromArguments(const SceneArguments& arguments);

/// Refuses an nX x nY image that cannot fit in this machine's memory (render and probe check
/// before their camera allocates it).
/// @throws UsageError naming the size and the memory.
void checkImageFits(int nX, int nY);

/// Prints "rt: warning: ..." on io.err for each warning the scene file's reader left in
/// doc.warnings (stage 7: glass faces wound both ways) and, when rendering, for a render by the
/// ambient tracer of a scene whose ambient light is zero (every shape would be black).
void warnAboutScene(const SceneDocument& doc, const SceneArguments& arguments, bool rendering,
                    const Io& io);

}  // namespace rt::cli
