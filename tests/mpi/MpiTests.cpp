// rt-mpi under mpirun, as a user runs it: the same bytes as rt render and rt animate for 1, 2 and
// 3 ranks and 1 or 2 threads per rank, a scene file and its model file sent to a rank that
// cannot read them, and the faults (a bad scene, a rank out of memory, a rank killed, Ctrl-C).
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "RtProcess.h"

#ifndef RT_MPI_EXE
#error "RT_MPI_EXE must name the rt-mpi executable"
#endif

namespace rt::cli::test {
namespace {

namespace fs = std::filesystem;

/// mpirun -np N rt-mpi ARGS...: as many ranks as asked on this machine whatever its cores, as
/// root if need be (CI), without the shared-memory single copy that containers forbid.
std::vector<std::string> mpirun(int ranks, const std::vector<std::string>& args) {
  std::vector<std::string> all{RT_MPIEXEC,
                               "--oversubscribe",
                               "--allow-run-as-root",
                               "--mca",
                               "btl_vader_single_copy_mechanism",
                               "none",
                               "-np",
                               std::to_string(ranks),
                               RT_MPI_EXE};
  all.insert(all.end(), args.begin(), args.end());
  return all;
}

RtResult runMpi(int ranks, const std::vector<std::string>& args) {
  return runProgram(mpirun(ranks, args));
}

/// The lines of err that rt-mpi printed (its own, not mpirun's).
std::vector<std::string> rtMpiLines(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("rt-mpi: ", 0) == 0) lines.push_back(line);
  return lines;
}

/// The process ids of rt-mpi ranks whose command line holds marker, with their rank.
std::vector<std::pair<pid_t, int>> ranksRunning(const std::string& marker) {
  std::vector<std::pair<pid_t, int>> found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string cmdline = readFile(entry.path().string() + "/cmdline");
    if (cmdline.find("rt-mpi") == std::string::npos || cmdline.find(marker) == std::string::npos)
      continue;
    const std::string environ = readFile(entry.path().string() + "/environ");
    const std::string key = std::string("OMPI_COMM_WORLD_RANK=");
    const std::size_t at = environ.find(key);
    if (at == std::string::npos) continue;
    found.emplace_back(static_cast<pid_t>(std::stol(name)),
                       std::stoi(environ.substr(at + key.size())));
  }
  return found;
}

class RtMpi : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::absolute(freshDirectory("mpi-" + name)).string();
  }
  std::string path(const std::string& file) const { return dir_ + "/" + file; }
  /// An existing image at path(name), which a failed job must leave as it was.
  std::string earlierImage(const std::string& name) const {
    const std::string out = path(name);
    std::ofstream(out) << "an earlier image";
    return out;
  }
  /// A render on 2 ranks of 1 thread, long enough to be stopped after its first 10 %.
  static Program interruptibleRender(const std::string& out) {
    return Program{mpirun(2, {"render", "galaxy", "--width", "480", "-o", out, "--threads", "1"})};
  }
  std::string dir_;
};

TEST_F(RtMpi, TheGalaxyIsTheBytesOfRtRenderForOneTwoAndThreeRanksAndAnyThreads) {
  const RtResult single =
      runRt({"render", "galaxy", "--width", "96", "-o", path("rt.png"), "-s", "--threads", "1"});
  ASSERT_EQ(single.exitCode, 0) << single.err;
  const std::string expected = readFile(path("rt.png"));
  for (const int ranks : {1, 2, 3})
    for (const int threads : {1, 2}) {
      const std::string out =
          path("mpi-" + std::to_string(ranks) + "x" + std::to_string(threads) + ".png");
      const RtResult r = runMpi(ranks, {"render", "galaxy", "--width", "96", "-o", out, "-q",
                                        "--threads", std::to_string(threads)});
      ASSERT_EQ(r.exitCode, 0) << ranks << "x" << threads << ": " << r.err;
      EXPECT_EQ(readFile(out), expected) << ranks << " ranks x " << threads << " threads";
      const std::string where = "on " + std::to_string(ranks) +
                                (ranks == 1 ? " rank x " : " ranks x ") + std::to_string(threads) +
                                (threads == 1 ? " thread" : " threads");
      EXPECT_NE(r.err.find("rt-mpi: wrote " + out + ": 96x54, tracer beams, 5184 primary rays"),
                std::string::npos)
          << r.err;
      EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
    }
}

