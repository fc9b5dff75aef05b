#include "cli/RenderRequest.h"

#include <unistd.h>

#include <algorithm>
#include <sstream>

#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "cli/Tracers.h"
#include "common/NearestName.h"

namespace rt::cli {

RenderRequest resolveRenderRequest(const SceneArguments& arguments, const RequestNeeds& needs) {
  // Everything is checked before the first ray: the scene, the options, the output path and the
  // image's size. A mistake costs no render time.
  RenderRequest request{sceneFromArguments(arguments), nullptr, "", {}};
  const SceneDocument& doc = request.doc;
  request.tracer = &findTracer(doc.render.tracer);
  if (needs.writesImage) {
    request.output = needs.output ? *needs.output : defaultOutputPath(arguments.argument);
    const std::string_view what = needs.output ? "-o" : "the default output";
    checkOutputWritable(request.output, PNG_IMAGE, what);
    checkOutputIsNoInput(request.output, what, "the image", arguments.argument, doc);
  }
  if (needs.makesImage)
    checkImageFits(doc.camera.nX, doc.camera.nY,
                   resolutionOrigin(arguments.width, arguments.height));
  request.warnings = sceneWarnings(doc, arguments, needs.renders);
  return request;
}

TracerSetup RenderRequest::buildTracer() const {
  const CliRegistry& registry = cliRegistry();
  std::unique_ptr<Intersectable> accelerator =
      registry.makeAccelerator ? registry.makeAccelerator(doc) : nullptr;
  std::unique_ptr<RayTracer> rayTracer = tracer->make(doc, accelerator.get());
  return {std::move(accelerator), std::move(rayTracer)};
}

RenderSetup RenderRequest::build() const {
  TracerSetup traced = buildTracer();
  return RenderSetup{std::move(traced.accelerator), std::move(traced.tracer),
                     cliRegistry().makeSampler(doc.render), doc.camera.builder().build()};
}

SceneDocument sceneFromArguments(const SceneArguments& arguments) {
  SceneDocument doc = loadSceneArgument(arguments.argument, arguments.params, arguments.fileInput);
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
  applyResolution(doc.camera, arguments.width, arguments.height);
  if (arguments.tracer) doc.render.tracer = *arguments.tracer;
  if (arguments.seed) doc.render.seed = static_cast<std::uint64_t>(*arguments.seed);
  if (arguments.settings.threads) doc.render.threads = *arguments.settings.threads;
  if (arguments.settings.accel) doc.render.accel = *arguments.settings.accel;
  if (arguments.settings.lightBuffers) doc.render.lightBuffers = *arguments.settings.lightBuffers;
  findTracer(doc.render.tracer, arguments.tracer ? "--tracer" : "render.tracer");
  return doc;
}

void applyResolution(CameraSpec& camera, const std::optional<int>& width,
                     const std::optional<int>& height) {
  CameraSpec& c = camera;
  constexpr int kMax = Image::MAX_SIDE;
  const int nX0 = c.nX, nY0 = c.nY;
  const auto scaled = [](int given, int num, int den) {
    return static_cast<int>(
        std::max<long long>(1, (2LL * given * num + den) / (2LL * den)));  // given·num/den, rounded
  };
  if (width && height) {
    c.nX = *width;
    c.nY = *height;
    // Another aspect ratio than the scene's: the view plane's height follows the image's, so
    // that pixels stay square and nothing is squashed.
    if (static_cast<long long>(c.nX) * nY0 != static_cast<long long>(c.nY) * nX0)
      c.vpHeight = c.vpWidth * c.nY / c.nX;
  } else if (width) {
    c.nX = *width;
    c.nY = scaled(c.nX, nY0, nX0);
  } else if (height) {
    c.nY = *height;
    c.nX = scaled(c.nY, nX0, nY0);
  }
  if (c.nX < 1 || c.nX > kMax || c.nY < 1 || c.nY > kMax)
    throw UsageError("the image's resolution " + std::to_string(c.nX) + "x" + std::to_string(c.nY) +
                     " (" + resolutionOrigin(width, height) + ") is outside 1.." +
                     std::to_string(kMax) + " per side");
}

std::string resolutionOrigin(const std::optional<int>& width, const std::optional<int>& height) {
  if (width && height) return "from --width and --height";
  if (width) return "from --width, the height keeping the scene's aspect ratio";
  if (height) return "from --height, the width keeping the scene's aspect ratio";
  return "the scene's resolution";
}

// An Image keeps a Color (three doubles) per pixel, and the PNG writer an RGB byte triple.
void checkImageFits(int nX, int nY, std::string_view origin) {
  const double bytes = static_cast<double>(nX) * nY * (sizeof(Color) + 3);
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return;  // unknown: let the allocation decide
  const double memory = static_cast<double>(pages) * static_cast<double>(pageSize);
  if (bytes > memory) {
    std::ostringstream os;
    os.precision(3);
    os << "a " << nX << "x" << nY << " image (" << origin << ") needs " << bytes / (1u << 30)
       << " GiB, more than this machine's " << memory / (1u << 30) << " GiB of memory";
    throw UsageError(os.str());
  }
}

std::vector<std::string> sceneWarnings(const SceneDocument& doc, const SceneArguments& arguments,
                                       bool rendering) {
  std::vector<std::string> warnings;
  for (const std::string& w : doc.warnings) warnings.push_back("warning: " + w);
  const Scene& scene = *doc.scene;
  const Double3& ambient = scene.ambientLight.intensity().rgb();
  const TracerKind* tracer = tracerNamed(doc.render.tracer);  // "": the build's default
  if (!rendering || !tracer || tracer->name != "ambient" ||
      scene.geometries.primitiveCount() == 0 || !ambient.isExactlyZero())
    return warnings;
  // The later stages' tracers, which show the lights (not the debugging views).
  std::string others;
  for (const TracerKind& t : tracerKinds())
    if (t.name != "ambient" && !t.debugView) others += (others.empty() ? "" : ", ") + t.name;
  warnings.push_back(
      std::string("warning: the ambient tracer (") +
      (arguments.tracer ? "--tracer ambient" : "the scene's render.tracer") +
      ") shows the ambient light wherever a ray hits a shape, and this scene's ambient light is "
      "zero (ambient.color x ambient.kA): every shape will be black; give the scene an ambient "
      "light" +
      (others.empty() ? "" : ", or render with a tracer that shows its lights (" + others + ")"));
  return warnings;
}

}  // namespace rt::cli
