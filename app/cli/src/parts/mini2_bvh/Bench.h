#pragma once
// Internal to mini2's part of rt: the `rt bench` command (timing across stages and accelerations,
// and the galaxy's star scaling and the teapot's triangle scaling), which only a build with mini
// project 2 has. Bench.cpp
// registers it; BenchRows.cpp runs the timing table, BenchScaling.cpp the scalings,
// BenchOutput.cpp chooses where the table goes and writes it.

#include <optional>
#include <string>
#include <vector>

#include "CommandRegistration.h"

namespace rt::cli {

class CommandLine;
struct Destinations;

/// Adds `rt bench [SCENE]` to rt's command line (registered by mini2's part, registry.commands).
void addBenchCommand(CommandLine& rt);

/// rt bench's arguments, as the command line binds them.
struct BenchArgs {
  SceneArguments scene;
  bool full = false;
  int repeat = 1;
  bool csv = false, json = false;
  std::vector<std::string> outputs;  ///< -o FILE, repeatable: one run, several files
  bool scaling = false;
  std::optional<std::string> stars;
  std::optional<std::string> details;
};

/// --stars' default: the galaxy at 10^3 to 10^6 stars.
inline constexpr const char* DEFAULT_STARS = "1000,10000,100000,1000000";
/// --details' default: the teapot at about 10^3, 10^4, 10^5 and 10^6 triangles (64·d² − 8·d:
/// 992, 10712, 102080, 999000).
inline constexpr const char* DEFAULT_DETAILS = "4,13,40,125";

/// "1000,10000" → {1000, 10000} (into values, when given), each from lo to hi.
/// @returns the message of the first bad item (without the option's name), or "" for a good
///          list.
std::string integerListError(const std::string& list, int lo, int hi,
                             std::vector<long>* values = nullptr);

/// The timing table: the scene rendered with the reference report's rows, then by every stage's
/// tracer through the BVH. @returns the exit code. @throws UsageError before the first ray.
int benchRows(const BenchArgs& args, const Destinations& to, const Io& io);

/// The galaxy's star scaling or the teapot's triangle scaling, each scene and structure in a
/// process of its own. @returns the exit code. @throws UsageError before the first scene.
int benchScaling(const BenchArgs& args, const Destinations& to, const Io& io);

/// The threads of the multi-threaded rows: --threads, 0 (the default) meaning one per core, at
/// most the pool's RenderOptions::MAX_THREADS.
int benchThreads(const BenchArgs& args);

/// "1 thread", "2 threads".
std::string threadsText(int n);

/// Says on io.err that the bench stopped at where and wrote nothing. @returns EXIT_INTERRUPTED.
int benchInterrupted(const std::string& where, const BenchArgs& args, const Io& io);

}  // namespace rt::cli
