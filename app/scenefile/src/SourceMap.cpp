#include "SourceMap.h"

#include <algorithm>
#include <cctype>
#include <unordered_set>

#include <nlohmann/json.hpp>

namespace rt::scenefile {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isSeparator(char c) { return isSpace(c) || c == ',' || c == ':'; }
/// A character of a number or of the literals true, false and null.
bool isWordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}
bool isIdentifier(std::string_view key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

/// The SAX handler of the first pass (see SourceMap.h).
class Recorder {
 public:
  using Json = nlohmann::ordered_json;

  Recorder(std::string_view text, SourceMap& map) : text_(text), map_(map) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") cursor_ = 3;  // nlohmann skips a UTF-8 BOM too
  }

  const std::optional<SyntaxProblem>& problem() const { return problem_; }

  // --- nlohmann's SAX interface ---
  bool null() { return scalar(); }
  bool boolean(bool) { return scalar(); }
  bool number_integer(Json::number_integer_t) { return scalar(); }
  bool number_unsigned(Json::number_unsigned_t) { return scalar(); }
  bool number_float(Json::number_float_t, const Json::string_t&) { return scalar(); }
  bool string(Json::string_t&) { return scalar(); }
  bool binary(Json::binary_t&) { return scalar(); }
  bool start_object(std::size_t) { return open(true); }
  bool start_array(std::size_t) { return open(false); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(Json::string_t& name) {
    const std::size_t at = tokenStart();
    skipToken();
    Frame& frame = frames_.back();
    if (!frame.keys.insert(name).second) {
      std::string path = pathOfTop();
      appendMember(path, name);
      problem_ = SyntaxProblem{at, std::move(path), "duplicate key '" + name + "'"};
      return false;
    }
    pendingKey_ = name;
    pendingKeyOffset_ = static_cast<std::uint32_t>(at);
    return true;
  }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    // position counts the characters read, the offending one included.
    const std::size_t failed = std::min(position == 0 ? 0 : position - 1, text_.size());
    const std::size_t start = tokenStart();
    // The lexer fails after reading a bad number or literal ("tru}" fails at '}'): point at
    // the token's start then. Elsewhere (inside a string, a stray separator) it points at the
    // offending character itself.
    std::size_t at = failed;
    if (start < failed &&
        std::all_of(text_.begin() + static_cast<std::ptrdiff_t>(start),
                    text_.begin() + static_cast<std::ptrdiff_t>(failed), isWordChar))
      at = start;
    if (e.id == 406) {  // out_of_range.406: a number too large for a double (1e999)
      std::size_t end = start;
      while (end < text_.size() && isWordChar(text_[end])) ++end;
      problem_ = SyntaxProblem{
          start, pathOfPending(),
          "expected a finite number, got " + std::string(text_.substr(start, end - start))};
      return false;
    }
    std::string message = e.what();
    const std::size_t head = message.find("parse error");
    const std::size_t colon = head == std::string::npos ? head : message.find(": ", head);
    if (colon != std::string::npos) message.erase(0, colon + 2);
    problem_ = SyntaxProblem{at, "", "malformed JSON: " + message};
    return false;
  }

 private:
  struct Frame {
    std::uint32_t entry;  ///< index of the container's entry
    bool isObject;
    std::size_t children = 0;  ///< children recorded so far
    std::unordered_set<std::string> keys;
    std::string segmentKey;  ///< the container's key in its parent object
  };

  std::size_t tokenStart() {
    while (cursor_ < text_.size() && isSeparator(text_[cursor_])) ++cursor_;
    return cursor_;
  }

  void skipToken() {
    if (cursor_ >= text_.size()) return;
    const char c = text_[cursor_];
    if (c == '"') {
      ++cursor_;
      while (cursor_ < text_.size() && text_[cursor_] != '"')
        cursor_ += text_[cursor_] == '\\' ? 2 : 1;
      cursor_ = std::min(cursor_ + 1, text_.size());
    } else if (isWordChar(c)) {
      while (cursor_ < text_.size() && isWordChar(text_[cursor_])) ++cursor_;
    } else {
      ++cursor_;  // { [ } ]
    }
  }

  /// Records the value whose token starts at the cursor; returns its entry index.
  std::uint32_t beginValue() {
    const std::size_t at = tokenStart();
    SourceEntry entry;
    entry.valueOffset = static_cast<std::uint32_t>(at);
    if (!frames_.empty()) {
      Frame& parent = frames_.back();
      if (parent.isObject) entry.keyOffset = pendingKeyOffset_;
      ++parent.children;
    }
    const auto index = static_cast<std::uint32_t>(map_.entries.size());
    entry.end = index + 1;
    map_.entries.push_back(entry);
    return index;
  }

  bool scalar() {
    beginValue();
    skipToken();
    return true;
  }

  bool open(bool isObject) {
    if (frames_.size() >= static_cast<std::size_t>(MAX_DEPTH)) {
      problem_ = SyntaxProblem{tokenStart(), pathOfPending(),
                               "nesting deeper than " + std::to_string(MAX_DEPTH) +
                                   " levels; a scene file needs at most 6"};
      return false;
    }
    std::string segmentKey =
        !frames_.empty() && frames_.back().isObject ? pendingKey_ : std::string();
    const std::uint32_t index = beginValue();
    skipToken();
    frames_.push_back(Frame{index, isObject, 0, {}, std::move(segmentKey)});
    return true;
  }

  bool close() {
    tokenStart();
    skipToken();
    map_.entries[frames_.back().entry].end = static_cast<std::uint32_t>(map_.entries.size());
    frames_.pop_back();
    return true;
  }

  /// The display path of the innermost open container.
  std::string pathOfTop() const {
    std::string path;
    for (std::size_t i = 1; i < frames_.size(); ++i) {
      if (frames_[i - 1].isObject)
        appendMember(path, frames_[i].segmentKey);
      else
        appendElement(path, frames_[i - 1].children - 1);
    }
    return path;
  }

  /// The display path of the value about to be read.
  std::string pathOfPending() const {
    std::string path = pathOfTop();
    if (frames_.empty()) return path;
    if (frames_.back().isObject)
      appendMember(path, pendingKey_);
    else
      appendElement(path, frames_.back().children);
    return path;
  }

  std::string_view text_;
  SourceMap& map_;
  std::size_t cursor_ = 0;
  std::vector<Frame> frames_;
  std::string pendingKey_;
  std::uint32_t pendingKeyOffset_ = SourceEntry::NONE;
  std::optional<SyntaxProblem> problem_;
};

}  // namespace

