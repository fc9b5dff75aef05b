// rt animate: the camera paths (in-process, exact where the arithmetic is exact), the frames
// against single renders, the video through ffmpeg where it is installed, and the refusals.
#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "RtProcess.h"
#include "cli/Animation.h"
#include "cli/CommandLine.h"

namespace rt::cli {
namespace {

using test::freshDirectory;
using test::readFile;
using test::runProgram;
using test::runRt;

/// ffprobe's count of the frames of video's first video stream, read by decoding them (its
/// output is "N\n").
test::RtResult videoFrameCount(const std::string& ffprobe, const std::string& video) {
  return runProgram({ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0",
                     "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", video});
}

CameraSpec targetCamera() {
  CameraSpec c;
  c.location = Point(10, 0, 0);
  c.target = Point(0, 0, 0);
  c.up = Vector(0, 1, 0);
  c.vpWidth = 4;
  c.vpHeight = 2;
  c.vpDistance = 5;
  c.nX = 40;
  c.nY = 20;
  return c;
}

TEST(OrbitCameras, FrameZeroIsTheCameraItselfBitForBit) {
  CameraSpec c = targetCamera();
  c.location = Point(0.1, 0.7, 3.3);  // (a - c) + c would round: frame 0 must not
  const std::vector<CameraSpec> frames = orbitCameras(c, 360, 7);
  ASSERT_EQ(frames.size(), 7u);
  EXPECT_EQ(frames[0].location, c.location);
  EXPECT_EQ(*frames[0].target, *c.target);
}

TEST(OrbitCameras, QuarterTurnsAboutTheUpAxisThroughTheTarget) {
  const std::vector<CameraSpec> frames = orbitCameras(targetCamera(), 360, 4);
  // About +Y by 90 degrees: (10, 0, 0) -> (0, 0, -10); by 180: (-10, 0, 0); by 270: (0, 0, 10).
  const double expected[4][3] = {{10, 0, 0}, {0, 0, -10}, {-10, 0, 0}, {0, 0, 10}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(frames[k].location.x(), expected[k][0], 1e-13) << k;
    EXPECT_EQ(frames[k].location.y(), 0) << k;
    EXPECT_NEAR(frames[k].location.z(), expected[k][2], 1e-13) << k;
    EXPECT_EQ(*frames[k].target, Point(0, 0, 0)) << k;
    EXPECT_EQ(frames[k].up, Vector(0, 1, 0)) << k;
    EXPECT_EQ(frames[k].nX, 40);
  }
}

TEST(OrbitCameras, ACameraGivenByADirectionTurnsItsDirectionAboutItsViewPlanePoint) {
  CameraSpec c = targetCamera();
  c.target.reset();
  c.location = Point(0, 0, 10);
  c.to = Vector(0, 0, -1);  // the centre: 5 along it (vpDistance), (0, 0, 5)
  const std::vector<CameraSpec> frames = orbitCameras(c, 360, 2);
  EXPECT_NEAR(frames[1].location.x(), 0, 1e-13);
  EXPECT_NEAR(frames[1].location.z(), 0, 1e-13);
  EXPECT_NEAR(frames[1].to->z(), 1, 1e-15);
  EXPECT_FALSE(frames[1].target.has_value());
}

TEST(ViewPathCameras, EndsOnTheViewsExactlyAndInterpolatesBetweenThem) {
  CameraSpec a = targetCamera(), b = targetCamera();
  b.location = Point(0, 4, 10);
  b.target = Point(2, 2, 2);
  b.vpDistance = 7;
  const std::vector<CameraSpec> frames = viewPathCameras({a, b}, 3);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].location, a.location);
  EXPECT_EQ(frames[2].location, b.location);
  EXPECT_EQ(*frames[2].target, *b.target);
  // Halfway: every quantity the mean of the two views' (exact for these numbers).
  EXPECT_EQ(frames[1].location, Point(5, 2, 5));
  EXPECT_EQ(*frames[1].target, Point(1, 1, 1));
  EXPECT_EQ(frames[1].vpDistance, 6);
  EXPECT_EQ(frames[1].vpWidth, 4);
}