TEST_F(RtMpi, ASampledSceneFileIsTheBytesOfRtRender) {
  const std::string scene = std::string(RT_SCENES_DIR) + "/soft-shadows.json";
  ASSERT_EQ(runRt({"render", scene, "--width", "64", "-o", path("rt.png"), "-s"}).exitCode, 0);
  for (const int ranks : {1, 2, 3}) {
    const std::string out = path("mpi-" + std::to_string(ranks) + ".png");
    const RtResult r = runMpi(ranks, {"render", scene, "--width", "64", "-o", out, "-s"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readFile(out), readFile(path("rt.png"))) << ranks << " ranks";
  }
}

TEST_F(RtMpi, RankZeroSendsTheSceneAndItsModelFileToRanksThatCannotReadThem) {
  // Rank 1 starts in an empty folder: the relative scene path, and the model file the scene
  // names, exist only for rank 0. Both ranks render (one thread each), so rank 1's tiles come
  // from the bytes rank 0 sent.
  const std::string scenesParent = fs::path(RT_SCENES_DIR).parent_path().string();
  const std::string empty = path("empty");
  fs::create_directories(empty);
  const std::string scene = "scenes/model-shading.json";
  RtOptions inRepository;
  inRepository.cwd = scenesParent;
  ASSERT_EQ(
      runRt({"render", scene, "--width", "640", "-o", path("rt.png"), "-s"}, inRepository).exitCode,
      0);
  std::vector<std::string> command{RT_MPIEXEC,
                                   "--oversubscribe",
                                   "--allow-run-as-root",
                                   "--mca",
                                   "btl_vader_single_copy_mechanism",
                                   "none"};
  const std::vector<std::string> args{"render", scene,           "--width",   "640",
                                      "-o",     path("mpi.png"), "--threads", "1"};
  for (const std::string& wdir : {scenesParent, empty}) {
    if (wdir == empty) command.push_back(":");
    command.insert(command.end(), {"-np", "1", "-wdir", wdir, RT_MPI_EXE});
    command.insert(command.end(), args.begin(), args.end());
  }
  const RtResult r = runProgram(command);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(path("mpi.png")), readFile(path("rt.png")));
  // 640x320 in tiles of 32: 20 x 10 tiles (0.15 s of work on one thread), enough that rank 1
  // renders some of them, from the bytes it got, before rank 0 alone has done them all.
  const std::size_t at = r.err.find("rt-mpi: dealt 200 tiles on demand (rank 0: ");
  ASSERT_NE(at, std::string::npos) << r.err;
  const std::size_t one = r.err.find(", rank 1: ", at);
  ASSERT_NE(one, std::string::npos) << r.err;
  const int rank0 = std::stoi(r.err.substr(at + 43));
  const int rank1 = std::stoi(r.err.substr(one + 10));
  EXPECT_EQ(rank0 + rank1, 200) << r.err;
  EXPECT_GE(rank1, 1) << r.err;
}