std::uint32_t SourceMap::child(std::uint32_t parent, std::size_t k) const {
  if (parent >= entries.size()) return SourceEntry::NONE;
  const std::uint32_t end = entries[parent].end;
  std::uint32_t i = parent + 1;
  for (; i < end && k > 0; --k) i = entries[i].end;
  return i < end ? i : SourceEntry::NONE;
}

LineColumn lineColumnOf(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  LineColumn lc{1, 1};
  // A byte-order mark is invisible in an editor: it takes no column.
  const std::size_t start =
      text.substr(0, 3) == "\xEF\xBB\xBF" ? std::min<std::size_t>(3, offset) : 0;
  for (std::size_t i = start; i < offset; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++lc.line;
      lc.column = 1;
    } else if ((c & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
      ++lc.column;
    }
  }
  return lc;
}

std::optional<SyntaxProblem> scanSource(std::string_view text, SourceMap& map) {
  map.entries.clear();
  if (text.size() > MAX_TEXT_BYTES) return SyntaxProblem{0, "", "the text is larger than 1 GiB"};
  Recorder recorder(text, map);
  const bool ok = nlohmann::ordered_json::sax_parse(text.begin(), text.end(), &recorder);
  if (ok) return std::nullopt;
  if (recorder.problem()) return recorder.problem();
  return SyntaxProblem{0, "", "malformed JSON"};  // not expected: every failure is recorded
}

void appendMember(std::string& path, std::string_view key) {
  if (isIdentifier(key)) {
    if (!path.empty()) path += '.';
    path += key;
  } else {
    path += '[';
    path += nlohmann::ordered_json(std::string(key))
                .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    path += ']';
  }
}

void appendElement(std::string& path, std::size_t index) {
  path += '[';
  path += std::to_string(index);
  path += ']';
}

}  // namespace rt::scenefile