TEST(ViewPathCameras, AFrameOnAMiddleViewIsThatView) {
  CameraSpec a = targetCamera(), b = targetCamera(), c = targetCamera();
  b.location = Point(0.3, 0.1, 7.7);
  c.location = Point(-9, 1, 0);
  const std::vector<CameraSpec> frames = viewPathCameras({a, b, c}, 5);  // 0, .5, 1, 1.5, 2
  EXPECT_EQ(frames[2].location, b.location);
  EXPECT_EQ(frames[4].location, c.location);
}

TEST(ViewPathCameras, BetweenADirectionAndATargetTheUpVectorStaysOrthogonal) {
  CameraSpec a = targetCamera(), b = targetCamera();
  b.target.reset();
  b.location = Point(0, 10, 0);
  b.to = Vector(0, -1, 0);
  b.up = Vector(0, 0, -1);
  const std::vector<CameraSpec> frames = viewPathCameras({a, b}, 4);
  for (int k = 1; k < 3; ++k) {
    ASSERT_TRUE(frames[k].to.has_value());
    EXPECT_NEAR(frames[k].to->dot(frames[k].up), 0, 1e-15) << k;
    EXPECT_NEAR(frames[k].to->length(), 1, 1e-15) << k;
  }
}

/// A camera at the origin looking along `to`, up +Y.
CameraSpec directionCamera(const Vector& to) {
  CameraSpec c = targetCamera();
  c.target.reset();
  c.location = Point(0, 0, 0);
  c.to = to;
  return c;
}

TEST(ViewPathCameras, DirectionsAtRightAnglesToTheUpVectorTurnEvenly) {
  // TC01: from +X to -Z, up +Y (orthogonal to both): halfway looks along (1, 0, -1)/√2, a third
  // of the way 30 degrees round; the up vector stays +Y exactly
  const std::vector<CameraSpec> frames =
      viewPathCameras({directionCamera(Vector(1, 0, 0)), directionCamera(Vector(0, 0, -1))}, 4);
  const double third = std::numbers::pi / 6;
  const double expected[2][3] = {{std::cos(third), 0, -std::sin(third)},
                                 {std::sin(third), 0, -std::cos(third)}};
  for (int k = 1; k < 3; ++k) {
    ASSERT_TRUE(frames[k].to.has_value()) << k;
    EXPECT_NEAR(frames[k].to->x(), expected[k - 1][0], 1e-15) << k;
    EXPECT_EQ(frames[k].to->y(), 0) << k;
    EXPECT_NEAR(frames[k].to->z(), expected[k - 1][2], 1e-15) << k;
    EXPECT_EQ(frames[k].up, Vector(0, 1, 0)) << k;
  }
}

TEST(ViewPathCameras, OppositeDirectionsTurnAboutTheUpVector) {
  // TC01: from -Z to +Z, up +Y: no great circle is given, so the camera pans about +Y (towards
  // up x direction = -X) rather than passing through a zero direction
  const std::vector<CameraSpec> frames =
      viewPathCameras({directionCamera(Vector(0, 0, -1)), directionCamera(Vector(0, 0, 1))}, 3);
  ASSERT_TRUE(frames[1].to.has_value());
  EXPECT_NEAR(frames[1].to->x(), -1, 1e-15);
  EXPECT_EQ(frames[1].to->y(), 0);
  EXPECT_NEAR(frames[1].to->z(), 0, 1e-15);
  EXPECT_EQ(frames[1].up, Vector(0, 1, 0));
  // TC02: opposite up vectors roll through the camera's side, keeping the direction
  CameraSpec upsideDown = directionCamera(Vector(0, 0, -1));
  upsideDown.up = Vector(0, -1, 0);
  const std::vector<CameraSpec> rolled =
      viewPathCameras({directionCamera(Vector(0, 0, -1)), upsideDown}, 3);
  EXPECT_EQ(*rolled[1].to, Vector(0, 0, -1));
  EXPECT_NEAR(std::fabs(rolled[1].up.x()), 1, 1e-15);
  EXPECT_NEAR(rolled[1].up.y(), 0, 1e-15);
  EXPECT_EQ(rolled[1].up.z(), 0);
}