TEST_F(RtMpi, AnimateFramesAreTheBytesOfRtAnimateDealtAsFramesOrAsTiles) {
  ASSERT_EQ(runRt({"animate", "galaxy", "--orbit", "60", "--frames", "3", "--width", "48", "-o",
                   path("rt"), "-s"})
                .exitCode,
            0);
  // 3 frames on 2 ranks: whole frames; 3 frames on 3 ranks: still frames; 1 frame (--frame) on
  // 3 ranks: tiles.
  for (const int ranks : {2, 3}) {
    const std::string out = path("mpi-" + std::to_string(ranks));
    const RtResult r = runMpi(ranks, {"animate", "galaxy", "--orbit", "60", "--frames", "3",
                                      "--width", "48", "-o", out, "--threads", "1"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("dealing frames"), std::string::npos) << r.err;
    for (const char* frame : {"frame-0000.png", "frame-0001.png", "frame-0002.png"})
      EXPECT_EQ(readFile(out + "/" + frame), readFile(path("rt/") + frame)) << ranks << frame;
  }
  const RtResult tiles = runMpi(3, {"animate", "galaxy", "--orbit", "60", "--frames", "3",
                                    "--frame", "1", "--width", "48", "-o", path("tiles")});
  ASSERT_EQ(tiles.exitCode, 0) << tiles.err;
  // 48 x 27 to 3 ranks x 2 threads: 2 tiles of 32 and 6 of 16 are fewer than 8 a thread.
  EXPECT_NE(tiles.err.find("dealing tiles of 8x8"), std::string::npos) << tiles.err;
  EXPECT_EQ(readFile(path("tiles/frame-0001.png")), readFile(path("rt/frame-0001.png")));
}

TEST_F(RtMpi, ABadSceneFailsEveryRankWithOneMessageAndWritesNothing) {
  {
    std::ofstream(path("bad.json"))
        << "{\n  \"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], "
           "\"vpDistance\": 10, \"vpSize\": [4, 4], \"resolution\": [8, 8]},\n"
           "  \"geometries\": [\n    {\"type\": \"sphere\", \"center\": [0, 0, 0], "
           "\"radius\": -2}\n  ]\n}\n";
  }
  std::ofstream(path("bad.png")) << "the image of an earlier run";
  // The message is rt render's, with rt-mpi's name: the scene's line and column, the key, the
  // value.
  const RtResult single = runRt({"render", path("bad.json"), "-o", path("bad.png")});
  ASSERT_EQ(single.exitCode, 2) << single.err;
  ASSERT_EQ(single.err.rfind("rt: ", 0), 0u) << single.err;
  const std::string message = single.err.substr(4, single.err.find('\n') - 4);
  EXPECT_EQ(message, path("bad.json") +
                         ":4:55: geometries[0].radius: expected a positive "
                         "number, got -2");
  const RtResult r = runMpi(3, {"render", path("bad.json"), "-o", path("bad.png")});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  const std::vector<std::string> lines = rtMpiLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0], "rt-mpi: " + message);
  EXPECT_EQ(readFile(path("bad.png")), "the image of an earlier run");
}

TEST_F(RtMpi, ARankOutOfMemoryBuildingTheSceneIsNamedAndNothingIsWritten) {
  // Rank 1 may map at most 400 MB: too little for a galaxy of four million stars (its shapes
  // alone are 4 x 10^6 x 104 bytes), which rank 0 builds (and checks) fine.
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "under AddressSanitizer a process reserves terabytes of address space for its "
                  "shadow memory, which ulimit -v refuses before main; the release build runs "
                  "this test";
#endif
  std::vector<std::string> command{RT_MPIEXEC,
                                   "--oversubscribe",
                                   "--allow-run-as-root",
                                   "--mca",
                                   "btl_vader_single_copy_mechanism",
                                   "none",
                                   "-np",
                                   "1",
                                   RT_MPI_EXE};
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string failure =
      "rt-mpi: rank 1 on " + std::string(host) + ": cannot build the scene: out of memory";
  // A render, then an animation, whose frames' folder rank 0 made before the failure.
  const std::vector<std::pair<std::vector<std::string>, std::string>> jobs{
      {{"render", "galaxy", "--param", "stars=4000000", "--width", "32", "-o", path("oom.png"),
        "-q"},
       failure},
      {{"animate", "galaxy", "--orbit", "30", "--frames", "2", "--param", "stars=4000000",
        "--width", "32", "-o", path("oom-frames"), "-q"},
       failure + "; no frame written; " + path("oom-frames") + ", which this run made, removed"}};
  for (const auto& [args, message] : jobs) {
    SCOPED_TRACE(args.front());
    std::vector<std::string> job = command;
    job.insert(job.end(), args.begin(), args.end());
    job.insert(job.end(), {":", "-np", "1", "sh", "-c",
                           std::string("ulimit -v 400000 && exec \"$0\" \"$@\""), RT_MPI_EXE});
    job.insert(job.end(), args.begin(), args.end());
    const RtResult r = runProgram(job);
    EXPECT_NE(r.exitCode, 0);
    const std::vector<std::string> lines = rtMpiLines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0], message);
  }
  EXPECT_FALSE(fs::exists(path("oom.png")));
  EXPECT_FALSE(fs::exists(path("oom-frames")));
}

