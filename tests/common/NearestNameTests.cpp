// The one nearest-name rule of every "did you mean" (common/NearestName.h).
#include <gtest/gtest.h>

#include <string_view>
#include <vector>

#include "common/NearestName.h"

namespace rt {
namespace {

using Names = std::vector<std::string_view>;

TEST(NearestNameTests, nearestName) {
  const Names commands{"list", "render", "probe", "export"};
  // ============ Equivalence Partitions Tests ==============
  // TC01: one letter missing from a long name
  EXPECT_EQ(nearestName("rendr", commands), "render");
  // TC02: two adjacent letters swapped count as one edit
  EXPECT_EQ(nearestName("raduis", Names{"center", "radius"}), "radius");
  // TC03: case is ignored: a slip of the shift key is distance 0
  EXPECT_EQ(nearestName("kd", Names{"kD", "kS", "kT"}), "kD");
  EXPECT_EQ(nearestName("RENDER", commands), "render");
  // TC04: nothing near
  EXPECT_EQ(nearestName("zzzzzz", commands), "");
  // TC05: of two near names, the nearer wins, wherever it is listed
  EXPECT_EQ(nearestName("colr", Names{"colour", "color"}), "color");
  // TC06: of two equally near names, the first listed wins
  EXPECT_EQ(nearestName("hat", Names{"cat", "bat"}), "cat");

  // =============== Boundary Values Tests ==================
  // TC11: a name of up to five characters allows one edit
  EXPECT_EQ(nearestName("phog", Names{"phong"}), "phong");
  // TC12: ... and not two ("prbo" is a swap and an insertion away from "probe")
  EXPECT_EQ(nearestName("prbo", commands), "");
  // TC13: a four-letter name two edits away is not suggested ("ls" for "list")
  EXPECT_EQ(nearestName("ls", commands), "");
  // TC14: a six-character name allows two edits
  EXPECT_EQ(nearestName("rndr", commands), "render");
  // TC15: ... and not three
  EXPECT_EQ(nearestName("rnd", commands), "");
  // TC16: a name of 18 characters allows three edits, the cap, and not four
  EXPECT_EQ(nearestName("al-fetures-abve", Names{"all-features-above"}), "all-features-above");
  EXPECT_EQ(nearestName("al-fetures-bve", Names{"all-features-above"}), "");
  // TC17: no known names
  EXPECT_EQ(nearestName("render", Names{}), "");
}

TEST(NearestNameTests, didYouMean) {
  const Names keys{"center", "radius"};
  // ============ Equivalence Partitions Tests ==============
  // TC01: a near name: the phrase the messages append
  EXPECT_EQ(didYouMean("raduis", keys), "; did you mean 'radius'?");
  // TC02: no near name: nothing
  EXPECT_EQ(didYouMean("colour", keys), "");
}

}  // namespace
}  // namespace rt