TEST(AnimationPlan, FrameNamesHaveAtLeastFourDigits) {
  AnimationPlan plan{{}, std::vector<CameraSpec>(12), {}, "out", {}, "", 30};
  EXPECT_EQ(plan.framePath(7), "out/frame-0007.png");
  plan.cameras.resize(12345);
  EXPECT_EQ(plan.framePath(7), "out/frame-00007.png");
}

// ---- rt animate, as a user runs it ----

TEST(RtAnimate, FramesAreSingleRendersAndFrameKAloneIsTheSameBytes) {
  const std::string dir = freshDirectory("animate-orbit");
  const test::RtResult all = runRt({"animate", "galaxy", "--orbit", "90", "--frames", "3",
                                    "--width", "48", "-o", dir + "/all", "-q"});
  ASSERT_EQ(all.exitCode, 0) << all.err;
  EXPECT_NE(all.err.find("(3 frames): 48x27"), std::string::npos) << all.err;
  const test::RtResult one = runRt({"animate", "galaxy", "--orbit", "90", "--frames", "3",
                                    "--frame", "2", "--width", "48", "-o", dir + "/one", "-s"});
  ASSERT_EQ(one.exitCode, 0) << one.err;
  const test::RtResult render =
      runRt({"render", "galaxy", "--width", "48", "-o", dir + "/render.png", "-s"});
  ASSERT_EQ(render.exitCode, 0) << render.err;

  const std::string f0 = readFile(dir + "/all/frame-0000.png");
  const std::string f1 = readFile(dir + "/all/frame-0001.png");
  const std::string f2 = readFile(dir + "/all/frame-0002.png");
  ASSERT_FALSE(f2.empty());
  EXPECT_EQ(f0, readFile(dir + "/render.png"));  // frame 0 is the scene's camera
  EXPECT_EQ(f2, readFile(dir + "/one/frame-0002.png"));
  EXPECT_NE(f0, f1);
  EXPECT_NE(f1, f2);
  EXPECT_FALSE(std::filesystem::exists(dir + "/one/frame-0000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/all/frame-0003.png"));
}

TEST(RtAnimate, APathThroughViewsStartsAndEndsOnThem) {
  const std::string dir = freshDirectory("animate-views");
  const test::RtResult r = runRt({"animate", "galaxy", "--through", "main,above", "--frames", "3",
                                  "--width", "40", "-o", dir + "/f", "-s"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_EQ(runRt({"render", "galaxy", "--view", "above", "--width", "40", "-o", dir + "/above.png",
                   "-s"})
                .exitCode,
            0);
  EXPECT_EQ(readFile(dir + "/f/frame-0002.png"), readFile(dir + "/above.png"));
}

TEST(RtAnimate, RefusesAPathItCannotMakeBeforeAnyFrame) {
  const std::string dir = freshDirectory("animate-refusals");
  const test::RtResult unknown =
      runRt({"animate", "galaxy", "--through", "main,abuve", "--frames", "3", "-o", dir + "/f"});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("rt: --through: the scene has no view 'abuve'; did you mean 'above'?"),
            std::string::npos)
      << unknown.err;
  const test::RtResult both = runRt({"animate", "galaxy", "--orbit", "30", "--through", "all",
                                     "--frames", "3", "-o", dir + "/f"});
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_EQ(both.err, "rt: --orbit and --through: give one camera path, not both\n");
  const test::RtResult none = runRt({"animate", "galaxy", "--frames", "3", "-o", dir + "/f"});
  EXPECT_EQ(none.err, "rt: give a camera path: --orbit DEGREES or --through VIEW,VIEW,...\n");
  const test::RtResult frame = runRt(
      {"animate", "galaxy", "--orbit", "30", "--frames", "3", "--frame", "3", "-o", dir + "/f"});
  EXPECT_EQ(frame.err, "rt: --frame: expected a frame from 0 to 2 (--frames 3), got 3\n");
  const test::RtResult negative = runRt(
      {"animate", "galaxy", "--orbit", "30", "--frames", "3", "--frame", "-1", "-o", dir + "/f"});
  EXPECT_EQ(negative.exitCode, 2);
  EXPECT_EQ(negative.err, "rt: --frame: expected a frame from 0 to 2 (--frames 3), got -1\n");
  // One frame cannot be on both ends of a path through views
  const test::RtResult single = runRt(
      {"animate", "galaxy", "--through", "main,side,above", "--frames", "1", "-o", dir + "/f"});
  EXPECT_EQ(single.exitCode, 2);
  EXPECT_EQ(single.err,
            "rt: --through: a path through 3 views starts on 'main' and ends on 'above', which "
            "takes at least 2 frames; got --frames 1 (one view alone: rt render --view main)\n");
  // Numbers: not a number, in rt's words; out of range, the value as given
  const test::RtResult word =
      runRt({"animate", "galaxy", "--orbit", "abc", "--frames", "3", "-o", dir + "/f"});
  EXPECT_EQ(word.exitCode, 2);
  EXPECT_EQ(word.err, "rt: --orbit: expected a number, got 'abc'\n");
  const test::RtResult fpsWord = runRt(
      {"animate", "galaxy", "--orbit", "30", "--frames", "3", "--fps", "1e400", "-o", dir + "/f"});
  EXPECT_EQ(fpsWord.err, "rt: --fps: expected a number, got '1e400'\n");
  const test::RtResult fps = runRt({"animate", "galaxy", "--orbit", "30", "--frames", "3", "--fps",
                                    "0", "-o", dir + "/f", "--video", dir + "/v.mp4"});
  EXPECT_EQ(fps.exitCode, 2);
  EXPECT_EQ(fps.err, "rt: --fps: expected a number of frames per second in (0, 1000], got 0\n");
  // --fps without --video, which alone it would change nothing for
  const test::RtResult fpsAlone = runRt(
      {"animate", "galaxy", "--orbit", "30", "--frames", "3", "--fps", "24", "-o", dir + "/f"});
  EXPECT_EQ(fpsAlone.exitCode, 2);
  EXPECT_EQ(fpsAlone.err, "rt: --fps requires --video (see rt animate --help)\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/f"));
}

