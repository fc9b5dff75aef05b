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

TEST(NearestNameTests, containedNames) {
  const Names lights{"directional", "point", "spot"};
  const Names shapes{"sphere", "plane", "triangle", "polygon", "tube", "cylinder"};
  // ============ Equivalence Partitions Tests ==============
  // TC01: a known name inside the word, five edits away ("spotlight" for "spot")
  EXPECT_EQ(nearestName("spotlight", lights), "spot");
  // TC02: the word is the start of a known name (an abbreviation)
  EXPECT_EQ(nearestName("cyl", shapes), "cylinder");
  // TC03: the word is inside a known name, not at its start
  EXPECT_EQ(nearestName("mirrors", Names{"two-color", "hall-of-mirrors"}), "hall-of-mirrors");
  // TC04: case is ignored
  EXPECT_EQ(nearestName("SpotLight", lights), "spot");
  // TC05: the edit-distance rule comes first: "spotlighs" is one edit away, though "spot",
  // listed first, is inside the word
  EXPECT_EQ(nearestName("spotlight", Names{"spot", "spotlighs"}), "spotlighs");
  // TC06: of several names that contain the word, the closest in length
  EXPECT_EQ(nearestName("light-sphere", Names{"light-sphere-directional", "light-sphere-spot",
                                              "light-sphere-point"}),
            "light-sphere-spot");
  // TC07: ... the first listed on a tie
  EXPECT_EQ(nearestName("all-features", Names{"all-features-below", "all-features-above"}),
            "all-features-below");
  // TC08: neither contains the other
  EXPECT_EQ(nearestName("sun", lights), "");

  // =============== Boundary Values Tests ==================
  // TC11: the shorter of the two has three characters: suggested
  EXPECT_EQ(nearestName("tri", shapes), "triangle");
  EXPECT_EQ(nearestName("index-ior", Names{"kD", "ior"}), "ior");
  // TC12: ... two characters: not ("cy" starts "cylinder", "kD" is inside "kDiffuse")
  EXPECT_EQ(nearestName("cy", shapes), "");
  EXPECT_EQ(nearestName("kDiffuse", Names{"kD", "kS"}), "");
}

TEST(NearestNameTests, didYouMean) {
  const Names keys{"center", "radius"};
  // ============ Equivalence Partitions Tests ==============
  // TC01: a near name: the phrase the messages append
  EXPECT_EQ(didYouMean("raduis", keys), "; did you mean 'radius'?");
  // TC02: no near name: nothing
  EXPECT_EQ(didYouMean("colour", keys), "");
  // TC03: a name inside the word
  EXPECT_EQ(didYouMean("spotlight", Names{"point", "spot"}), "; did you mean 'spot'?");
}

TEST(NearestNameTests, joinNames) {
  const Names three{"a", "bb", "c"};
  // ============ Equivalence Partitions Tests ==============
  // TC01: comma-separated by default; TC02: another separator
  EXPECT_EQ(joinNames(three), "a, bb, c");
  EXPECT_EQ(joinNames(three, " "), "a bb c");
  // TC03: more names than listed: the rest counted
  EXPECT_EQ(joinNames(three, ", ", 2), "a, bb and 1 more");
  // =============== Boundary Values Tests ==================
  // TC11: exactly as many names as listed: no count; TC12: no names, nothing
  EXPECT_EQ(joinNames(three, ", ", 3), "a, bb, c");
  EXPECT_EQ(joinNames(Names{}), "");
}

TEST(NearestNameTests, unknownNameMessage) {
  const Names tracers{"rays", "phong", "shadows"};
  // ============ Equivalence Partitions Tests ==============
  // TC01: a near name: suggested, then every known name
  EXPECT_EQ(unknownNameMessage("tracer", "phog", tracers),
            "unknown tracer 'phog'; did you mean 'phong'? (known: rays phong shadows)");
  // TC02: no near name: only the known names
  EXPECT_EQ(unknownNameMessage("tracer", "zzzz", tracers),
            "unknown tracer 'zzzz' (known: rays phong shadows)");
}

TEST(NearestNameTests, needsStageMessage) {
  // TC01: the kind of name, the name and the stage that would know it
  EXPECT_EQ(needsStageMessage("key", "lights", "stage05_lighting"),
            "the key 'lights' needs stage05_lighting, which this build does not include (a "
            "course cut before it)");
}

}  // namespace
}  // namespace rt
