#pragma once
/// @file Animation.h
/// `rt animate`: a camera path rendered into numbered frames, and optionally a video of them.
///
///     path      --orbit DEGREES: about the camera's target, about its up vector, frame k at
///                 k·DEGREES/N (360 loops without a repeated frame; frame 0 is the scene's own
///                 camera, exactly)
///               --through A,B,C (or all): the scene's named views in that order, positions,
///                 targets (or directions), up vectors and view planes interpolated linearly;
///                 the first frame is view A and the last view C, exactly
///     frames    DIR/frame-0000.png ... (at least 4 digits), each written atomically; every
///               frame is a pure function of (scene, options, k), so `--frame K` alone gives the
///               bytes frame K has in the whole sequence
///     video     --video FILE.mp4: ffmpeg (H.264, yuv420p, --fps) over the frames, written to a
///               temporary name and renamed; without ffmpeg, refused before any frame
///
/// rt animate renders the frames one after another with the build's render loop; rt-mpi animate
/// (app/mpi) deals them to ranks. Both resolve the same AnimationPlan.

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/CameraSpec.h"
#include "cli/RenderRequest.h"

namespace CLI {
class App;
}

namespace rt::cli {

/// rt animate's arguments, as the command line binds them.
struct AnimateArgs {
  SceneArguments scene;
  std::optional<double> orbit;         ///< --orbit DEGREES
  std::optional<std::string> through;  ///< --through VIEW,VIEW,... or "all"
  int frames = 0;                      ///< --frames N (required)
  std::optional<int> frame;            ///< --frame K: only frame K
  std::optional<std::string> output;   ///< -o DIR: the frames' folder (default: SCENE-frames)
  std::optional<std::string> video;    ///< --video FILE.mp4
  double fps = 30;                     ///< --fps
  std::optional<int> gridLines;
  bool quiet = false;
  bool silent = false;
};

/// The most frames an animation has.
inline constexpr int MAX_FRAMES = 1000000;

/// Adds SCENE and every option of rt animate to command, bound to into (the scene's arguments
/// and the stages' options as rt render's, --grid-lines, -q, -s, and the path's).
void addAnimateOptions(CLI::App& command, AnimateArgs& into);

/// What `rt animate --help` says after its options.
std::string animateCommandDetails();

/// An animation resolved and checked before any frame: the scene and options as a render
/// request, every frame's camera, which frames are rendered, where they go.
struct AnimationPlan {
  RenderRequest request;             ///< the scene with the options applied (output unused)
  std::vector<CameraSpec> cameras;   ///< frame k's camera, for every k of the path
  std::vector<int> frames;           ///< the frames to render: all, or --frame's
  std::filesystem::path directory;   ///< where the frames are written
  std::optional<std::string> video;  ///< the video's path, when asked
  std::string ffmpeg;                ///< the ffmpeg found on PATH (when a video is asked)
  double fps = 30;
  bool madeDirectory = false;  ///< the folder was missing and resolveAnimation made it

  /// DIR/frame-0007.png: the frame's number with at least 4 digits (as many as the last needs).
  std::string framePath(int k) const;
  /// How many digits the frames' numbers have: at least 4, as many as the last frame needs.
  int frameDigits() const;
  /// What a run stopped or failed after `written` frames leaves, for its message: "2 whole
  /// frames written to DIR". With none written, the folder is removed when this run made it
  /// and it is still empty ("no frame written; DIR, which this run made, removed"); a folder
  /// that was there before stays ("no frame written to DIR").
  std::string settleUnfinished(std::size_t written) const;
};

/// Resolves args: the request (as rt render's, nothing written by it), the path (exactly one of
/// --orbit and --through; --frames 1..MAX_FRAMES; --frame within them; views known, at least
/// two), the folder (created when missing; its parent must exist; checked writable), the video
/// (ending .mp4, writable, ffmpeg on PATH, not with --frame).
/// writes false (a rank of rt-mpi other than 0, which writes nothing): the folder and the video
/// are neither checked nor made.
/// @throws UsageError, SceneError naming the value and where it came from; the message for a
///         missing ffmpeg says how to install it.
AnimationPlan resolveAnimation(const AnimateArgs& args, bool writes = true);

/// The cameras of an orbit of degrees about camera's target (or, for a camera given by a
/// direction, the point at its focal distance along it, else at its view plane's distance):
/// location (and direction) turned about the axis through that point along camera.up, frame k
/// by k·degrees/frames. Frame 0 is camera itself.
std::vector<CameraSpec> orbitCameras(const CameraSpec& camera, double degrees, int frames);

/// The cameras of a path through views (at least two, the same resolution), frames of them:
/// frame k at k·(views−1)/(frames−1) along the path, each quantity interpolated linearly between
/// its two views (a direction or up vector normalised, the up vector made orthogonal to a
/// direction); a frame that falls on a view is that view's camera exactly.
std::vector<CameraSpec> viewPathCameras(const std::vector<CameraSpec>& views, int frames);

/// The path of the program called name on PATH, or nothing.
std::optional<std::string> findOnPath(const std::string& name);

/// Encodes plan's frames (all of them) into plan.video with ffmpeg, through a temporary file
/// renamed at the end. @returns true when written; false when stop (if given) was raised, or a
/// Ctrl-C or a kill ended ffmpeg, before it was done: ffmpeg is ended, nothing is written.
/// @throws std::runtime_error with ffmpeg's message when it fails. Either way the frames stay
/// and an existing video is left as it was.
bool encodeVideo(const AnimationPlan& plan, const std::atomic<bool>* stop = nullptr);

}  // namespace rt::cli