TEST_F(RtMpi, ARankKilledMidRenderFailsTheJobAndNothingIsWritten) {
  const std::string out = earlierImage("kept.png");
  RtChild job(interruptibleRender(out));
  ASSERT_TRUE(job.waitForLine("rt-mpi: rendering 10%")) << job.err();
  std::vector<std::pair<pid_t, int>> ranks = ranksRunning(out);
  pid_t victim = -1;
  for (const auto& [pid, rank] : ranks)
    if (rank == 1) victim = pid;
  ASSERT_GT(victim, 0) << "rank 1 not found among " << ranks.size() << " processes";
  ::kill(victim, SIGKILL);
  const int code = job.wait();
  EXPECT_NE(code, 0) << job.err();
  EXPECT_NE(job.err().find("rank 1"), std::string::npos) << job.err();  // mpirun names it
  EXPECT_EQ(readFile(out), "an earlier image");
  EXPECT_TRUE(ranksRunning(out).empty());
}

TEST_F(RtMpi, CtrlCOnMpirunStopsEveryRankAndLeavesTheImageAsItWas) {
  const std::string out = earlierImage("kept.png");
  RtChild job(interruptibleRender(out));
  ASSERT_TRUE(job.waitForLine("rt-mpi: rendering 10%")) << job.err();
  job.signal(SIGINT);
  const int code = job.wait();
  EXPECT_NE(code, 0) << job.err();
  EXPECT_NE(job.err().find("rt-mpi: interrupted after "), std::string::npos) << job.err();
  EXPECT_NE(job.err().find("pixels; nothing written to " + out), std::string::npos) << job.err();
  EXPECT_EQ(readFile(out), "an earlier image");
  // Every rank has ended (mpirun waits for them).
  EXPECT_TRUE(ranksRunning(out).empty());
}

TEST_F(RtMpi, CtrlCOnMpirunBeforeAnyFrameLeavesNoFolderOfItsOwn) {
  const std::string frames = path("frames");
  RtChild job(Program{mpirun(2, {"animate", "galaxy", "--orbit", "30", "--frames", "2", "--width",
                                 "480", "--threads", "1", "-o", frames})});
  ASSERT_TRUE(job.waitForLine("rt-mpi: animating galaxy (2 frames")) << job.err();
  job.signal(SIGINT);
  EXPECT_NE(job.wait(), 0) << job.err();
  EXPECT_NE(
      job.err().find("pixels; no frame written; " + frames + ", which this run made, removed"),
      std::string::npos)
      << job.err();
  EXPECT_FALSE(fs::exists(frames));
  EXPECT_TRUE(ranksRunning(frames).empty());
}