TEST(RtAnimate, WithoutFfmpegAVideoIsRefusedWithExitTwoBeforeAnyFrame) {
  const std::string dir = freshDirectory("animate-no-ffmpeg");
  test::RtOptions options;
  options.path = std::filesystem::absolute(dir).string();  // a PATH without ffmpeg
  const test::RtResult r = runRt({"animate", "galaxy", "--orbit", "30", "--frames", "2", "--width",
                                  "32", "-o", dir + "/f", "--video", dir + "/v.mp4"},
                                 options);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err,
            "rt: --video: encoding a video needs ffmpeg, which is not on PATH; install it "
            "(apt-get install ffmpeg, or scripts/deps.sh --video), or leave out --video to write "
            "the frames only\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/f"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/v.mp4"));
}

TEST(RtAnimate, TheVideoHoldsEveryFrameAtTheFramesSize) {
  const std::optional<std::string> ffprobe = findOnPath("ffprobe");
  if (!findOnPath("ffmpeg") || !ffprobe)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/deps.sh --video installs it)";
  const std::string dir = freshDirectory("animate-video");
  const test::RtResult r =
      runRt({"animate", "galaxy", "--orbit", "360", "--frames", "5", "--width", "64", "-o",
             dir + "/f", "--video", dir + "/orbit.mp4", "--fps", "10", "-q"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("rt: wrote " + dir + "/orbit.mp4: 5 frames at 10 frames/s (H.264)\n"),
            std::string::npos)
      << r.err;
  const test::RtResult probe = runProgram(
      {*ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
       "stream=nb_read_frames,width,height", "-of", "csv=p=0", dir + "/orbit.mp4"});
  ASSERT_EQ(probe.exitCode, 0) << probe.err;
  EXPECT_EQ(probe.out, "64,36,5\n");
  // Nothing but the video is left beside it (the temporary file was renamed).
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(RtAnimate, TheVideoHoldsThisRunsFramesOnly) {
  const std::optional<std::string> ffprobe = findOnPath("ffprobe");
  if (!findOnPath("ffmpeg") || !ffprobe)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/deps.sh --video installs it)";
  const std::string dir = freshDirectory("animate-video-fewer");
  // An earlier run left 5 frames in the folder; this one renders 2 into it: its video holds 2.
  test::RtResult r = runRt({"animate", "galaxy", "--orbit", "90", "--frames", "5", "--width", "32",
                            "-o", dir + "/f", "-q"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runRt({"animate", "galaxy", "--orbit", "90", "--frames", "2", "--width", "32", "-o",
             dir + "/f", "--video", dir + "/v.mp4", "-q"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const test::RtResult probe = videoFrameCount(*ffprobe, dir + "/v.mp4");
  ASSERT_EQ(probe.exitCode, 0) << probe.err;
  EXPECT_EQ(probe.out, "2\n");
}

TEST(RtAnimate, TheVideoMayGoIntoTheFramesFolderTheCommandMakes) {
  const std::optional<std::string> ffprobe = findOnPath("ffprobe");
  if (!findOnPath("ffmpeg") || !ffprobe)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/deps.sh --video installs it)";
  const std::string dir = freshDirectory("animate-video-inside");
  const test::RtResult r = runRt({"animate", "galaxy", "--orbit", "90", "--frames", "2", "--width",
                                  "32", "-o", dir + "/new", "--video", dir + "/new/v.mp4", "-q"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/new/v.mp4"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/new/frame-0001.png"));
  // The video holds the two frames, exactly.
  const test::RtResult probe = videoFrameCount(*ffprobe, dir + "/new/v.mp4");
  ASSERT_EQ(probe.exitCode, 0) << probe.err;
  EXPECT_EQ(probe.out, "2\n");
}

// Ctrl-C while ffmpeg encodes: ffmpeg is ended, the video is not written (an earlier one stays
// as it was), the frames stay, exit 130. The ffmpeg on PATH here is a stand-in that only waits,
// so that the signal surely comes while it runs, with or without a real ffmpeg installed.
TEST(RtAnimate, CtrlCWhileEncodingEndsFfmpegAndWritesNoVideo) {
  namespace fs = std::filesystem;
  const std::string dir = freshDirectory("animate-encoding-interrupted");
  const fs::path bin = fs::absolute(fs::path(dir) / "bin");
  fs::create_directories(bin);
  test::writeText((bin / "ffmpeg").string(), "#!/bin/sh\nexec sleep 60\n");
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  test::writeText(dir + "/v.mp4", "an earlier video");
  test::RtChild rt(test::Program{{"/usr/bin/env", "PATH=" + bin.string() + ":/usr/bin:/bin", RT_EXE,
                                  "animate", "galaxy", "--orbit", "30", "--frames", "2", "--width",
                                  "16", "-o", dir + "/f", "--video", dir + "/v.mp4"}});
  ASSERT_TRUE(rt.waitForLine(" (2 frames): ")) << rt.err();  // the frames' summary: ffmpeg next
  rt.signal(SIGINT);
  EXPECT_EQ(rt.wait(), 130) << rt.err();
  EXPECT_NE(rt.err().find("rt: interrupted while encoding " + dir +
                          "/v.mp4 (nothing written to it; the 2 frames are in " + dir + "/f)\n"),
            std::string::npos)
      << rt.err();
  EXPECT_EQ(readFile(dir + "/v.mp4"), "an earlier video");
  EXPECT_TRUE(fs::is_regular_file(dir + "/f/frame-0000.png"));
  EXPECT_TRUE(fs::is_regular_file(dir + "/f/frame-0001.png"));
  // Nothing else in the folder: no temporary video left.
  std::size_t entries = 0;
  for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 3u);  // bin, f, v.mp4
}

// The temporary video renamed over the destination fails: the message gives the rename's
// reason (once "Success", the outcome of removing the temporary file after it). The ffmpeg on
// PATH is a stand-in: one that writes its output (the last argument) and makes the destination
// a folder with a file in it meanwhile, and one that exits 0 having written nothing.
TEST(RtAnimate, AFailedRenameOfTheVideoSaysWhy) {
  namespace fs = std::filesystem;
  const std::string dir = freshDirectory("animate-video-rename-fails");
  const fs::path bin = fs::absolute(fs::path(dir) / "bin");
  fs::create_directories(bin);
  const std::string video = dir + "/v.mp4";
  struct Case {
    const char* partition;
    std::string ffmpeg;  // the stand-in's script
    int error;           // what the rename gives
  };
  const std::vector<Case> cases = {
      // TC01: the destination became a folder that is not empty
      {"TC01",
       "#!/bin/sh\nfor last; do :; done\necho encoded > \"$last\"\nmkdir '" + video +
           "' && echo older > '" + video + "/kept.txt'\n",
       EISDIR},
      // TC02: ffmpeg said it succeeded but wrote no file
      {"TC02", "#!/bin/sh\nexit 0\n", ENOENT},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.partition);
    fs::remove_all(video);
    test::writeText((bin / "ffmpeg").string(), c.ffmpeg);
    fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
    test::RtOptions options;
    options.path = bin.string() + ":/usr/bin:/bin";
    const test::RtResult r =
        runRt({"animate", "galaxy", "--orbit", "30", "--frames", "2", "--width", "16", "-o",
               dir + "/f", "--video", video, "--silent"},
              options);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "rt: cannot write '" + video +
                         "': " + std::error_code(c.error, std::system_category()).message() + "\n");
    // No temporary video left beside the destination: bin, f (and the folder v.mp4)
    std::size_t entries = 0;
    for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, c.error == EISDIR ? 3u : 2u);
    // The folder's older content stays
    if (c.error == EISDIR) {
      EXPECT_EQ(readFile(video + "/kept.txt"), "older\n");
    }
  }
}

