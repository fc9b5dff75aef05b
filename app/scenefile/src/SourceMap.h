#pragma once
/// @file SourceMap.h
/// Where every value of a JSON text starts, so that an error found after parsing (a negative
/// radius, an unknown key) can name its line and column.
///
/// nlohmann's DOM keeps no positions, so the text is first read through nlohmann's SAX
/// interface. The SAX events come in document order; the handler keeps a cursor into the text
/// and, at each event, skips the whitespace and separators (',' ':') in front of the token and
/// then the token itself. The cursor therefore sits on the first character of each value when
/// its event arrives, and that offset is recorded.
///
/// The values are stored flat, in document (pre-)order, each with the index one past its
/// subtree: the first child of entry i is i + 1, the next sibling of entry i is entries[i].end.
/// Twelve bytes a value, and no key strings: a member's key is the key at the same index in the
/// DOM object (duplicate keys are rejected, so the DOM keeps the document's order).
///
/// The same pass enforces what the DOM would hide or what would cost too much: duplicate keys
/// (the DOM silently keeps the last), non-finite numbers (reported with their path), and absurd
/// nesting (the format is at most six levels deep, a beam of the material of a model file's
/// group; MAX_DEPTH stops a hostile file early).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt::scenefile {

/// The position of one value of the document.
struct SourceEntry {
  static constexpr std::uint32_t NONE = 0xFFFFFFFFu;
  std::uint32_t keyOffset = NONE;    ///< offset of the member's key (its opening quote)
  std::uint32_t valueOffset = NONE;  ///< offset of the value's first character
  std::uint32_t end = 0;             ///< index one past this value's subtree
};

/// The positions of every value of a document; entry 0 is the document itself.
struct SourceMap {
  std::vector<SourceEntry> entries;

  /// Index of the k-th child of entry parent (member or element, in document order), or NONE.
  std::uint32_t child(std::uint32_t parent, std::size_t k) const;
};

/// A line and a column, both 1-based; the column counts characters (UTF-8 code points).
struct LineColumn {
  int line = 0;
  int column = 0;
};

/// Line and column of a byte offset in text (an offset past the end is clamped to the end).
LineColumn lineColumnOf(std::string_view text, std::size_t offset);

/// What the first pass found wrong.
struct SyntaxProblem {
  std::size_t offset = 0;  ///< byte offset of the offending character or token
  std::string path;        ///< display path of the value concerned ("" for malformed JSON)
  std::string detail;
};

/// Deepest nesting of arrays and objects accepted.
inline constexpr int MAX_DEPTH = 64;

/// The largest text parseScene accepts (offsets are kept in 32 bits): 1 GiB.
inline constexpr std::size_t MAX_TEXT_BYTES = std::size_t{1} << 30;

/// Runs the first pass over text (strict JSON: one value, then only whitespace). Fills map and
/// returns nothing when the text is valid; returns the first problem otherwise.
std::optional<SyntaxProblem> scanSource(std::string_view text, SourceMap& map);

/// Display paths: "camera" + "location" -> "camera.location"; a key that is not an identifier
/// is quoted (materials["my glass"]); an element is "[3]". The document's path is "".
void appendMember(std::string& path, std::string_view key);
void appendElement(std::string& path, std::size_t index);

}  // namespace rt::scenefile