// Ctrl-C on mpirun while rank 0 encodes the video: ffmpeg is ended, the partial video removed,
// an earlier one left as it was, and the frames, all written, stay. The ffmpeg here is a stand-in
// that begins the temporary video it is asked for (its last argument), then writes its process
// id to a file and waits: the signal is sent once that file is there. mpirun, run by its full
// path, puts its own folder (where the real ffmpeg may be) first on the ranks' PATH, so the
// stand-in's folder is put first by env, between mpirun and rt-mpi.
TEST_F(RtMpi, CtrlCOnMpirunWhileEncodingEndsFfmpegAndKeepsTheFrames) {
  const fs::path bin = path("bin");
  fs::create_directory(bin);
  const std::string started = (bin / "started").string();
  writeText((bin / "ffmpeg").string(),
            "#!/bin/sh\n"
            "for last; do :; done\n"
            "printf 'a partial video' > \"$last\"\n"
            "echo $$ > \"$0.pid\" && mv \"$0.pid\" '" +
                started + "'\nexec sleep 60\n");
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  const std::string frames = path("f"), video = writeText(path("v.mp4"), "an earlier video");
  std::vector<std::string> argv =
      mpirun(2, {"animate", "galaxy", "--orbit", "30", "--frames", "2", "--width", "16",
                 "--threads", "1", "-o", frames, "--video", video});
  const auto program = std::find(argv.begin(), argv.end(), std::string(RT_MPI_EXE));
  argv.insert(program, {"/usr/bin/env", "PATH=" + bin.string() + ":/usr/bin:/bin"});
  RtChild job(Program{argv});
  ASSERT_TRUE(job.waitForLine("rt-mpi: dealt 2 frames")) << job.err();  // the encoding next
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(started) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(started)) << "the stand-in ffmpeg did not start";
  std::string ffmpeg = readFile(started);
  ffmpeg.erase(ffmpeg.find_last_not_of('\n') + 1);  // its process id
  // The partial video is there before the signal: its removal is what is checked below.
  std::vector<std::string> partial;
  for (const fs::directory_entry& e : fs::directory_iterator(dir_))
    if (e.path().filename().string().starts_with(".rt-")) partial.push_back(readFile(e.path()));
  ASSERT_EQ(partial, std::vector<std::string>{"a partial video"});
  job.signal(SIGINT);
  // mpirun, interrupted itself, exits with 1 (docs/distributed.md); rank 0's line says what
  // happened.
  EXPECT_EQ(job.wait(), 1) << job.err();
  const std::vector<std::string> lines = rtMpiLines(job.err());
  ASSERT_FALSE(lines.empty()) << job.err();
  EXPECT_EQ(lines.back(), "rt-mpi: interrupted while encoding " + video +
                              " (nothing written to it; 2 whole frames written to " + frames + ")");
  // ffmpeg has ended: no process of its id runs (a zombie has no command line).
  EXPECT_EQ(readFile("/proc/" + ffmpeg + "/cmdline"), "") << "ffmpeg, process " << ffmpeg;
  EXPECT_EQ(readFile(video), "an earlier video");
  std::vector<std::string> left, framesLeft;
  for (const fs::directory_entry& e : fs::directory_iterator(dir_))
    left.push_back(e.path().filename().string());
  for (const fs::directory_entry& e : fs::directory_iterator(frames))
    framesLeft.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  std::sort(framesLeft.begin(), framesLeft.end());
  EXPECT_EQ(left, (std::vector<std::string>{"bin", "f", "v.mp4"}));  // no partial video
  EXPECT_EQ(framesLeft, (std::vector<std::string>{"frame-0000.png", "frame-0001.png"}));
  EXPECT_TRUE(ranksRunning(frames).empty());
  // The frames are whole: rt animate's bytes.
  const RtResult rt = runRt({"animate", "galaxy", "--orbit", "30", "--frames", "2", "--width", "16",
                             "-o", path("rt"), "-q"});
  ASSERT_EQ(rt.exitCode, 0) << rt.err;
  for (const std::string& frame : framesLeft)
    EXPECT_EQ(readFile(frames + "/" + frame), readFile(path("rt/" + frame))) << frame;
}

TEST_F(RtMpi, AnimateEncodesTheVideoOnRankZero) {
  if (runProgram({"/bin/sh", "-c", "command -v ffmpeg && command -v ffprobe"}).exitCode != 0)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/deps.sh --video installs it)";
  const RtResult r =
      runMpi(2, {"animate", "galaxy", "--orbit", "360", "--frames", "4", "--width", "48", "-o",
                 path("f"), "--video", path("v.mp4"), "--threads", "1", "-q"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const RtResult probe =
      runProgram({"/bin/sh", "-c",
                  "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                  "stream=nb_read_frames,width,height -of csv=p=0 \"$0\"",
                  path("v.mp4")});
  EXPECT_EQ(probe.out, "48,28,4\n") << probe.err;  // 48x27 padded to an even height
}

}  // namespace
}  // namespace rt::cli::test