// Ctrl-C during the first frame: no frame written, and the folder the run made is removed; a
// folder that was there before stays, empty or not.
TEST(RtAnimate, CtrlCBeforeTheFirstFrameLeavesNoFolderOfItsOwn) {
  namespace fs = std::filesystem;
  const std::string dir = freshDirectory("animate-first-frame-interrupted");
  fs::create_directory(dir + "/empty");
  fs::create_directory(dir + "/kept");
  test::writeText(dir + "/kept/notes.txt", "mine");
  for (const std::string name : {"made", "empty", "kept"}) {
    SCOPED_TRACE(name);
    // The galaxy at 1280x720 on one thread: many seconds a frame, so the signal comes in frame 0.
    test::RtChild rt(test::Program{{RT_EXE, "animate", "galaxy", "--orbit", "30", "--frames", "2",
                                    "--threads", "1", "-o", dir + "/" + name}});
    ASSERT_TRUE(rt.waitForLine("rt: animating galaxy (2 frames")) << rt.err();
    rt.signal(SIGINT);
    EXPECT_EQ(rt.wait(), 130) << rt.err();
    const std::string left = name == "made" ? "no frame written; " + dir +
                                                  "/made, which this run "
                                                  "made, removed"
                                            : "no frame written to " + dir + "/" + name;
    EXPECT_NE(rt.err().find("rt: interrupted after 0 of 2 frames (" + left + ")\n"),
              std::string::npos)
        << rt.err();
  }
  EXPECT_FALSE(fs::exists(dir + "/made"));
  EXPECT_TRUE(fs::is_directory(dir + "/empty"));
  EXPECT_TRUE(fs::is_empty(dir + "/empty"));
  EXPECT_EQ(readFile(dir + "/kept/notes.txt"), "mine");
  std::size_t entries = 0;
  for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir + "/kept"))
    ++entries;
  EXPECT_EQ(entries, 1u);
}

// A refusal that comes once the frames' folder is made (here a video in it with the wrong
// ending, checked after the folder exists) leaves no folder either.
TEST(RtAnimate, ARefusalAfterTheFolderIsMadeRemovesIt) {
  namespace fs = std::filesystem;
  const std::string dir = freshDirectory("animate-refused-in-folder");
  const fs::path bin = fs::absolute(fs::path(dir) / "bin");
  fs::create_directories(bin);
  test::writeText((bin / "ffmpeg").string(), "#!/bin/sh\nexit 0\n");  // found, never run
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  test::RtOptions options;
  options.path = bin.string();
  const test::RtResult r = runRt({"animate", "galaxy", "--orbit", "30", "--frames", "2", "-o",
                                  dir + "/f", "--video", dir + "/f/v.avi"},
                                 options);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("v.avi"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/f"));
}

}  // namespace
}  // namespace rt::cli
