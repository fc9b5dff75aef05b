// Hostile input: whatever the bytes, parseScene returns a document or throws SceneError, never
// anything else (the contract the fuzzer, fuzz/SceneFuzzer.cpp, checks). Inputs the fuzzer
// found are kept here as regressions.
#include <gtest/gtest.h>

#include <string>

#include "scenefile/SceneFile.h"

namespace rt {
namespace {

/// True when text is rejected with a SceneError (any other exception fails the test).
bool rejected(const std::string& text) {
  try {
    (void)parseScene(text, "fuzz.json");
    return false;
  } catch (const SceneError&) {
    return true;
  }
}

TEST(HostileInputTest, Rejected) {
  // EP01: invalid UTF-8 inside a string.
  EXPECT_TRUE(rejected("{\"name\": \"\xFF\xFE\"}"));
  // EP02: a NUL byte in the text.
  EXPECT_TRUE(rejected(std::string("{\"name\": \"a\0b\"}", 15)));
  // EP03: nesting far deeper than the limit (stopped before it costs stack or memory).
  EXPECT_TRUE(rejected(std::string(100000, '[') + std::string(100000, ']')));
  // EP04: a huge key, quoted back shortened.
  EXPECT_TRUE(rejected("{\"" + std::string(1 << 20, 'k') + "\": 1}"));
  // EP05: an integer beyond 64 bits where an integer is expected.
  EXPECT_TRUE(
      rejected("{\"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], "
               "\"vpDistance\": 1, \"vpSize\": [1, 1], "
               "\"resolution\": [123456789012345678901234567890, 1]}}"));
  // EP06: integers at the edges of the int64 and uint64 ranges.
  for (const char* n : {"-9223372036854775808", "18446744073709551615", "-1", "2147483648"})
    EXPECT_TRUE(
        rejected(std::string("{\"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], "
                             "\"vpDistance\": 1, \"vpSize\": [1, 1], \"resolution\": [") +
                 n + ", 1]}}"))
        << n;
  // EP07: a camera whose view is degenerate (up along the view direction).
  EXPECT_TRUE(
      rejected("{\"camera\": {\"location\": [0, 0, 0], \"target\": [0, 5, 0], "
               "\"vpDistance\": 1, \"vpSize\": [1, 1], \"resolution\": [1, 1]}}"));
}

}  // namespace
}  // namespace rt
