#pragma once
// Internal to mini2's part of rt: the `rt bench` command (timing across stages and accelerations,
// and the galaxy's star scaling), which only a build with mini project 2 has.

namespace rt::cli {

class CommandLine;

/// Adds `rt bench [SCENE]` to rt's command line (registered by mini2's part, registry.commands).
void addBenchCommand(CommandLine& rt);

}  // namespace rt::cli
