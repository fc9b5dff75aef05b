// Positions in messages: lines and columns as an editor shows them, whatever the file's line
// endings, byte-order mark or non-ASCII text.
#include <gtest/gtest.h>

#include <string>

#include "scenefile/SceneFile.h"

namespace rt {
namespace {

/// The SceneError of text, or a failure.
SceneError errorOf(const std::string& text) {
  try {
    (void)parseScene(text, "p.json");
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return SceneError("accepted");
}

TEST(SourcePositionTest, LineAndColumn) {
  // EP01: a value on line 3: the column of its first character.
  const SceneError e = errorOf("{\n\n    \"camera\": 5}");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 15);
  // BV01: the first character of the file is 1:1.
  const SceneError first = errorOf("5");
  EXPECT_EQ(first.line, 1);
  EXPECT_EQ(first.column, 1);
}

TEST(SourcePositionTest, WindowsLineEndings) {
  // EP01: CRLF line ends count one line each.
  const SceneError e = errorOf("{\r\n\r\n  \"camera\": 5}");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 13);
}

TEST(SourcePositionTest, ByteOrderMark) {
  // EP01: a UTF-8 byte-order mark is accepted and not counted as a column.
  const SceneError e = errorOf("\xEF\xBB\xBF{\"camera\": 5}");
  EXPECT_EQ(e.line, 1);
  EXPECT_EQ(e.column, 12);
}

TEST(SourcePositionTest, ColumnsCountCharacters) {
  // EP01: "é" (2 bytes) and "☺" (3 bytes) count one column each.
  const SceneError e = errorOf("{\"name\": \"\xC3\xA9\xE2\x98\xBA\", \"camera\": 5}");
  EXPECT_EQ(e.column, 26);
}

TEST(SourcePositionTest, KeyErrorsPointAtTheKey) {
  // EP01: an unknown key is reported where the key starts, not its value.
  const SceneError e = errorOf("{\"camera\": {},\n   \"colour\": [0, 0, 0]}");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 4);
  EXPECT_EQ(e.path, "colour");
}

TEST(SourcePositionTest, LongValuesAreShortened) {
  // EP01: a value longer than 60 characters is quoted up to there, then "...".
  const SceneError e = errorOf("{\"camera\": \"" + std::string(100, 'a') + "\"}");
  EXPECT_EQ(e.detail, "expected a camera object, got \"" + std::string(59, 'a') + "...");
}

}  // namespace
}  // namespace rt
